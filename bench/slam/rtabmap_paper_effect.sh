#!/usr/bin/env bash
# The paper's RTAB-Map effect on the j_hall twin (issue "RTAB-Map-style front end"): its route
# goes round the loop and on into the east corridor again, a revisit with the same heading (the
# paper's figure 9). Under Rtabmap/TimeThr 70 ms (cost model) vanilla moves the first pass's nodes
# to LTM and misses the revisit; Wi-Fi immunises and retrieves the nodes of the similar clusters
# and closes it; at inf both close it. Deterministic (cost-model time, scene seed). About 15 min
# on 2 cores at 3 fps. `wifislam paper --parts rtabmap` runs the paper's whole table.
#
#   bench/slam/rtabmap_paper_effect.sh [build-dir] [fps] [output-dir] [compare options...]
#   (defaults: build/release, 3, a temp dir; e.g. --seeds 4 for seeds 3003-3006; JOBS=2 runs two
#   at a time, which leaves the cost-model results unchanged but shares the cores)
set -euo pipefail
build=${1:-build/release}
fps=${2:-3}
out=${3:-$(mktemp -d)/rtabmap_paper_effect}
here=$(cd "$(dirname "$0")/../.." && pwd)
"$build/apps/wifislam" compare "$here/scenes/j_hall.yaml" --frontend rtabmap \
  --sweep time_threshold_ms=inf,70,40 --fps "$fps" --jobs "${JOBS:-1}" --no-plots -o "$out" "${@:4}"
cat "$out/comparison.md"
echo "full results: $out"
