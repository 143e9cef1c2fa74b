#!/usr/bin/env bash
# Peak memory of the text readers against input size (issue 44, "memory bounded by the input"):
# `wifislam eval FILE --gt DATASET` on trajectories that are mostly blank lines (one pose), that
# are bad from line 2 on (a reader must stop there), and that are valid, from 10 to 1000 MB. The
# readers stream: peak RSS should stay near the program's own, whatever the size, except for
# the poses a valid file really holds (valid files up to 100 MB). Reports max RSS (kB, /usr/bin/time) and its ratio to the
# smallest input's in the same run.
#
#   bench/core/reader_memory.sh [build-dir] [scratch] [sizes-in-MB...]
#   (defaults: build/release, a temp dir, 10 100 1000)
set -euo pipefail
build=${1:-build/release}
scratch=${2:-$(mktemp -d)}
shift $(( $# > 2 ? 2 : $# )) || true
sizes=("$@")
[ ${#sizes[@]} -eq 0 ] && sizes=(10 100 1000)
bin="$build/apps/wifislam"
here=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$scratch"
cat >"$scratch/tiny.yaml" <<'YAML'
version: 1
name: tiny
seed: 1
nodes: [{id: A, position_m: [0, 0]}, {id: B, position_m: [8, 0]}]
corridors: [{id: c, from: A, to: B, width_m: 2.4}]
route: {nodes: [A, B], speed_mps: 0.5, pause: {spacing_m: [3.0, 4.0], duration_s: 1.0}}
YAML
rm -rf "$scratch/ds"
"$bin" generate "$scratch/tiny.yaml" --fps 1 --no-images -q -o "$scratch/ds"
first=$(grep -v '^#' "$scratch/ds/groundtruth.txt" | head -1)
rss() {  # max RSS in kB of: "$@"
  /usr/bin/time -f '%M' -o "$scratch/time.txt" "$@" >/dev/null 2>&1 || true
  tail -1 "$scratch/time.txt"
}
echo "kind, MB, max RSS kB, ratio to the smallest, seconds"
for kind in blank bad valid; do
  base=""
  for mb in "${sizes[@]}"; do
    # A valid file's poses are kept: 1000 MB of them is 25 M poses; 100 MB shows the slope.
    if [ "$kind" = valid ] && [ "$mb" -gt 100 ]; then continue; fi
    f="$scratch/$kind-$mb.txt"
    case $kind in
      blank) { head -c $((mb * 1024 * 1024)) /dev/zero | tr '\0' '\n'; echo "$first"; } >"$f" ;;
      bad) { echo "$first"; echo "not a pose"; head -c $((mb * 1024 * 1024)) /dev/zero | tr '\0' 'x'; } >"$f" ;;
      valid) /usr/bin/python3 - "$f" "$mb" <<'PY'
import sys
path, mb = sys.argv[1], int(sys.argv[2])
with open(path, "w") as out:
    t, n = 1700000000.0, 0
    line = "{:.6f} 1.0 2.0 0.0 0 0 0 1\n"
    while n < mb * 1024 * 1024:
        s = line.format(t); out.write(s); n += len(s); t += 0.01
PY
      ;;
    esac
    start=$(date +%s.%N)
    kb=$(rss "$bin" eval "$f" --gt "$scratch/ds" -o "$scratch/eval-$kind-$mb")
    took=$(echo "$(date +%s.%N) - $start" | bc)
    [ -z "$base" ] && base=$kb
    echo "$kind, $mb, $kb, $(echo "scale=2; $kb / $base" | bc), $took"
    rm -f "$f"
  done
done
