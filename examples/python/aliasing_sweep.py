#!/usr/bin/python3
"""ATE against perceptual aliasing, vanilla against Wi-Fi SLAM: a sweep in a dozen lines of API.

For each aliasing level (appearance.aliasing: 1 = every wall segment looks alike), the scene is
changed as a dict, generated, run through a front end without and with the Wi-Fi module,
scored against its exact ground truth, and the two ATEs are plotted against the level.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/aliasing_sweep.py \\
        --out /tmp/aliasing_sweep

writes, in --out (which must not exist, or holds a previous sweep: each level's folders are
replaced), results.csv and ate_vs_aliasing.png. The defaults take about an hour on 2 cores;
--fps 1 --max-frames 30 --levels 0,1 takes a minute (what the test suite runs).
"""

import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

import wifislam  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENE = os.path.join(HERE, "..", "..", "scenes", "aliasing_ladder.yaml")


def parse_args(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scene", default=DEFAULT_SCENE, help="scene file (default: %(default)s)")
    parser.add_argument("--levels", default="0,0.25,0.5,0.75,1",
                        help="aliasing levels in [0, 1], comma-separated (default: %(default)s)")
    parser.add_argument("--frontend", default="rgbdslam", help="front end (default: %(default)s)")
    parser.add_argument("--fps", type=float, default=3.0, help="frame rate (default: %(default)s)")
    parser.add_argument("--max-frames", type=int, default=-1,
                        help="frames per dataset (default: the whole route)")
    parser.add_argument("--seed", type=int, default=None, help="replace the scene's seed")
    parser.add_argument("--out", required=True, help="output folder")
    args = parser.parse_args(argv)
    try:
        args.levels = [float(x) for x in args.levels.split(",")]
    except ValueError:
        parser.error(f"--levels '{args.levels}': expected numbers separated by commas")
    return args


def scene_at(base, level):
    """The scene with appearance.aliasing set: the loader checks the level (in [0, 1])."""
    scene_dict = base.to_dict()
    scene_dict["appearance"]["aliasing"] = level
    return wifislam.Scene.from_dict(scene_dict, source_name=f"{base.name} aliasing {level}")


def run_level(scene, level, args):
    """Generates the scene at one aliasing level and scores vanilla and Wi-Fi SLAM on it."""
    folder = os.path.join(args.out, f"aliasing_{level:g}")
    os.makedirs(folder, exist_ok=True)
    dataset = wifislam.generate(scene, os.path.join(folder, "dataset"), seed=args.seed,
                                fps=args.fps, max_frames=args.max_frames, force=True)["dataset"]
    row = {"aliasing": level}
    for variant, wifi in (("vanilla", False), ("wifi", True)):
        run = wifislam.slam(dataset, os.path.join(folder, variant), frontend=args.frontend,
                            wifi=wifi, force=True)
        metrics = wifislam.evaluate(run["run"], dataset)
        row[f"{variant}_ate_rmse_m"] = metrics["ate_rmse_m"]
        row[f"{variant}_false_positives"] = metrics.get("false_positives")
        print(f"aliasing {level:g} {variant}: ATE {metrics['ate_rmse_m']:.3f} m", flush=True)
    return row


def plot(rows, path, title):
    levels = [r["aliasing"] for r in rows]
    figure, axes = plt.subplots(figsize=(6, 4))
    axes.plot(levels, [r["vanilla_ate_rmse_m"] for r in rows], "o-", label="vanilla")
    axes.plot(levels, [r["wifi_ate_rmse_m"] for r in rows], "s-", label="Wi-Fi")
    axes.set_xlabel("aliasing (share of wall segments that look alike)")
    axes.set_ylabel("ATE RMSE (m)")
    axes.set_title(title)
    axes.grid(True, alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(path, dpi=120)
    plt.close(figure)


def main(argv):
    args = parse_args(argv)
    base = wifislam.Scene.load(args.scene)
    # Every level's scene first, so a bad level fails before an hour of work.
    scenes = [scene_at(base, level) for level in args.levels]
    rows = [run_level(scene, level, args) for scene, level in zip(scenes, args.levels)]
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "results.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    plot(rows, os.path.join(args.out, "ate_vs_aliasing.png"),
         f"{base.name}, {args.frontend}, {args.fps:g} fps")
    print(f"wrote {os.path.join(args.out, 'results.csv')} and ate_vs_aliasing.png")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except (ValueError, OSError) as error:  # wifislam's bad-input errors: the message, exit 2
        print(f"aliasing_sweep: {error}", file=sys.stderr)
        sys.exit(2)
