#!/bin/sh
# A regression test of another SLAM system on this harness: OpenCV's RGB-D odometry (the shipped
# external system systems/opencv_rgbd_odometry.yaml) on the first 120 frames of the shipped C-hall
# twin (40 s at 3 fps, 7.3 m of corridor with the pauses to scan), seed 1001, held to an error
# bound. Exit 0 when it holds, 6 when it does not (wifislam
# eval --require), anything else when the harness itself failed.
#
#   opencv_odometry_regression.sh WIFISLAM_BINARY SCRATCH_DIR
#
# SCRATCH_DIR is a folder of the test's own: its dataset/ and run/ are replaced on every run, and
# nothing else in it or around it is touched.
#
# Same scene and seed give the same dataset, so the bound is the system's, not the data's luck.
# The bound: this odometry drifts along the corridors (docs/external_systems.md); it measured
# 2.47 m RMSE here, and 3.0 m leaves room for another OpenCV version, not for a regression.
set -eu
wifislam="$1"
scratch="$2"
scenes="$(dirname "$0")/../../scenes"
rm -rf "$scratch/dataset" "$scratch/run"
mkdir -p "$scratch"
"$wifislam" generate "$scenes/c_hall.yaml" --fps 3 --max-frames 120 -q -o "$scratch/dataset"
"$wifislam" slam "$scratch/dataset" --frontend external:opencv_rgbd_odometry -o "$scratch/run" \
  > "$scratch/slam.log"
exec "$wifislam" eval "$scratch/run" --gt "$scratch/dataset" --no-plots --force \
  --require 'ate_rmse_m<=3.0' --require 'frames_associated>=115'
