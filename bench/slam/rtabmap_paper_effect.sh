#!/usr/bin/env bash
# The paper's RTAB-Map effect on the j_hall twin's layout (issue "RTAB-Map-style front end"):
# the route goes round the loop and on into the east corridor again, a revisit with the same
# heading (the shipped twin returns down the tail, which no camera sees as a revisit). Under
# Rtabmap/TimeThr 70 ms (cost model) vanilla moves the first pass's nodes to LTM and misses the
# revisit; Wi-Fi immunises and retrieves the nodes of the similar clusters and closes it; at inf
# both close it. Deterministic (cost-model time, scene seed). About 15 min on 2 cores at 3 fps.
#
#   bench/slam/rtabmap_paper_effect.sh [build-dir] [fps] [output-dir] [compare options...]
#   (defaults: build/release, 3, a temp dir; e.g. --seeds 4 for seeds 3003-3006; JOBS=2 runs two
#   at a time, which leaves the cost-model results unchanged but shares the cores)
set -euo pipefail
build=${1:-build/release}
fps=${2:-3}
out=${3:-$(mktemp -d)/rtabmap_paper_effect}
here=$(cd "$(dirname "$0")/../.." && pwd)
scene=$(mktemp -d)/j_hall_revisit.yaml
sed -e 's/^  nodes: \[E, B, C, D, A, B, E\]$/  nodes: [E, B, C, D, A, B, C]/' \
    -e 's/^name: j_hall$/name: j_hall_revisit/' "$here/scenes/j_hall.yaml" >"$scene"
grep -q 'nodes: \[E, B, C, D, A, B, C\]' "$scene" || { echo "j_hall route not found" >&2; exit 1; }
"$build/apps/wifislam" compare "$scene" --frontend rtabmap --sweep time_threshold_ms=inf,70,40 \
  --fps "$fps" --jobs "${JOBS:-1}" --no-plots -o "$out" "${@:4}"
cat "$out/comparison.md"
echo "full results: $out"
