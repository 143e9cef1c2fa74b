#!/usr/bin/env bash
# The shipped studies in full, with their plots, and greedy placement against random on the twins.
#
#   bench/study/shipped_studies.sh OUT [radio|slam|all]   (default: radio)
#
# radio: studies/ap_placement.yaml and ap_placement_j_hall.yaml (140 radio cases each, minutes),
#        their plots, and `study place` with a budget of 40 APs on c_hall and j_hall (the paper's
#        discussion: about 40 well-spread APs suffice);
# slam:  studies/aliasing.yaml (SLAM level, hours: see its header), and its plot.
# Each study resumes when run again into the same OUT.
set -euo pipefail
cd "$(dirname "$0")/../.."
[ $# -ge 1 ] || { sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
out="$1"
what="${2:-radio}"
bin=build/release/apps/wifislam
[ -x "$bin" ] || { echo "build the release preset first (scripts/build.sh)" >&2; exit 2; }
mkdir -p "$out"
jobs=$(nproc)

study() {  # file name
  local start=$SECONDS
  "$bin" study run "studies/$1" -q --jobs "$jobs" -o "$out/$2.sqlite"
  "$bin" study plot "$out/$2.sqlite" -o "$out/$2_plots" --force
  echo "$2: $((SECONDS - start)) s wall on $jobs cores"
}

if [ "$what" = radio ] || [ "$what" = all ]; then
  study ap_placement.yaml ap_placement_c_hall
  study ap_placement_j_hall.yaml ap_placement_j_hall
  for scene in c_hall j_hall; do
    start=$SECONDS
    "$bin" study place "scenes/$scene.yaml" --budget 40 -q --force -o "$out/place_$scene" \
      | tee "$out/place_$scene.txt"
    echo "place $scene: $((SECONDS - start)) s wall"
  done
fi
if [ "$what" = slam ] || [ "$what" = all ]; then
  study aliasing.yaml aliasing
fi
