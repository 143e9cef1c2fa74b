#!/usr/bin/python3
"""Frame-to-frame RGB-D odometry with OpenCV's rgbd module (cv2.rgbd.RgbdOdometry, the dense
photometric + depth method of Steinbruecker, Sturm and Cremers 2011), run on a TUM-layout dataset.

    opencv_rgbd_odometry.py DATASET OUT_FOLDER

Reads DATASET/associations.txt (TUM associate.py output: stamp rgb stamp depth), the intrinsics
and depth scale from DATASET/calibration.yaml when present (else the TUM defaults: 525 px,
centre 319.5/239.5, 5000 units per metre), and writes OUT_FOLDER/trajectory.txt: one TUM line per
frame, camera-to-map, the map being the first camera frame. It closes no loops.

When OpenCV reports a failed registration (too little texture or depth) the frame keeps the last
pose (zero motion), as a plain odometry front end would; the count goes to stderr. Deterministic:
the seed is not used.
"""
import math
import re
import sys
from pathlib import Path

import cv2
import numpy as np


def read_calibration(dataset: Path):
    """fx, fy, cx, cy in pixels and depth units per metre."""
    values = {"fx_px": 525.0, "fy_px": 525.0, "cx_px": 319.5, "cy_px": 239.5,
              "units_per_metre": 5000.0}
    path = dataset / "calibration.yaml"
    if path.exists():
        for line in path.read_text().splitlines():
            match = re.match(r"\s*(\w+):\s*([-0-9.eE+]+)\s*(#.*)?$", line)
            if match and match.group(1) in values:
                values[match.group(1)] = float(match.group(2))
    return values


def read_associations(dataset: Path):
    """(stamp text, rgb path, depth path) per frame, in file order."""
    path = dataset / "associations.txt"
    if not path.exists():
        sys.exit(f"{path}: missing (this system reads associate.py's output)")
    frames = []
    for number, line in enumerate(path.read_text().splitlines(), start=1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = line.split()
        if len(fields) < 4:
            sys.exit(f"{path}:{number}: expected 'stamp rgb stamp depth'")
        frames.append((fields[0], dataset / fields[1], dataset / fields[3]))
    return frames


def load_frame(rgb_path: Path, depth_path: Path, depth_units_per_m: float):
    grey = cv2.imread(str(rgb_path), cv2.IMREAD_GRAYSCALE)
    depth = cv2.imread(str(depth_path), cv2.IMREAD_UNCHANGED)
    if grey is None or depth is None:
        sys.exit(f"cannot read {rgb_path} or {depth_path}")
    return grey, depth.astype(np.float32) / depth_units_per_m


def quaternion_xyzw(rotation):
    """Unit quaternion of a rotation matrix (Shepperd's method, stable near every angle)."""
    m = rotation
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = [(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s]
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = [0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s]
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = [(m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s]
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = [(m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s]
    norm = math.sqrt(sum(c * c for c in q))
    return [c / norm for c in q]


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    dataset, out = Path(sys.argv[1]), Path(sys.argv[2])
    calibration = read_calibration(dataset)
    frames = read_associations(dataset)
    if not frames:
        sys.exit(f"{dataset}: no frames")
    camera = np.array([[calibration["fx_px"], 0, calibration["cx_px"]],
                       [0, calibration["fy_px"], calibration["cy_px"]], [0, 0, 1]], np.float64)
    # Depth range of a Kinect-class sensor; the defaults of RgbdOdometry otherwise.
    odometry = cv2.rgbd.RgbdOdometry_create(camera, 0.3, 8.0)
    camera_to_map = np.eye(4)
    lines = ["# timestamp tx ty tz qx qy qz qw (camera to first camera, cv2.rgbd.RgbdOdometry)"]
    failures = 0
    previous = None
    for index, (stamp, rgb_path, depth_path) in enumerate(frames):
        grey, depth_m = load_frame(rgb_path, depth_path, calibration["units_per_metre"])
        if previous is not None:
            # compute() gives Rt with p_current = Rt * p_previous.
            ok, previous_to_current = odometry.compute(previous[0], previous[1], None, grey,
                                                       depth_m, None)
            if ok:
                camera_to_map = camera_to_map @ np.linalg.inv(previous_to_current)
            else:
                failures += 1
        previous = (grey, depth_m)
        t = camera_to_map[:3, 3]
        q = quaternion_xyzw(camera_to_map[:3, :3])
        lines.append(f"{stamp} {t[0]:.6f} {t[1]:.6f} {t[2]:.6f} "
                     f"{q[0]:.9f} {q[1]:.9f} {q[2]:.9f} {q[3]:.9f}")
        if (index + 1) % 100 == 0:
            print(f"{index + 1}/{len(frames)} frames", file=sys.stderr, flush=True)
    (out / "trajectory.txt").write_text("\n".join(lines) + "\n")
    print(f"{len(frames)} frames, {failures} failed registrations (zero motion kept)",
          file=sys.stderr)


if __name__ == "__main__":
    main()
