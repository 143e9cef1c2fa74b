#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite. Usage: scripts/test.sh [release|asan]...
# With no argument runs the release preset. Exits non-zero if anything fails.
set -euo pipefail
cd "$(dirname "$0")/.."
presets=("$@")
[ ${#presets[@]} -eq 0 ] && presets=(release)
scripts/install-deps.sh
for preset in "${presets[@]}"; do
  start=$(date +%s)
  scripts/build.sh "$preset"
  built=$(date +%s)
  echo "build ($preset): $((built - start)) s"
  ctest --preset "$preset"
  echo "tests ($preset): $(( $(date +%s) - built )) s"
done
