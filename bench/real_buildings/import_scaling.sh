#!/usr/bin/env bash
# `wifislam import` time and peak memory against the size of the building (issue "Reliability",
# import): comb-shaped plans (bench/real_buildings/comb_plan.py) of 1 000 to 10 000 rooms. The goal:
# 10 000 rooms in under a minute. Times are also given as ratios to the 1 000-room time of the
# same run (these machines are noisy); with a second binary (an older build), each size is timed
# with it too, as a ratio to the first binary's time at that size, up to LIMIT seconds a run.
#
#   bench/real_buildings/import_scaling.sh [build-dir] [baseline-binary] [limit-s]
#   (defaults: build/release, none, 300)
set -euo pipefail
build=${1:-build/release}
baseline=${2:-}
limit=${3:-300}
bin="$build/apps/wifislam"
here="$(cd "$(dirname "$0")" && pwd)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run BINARY PLAN: "seconds peak-MB" of one import, or "timeout" past the limit.
run() {
  rm -f "$work/scene.yaml"
  if timeout "$limit" /usr/bin/time -f "%e %M" -o "$work/time" "$1" import "$2" \
      -o "$work/scene.yaml" --access-points 10 >/dev/null 2>"$work/err"; then
    awk '{ printf "%.1f %.0f", $1, $2 / 1024 }' "$work/time"
  else
    echo "timeout"
  fi
}

printf "%6s %8s %10s %9s %12s %s\n" gap_m rooms seconds peak_MB "vs 1000" \
  "${baseline:+baseline (ratio)}"
for gap in 0 0.2; do
  first=""
  for rooms in 1000 2000 5000 10000; do
    /usr/bin/python3 "$here/comb_plan.py" "$rooms" "$work/plan.geojson" "$gap"
    read -r s mb <<<"$(run "$bin" "$work/plan.geojson")"
    [ -n "$first" ] || first=$s
    extra=""
    if [ -n "$baseline" ]; then
      read -r bs _ <<<"$(run "$baseline" "$work/plan.geojson")"
      if [ "$bs" = timeout ]; then
        extra="over ${limit} s"
      else
        extra="$bs s ($(awk -v a="$bs" -v b="$s" 'BEGIN { printf "%.1f", a / b }')x)"
      fi
    fi
    printf "%6s %8d %10s %9s %12s %s\n" "$gap" "$rooms" "$s" "$mb" \
      "$(awk -v a="$s" -v b="$first" 'BEGIN { printf "%.1fx", a / b }')" "$extra"
  done
done
/usr/bin/python3 "$here/comb_plan.py" 9999 "$work/plan.geojson" 0 9999
echo "one corridor and 9 999 rooms: $(run "$bin" "$work/plan.geojson") (seconds, peak MB)"
