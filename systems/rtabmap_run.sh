#!/bin/sh
# Runs rtabmap-rgbd_dataset on an export (`wifislam export --for rtabmap`: rgb_sync/, depth_sync/,
# rtabmap_calib.yaml with the dataset's intrinsics) and writes what the external-system contract
# reads. $1: the export, $2: the output folder. RTAB-Map's tools must be on PATH
# (RTABMAP_DATASET_TOOL names another binary).
set -eu
tool="${RTABMAP_DATASET_TOOL:-rtabmap-rgbd_dataset}"
"$tool" --output "$2" "$1"
# Accepted global loop closures (Link.type 1) as stamp pairs, from RTAB-Map's database, kept only
# where both nodes are in the exported graph (rtabmap_poses.txt): after an odometry reset the
# database also holds nodes of earlier maps that the exported poses leave out.
sqlite3 -csv "$2/rtabmap.db" \
  "SELECT printf('%.6f', a.stamp), printf('%.6f', b.stamp)
   FROM Link JOIN Node a ON a.id = Link.from_id JOIN Node b ON b.id = Link.to_id
   WHERE Link.type = 1 ORDER BY Link.from_id, Link.to_id" > "$2/database_closures.csv"
echo "from_time,to_time" > "$2/loop_closures.csv"
awk -F'[ ,]' 'NR == FNR { if ($1 !~ /^#/ && NF >= 8) graph[sprintf("%.6f", $1)] = 1; next }
              (sprintf("%.6f", $1) in graph) && (sprintf("%.6f", $2) in graph)' \
  "$2/rtabmap_poses.txt" "$2/database_closures.csv" >> "$2/loop_closures.csv"
