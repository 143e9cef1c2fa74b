#!/usr/bin/env bash
# The paper's ORB-SLAM experiment (issue "ORB-SLAM-style front end", evaluation): vanilla and
# Wi-Fi orbslam on the four twins at min_matches 10, 15, 20, 50 and 100 (min_matches is ORB-SLAM2's
# Sim3 RANSAC-inlier gate; slam/frontend/orbslam/orbslam_options.hpp): trajectory error,
# loop-closure time (and its Wi-Fi / vanilla ratio, same run), Wi-Fi overhead, false-positive %
# (wrong place, online and after pruning) and far wrong-place closures. The per-keyframe query cost
# is in each run's orbslam_queries.csv. --jobs 2 by default (about 40 min on 2 cores at 3 fps);
# give 1 for time columns free of interference.
#
#   bench/slam/orbslam_tables.sh [build-dir] [fps] [output-dir] [jobs]
#   (defaults: build/release, 3, a temp dir, 2)
set -euo pipefail
build=${1:-build/release}
fps=${2:-3}
out=${3:-$(mktemp -d)/orbslam_tables}
jobs=${4:-2}
here=$(cd "$(dirname "$0")/../.." && pwd)
"$build/apps/wifislam" compare "$here"/scenes/{c,b,a,j}_hall.yaml --frontend orbslam \
  --sweep min_matches=10,15,20,50,100 --fps "$fps" --jobs "$jobs" --no-plots -o "$out"
cat "$out/comparison.md"
echo "full results: $out"
