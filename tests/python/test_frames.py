"""The simulator's frames, the dataset's files and the Dataset reader agree bit for bit."""

import math
import os
import subprocess

import numpy as np
import pytest

import wifislam
from conftest import SMALL


def read(path):
    with open(path, "rb") as f:
        return f.read()


def listed(dataset, name):
    """(stamp text, path) of a TUM list file's lines."""
    rows = []
    with open(os.path.join(dataset, name)) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                stamp, path = line.split()[:2]
                rows.append((stamp, path))
    return rows


@pytest.fixture(scope="module")
def simulated(c_hall):
    return list(wifislam.Simulator(wifislam.Scene.load(c_hall), **SMALL))


@pytest.fixture(scope="module")
def read_back(small_dataset):
    return list(wifislam.Dataset(small_dataset))


def test_frames_have_the_promised_types(simulated, c_hall):
    assert len(simulated) == SMALL["max_frames"]
    frame = simulated[0]
    assert frame.rgb.dtype == np.uint8 and frame.rgb.shape == (480, 640, 3)
    assert frame.depth.dtype == np.float32 and frame.depth.shape == (480, 640)
    assert frame.pose.shape == (4, 4)
    assert np.allclose(frame.pose[:3, :3] @ frame.pose[:3, :3].T, np.eye(3))
    # No reading is NaN, never 0.
    depth = np.concatenate([f.depth.ravel() for f in simulated])
    assert np.isnan(depth).any()
    assert not (depth == 0).any()
    assert [f.index for f in simulated] == list(range(SMALL["max_frames"]))
    stamps = [f.stamp_ns for f in simulated]
    assert stamps == sorted(stamps)


def test_simulator_frames_encode_to_the_datasets_png_bytes(simulated, small_dataset):
    rgb_files = listed(small_dataset, "rgb.txt")
    depth_files = listed(small_dataset, "depth.txt")
    assert len(rgb_files) == len(simulated)
    for frame, (rgb_stamp, rgb_path), (_, depth_path) in zip(simulated, rgb_files, depth_files):
        assert wifislam.encode_rgb_png(frame.rgb) == read(os.path.join(small_dataset, rgb_path))
        assert wifislam.encode_depth_png(frame.depth) == read(
            os.path.join(small_dataset, depth_path))
        assert f"{frame.stamp_ns // 1000 // 1_000_000}.{frame.stamp_ns // 1000 % 1_000_000:06d}" \
            == rgb_stamp


def test_the_dataset_reader_returns_the_simulators_frames(simulated, read_back):
    assert len(read_back) == len(simulated)
    for sim, disk in zip(simulated, read_back):
        assert sim.stamp_ns == disk.stamp_ns
        assert np.array_equal(sim.rgb, disk.rgb)
        assert np.array_equal(sim.depth, disk.depth, equal_nan=True)
        # groundtruth.txt keeps the pose to its printed decimals.
        assert np.allclose(sim.pose, disk.pose, atol=1e-6)
        assert sim.scans == disk.scans


def test_scans_arrive_with_the_frame_after_them(simulated, small_dataset):
    scans = [s for f in simulated for s in f.scans]
    assert scans, "c_hall pauses within its first 16 s: the test needs its scans"
    rows = 0
    for frame in simulated:
        for scan in frame.scans:
            assert scan.stamp_ns <= frame.stamp_ns
            for reading in scan.readings:
                assert -120 <= reading.rssi_dbm <= 30
                assert reading.channel in range(1, 15) or reading.channel >= 32
                assert len(reading.bssid) == 17
            rows += len(scan.readings)
    with open(os.path.join(small_dataset, "wifi.csv")) as f:
        csv_rows = [line for line in f if line.strip() and not line.startswith(("#", "timestamp"))]
    # Scans after the last frame belong to no frame.
    assert 0 < rows <= len(csv_rows)


def test_ground_truth_and_intrinsics(small_dataset):
    dataset = wifislam.Dataset(small_dataset)
    assert len(dataset) == SMALL["max_frames"]
    assert dataset.ground_truth.shape == (SMALL["max_frames"], 8)
    assert dataset.intrinsics["fx_px"] > 0
    assert dataset.has_wifi
    first = next(iter(dataset))
    again = next(iter(dataset))
    assert first.stamp_ns == again.stamp_ns


def test_a_folder_that_is_not_a_dataset_is_an_error(tmp_path):
    with pytest.raises(OSError):
        wifislam.Dataset(tmp_path / "missing")
    (tmp_path / "empty").mkdir()
    with pytest.raises((OSError, ValueError)):
        wifislam.Dataset(tmp_path / "empty")


