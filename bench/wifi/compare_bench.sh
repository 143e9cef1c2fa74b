#!/usr/bin/env bash
# Loop-closure detection time of RGBD-SLAM with Wi-Fi relative to vanilla, and the Wi-Fi overhead
# as a share of the pipeline's time, on c_hall and j_hall (issue: "Benchmark"). Both variants run
# on the same dataset in the same invocation, one at a time (--jobs 1), so the ratio is not skewed
# by the two runs competing for the cores.
#
#   bench/wifi/compare_bench.sh [build-dir] [fps]     (defaults: build/release, 5)
set -euo pipefail
build=${1:-build/release}
fps=${2:-5}
here=$(cd "$(dirname "$0")/../.." && pwd)
out=$(mktemp -d)/wifi_compare_bench
"$build/apps/wifislam" compare "$here/scenes/c_hall.yaml" "$here/scenes/j_hall.yaml" \
  --fps "$fps" --jobs 1 --no-plots -o "$out"
echo "full results: $out"
