#!/usr/bin/python3
"""One Markdown table of several `wifislam localize` outputs: per run and method, the queries,
the share matched within 2 m, the median error and, for wifi-clusters, the share of queries whose
Wi-Fi narrowed nothing (they were matched against the whole map: no pause signature, or no similar
cluster).

  scripts/localize_table.py LABEL=OUTPUT_DIR [LABEL=OUTPUT_DIR ...]
"""
import csv
import json
import statistics
import sys
from pathlib import Path


def main():
    if len(sys.argv) < 2 or any("=" not in a for a in sys.argv[1:]):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    print("| run | method | queries | within 2 m | median error (m) | whole map (wifi-clusters) |")
    print("| --- | --- | ---: | ---: | ---: | ---: |")
    for arg in sys.argv[1:]:
        label, folder = arg.split("=", 1)
        folder = Path(folder)
        summary = json.loads((folder / "summary.json").read_text())
        rows = {}
        with open(folder / "queries.csv", newline="") as f:
            for row in csv.DictReader(f):
                rows.setdefault(row["method"], []).append(row)
        for m in summary["methods"]:
            name = m["method"]
            errors = [float(r["error_m"]) for r in rows.get(name, [])]
            whole = ""
            if name == "wifi-clusters":
                map_images = summary["map_images"]
                fallback = sum(int(r["candidates"]) == map_images for r in rows[name])
                whole = f"{100.0 * fallback / len(rows[name]):.1f} %"
            print(f"| {label} | {name} | {m['queries']} | {100.0 * m['all']['within_2m']:.1f} % | "
                  f"{statistics.median(errors):.2f} | {whole} |")


if __name__ == "__main__":
    main()
