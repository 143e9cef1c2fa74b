#!/usr/bin/python3
"""The device part of bench/localize/devices_sessions.sh, summarised over the seeds: per query
device and method, the share of queries within 2 m (mean and range), the median error's range,
and for wifi-clusters the share of queries its Wi-Fi left on the whole map.

  scripts/device_table.py RESULTS_DIR

RESULTS_DIR holds localize outputs named dev_<device>_<seed>.
"""
import csv
import json
import statistics
import sys
from collections import defaultdict
from pathlib import Path

METHODS = ["fabmap", "wifi-fabmap", "wifi-clusters"]


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    within, medians, whole, devices = defaultdict(list), defaultdict(list), defaultdict(list), []
    for folder in sorted(Path(sys.argv[1]).glob("dev_*_*")):
        device = folder.name[len("dev_"):folder.name.rindex("_")]
        if device not in devices:
            devices.append(device)
        summary = json.loads((folder / "summary.json").read_text())
        with open(folder / "queries.csv", newline="") as f:
            rows = list(csv.DictReader(f))
        for m in summary["methods"]:
            within[device, m["method"]].append(m["all"]["within_2m"])
            errors = [float(r["error_m"]) for r in rows if r["method"] == m["method"]]
            medians[device, m["method"]].append(statistics.median(errors))
        clusters = [r for r in rows if r["method"] == "wifi-clusters"]
        whole[device].append(
            sum(int(r["candidates"]) == summary["map_images"] for r in clusters) / len(clusters))
    print("| query device | method | within 2 m (mean, range) | median error (m) | "
          "wifi-clusters on the whole map |")
    print("| --- | --- | ---: | ---: | ---: |")
    for device in devices:
        for m in METHODS:
            w, med = within[device, m], medians[device, m]
            extra = f"{100.0 * statistics.mean(whole[device]):.1f} %" if m == "wifi-clusters" else ""
            print(f"| {device} | {m} | {100.0 * statistics.mean(w):.1f} % "
                  f"({100.0 * min(w):.1f}-{100.0 * max(w):.1f}) | {min(med):.2f}-{max(med):.2f} | "
                  f"{extra} |")


if __name__ == "__main__":
    main()
