#!/usr/bin/env bash
# ATE and loop-closure verdicts of vanilla and Wi-Fi RGBD-SLAM on every shipped scene at default
# settings (one seed each, the scene's own), as the issue's benchmark asks. There is no target for
# vanilla: it is whatever RGBDSLAMv2's design gives here.
#
#   bench/slam/every_scene_ate.sh [build-dir] [fps] [output-dir]
#   (defaults: build/release, 3, a temp dir)
set -euo pipefail
build=${1:-build/release}
fps=${2:-3}
out=${3:-$(mktemp -d)/every_scene_ate}
here=$(cd "$(dirname "$0")/../.." && pwd)
"$build/apps/wifislam" compare "$here"/scenes/*.yaml --fps "$fps" --jobs 2 --no-plots -o "$out"
cat "$out/comparison.md"
echo "full results: $out"
