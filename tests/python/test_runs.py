"""generate, slam and evaluate give what the commands write and print."""

import json
import os
import subprocess

import numpy as np
import pytest

import wifislam
from conftest import SMALL


def read(path):
    with open(path, "rb") as f:
        return f.read()


def test_generate_writes_the_commands_dataset(tmp_path, small_dataset, c_hall):
    info = wifislam.generate(c_hall, tmp_path / "again", **SMALL)
    assert info["dataset"] == str(tmp_path / "again")
    assert info["frames"] == SMALL["max_frames"]
    assert info["wifi_scans"] > 0
    for name in ("manifest.json", "groundtruth.txt", "wifi.csv", "rgb.txt", "depth.txt"):
        assert read(tmp_path / "again" / name) == read(small_dataset / name), name


def test_generate_replaces_only_its_own_output_and_only_when_forced(tmp_path, c_hall):
    small = {"images": False, "max_frames": 2}
    wifislam.generate(c_hall, tmp_path / "d", **small)
    with pytest.raises(ValueError, match="exists"):
        wifislam.generate(c_hall, tmp_path / "d", **small)
    wifislam.generate(c_hall, tmp_path / "d", force=True, **small)
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("mine")
    with pytest.raises(ValueError, match="does not look like wifislam output"):
        wifislam.generate(c_hall, tmp_path / "mine", force=True, **small)
    assert (tmp_path / "mine" / "notes.txt").read_text() == "mine"


@pytest.fixture(scope="module")
def wifi_run(tmp_path_factory, small_dataset):
    out = tmp_path_factory.mktemp("runs") / "wifi"
    return wifislam.slam(small_dataset, out, frontend="rgbdslam", wifi=True,
                         settings={"min_matches": 50})


def test_slam_writes_a_run_folder(wifi_run):
    assert os.path.isfile(os.path.join(wifi_run["run"], "trajectory.txt"))
    assert wifi_run["summary"]["frames"] == SMALL["max_frames"]
    assert wifi_run["wifi"]


def test_slam_bad_setting_is_a_value_error(tmp_path, small_dataset):
    # The message names the argument the key came from (`settings`), not the command line's --set.
    with pytest.raises(ValueError, match="^settings: key 'min_matchez'") as failure:
        wifislam.slam(small_dataset, tmp_path / "run", settings={"min_matchez": 5})
    assert "--set" not in str(failure.value)
    assert not (tmp_path / "run").exists()


def test_evaluate_equals_the_eval_command(tmp_path, wifislam_binary, wifi_run, small_dataset):
    out = tmp_path / "eval"
    subprocess.run([wifislam_binary, "eval", wifi_run["run"], "--gt", str(small_dataset),
                    "-o", str(out), "--no-plots"], check=True, stdout=subprocess.DEVNULL)
    with open(out / "metrics.csv") as f:
        header, row = [line.rstrip("\n").split(",") for line in f.readlines()[:2]]
    metrics = wifislam.evaluate(wifi_run["run"], small_dataset)
    assert list(metrics) == header
    for name, text in zip(header, row):
        value = metrics[name]
        if isinstance(value, float):
            assert value == pytest.approx(float(text), rel=1e-9, abs=1e-12), name
        elif isinstance(value, bool):
            assert text == str(value).lower(), name
        elif value is None:
            assert text == "", name
        else:
            assert str(value) == text, name


def test_arrays_files_and_folders_score_alike(tmp_path, wifi_run, small_dataset):
    trajectory = os.path.join(wifi_run["run"], "trajectory.txt")
    estimate = wifislam.read_trajectory(trajectory)
    truth = wifislam.Dataset(small_dataset).ground_truth
    from_files = wifislam.evaluate(trajectory, small_dataset)
    from_arrays = wifislam.evaluate(estimate, truth)
    for name in ("ate_rmse_m", "ate_max_m", "rpe_trans_per_m", "frames_associated"):
        assert from_arrays[name] == pytest.approx(from_files[name], rel=1e-9), name
    shifted = estimate.copy()
    shifted[:, 1] += 1.0
    assert wifislam.evaluate(shifted, truth)["ate_rmse_m"] == pytest.approx(
        from_arrays["ate_rmse_m"], rel=1e-6)
    assert wifislam.evaluate(shifted, truth, align="none")["ate_rmse_m"] > 0.9


def test_evaluate_bad_input(tmp_path, small_dataset):
    truth = wifislam.Dataset(small_dataset).ground_truth
    with pytest.raises(ValueError, match="N x 8"):
        wifislam.evaluate(np.zeros((5, 7)), truth)
    bad = truth.copy()
    bad[2, 1] = np.nan
    with pytest.raises(ValueError, match="estimate row 2"):
        wifislam.evaluate(bad, truth)
    with pytest.raises(ValueError, match="align"):
        wifislam.evaluate(truth, truth, align="affine")
    with pytest.raises(ValueError, match="^settings: key 'overlap_min_fractio'"):
        wifislam.evaluate(truth, truth, settings={"overlap_min_fractio": "0.3"})
    with pytest.raises(OSError):
        wifislam.evaluate(tmp_path / "missing.txt", small_dataset)
    with pytest.raises(ValueError, match="share a timestamp"):
        wifislam.evaluate(truth[:2], truth)


def test_require_is_an_assertion_with_the_commands_message(small_dataset):
    truth = wifislam.Dataset(small_dataset).ground_truth
    metrics = wifislam.evaluate(truth, truth)
    assert wifislam.require(metrics, "ate_rmse_m <= 0.001")[0].startswith("met")
    with pytest.raises(AssertionError, match="ate_rmse_m") as failure:
        wifislam.require(metrics, "ate_rmse_m > 1", "frames_associated >= 1")
    assert "1 of 2 requirements not met" in str(failure.value)
    with pytest.raises(ValueError):
        wifislam.require(metrics, "ate_rmse_m ~ 1")
    with pytest.raises(ValueError, match="ate_rmse"):
        wifislam.require(metrics, "ate_rmsee_m <= 1")
