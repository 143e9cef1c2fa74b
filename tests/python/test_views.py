"""render and radio_map give what `wifislam render` and `wifislam radiomap` write."""

import csv
import math
import os
import subprocess

import numpy as np
import pytest

import wifislam


def test_render_equals_the_render_command(tmp_path, wifislam_binary, c_hall):
    prefix = str(tmp_path / "view")
    subprocess.run([wifislam_binary, "render", c_hall, "--pose", "2.0,1.5,30", "-o", prefix],
                   check=True, stdout=subprocess.DEVNULL)
    renderer = wifislam.Renderer(c_hall)
    pose = renderer.camera_pose(2.0, 1.5, 30.0)
    rgb, depth = renderer.render(pose)
    with open(prefix + "_rgb.png", "rb") as f:
        assert wifislam.encode_rgb_png(rgb) == f.read()
    with open(prefix + "_depth.png", "rb") as f:
        assert wifislam.encode_depth_png(depth) == f.read()
    assert np.isfinite(depth).any()
    ideal_rgb, ideal = renderer.render(pose, noise=False)
    assert np.array_equal(ideal_rgb, rgb)
    assert not np.array_equal(ideal, depth, equal_nan=True)


def test_a_pose_that_is_not_rigid_is_a_value_error(c_hall):
    renderer = wifislam.Renderer(c_hall)
    with pytest.raises(ValueError, match="4 x 4"):
        renderer.render(np.eye(3))
    with pytest.raises(ValueError, match="rigid"):
        renderer.render(np.diag([2.0, 1.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match="ceiling"):
        renderer.camera_pose(1.0, 1.0, 0.0, height_m=100.0)


def test_radio_map_equals_the_radiomap_command(tmp_path, wifislam_binary, c_hall):
    csv_path = tmp_path / "map.csv"
    subprocess.run([wifislam_binary, "radiomap", c_hall, "--strongest", "--res", "1.0",
                    "-o", str(tmp_path / "map.png"), "--csv", str(csv_path)],
                   check=True, stdout=subprocess.DEVNULL)
    grid = wifislam.radio_map(c_hall, resolution_m=1.0)
    assert grid.rssi_dbm.shape == grid.best_ap_id.shape
    assert len(grid.access_points) > 0
    with open(csv_path) as f:
        rows = [r for r in csv.DictReader(f)]
    assert rows
    for row in rows:
        x, y = float(row["x_m"]), float(row["y_m"])
        col = int(math.floor((x - grid.origin_m[0]) / grid.resolution_m))
        r = int(math.floor((y - grid.origin_m[1]) / grid.resolution_m))
        assert grid.cell_center_m(col, r) == pytest.approx((x, y), abs=1e-3)
        assert float(grid.rssi_dbm[r, col]) == pytest.approx(float(row["rssi_dbm"]), abs=0.01)
        assert int(grid.best_ap_id[r, col]) == int(row["ap_id"])


def test_radio_map_bad_arguments_are_value_errors(c_hall):
    with pytest.raises(ValueError, match="band"):
        wifislam.radio_map(c_hall, band="60")
    with pytest.raises(ValueError):
        wifislam.radio_map(c_hall, ap=999)


def test_radio_map_of_a_level_equals_the_radiomap_command(tmp_path, wifislam_binary, scenes_dir):
    two_storeys = os.path.join(scenes_dir, "two_storey_office.yaml")
    csv_path = tmp_path / "first.csv"
    subprocess.run([wifislam_binary, "radiomap", two_storeys, "--ap", "0", "--res", "1.0",
                    "--level", "first", "-o", str(tmp_path / "first.png"), "--csv", str(csv_path)],
                   check=True, stdout=subprocess.DEVNULL)
    upstairs = wifislam.radio_map(two_storeys, resolution_m=1.0, ap=0, level="first")
    ground = wifislam.radio_map(two_storeys, resolution_m=1.0, ap=0)
    with open(csv_path) as f:
        rows = [r for r in csv.DictReader(f)]
    assert rows
    for row in rows:
        col = int(math.floor((float(row["x_m"]) - upstairs.origin_m[0]) / upstairs.resolution_m))
        r = int(math.floor((float(row["y_m"]) - upstairs.origin_m[1]) / upstairs.resolution_m))
        assert float(upstairs.rssi_dbm[r, col]) == pytest.approx(float(row["rssi_dbm"]), abs=0.01)
    # AP 0 stands on the ground floor: upstairs hears it through the slab, weaker.
    assert np.nanmax(upstairs.rssi_dbm) < np.nanmax(ground.rssi_dbm)
    with pytest.raises(ValueError, match="no such level"):
        wifislam.radio_map(two_storeys, level="roof")
