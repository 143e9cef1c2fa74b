#!/usr/bin/env bash
# Radio-level study speed, one build against another (issue 32: >= 20 cases per second on 2
# cores), on the shipped radio-level study (studies/ap_placement.yaml: C hall, 140 cases).
#
#   bench/study/radio_study_speed.sh BASELINE_BINARY [BINARY=build/release/apps/wifislam] [RUNS=3] [JOBS=2]
#
# Runs the study RUNS times with each binary, alternating (baseline, new, baseline, new, ...) so
# that machine noise hits both alike, and prints the median cases per second of each and their
# ratio, and the median cases per CPU second (user + sys over all threads: what a loaded machine
# distorts least; on an idle machine, cases per second with --jobs 2 approach twice it). Then checks that both wrote the same results table (sqlite3 .dump, rows sorted: parallel cases finish in any order; the timing table
# differs by nature): a speed-up must not move a number. Keep a baseline binary with
#   cp build/release/apps/wifislam /tmp/wifislam_before
# before rebuilding.
set -euo pipefail
cd "$(dirname "$0")/../.."
base="${1:?usage: $0 BASELINE_BINARY [BINARY] [RUNS] [JOBS]}"
bin="${2:-build/release/apps/wifislam}"
runs="${3:-3}"
jobs="${4:-2}"
study=studies/ap_placement.yaml
work=$(mktemp -d /tmp/wifislam_radio_speed.XXXXXX)
trap 'rm -rf -- "$work"' EXIT

run() {  # binary label index -> prints cases per second and cases per CPU second
  local db="$work/$2.$3.sqlite" start end
  start=$(date +%s.%N)
  /usr/bin/time -f '%U %S' -o "$work/$2.$3.cpu" "$1" study run "$study" -q --jobs "$jobs" -o "$db" \
    > "$work/$2.$3.out"
  end=$(date +%s.%N)
  local cases
  cases=$(sqlite3 "$db" 'select count(*) from results')
  awk -v c="$cases" -v a="$start" -v b="$end" 'BEGIN {print c / (b - a)}'
  awk -v c="$cases" '{print c / ($1 + $2)}' "$work/$2.$3.cpu" >> "$work/$2.cpu_rates"
}
median() { sort -g | awk '{v[NR] = $1} END {print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }

: > "$work/base.rates"
: > "$work/new.rates"
: > "$work/base.cpu_rates"
: > "$work/new.cpu_rates"
for i in $(seq 1 "$runs"); do
  run "$base" base "$i" >> "$work/base.rates"
  run "$bin" new "$i" >> "$work/new.rates"
done
b=$(median < "$work/base.rates")
n=$(median < "$work/new.rates")
printf 'baseline %s: %s cases/s (median of %d: %s)\n' "$base" "$b" "$runs" "$(tr '\n' ' ' < "$work/base.rates")"
printf 'new      %s: %s cases/s (median of %d: %s)\n' "$bin" "$n" "$runs" "$(tr '\n' ' ' < "$work/new.rates")"
bc=$(median < "$work/base.cpu_rates")
nc=$(median < "$work/new.cpu_rates")
printf 'per CPU second (user + sys, all threads): baseline %s, new %s cases (%.2fx)\n' "$bc" "$nc" \
  "$(awk -v a="$nc" -v b="$bc" 'BEGIN {print a / b}')"
printf 'ratio new / baseline: %.2fx (--jobs %d, %d cores, load average %s)\n' \
  "$(awk -v a="$n" -v b="$b" 'BEGIN {print a / b}')" "$jobs" "$(nproc)" "$(cut -d' ' -f1-3 /proc/loadavg)"
if cmp -s <(sqlite3 "$work/base.1.sqlite" '.dump results' | sort) <(sqlite3 "$work/new.1.sqlite" '.dump results' | sort); then
  echo "results tables identical (sqlite3 .dump results, sorted)"
else
  echo "RESULTS DIFFER between the two binaries" >&2
  exit 1
fi
