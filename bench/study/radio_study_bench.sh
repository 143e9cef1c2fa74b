#!/usr/bin/env bash
# Radio-level study throughput and memory (issue: >= 20 cases per second on 2 cores for a
# c_hall-sized scene; memory flat over a 1000-case study).
#
#   bench/study/radio_study_bench.sh [CASES_PER_SEED_ROW=1000] [JOBS=2]
#
# Writes a study of c_hall x access_points.count (10..80) x placement (rooms, random) x seeds, as
# many cases as asked (rounded to whole seed rows), runs it with --jobs 1 on the first tenth (the
# baseline: one core) and with --jobs JOBS on the whole, samples the process's resident memory every
# second, and prints cases per second, the parallel ratio against the one-core baseline measured
# in the same run, and resident memory at 10 %, 50 % and 100 % of the cases (flat: the later
# samples stay within the shadowing cache's bound, 256 MiB, of the first).
set -euo pipefail
cd "$(dirname "$0")/../.."
want="${1:-1000}"
jobs="${2:-2}"
bin=build/release/apps/wifislam
[ -x "$bin" ] || { echo "build the release preset first (scripts/build.sh)" >&2; exit 2; }
work=$(mktemp -d /tmp/wifislam_radio_bench.XXXXXX)
trap 'rm -rf -- "$work"' EXIT

per_seed=16  # 8 counts x 2 placements
seeds=$(( (want + per_seed - 1) / per_seed ))
seed_list=$(seq -s, 1 "$seeds")
make_study() {  # name seeds
  cat > "$work/$1.yaml" <<YAML
version: 1
name: $1
scene: $PWD/scenes/c_hall.yaml
level: radio
axes:
  access_points.count: [10, 20, 30, 40, 50, 60, 70, 80]
  access_points.placement: [rooms, random]
  seed: [$2]
YAML
}
make_study bench_all "$seed_list"
make_study bench_base "$(seq -s, 1 $(( (seeds + 9) / 10 )))"

run() {  # name jobs -> prints "cases seconds" and writes $work/name.rss
  local name=$1 j=$2 start end pid
  start=$(date +%s.%N)
  "$bin" study run "$work/$name.yaml" -q --jobs "$j" -o "$work/$name.sqlite" > "$work/$name.out" &
  pid=$!
  : > "$work/$name.rss"
  while kill -0 "$pid" 2>/dev/null; do
    awk '/VmRSS/ {print $2}' "/proc/$pid/status" 2>/dev/null >> "$work/$name.rss" || true
    sleep 1
  done
  wait "$pid"
  end=$(date +%s.%N)
  local cases
  cases=$(sqlite3 "$work/$name.sqlite" 'select count(*) from results')
  echo "$cases $(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')"
}

read -r base_cases base_s < <(run bench_base 1)
read -r all_cases all_s < <(run bench_all "$jobs")
base_rate=$(awk -v c="$base_cases" -v s="$base_s" 'BEGIN {print c / s}')
all_rate=$(awk -v c="$all_cases" -v s="$all_s" 'BEGIN {print c / s}')
printf 'one core (baseline): %d cases in %.1f s = %.1f cases/s\n' "$base_cases" "$base_s" "$base_rate"
printf '%d jobs:             %d cases in %.1f s = %.1f cases/s (%.2fx the baseline)\n' \
  "$jobs" "$all_cases" "$all_s" "$all_rate" "$(awk -v a="$all_rate" -v b="$base_rate" 'BEGIN {print a / b}')"
n=$(wc -l < "$work/bench_all.rss")
if [ "$n" -ge 3 ]; then
  at() { sed -n "$(( ($1 * n + 99) / 100 ))p" "$work/bench_all.rss"; }
  printf 'resident memory at 10 %% / 50 %% / 100 %% of the run: %d / %d / %d MiB (%d samples)\n' \
    $(( $(at 10) / 1024 )) $(( $(at 50) / 1024 )) $(( $(at 100) / 1024 )) "$n"
fi