def test_reprs_say_what_a_source_is_and_frames_compare_as_objects(small_dataset, c_hall):
    dataset = wifislam.Dataset(small_dataset)
    assert repr(dataset).startswith("<wifislam.Dataset: ") and "16 frames>" in repr(dataset)
    simulator = wifislam.Simulator(c_hall, fps=1.0, max_frames=2, images=False)
    assert repr(simulator).startswith("<wifislam.Simulator: ") and "2 frames>" in repr(simulator)
    assert "c_hall" in repr(wifislam.Renderer(c_hall))
    first, second = list(dataset)[:2]
    # A field-wise == of arrays raised "truth value of an array is ambiguous".
    assert first == first and first != second
    assert len({first, second}) == 2
    # The module's own helpers (typing, numpy, os) are not listed as its API.
    assert "np" not in dir(wifislam) and "Optional" not in dir(wifislam)
    assert "Dataset" in dir(wifislam) and "generate" in dir(wifislam)


def test_a_dataset_without_images_gives_the_simulators_pose_only_frames(tmp_path, c_hall):
    # It gave no frame at all: the frames of such a folder are its ground-truth stamps.
    settings = {"fps": 2.0, "max_frames": 40}
    folder = tmp_path / "no_images"
    wifislam.generate(c_hall, folder, images=False, **settings)
    simulated = list(wifislam.Simulator(c_hall, images=False, **settings))
    dataset = wifislam.Dataset(folder)
    read_back = list(dataset)
    assert len(dataset) == len(read_back) == len(simulated) == settings["max_frames"]
    assert "(0 frames" not in repr(dataset) and "40 frames>" in repr(dataset)
    assert sum(len(f.scans) for f in simulated) > 0, "the test needs c_hall's first pauses"
    assert sum(len(f.odometry) for f in simulated) > 0
    for sim, disk in zip(simulated, read_back):
        assert (disk.index, disk.stamp_ns) == (sim.index, sim.stamp_ns)
        assert disk.rgb is None and disk.depth is None
        assert np.allclose(sim.pose, disk.pose, atol=1e-6)
        assert sim.scans == disk.scans
        assert [t for t, _ in sim.odometry] == [t for t, _ in disk.odometry]
        for (_, a), (_, b) in zip(sim.odometry, disk.odometry):
            assert np.allclose(a, b, atol=1e-6)
    # A second pass gives the same frames.
    assert [f.stamp_ns for f in dataset] == [f.stamp_ns for f in read_back]


def test_a_datasets_imu_is_its_imu_csv(tmp_path, small_dataset, c_hall):
    dataset = wifislam.Dataset(small_dataset)
    rows = np.loadtxt(os.path.join(small_dataset, "imu.csv"), delimiter=",", skiprows=1)
    imu = dataset.imu
    assert imu.dtype == np.float64 and imu.shape == rows.shape and imu.shape[1] == 7
    assert np.allclose(imu[:, 0], rows[:, 0], rtol=0, atol=1e-6)  # stamps: whole microseconds
    assert np.array_equal(imu[:, 1:], rows[:, 1:])
    assert np.all(np.diff(imu[:, 0]) > 0)
    # Gravity is in the specific force: its norm is about g over the route.
    assert abs(np.median(np.linalg.norm(imu[:, 4:], axis=1)) - 9.80665) < 0.5
    imu_in_base = dataset.imu_in_base
    assert imu_in_base.shape == (4, 4)
    assert np.allclose(imu_in_base[:3, :3] @ imu_in_base[:3, :3].T, np.eye(3))
    assert np.allclose(imu_in_base[3], [0, 0, 0, 1])
    # Kalibr's T_cam_imu, as calibration.yaml and the EuRoC export write it.
    import yaml
    with open(os.path.join(small_dataset, "calibration.yaml")) as f:
        t_cam_imu = np.array(yaml.safe_load(f)["imu"]["T_cam_imu"]).reshape(4, 4)
    assert np.allclose(np.linalg.inv(dataset.camera_in_base) @ imu_in_base, t_cam_imu, atol=1e-6)
    # A dataset whose scene has no IMU: none.
    scene = wifislam.Scene.load(c_hall).to_dict()
    scene["sensors"]["imu"]["enabled"] = False
    folder = tmp_path / "no_imu"
    wifislam.generate(wifislam.Scene.from_dict(scene), folder, fps=1.0, max_frames=2,
                      images=False)
    assert wifislam.Dataset(folder).imu is None
    without = wifislam.Dataset(folder)
    assert without.imu_in_base is None
    # Read at the first access, from the folder as it was opened: one replaced since is
    # refused, as a pass over its frames is.
    wifislam.generate(c_hall, folder, fps=1.0, max_frames=3, images=False, force=True)
    with pytest.raises(wifislam.InvalidInputError, match="changed since it was opened"):
        without.imu
