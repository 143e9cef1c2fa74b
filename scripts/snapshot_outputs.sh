#!/usr/bin/env bash
# Runs every wifislam command on small inputs and keeps what each writes, so two builds can be
# compared file by file (scripts/diff_outputs.py). A refactor that must not change what users get
# (datasets, run folders, evaluations, plots, study rows) is checked by a snapshot before and one
# after:
#
#   scripts/snapshot_outputs.sh build/release /tmp/before      # on the old commit
#   scripts/snapshot_outputs.sh build/release /tmp/after       # on the new one
#   scripts/diff_outputs.py /tmp/before /tmp/after             # exit 0 when only timings differ
#
# About 3 minutes on 2 cores. OUT must not exist. Commands run from the repository root, with
# relative paths, so both snapshots name the same inputs; stdout of each command is kept as
# <name>.stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -eq 2 ] || { sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
build="$1"
out="$2"
bin="$build/apps/wifislam"
[ -x "$bin" ] || { echo "snapshot_outputs: no $bin (build first)" >&2; exit 2; }
[ ! -e "$out" ] || { echo "snapshot_outputs: $out exists" >&2; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"
realpath "$bin" >"$out/binary.path"

step() {  # step NAME COMMAND...: runs the command, keeps its stdout, stops on failure
  local name="$1"
  shift
  echo "snapshot: $name" >&2
  "$@" >"$out/$name.stdout"
}

step info "$bin" info
# World, render, radio maps.
for scene in scenes/*.yaml; do
  name="$(basename "$scene" .yaml)"
  step "world_$name" "$bin" world "$scene" --plan "$out/plan_$name.png" --svg
done
step render "$bin" render scenes/c_hall.yaml --pose 2,1,90 -o "$out/render_c_hall"
step radiomap_strongest "$bin" radiomap scenes/c_hall.yaml --strongest --res 0.5 \
  -o "$out/radiomap_c_hall.png" --csv "$out/radiomap_c_hall.csv"
step radiomap_ap "$bin" radiomap scenes/j_hall.yaml --ap 1 --band 5 --res 0.4 -o "$out/radiomap_j_hall_ap1.png"

# Datasets: the start of every shipped scene, and a longer c_hall one for SLAM.
for scene in scenes/*.yaml; do
  name="$(basename "$scene" .yaml)"
  step "generate_$name" "$bin" generate "$scene" -o "$out/datasets/$name" --max-frames 12 --fps 2 -q
done
step generate_c_hall_slam "$bin" generate scenes/c_hall.yaml -o "$out/datasets/c_hall_slam" --fps 2 --max-frames 160 -q
step generate_no_images "$bin" generate scenes/b_hall.yaml -o "$out/datasets/b_hall_no_images" --no-images -q
step check "$bin" check "$out/datasets/c_hall_slam"
step export_rtabmap "$bin" export "$out/datasets/c_hall" --for rtabmap -o "$out/export_rtabmap" -q
step export_orbslam2 "$bin" export "$out/datasets/c_hall" --for orbslam2 -o "$out/export_orbslam2" -q

# SLAM: every front end, vanilla and Wi-Fi, on the dataset and (rgbdslam) on the scene streamed.
for frontend in rgbdslam rtabmap orbslam; do
  for variant in vanilla wifi; do
    flag=""
    [ "$variant" = wifi ] && flag="--wifi"
    run="$out/runs/$frontend-$variant"
    step "slam_$frontend-$variant" "$bin" slam "$out/datasets/c_hall_slam" --frontend "$frontend" $flag -o "$run"
    step "eval_$frontend-$variant" "$bin" eval "$run" --gt "$out/datasets/c_hall_slam"
  done
done
step slam_scene "$bin" slam scenes/c_hall.yaml --wifi --fps 2 --max-frames 160 -o "$out/runs/scene-wifi"
cp "$out/runs/rgbdslam-vanilla/trajectory.txt" "$out/bare_trajectory.txt"
step eval_bare "$bin" eval "$out/bare_trajectory.txt" --gt "$out/datasets/c_hall_slam" --align sim3

# Comparisons: the demo (the embedded scene), and a small sweep with another front end.
step demo "$bin" demo -o "$out/demo" -q
step compare "$bin" compare scenes/b_hall.yaml --frontend orbslam --fps 2 --max-frames 100 \
  --sweep min_matches=20,30 --jobs 2 -o "$out/compare" -q

# Studies: a radio-level shard, its plot and merge, a tiny SLAM-level study, placement, Slurm files.
step study_cases "$bin" study cases studies/ap_placement.yaml
step study_radio "$bin" study run studies/ap_placement.yaml --shard 0/10 --jobs 2 -o "$out/study_radio.sqlite" -q
step study_radio_b "$bin" study run studies/ap_placement.yaml --shard 1/10 -o "$out/study_radio_b.sqlite" -q
step study_merge "$bin" study merge "$out/study_radio.sqlite" "$out/study_radio_b.sqlite" -o "$out/study_merged.sqlite"
step study_plot "$bin" study plot "$out/study_merged.sqlite" -o "$out/study_plot"
cat >"$out/slam_study.yaml" <<EOF
version: 1
name: snapshot_slam
scene: $(pwd)/scenes/c_hall.yaml
level: slam
slam: {frontend: rgbdslam, fps: 2, max_frames: 60, settings: {min_matches: 15}}
axes:
  seed: [1001, 1002]
  slam.wifi_similarity: [0.8, 0.9]
EOF
step study_slam "$bin" study run "$out/slam_study.yaml" --jobs 2 -o "$out/study_slam.sqlite" -q
step study_place "$bin" study place scenes/c_hall.yaml --budget 4 --spacing 4 -o "$out/place" -q
step study_slurm "$bin" study slurm studies/ap_placement.yaml --tasks 4 -o "$out/slurm"
for db in study_radio study_merged study_slam; do
  for table in study results; do
    sqlite3 -header -csv "$out/$db.sqlite" "select * from $table order by 1, 2" >"$out/$db.$table.csv"
  done
done

# Vocabulary: a small one trained on the c_hall dataset.
step vocab_train "$bin" vocab train "$out/datasets/c_hall_slam" --every 8 --branching 4 --depth 3 \
  -o "$out/voc.bin" -q
step vocab_info "$bin" vocab info "$out/voc.bin"
# The radio model calibrated to the shipped Royal Holloway survey (two rooms, held-out halves).
surveys=assets/surveys/royal_holloway
for room in office corridor; do
  step "calibrate_$room" "$bin" radio calibrate "$surveys/database_${room}_train.csv" \
    --scene "scenes/real/royal_holloway_$room.yaml" --aps "$surveys/${room}_aps.csv" \
    --test "$surveys/database_${room}_test.csv" --format royal-holloway -o "$out/calibrate_$room.yaml" \
    --report "$out/calibrate_$room.md" --json "$out/calibrate_$room.json"
done
echo "snapshot: done -> $out" >&2
