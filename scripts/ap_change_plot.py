#!/usr/bin/python3
"""The access-point change study of bench/localize/devices_sessions.sh, summarised: for each
change (off, moved) and share of APs changed, each method's share of queries within 2 m (mean and
range over the seeds) and, for wifi-clusters, the share of queries its Wi-Fi left on the whole
map. Prints a Markdown table and draws the means against the share changed.

  scripts/ap_change_plot.py RESULTS_DIR TITLE OUT.png

RESULTS_DIR holds localize outputs named loc_<change>_<share>_<seed>.
"""
import csv
import json
import statistics
import sys
from collections import defaultdict
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

METHODS = ["fabmap", "wifi-fabmap", "wifi-clusters"]


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    results, title, out = Path(sys.argv[1]), sys.argv[2], sys.argv[3]
    within = defaultdict(list)  # (change, share, method) -> [share within 2 m per seed]
    whole = defaultdict(list)   # (change, share) -> [share on the whole map per seed]
    for folder in sorted(results.glob("loc_*_*_*")):
        _, change, share, _seed = folder.name.split("_")
        summary = json.loads((folder / "summary.json").read_text())
        for m in summary["methods"]:
            within[change, float(share), m["method"]].append(m["all"]["within_2m"])
        with open(folder / "queries.csv", newline="") as f:
            rows = [r for r in csv.DictReader(f) if r["method"] == "wifi-clusters"]
        whole[change, float(share)].append(
            sum(int(r["candidates"]) == summary["map_images"] for r in rows) / len(rows))
    changes = sorted({k[0] for k in within}, reverse=True)  # off, moved
    shares = sorted({k[1] for k in within})
    print("| APs changed | share | " + " | ".join(f"{m} within 2 m" for m in METHODS) +
          " | wifi-clusters on the whole map |")
    print("| --- | ---: |" + " ---: |" * (len(METHODS) + 1))

    def cell(values):
        mean = 100.0 * statistics.mean(values)
        return f"{mean:.1f} % ({100.0 * min(values):.1f}-{100.0 * max(values):.1f})"

    for change in changes:
        for share in shares:
            cells = [cell(within[change, share, m]) for m in METHODS]
            print(f"| {change} | {100 * share:.0f} % | " + " | ".join(cells) +
                  f" | {cell(whole[change, share])} |")
    fig, axes = plt.subplots(1, len(changes), figsize=(5 * len(changes), 3.6), sharey=True)
    for ax, change in zip(axes, changes):
        for m in METHODS:
            ax.plot([100 * s for s in shares],
                    [100 * statistics.mean(within[change, s, m]) for s in shares],
                    marker="o", label=m)
        ax.set_title(f"APs {change} between the sessions")
        ax.set_xlabel("share of access points changed (%)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("queries within 2 m (%, mean of seeds)")
    axes[0].legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
