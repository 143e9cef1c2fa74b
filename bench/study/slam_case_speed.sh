#!/usr/bin/env bash
# Speed of one SLAM-level study case, one build against another (issue 32: <= 0.2x the 445 s a
# case took when the issue was filed), on the shipped aliasing study's first case (C hall, 3 fps,
# 2315 frames, RGBD-SLAM vanilla and Wi-Fi), next to the sum of its parts' limits.
#
#   bench/study/slam_case_speed.sh BASELINE_BINARY [BINARY=build/release/apps/wifislam] [RUNS=3] [JOBS=2]
#
# Runs the case RUNS times with each binary, alternating (baseline, new, ...) so that machine
# noise hits both alike; prints the median wall-clock seconds per case of each, their ratio, and
# the median CPU seconds (user + sys, all threads). Then checks that both wrote the same results
# table (sqlite3 .dump; the timing table differs by nature): a speed-up must not move a number.
# Last, the parts' limits measured in the same run: rendering a frame (the harness's render +
# sensor model, from `generate`'s own report) and ORB on it (slam_bench's bare
# ORB, detect + compute at the pipeline's settings), as frames x (render + 2 x ORB): what a case
# that did nothing but render once and extract features for both runs would cost on one core.
# Keep a baseline binary with `cp build/release/apps/wifislam /tmp/wifislam_before` before
# rebuilding.
set -euo pipefail
cd "$(dirname "$0")/../.."
base="${1:?usage: $0 BASELINE_BINARY [BINARY] [RUNS] [JOBS]}"
bin="${2:-build/release/apps/wifislam}"
runs="${3:-3}"
jobs="${4:-2}"
study=studies/aliasing.yaml
work=$(mktemp -d /tmp/wifislam_slam_case_speed.XXXXXX)
trap 'rm -rf -- "$work"' EXIT

run() {  # binary label index -> appends wall and CPU seconds
  local db="$work/$2.$3.sqlite" start end
  start=$(date +%s.%N)
  /usr/bin/time -f '%U %S' -o "$work/$2.$3.cpu" "$1" study run "$study" -q --shard 0/30 \
    --jobs "$jobs" -o "$db" > "$work/$2.$3.out"
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN {print b - a}' >> "$work/$2.wall"
  awk '{print $1 + $2}' "$work/$2.$3.cpu" >> "$work/$2.cpu"
}
median() { sort -g | awk '{v[NR] = $1} END {print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

for i in $(seq 1 "$runs"); do
  echo "run $i of $runs: baseline, then new" >&2
  run "$base" base "$i"
  run "$bin" new "$i"
done
bw=$(median < "$work/base.wall")
nw=$(median < "$work/new.wall")
bc=$(median < "$work/base.cpu")
nc=$(median < "$work/new.cpu")
printf 'baseline %s: %.1f s a case wall, %.1f CPU-s (medians of %d: %s)\n' "$base" "$bw" "$bc" \
  "$runs" "$(tr '\n' ' ' < "$work/base.wall")"
printf 'new      %s: %.1f s a case wall, %.1f CPU-s (medians of %d: %s)\n' "$bin" "$nw" "$nc" \
  "$runs" "$(tr '\n' ' ' < "$work/new.wall")"
printf 'ratio new / baseline: %.2fx wall, %.2fx CPU (--jobs %d, %d cores, load average %s)\n' \
  "$(awk -v a="$nw" -v b="$bw" 'BEGIN {print a / b}')" \
  "$(awk -v a="$nc" -v b="$bc" 'BEGIN {print a / b}')" "$jobs" "$(nproc)" \
  "$(cut -d' ' -f1-3 /proc/loadavg)"
printf 'against the 445 s of the issue: %.2fx\n' "$(awk -v a="$nw" 'BEGIN {print a / 445}')"
if cmp -s <(sqlite3 "$work/base.1.sqlite" '.dump results' | sort) \
  <(sqlite3 "$work/new.1.sqlite" '.dump results' | sort); then
  echo "results tables identical (sqlite3 .dump results, sorted)"
else
  echo "RESULTS DIFFER between the two binaries" >&2
  exit 1
fi

# The parts' limits on this machine, now: the C hall at the case's seed and frame rate (the
# case's own scene differs only in its wall textures' aliasing).
# One thread: no PNG encoder competes with the renderer for the cores while it is timed.
"$bin" generate scenes/c_hall.yaml --fps 3 --seed 1001 --threads 1 -o "$work/dataset" \
  > "$work/generate.out"
frames=$(awk '/^frames/ {print $2}' "$work/generate.out")
render_s=$(awk '/^  render/ {r = $2} /^  sensor model/ {s = $3} END {print r + s}' "$work/generate.out")
orb_fps=$(WIFISLAM_BENCH_FPS=3 WIFISLAM_BENCH_MAX_FRAMES=600 build/release/bench/slam/slam_bench \
  2> /dev/null | awk '/bare ORB/ {for (i = 1; i <= NF; ++i) if ($i == "ORB") print $(i + 1)}' |
  head -1)
awk -v f="$frames" -v r="$render_s" -v o="$orb_fps" -v w="$nw" -v c="$nc" 'BEGIN {
  orb = f / o; limit = r + 2 * orb
  printf "parts: %d frames; render + sensor model %.1f s (%.2f ms a frame), ORB %.1f s a run (%.2f ms a frame)\n", f, r, 1000 * r / f, orb, 1000 / o
  printf "sum of the parts (render + 2 x ORB, one core): %.1f s; the case: %.1f CPU-s (%.1fx the parts), %.1f s wall\n", limit, c, c / limit, w
}'
