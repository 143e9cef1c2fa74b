#!/usr/bin/env bash
# Renderer benchmark with 1 and 2 llvmpipe threads (llvmpipe reads LP_NUM_THREADS once per
# process), 5 repetitions each, medians over the repetitions only.
# Usage: bench/render/run.sh [build dir]
set -euo pipefail
build=${1:-build/release}
for threads in 1 2; do
  echo "== LP_NUM_THREADS=${threads}"
  LP_NUM_THREADS=${threads} "${build}/bench/render/render_bench" --benchmark_repetitions=5 \
    --benchmark_report_aggregates_only=true
done
