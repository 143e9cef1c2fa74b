#!/usr/bin/python3
"""Do Wi-Fi scans on one floor look like scans on another?

Usage: scripts/floor_aliasing.py THIS_FLOOR_DATASET OTHER_FLOOR_DATASET [--similarity 0.9]

Both datasets come from one building scene (`levels:`), with their routes on two levels
(`wifislam import --all-levels --level L`, or route.level). Each scan is a vector of RSSI per
BSSID weighted as the SLAM Wi-Fi module weighs it, max(0, rssi_dbm - (-100)), and two scans are
similar when the cosine of their vectors is at least --similarity (the module's default 0.9,
slam/wifi/signature_similarity.hpp). Single scans, not the module's pause signatures: a pause's
signature averages about five of them, so this is the noisier side of what the clustering sees.
Positions are the ground truth's (x, y) at the scan's end; "distance" is horizontal.

Prints a Markdown table: for horizontal distance bins, the pairs of scans on this floor (two
different scans) and of a scan here with a scan on the other floor, and the share judged
similar; then the share of this floor's scans that have a similar scan on the other floor, and
that have a similar scan on this floor more than 16 m away; and how close each scan's most similar
scan on the other floor comes (cosine).
"""
import argparse
import bisect
import csv
from collections import defaultdict
from pathlib import Path

import numpy as np

from tum_text import read_tum_xy

FLOOR_DBM = -100.0
BINS_M = [0.0, 2.0, 4.0, 8.0, 16.0, float("inf")]


def read_scans(dataset):
    scans = defaultdict(dict)
    with open(dataset / "wifi.csv", newline="") as f:
        for row in csv.DictReader(f):
            scans[int(row["timestamp"])][row["mac_addr"]] = float(row["rssi_dbm"])
    stamps, xy = read_tum_xy(dataset / "groundtruth.txt")
    positions = []
    for t_us in sorted(scans):
        i = bisect.bisect_left(stamps, t_us * 1e-6)
        i = min(range(max(0, i - 1), min(len(stamps), i + 1)), key=lambda k: abs(stamps[k] - t_us * 1e-6))
        positions.append(xy[i])
    return [scans[t] for t in sorted(scans)], np.array(positions)


def weighted(scans, bssids):
    index = {b: i for i, b in enumerate(bssids)}
    m = np.zeros((len(scans), len(bssids)))
    for r, scan in enumerate(scans):
        for b, rssi in scan.items():
            m[r, index[b]] = max(0.0, rssi - FLOOR_DBM)
    norms = np.linalg.norm(m, axis=1, keepdims=True)
    return m / np.where(norms > 0, norms, 1.0)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("this_floor", type=Path)
    parser.add_argument("other_floor", type=Path)
    parser.add_argument("--similarity", type=float, default=0.9)
    args = parser.parse_args()
    here, here_xy = read_scans(args.this_floor)
    there, there_xy = read_scans(args.other_floor)
    bssids = sorted({b for s in here + there for b in s})
    a, b = weighted(here, bssids), weighted(there, bssids)
    same = a @ a.T
    cross = a @ b.T
    d_same = np.linalg.norm(here_xy[:, None, :] - here_xy[None, :, :], axis=2)
    d_cross = np.linalg.norm(here_xy[:, None, :] - there_xy[None, :, :], axis=2)
    off_diagonal = ~np.eye(len(here), dtype=bool)
    print(f"{args.this_floor.name}: {len(here)} scans; {args.other_floor.name}: {len(there)} "
          f"scans; similar at cosine >= {args.similarity}\n")
    print("| horizontal distance | pairs on this floor | similar | pairs across floors | similar |")
    print("| --- | ---: | ---: | ---: | ---: |")
    for lo, hi in zip(BINS_M[:-1], BINS_M[1:]):
        in_same = off_diagonal & (d_same >= lo) & (d_same < hi)
        in_cross = (d_cross >= lo) & (d_cross < hi)
        s_pairs, c_pairs = int(in_same.sum()) // 2, int(in_cross.sum())
        s_sim = int((in_same & (same >= args.similarity)).sum()) // 2
        c_sim = int((in_cross & (cross >= args.similarity)).sum())
        label = f"{lo:g}-{hi:g} m" if hi != float("inf") else f">= {lo:g} m"
        share = lambda k, n: f"{100.0 * k / n:.1f} %" if n else "-"
        print(f"| {label} | {s_pairs} | {share(s_sim, s_pairs)} | {c_pairs} | {share(c_sim, c_pairs)} |")
    any_cross = (cross >= args.similarity).any(axis=1).mean()
    far_same = ((same >= args.similarity) & off_diagonal & (d_same >= 16.0)).any(axis=1).mean()
    best_cross = cross.max(axis=1)
    best_below = np.where(d_cross < 2.0, cross, -1.0).max(axis=1)
    print(f"\nscans with a similar scan on the other floor: {100.0 * any_cross:.1f} %; "
          f"with a similar scan on this floor >= 16 m away: {100.0 * far_same:.1f} %")
    print(f"a scan's most similar scan on the other floor: cosine median {np.median(best_cross):.3f}, "
          f"95th percentile {np.percentile(best_cross, 95):.3f}; among those within 2 m "
          f"(the same spot one floor away, {int((best_below >= 0).sum())} scans): median "
          f"{np.median(best_below[best_below >= 0]):.3f}")


if __name__ == "__main__":
    main()
