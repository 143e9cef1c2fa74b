#!/usr/bin/python3
"""Writes a scene whose access points change at one session: a share of them switched off, or
moved (the chosen APs' positions permuted among themselves, so each lands where an AP of the
building stood). The AP ids and positions are read from a dataset of the scene
(access_points.csv), so the changes name the APs the scene places.

  scripts/ap_changes.py SCENE DATASET --share 0.25 --change off [--session 1] [--seed 1] -o OUT

Used by bench/localize/devices_sessions.sh.
"""
import argparse
import csv
import random
import sys

import yaml


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("scene")
    ap.add_argument("dataset", help="a dataset of the scene (its access_points.csv)")
    ap.add_argument("--share", type=float, required=True, help="share of the APs changed, 0-1")
    ap.add_argument("--change", choices=["off", "moved"], required=True)
    ap.add_argument("--session", type=int, default=1)
    ap.add_argument("--seed", type=int, default=1, help="which APs are chosen")
    ap.add_argument("-o", "--output", required=True)
    args = ap.parse_args()
    if not 0.0 <= args.share <= 1.0:
        sys.exit(f"--share: {args.share} is not in [0, 1]")
    with open(args.scene) as f:
        scene = yaml.safe_load(f)
    positions = {}
    with open(f"{args.dataset}/access_points.csv") as f:
        for row in csv.DictReader(f):
            positions[int(row["ap_id"])] = [float(row["x_m"]), float(row["y_m"]), float(row["z_m"])]
    ids = sorted(positions)
    chosen = sorted(random.Random(args.seed).sample(ids, round(args.share * len(ids))))
    changes = []
    if args.change == "off":
        changes = [{"session": args.session, "change": "off", "ap": i} for i in chosen]
    elif len(chosen) > 1:
        for k, i in enumerate(chosen):
            to = positions[chosen[(k + 1) % len(chosen)]]
            changes.append({"session": args.session, "change": "moved", "ap": i, "position_m": to})
    scene.setdefault("access_points", {})["changes"] = changes
    scene["name"] = f"{scene.get('name', 'scene')}_{args.change}_{round(100 * args.share)}pc"
    with open(args.output, "w") as f:
        yaml.safe_dump(scene, f, sort_keys=False, default_flow_style=None)
    print(f"{args.output}: {len(changes)} of {len(ids)} APs {args.change} from session {args.session}")


if __name__ == "__main__":
    main()
