#!/usr/bin/python3
"""Time per frame from Python against the command line's generate, measured in the same run.

Three ways to get the same frames of one scene, alternated over --repeats rounds (this machine is
noisy; the medians are quoted, and ratios are to the CLI measured in the same round):

  cli        `wifislam generate SCENE --fps F --max-frames N` (a subprocess; writes PNGs)
  generate   wifislam.generate(...) from Python (the same library call; writes PNGs)
  simulator  iterating wifislam.Simulator(...) (frames as numpy arrays; no PNG, no disk)

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python/frames_per_second.py \\
        --wifislam build/release/apps/wifislam

Prints a Markdown table (docs/benchmarks.md quotes it).
"""

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

import wifislam

HERE = os.path.dirname(os.path.abspath(__file__))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--wifislam", required=True, help="the wifislam program")
    parser.add_argument("--scene", default=os.path.join(HERE, "..", "..", "scenes", "c_hall.yaml"))
    parser.add_argument("--fps", type=float, default=3.0)
    parser.add_argument("--frames", type=int, default=90)
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    scene = wifislam.Scene.load(args.scene)
    times = {"cli": [], "generate": [], "simulator": []}
    scratch = tempfile.mkdtemp(prefix="wifislam_bench_python_")
    try:
        for _ in range(args.repeats):
            out = os.path.join(scratch, "cli")
            start = time.monotonic()
            subprocess.run([args.wifislam, "generate", args.scene, "-o", out, "--fps",
                            str(args.fps), "--max-frames", str(args.frames), "-q"], check=True)
            times["cli"].append(time.monotonic() - start)
            shutil.rmtree(out)  # this script's own scratch folder
            out = os.path.join(scratch, "python")
            start = time.monotonic()
            wifislam.generate(scene, out, fps=args.fps, max_frames=args.frames)
            times["generate"].append(time.monotonic() - start)
            shutil.rmtree(out)
            start = time.monotonic()
            count = sum(1 for _ in wifislam.Simulator(scene, fps=args.fps, max_frames=args.frames))
            times["simulator"].append(time.monotonic() - start)
            assert count == args.frames
    finally:
        shutil.rmtree(scratch)
    cli = statistics.median(times["cli"])
    print(f"{scene.name}, {args.frames} frames at {args.fps:g} fps, median of {args.repeats}\n")
    print("| way | ms per frame (median) | ratio to the CLI |")
    print("| --- | ---: | ---: |")
    for name, values in times.items():
        median = statistics.median(values)
        print(f"| {name} | {1000 * median / args.frames:.1f} | {median / cli:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
