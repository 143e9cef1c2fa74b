#!/usr/bin/env bash
# The paper's RTAB-Map experiment (issue "RTAB-Map-style front end", benchmarks): vanilla and
# Wi-Fi rtabmap on the four twins at Rtabmap/TimeThr inf, 70, 100 and 200 ms (the deterministic
# cost model, calibrated in slam/frontend/rtabmap/rtabmap_options.hpp): trajectory error, false
# negative %, loop-closure time (Wi-Fi / vanilla ratio, same run), Wi-Fi overhead; WM size over
# time is in each run's rtabmap_memory.csv. One run at a time (--jobs 1) so the time columns are
# comparable. 31 min on 2 idle cores at 3 fps (32 runs; results: docs/results/rtabmap/README.md).
#
#   bench/slam/rtabmap_thresholds.sh [build-dir] [fps] [output-dir]
#   (defaults: build/release, 3, a temp dir)
set -euo pipefail
build=${1:-build/release}
fps=${2:-3}
out=${3:-$(mktemp -d)/rtabmap_thresholds}
here=$(cd "$(dirname "$0")/../.." && pwd)
"$build/apps/wifislam" compare "$here"/scenes/{a,b,c,j}_hall.yaml --frontend rtabmap \
  --sweep time_threshold_ms=inf,70,100,200 --fps "$fps" --jobs 1 --no-plots -o "$out"
cat "$out/comparison.md"
echo "full results: $out"
