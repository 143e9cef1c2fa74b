#!/usr/bin/env bash
# Sets up, builds and runs the main job: `wifislam demo` (writes into ./demo-output).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh release
./build/release/apps/wifislam demo -o demo-output "$@"
