#!/usr/bin/env bash
# Sets up, builds and runs the main job: `wifislam demo` (writes into ./demo-output).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
# Only the binary the demo runs: the tests and benchmarks are the test script's to build.
scripts/build.sh release wifislam
./build/release/apps/wifislam demo -o demo-output "$@"
