#!/usr/bin/env bash
# docs/results/real_buildings/README.md's pictures and tables: imports the two shipped real plans (and
# checks that the result equals the shipped scenes/real/*.yaml), draws their plans and strongest-AP
# radio maps, and runs greedy-against-random AP placement on each (8 APs). About a minute on one
# core.
#
#   bench/real_buildings/run.sh [build-dir] [output-dir]
#   (defaults: build/release, a temp dir)
set -euo pipefail
build=${1:-build/release}
out=${2:-$(mktemp -d)/real_buildings}
here=$(cd "$(dirname "$0")/../.." && pwd)
wifislam="$build/apps/wifislam"
mkdir -p "$out"
plans="$here/assets/floorplans"
"$wifislam" import "$plans/fei_uv_xalapa_osm_sit/fei_levels_1_2.geojson" --level 1 \
  --name fei_level_1 -o "$out/fei_level_1.yaml" >/dev/null
"$wifislam" import "$plans/westport_house_wrld/westport-house-floor-2.geojson" \
  --name westport_house_level_2 -o "$out/westport_house_level_2.yaml" >/dev/null
for scene in fei_level_1 westport_house_level_2; do
  # The shipped scene's header names the plan by the path it was imported from; compare the rest.
  if ! diff <(tail -n +2 "$here/scenes/real/$scene.yaml") <(tail -n +2 "$out/$scene.yaml") >/dev/null; then
    echo "note: importing again gives another scene than scenes/real/$scene.yaml"
  fi
  "$wifislam" world "$out/$scene.yaml" --plan "$out/${scene}_plan.png" | tail -n 3
  "$wifislam" radiomap "$out/$scene.yaml" --strongest -o "$out/${scene}_radiomap.png" >/dev/null
  "$wifislam" study place "$out/$scene.yaml" --budget 8 -q --force -o "$out/place_$scene"
done
echo "results: $out"
