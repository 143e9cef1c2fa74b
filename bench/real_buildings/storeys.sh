#!/usr/bin/env bash
# docs/results/real_buildings/README.md's "Several storeys" tables and pictures: imports FEI and Westport
# House whole (import --all-levels) with the route on two levels each, generates their scans
# (--no-images) beside the one-level imports, counts what scans hear from other floors, compares
# signatures across floors, runs RGBD-SLAM's Wi-Fi clustering on FEI level 1 with and without
# the floor above, and localize's three methods with and without another floor in the map. About
# 20 minutes on 2 cores.
#
#   bench/real_buildings/storeys.sh [build-dir] [output-dir]
#   (defaults: build/release, a temp dir)
set -euo pipefail
build=$(cd "${1:-build/release}" && pwd)
out=${2:-$(mktemp -d)/storeys}
here=$(cd "$(dirname "$0")/../.." && pwd)
wifislam="$build/apps/wifislam"
py=/usr/bin/python3
mkdir -p "$out"
cd "$out"
fei="$here/assets/floorplans/fei_uv_xalapa_osm_sit/fei_levels_1_2.geojson"
wh="$here/assets/floorplans/westport_house_wrld/westport-house-floor-2.geojson"
"$wifislam" import "$fei" -o fei_single.yaml >/dev/null
"$wifislam" import "$fei" --all-levels -o fei_building.yaml | tail -n 2
"$wifislam" import "$fei" --all-levels --level 2 -o fei_building_l2.yaml >/dev/null
"$wifislam" import "$wh" -o wh_single.yaml >/dev/null
"$wifislam" import "$wh" --all-levels -o wh_building.yaml | tail -n 2
"$wifislam" import "$wh" --all-levels --level 3 -o wh_building_l3.yaml >/dev/null
for s in fei_single fei_building fei_building_l2 wh_single wh_building wh_building_l3; do
  "$wifislam" generate $s.yaml -o ds_$s --no-images -q --force
done
$py "$here/scripts/other_floor_scans.py" ds_fei_single ds_fei_building ds_fei_building_l2 \
  ds_wh_single ds_wh_building ds_wh_building_l3
$py "$here/scripts/floor_aliasing.py" ds_fei_building ds_fei_building_l2
$py "$here/scripts/floor_aliasing.py" ds_wh_building ds_wh_building_l3
"$wifislam" radiomap fei_building.yaml --ap 30 --level 1 -o fei_building_level_1_hears_ap30_upstairs.png
"$wifislam" radiomap fei_building.yaml --strongest --level 2 -o fei_building_level_2_radiomap.png
for s in fei_single fei_building; do
  "$wifislam" slam $s.yaml --wifi --fps 1 -o slam_$s --force >/dev/null
  $py "$here/scripts/cluster_spread.py" slam_$s ds_$s
done
for s in fei_single fei_building wh_single wh_building; do
  "$wifislam" localize $s.yaml -o loc_$s -q --force >/dev/null
  tail -n 3 loc_$s/summary.md
done
"$wifislam" localize fei_building.yaml --other-floor fei_building_l2.yaml -o loc_fei_cross -q --force >/dev/null
"$wifislam" localize fei_building_l2.yaml --other-floor fei_building.yaml -o loc_fei_cross_l2 -q --force >/dev/null
"$wifislam" localize wh_building.yaml --other-floor wh_building_l3.yaml -o loc_wh_cross -q --force >/dev/null
"$wifislam" localize fei_building.yaml --other-floor fei_building_l2.yaml --method wifi-fabmap \
  --wifi-words thermometer -o loc_fei_cross_thermometer -q --force >/dev/null
for s in loc_fei_cross loc_fei_cross_l2 loc_wh_cross loc_fei_cross_thermometer; do
  tail -n 3 $s/summary.md
done
echo "results: $out"
