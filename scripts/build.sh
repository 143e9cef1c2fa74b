#!/usr/bin/env bash
# Configures and builds one CMake preset (default: release), all targets or the ones named.
# Usage: scripts/build.sh [preset] [target...]   e.g. scripts/build.sh release wifislam
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-release}"
shift || true
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)" "${targets[@]}"
