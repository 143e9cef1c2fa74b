#!/usr/bin/python3
"""How much of a dataset's Wi-Fi comes from other floors.

Usage: scripts/other_floor_scans.py DATASET [DATASET ...]

For each dataset of a scene with `levels:` (docs/results/real_buildings/README.md, "Several storeys"),
reads scene.yaml (the levels, the route's level, the wall height), access_points.csv (each AP's z
in the building's frame) and wifi.csv (the scans), and prints one Markdown table row: scans,
BSSIDs heard per scan (median and mean), how many of them are from APs on other levels (median,
mean, share), the share of scans whose strongest BSSID is from another level, and the share of
scans that hear at least one. A dataset of a one-level scene counts everything as its own level.
"""
import csv
import statistics
import sys
from collections import defaultdict
from pathlib import Path

import yaml


def level_of_ap(z_m, levels, wall_height_m):
    for level_id, elevation_m in levels:
        if elevation_m - 1e-6 <= z_m <= elevation_m + wall_height_m + 1e-6:
            return level_id
    return None


def measure(dataset):
    scene = yaml.safe_load((dataset / "scene.yaml").read_text())
    wall_height_m = float(scene.get("building", {}).get("wall_height_m", 2.8))
    levels = [(str(l["id"]), float(l["elevation_m"])) for l in scene.get("levels", [])]
    route_level = str(scene.get("route", {}).get("level", levels[0][0] if levels else ""))
    if not levels:
        levels = [("", 0.0)]
    ap_level = {}
    with open(dataset / "access_points.csv", newline="") as f:
        for row in csv.DictReader(f):
            ap_level[row["bssid"]] = level_of_ap(float(row["z_m"]), levels, wall_height_m)
    scans = defaultdict(list)  # scan end -> [(rssi, bssid)]
    with open(dataset / "wifi.csv", newline="") as f:
        for row in csv.DictReader(f):
            scans[row["timestamp"]].append((int(row["rssi_dbm"]), row["mac_addr"]))
    heard, other, strongest_other, any_other = [], [], 0, 0
    for readings in scans.values():
        heard.append(len(readings))
        n_other = sum(1 for _, mac in readings if ap_level.get(mac) != route_level)
        other.append(n_other)
        any_other += n_other > 0
        strongest = max(readings)
        strongest_other += ap_level.get(strongest[1]) != route_level
    n = len(scans)
    return (
        f"| {dataset.name} | {route_level} | {n} | {statistics.median(heard):.0f} / "
        f"{statistics.mean(heard):.1f} | {statistics.median(other):.0f} / "
        f"{statistics.mean(other):.1f} | {100.0 * sum(other) / max(1, sum(heard)):.1f} % | "
        f"{100.0 * strongest_other / max(1, n):.1f} % | {100.0 * any_other / max(1, n):.1f} % |"
    )


def main():
    if len(sys.argv) < 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    print("| dataset | route level | scans | BSSIDs a scan, median / mean | from other levels, "
          "median / mean | share from other levels | strongest from another level | scans "
          "hearing another level |")
    print("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for arg in sys.argv[1:]:
        print(measure(Path(arg)))


if __name__ == "__main__":
    main()
