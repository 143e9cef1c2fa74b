#!/usr/bin/env bash
# docs/results/devices/README.md's tables: on a twin (c_hall; SCENE=aliasing_ladder for the look-alike
# corridors), the map from session 0 and the
# queries from session 1 (its own pauses and Wi-Fi draws), for localize's three methods:
#   - devices: queries read by the reference receiver, by a phone 5 dB low with a 5 dB higher
#     floor (weaker_phone), and by a throttled Android foreground app (android_foreground);
#   - access points changed between the sessions: a share of them switched off, or moved;
#   - RGBD-SLAM's Wi-Fi clustering with the reference receiver and a throttled one.
# Each over three scene seeds. About 20 minutes per scene on 2 cores.
#
#   [SCENE=c_hall] [PARTS="devices changes slam"] bench/localize/devices_sessions.sh [build-dir] [output-dir]
#   (defaults: build/release, a temp dir)
set -euo pipefail
build=$(cd "${1:-build/release}" && pwd)
out=${2:-$(mktemp -d)/devices_sessions}
here=$(cd "$(dirname "$0")/../.." && pwd)
wifislam="$build/apps/wifislam"
py=/usr/bin/python3
scene="$here/scenes/${SCENE:-c_hall}.yaml"
seeds=(101 102 103)
mkdir -p "$out"
cd "$out"
start=$(date +%s)

parts=${PARTS:-devices changes slam}
for seed in "${seeds[@]}"; do
  sed "s/^seed: .*/seed: $seed/" "$scene" > "scene_$seed.yaml"
done

if [[ $parts == *devices* ]]; then
device_runs=()
for seed in "${seeds[@]}"; do
  for device in reference weaker_phone android_foreground; do
    "$wifislam" localize "$scene" --seed "$seed" --queries-session 1 --queries-device "$device" \
      -o "dev_${device}_$seed" -q --force >/dev/null
    device_runs+=("$device seed $seed=dev_${device}_$seed")
  done
done
echo "## Devices (map: session 0, reference receiver; queries: session 1)"
$py "$here/scripts/localize_table.py" "${device_runs[@]}"
echo "## Devices, over the seeds"
$py "$here/scripts/device_table.py" .
fi

if [[ $parts == *changes* ]]; then
change_runs=()
for seed in "${seeds[@]}"; do
  "$wifislam" generate "scene_$seed.yaml" --no-images -o "aps_$seed" -q --force
  for change in off moved; do
    for share in 0 0.1 0.25 0.5 0.75; do
      name="${change}_${share}_$seed"
      $py "$here/scripts/ap_changes.py" "scene_$seed.yaml" "aps_$seed" --share "$share" \
        --change "$change" -o "$name.yaml" >/dev/null
      "$wifislam" localize "$name.yaml" --queries-session 1 -o "loc_$name" -q --force >/dev/null
      change_runs+=("$change $share seed $seed=loc_$name")
    done
  done
done
echo "## Access points changed between the sessions"
$py "$here/scripts/localize_table.py" "${change_runs[@]}"
echo "## Access points changed, over the seeds (the plot: ap_changes.png)"
$py "$here/scripts/ap_change_plot.py" . "${SCENE:-c_hall}: map from session 0, queries from session 1 (${#seeds[@]} seeds)" \
  ap_changes.png
fi

if [[ $parts == *slam* ]]; then
echo "## RGBD-SLAM's Wi-Fi clusters: the reference receiver, a throttled phone scanning every 2 s"
echo "## of a pause as the robot does, and one asking once a pause (scan_interval_s 10)"
echo "| run | wifi.csv rows | run folder | clusters | keyframes per cluster | spread median | spread p90 | clusters wider than 12 m |"
echo "| --- | ---: | --- | ---: | ---: | ---: | ---: | ---: |"
for seed in "${seeds[@]}"; do
  for variant in "reference 2" "android_foreground 2" "android_foreground 10"; do
    set -- $variant
    name="slam_$1_$2_$seed"
    { cat "scene_$seed.yaml"; printf 'sensors:\n  wifi: {device: %s, scan_interval_s: %s}\n' "$1" "$2"; } \
      > "$name.yaml"
    "$wifislam" generate "$name.yaml" --no-images -o "truth_$name" -q --force
    "$wifislam" slam "$name.yaml" --wifi --fps 1 -o "$name" --force >/dev/null
    echo -n "| $1, every $2 s, seed $seed | $(($(wc -l < "truth_$name/wifi.csv") - 1)) "
    $py "$here/scripts/cluster_spread.py" "$name" "truth_$name"
  done
done
fi
echo "took $(( $(date +%s) - start )) s; results: $out"
