#!/usr/bin/python3
"""How far apart the keyframes of one Wi-Fi cluster stand.

Usage: scripts/cluster_spread.py RUN_FOLDER DATASET_OR_GROUNDTRUTH

RUN_FOLDER is a `wifislam slam --wifi` run (wifi_clusters.csv, keyframes.txt); the second
argument is a dataset folder (its groundtruth.txt) or a TUM file of the same route and time
origin (e.g. a `--no-images` dataset of the scene the run streamed). Each keyframe is placed at
the ground truth's (x, y) at its stamp. Prints one Markdown table row: clusters, keyframes per
cluster (median), each cluster's spread (the largest distance from its founder keyframe to a
member; median and 90th percentile) and the share of clusters with a member more than 12 m from
the founder (a cluster that joins places the loop-closure bound should keep apart).
"""
import bisect
import csv
import statistics
import sys
from pathlib import Path

from tum_text import read_tum_xy as read_tum


def main():
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    run, truth = Path(sys.argv[1]), Path(sys.argv[2])
    if truth.is_dir():
        truth = truth / "groundtruth.txt"
    stamps, xy = read_tum(truth)
    keyframe_time = [t for t, _ in zip(*read_tum(run / "keyframes.txt"))]

    def at(keyframe):
        t = keyframe_time[keyframe]
        i = bisect.bisect_left(stamps, t)
        i = min((k for k in (i - 1, i) if 0 <= k < len(stamps)), key=lambda k: abs(stamps[k] - t))
        return xy[i]

    spreads, sizes = [], []
    with open(run / "wifi_clusters.csv", newline="") as f:
        for row in csv.DictReader(f):
            members = [int(k) for k in row["keyframes"].split()]
            fx, fy = at(int(row["founder_keyframe"]))
            spreads.append(max(((x - fx) ** 2 + (y - fy) ** 2) ** 0.5
                               for x, y in map(at, members)))
            sizes.append(len(members))
    spreads.sort()
    far = sum(s > 12.0 for s in spreads)
    print(f"| {run.name} | {len(spreads)} | {statistics.median(sizes):.0f} | "
          f"{statistics.median(spreads):.1f} m | {spreads[int(0.9 * (len(spreads) - 1))]:.1f} m | "
          f"{100.0 * far / len(spreads):.1f} % |")


if __name__ == "__main__":
    main()
