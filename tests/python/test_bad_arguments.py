"""Arguments a notebook can pass that the command line's options never let through: infinite
rates, NaN positions, paths with a NUL byte or as bytes, empty images, NaN metrics, folders of
the wrong kind. Each is a clear error of the module's classes naming the argument (or, where a
value is legitimate, it works as its str equivalent does), never a hang, a crash or a silent
answer about something else."""

import json
import os
import pathlib

import numpy as np
import pytest

import wifislam


@pytest.fixture(scope="module")
def a_hall(scenes_dir):
    return os.path.join(scenes_dir, "a_hall.yaml")


def test_an_unbounded_frame_rate_is_refused_before_any_work(tmp_path, a_hall):
    # fps=inf made the frame schedule count for ever (the call hung).
    for fps in (float("inf"), 1e7, 0.01):
        with pytest.raises(wifislam.InvalidInputError, match="fps"):
            wifislam.Simulator(a_hall, fps=fps, max_frames=3)
        with pytest.raises(wifislam.InvalidInputError, match="fps"):
            wifislam.generate(a_hall, tmp_path / "d", fps=fps, max_frames=3)
        with pytest.raises(wifislam.InvalidInputError, match="fps"):
            wifislam.slam(a_hall, tmp_path / "r", fps=fps, max_frames=3)
    assert not (tmp_path / "d").exists() and not (tmp_path / "r").exists()
    with pytest.raises(wifislam.InvalidInputError, match="threads"):
        wifislam.generate(a_hall, tmp_path / "d", fps=1, max_frames=3, threads=-3)
    assert not (tmp_path / "d").exists()


def test_zero_frames_is_refused_not_a_dataset_no_reader_takes(tmp_path, a_hall, small_dataset):
    # generate(max_frames=0) wrote a dataset of no frames, which `check` refuses.
    with pytest.raises(wifislam.InvalidInputError, match="max_frames"):
        wifislam.generate(a_hall, tmp_path / "d", fps=1, max_frames=0)
    with pytest.raises(wifislam.InvalidInputError, match="max_frames"):
        wifislam.Simulator(a_hall, fps=1, max_frames=0)
    for source in (a_hall, small_dataset):
        with pytest.raises(wifislam.InvalidInputError, match="max_frames"):
            wifislam.slam(source, tmp_path / "r", fps=1 if source == a_hall else None,
                          max_frames=0)
    assert not (tmp_path / "d").exists() and not (tmp_path / "r").exists()


def test_positions_and_grids_must_be_finite(a_hall):
    for bad in ((float("nan"), 1.5, 30), (2.0, float("inf"), 30), (2.0, 1.5, float("nan"))):
        with pytest.raises(wifislam.InvalidInputError, match="finite"):
            wifislam.camera_pose(a_hall, *bad)
    for resolution in (float("inf"), 10.5):
        with pytest.raises(wifislam.InvalidInputError, match="resolution"):
            wifislam.radio_map(a_hall, resolution_m=resolution)
    assert wifislam.radio_map(a_hall, resolution_m=10.0).resolution_m == 10.0


def test_paths_are_str_bytes_or_pathlike_and_never_hold_a_nul_byte(tmp_path, a_hall,
                                                                   small_dataset):
    # The C++ side stopped at the NUL and read another file without a word.
    for call in (lambda p: wifislam.Scene.load(p), lambda p: wifislam.Simulator(p),
                 lambda p: wifislam.read_trajectory(p), lambda p: wifislam.Dataset(p)):
        with pytest.raises(ValueError, match="null byte"):
            call(a_hall + "\0junk")
    assert wifislam.Scene.load(pathlib.Path(a_hall)).name == "a_hall"
    assert wifislam.Scene.load(os.fsencode(a_hall)).name == "a_hall"
    truth = os.path.join(small_dataset, "groundtruth.txt")
    as_str = wifislam.evaluate(truth, str(small_dataset))
    as_bytes = wifislam.evaluate(os.fsencode(truth), os.fsencode(str(small_dataset)))
    assert as_bytes["ate_rmse_m"] == as_str["ate_rmse_m"]
    with pytest.raises(TypeError, match="path"):
        wifislam.Dataset(42)


def test_empty_images_are_named_not_an_opencv_error():
    with pytest.raises(wifislam.InvalidInputError, match="rgb.*empty"):
        wifislam.encode_rgb_png(np.zeros((0, 0, 3), np.uint8))
    with pytest.raises(wifislam.InvalidInputError, match="depth.*empty"):
        wifislam.encode_depth_png(np.zeros((0, 4), np.float32))


def test_channel_of_knows_the_bands_and_refuses_the_rest():
    assert wifislam.channel_of(2412000) == 1
    assert wifislam.channel_of(2472000) == 13
    assert wifislam.channel_of(2484000) == 14
    assert wifislam.channel_of(5180000) == 36
    assert wifislam.channel_of(np.int64(5825000)) == 165
    # 6 GHz (802.11ax): 5950 MHz + 5 MHz per channel, and 5935 MHz channel 2.
    assert wifislam.channel_of(5930000) == 186  # the last 5 GHz number
    assert wifislam.channel_of(5955000) == 1
    assert wifislam.channel_of(5935000) == 2
    assert wifislam.channel_of(6115000) == 33
    assert wifislam.channel_of(7115000) == 233
    for bad in (0, -5, 2401000, 2413000, 2412500, 5932000, 7120000, 60480000):
        with pytest.raises(ValueError, match="channel"):
            wifislam.channel_of(bad)
    with pytest.raises(TypeError):
        wifislam.channel_of(2412000.0)


def test_a_nan_metric_is_not_available_as_none_is(small_dataset):
    # metrics.csv writes a metric a run cannot give as "-nan"; pandas reads it back as NaN.
    truth = wifislam.Dataset(small_dataset).ground_truth
    metrics = wifislam.evaluate(truth, truth)
    outcomes = []
    for missing in (None, float("nan"), np.float32("inf")):
        with pytest.raises(wifislam.RequirementNotMetError) as failure:
            wifislam.require(dict(metrics, ate_rmse_m=missing), "ate_rmse_m <= 0.5")
        outcomes.append(str(failure.value))
    assert "not available" in outcomes[0]
    assert outcomes[1] == outcomes[0] and outcomes[2] == outcomes[0]


def test_a_folder_is_scored_for_what_it_holds(tmp_path, small_dataset):
    truth = wifislam.Dataset(small_dataset).ground_truth
    # A dataset folder as the estimate was scored against itself: a perfect 0 m.
    with pytest.raises(wifislam.InvalidInputError, match="dataset folder"):
        wifislam.evaluate(small_dataset, truth)
    run = wifislam.slam(small_dataset, tmp_path / "run", wifi=False, settings={"wifi": True})
    # `settings` ran the Wi-Fi variant: the dict says what ran, as run.json does.
    assert run["wifi"] is True and run["frontend"] == "rgbdslam"
    from_folder = wifislam.evaluate(run["run"], truth)
    from_file = wifislam.evaluate(os.path.join(run["run"], "trajectory.txt"), truth)
    assert from_folder["ate_rmse_m"] == from_file["ate_rmse_m"]
    with pytest.raises(wifislam.InvalidInputError, match="without trajectory.txt"):
        wifislam.evaluate(tmp_path, truth)


def test_a_wrong_type_names_the_function_and_the_argument(tmp_path, a_hall, small_dataset):
    # pybind11 listed the internal function's parameters as arg0, arg1, ... instead.
    cases = [
        (lambda: wifislam.generate(a_hall, tmp_path / "d", fps="3"),
         r"generate\(\): fps takes a number or None, got str '3'"),
        (lambda: wifislam.Simulator(a_hall, max_frames=2.5),
         r"Simulator\(\): max_frames takes a whole number, got float 2.5"),
        (lambda: wifislam.slam(small_dataset, tmp_path / "r", wifi="yes"),
         r"slam\(\): wifi takes True or False, got str 'yes'"),
        (lambda: wifislam.radio_map(a_hall, resolution_m=None),
         r"radio_map\(\): resolution_m takes a number, got NoneType None"),
        (lambda: wifislam.require({"ate_rmse_m": 0.1}, "ate_rmse_m <= 1", 5),
         r"require\(\): requirements takes text \(str\), got int 5"),
        (lambda: wifislam.Dataset(small_dataset, verify=None),
         r"Dataset\(\): verify takes True or False, got NoneType None"),
        (lambda: wifislam.Renderer(42),
         r"Renderer\(\): scene takes a Scene or a path \(str, bytes or os.PathLike\), got int 42"),
        (lambda: wifislam.evaluate(small_dataset, small_dataset, time_offset_s="0"),
         r"evaluate\(\): time_offset_s takes a number, got str '0'"),
    ]
    for call, message in cases:
        with pytest.raises(TypeError, match=message):
            call()
    assert not (tmp_path / "d").exists() and not (tmp_path / "r").exists()


def test_numpy_scalars_and_number_kinds_pass_as_python_ones(a_hall):
    frames = list(wifislam.Simulator(a_hall, fps=np.float32(2), max_frames=np.int64(2),
                                     images=np.bool_(False)))
    assert [f.index for f in frames] == [0, 1]
    assert wifislam.radio_map(a_hall, resolution_m=5, band=5).resolution_m == 5.0
    assert wifislam.camera_pose(a_hall, np.float64(2), 1, np.int32(30)).shape == (4, 4)


def test_poses_and_trajectories_take_real_numbers_only(a_hall, small_dataset):
    # A complex pose rendered its real part with numpy's ComplexWarning only; strings and
    # booleans were read as numbers.
    import warnings
    pose = wifislam.camera_pose(a_hall, 2.0, 1.5, 30)
    truth = wifislam.Dataset(small_dataset).ground_truth
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a warning on the way is a failure too
        with_boolean = pose.tolist()
        with_boolean[3][3] = True  # numpy would read it as 1.0
        for bad, kind in ((pose.astype(np.complex128), "complex numbers"),
                          (pose.astype(str), "text"), (pose > 0, "booleans"),
                          (with_boolean, "a boolean")):
            with pytest.raises(wifislam.InvalidInputError,
                               match=rf"render\(\): pose: expected real numbers, got {kind}"):
                wifislam.render(a_hall, bad)
        with pytest.raises(wifislam.InvalidInputError,
                           match=r"evaluate\(\): estimate: expected real numbers, got complex"):
            wifislam.evaluate(truth + 1e-3j, truth)
        with pytest.raises(wifislam.InvalidInputError,
                           match=r"evaluate\(\): ground_truth: expected real numbers, got objects"):
            wifislam.evaluate(truth, [[None] * 8] * 3)
        with pytest.raises(wifislam.InvalidInputError, match=r"estimate: .*float's range"):
            wifislam.evaluate([[10**400, 0, 0, 0, 0, 0, 0, 1]] * 3, truth)
        with pytest.raises(wifislam.InvalidInputError, match=r"pose: .*got a boolean"):
            wifislam.render(a_hall, [np.array([True, False, False, False])] + pose.tolist()[1:])
        masked = np.ma.masked_array(truth, mask=np.zeros_like(truth, dtype=bool))
        masked[0, 1] = np.ma.masked
        with pytest.raises(wifislam.InvalidInputError, match=r"ground_truth: has masked values"):
            wifislam.evaluate(truth, masked)
        # Real numbers held as objects (a pandas column of mixed types) are numbers.
        from fractions import Fraction
        as_objects = pose.astype(object)
        as_objects[0, 3] = Fraction(int(pose[0, 3] * 4), 4)
        wifislam.render(a_hall, as_objects, noise=False)
        assert wifislam.evaluate(truth.astype(object), truth) == wifislam.evaluate(truth, truth)
        # Real numbers of any width still pass, as the float64 they are.
        assert wifislam.evaluate(truth.tolist(), truth) == wifislam.evaluate(truth, truth)
        assert np.array_equal(wifislam.render(a_hall, pose.astype(np.float32), noise=False)[0],
                              wifislam.render(a_hall, pose.astype(np.float32).astype(np.float64),
                                              noise=False)[0])


def test_an_array_argument_takes_arrays_and_nested_lists_only(a_hall, small_dataset):
    with pytest.raises(TypeError, match=r"evaluate\(\): estimate takes a path .* or an array "):
        wifislam.evaluate({}, small_dataset)
    with pytest.raises(TypeError, match=r"render\(\): pose takes an array, got int 5"):
        wifislam.render(a_hall, 5)
    pose = wifislam.camera_pose(a_hall, 2.0, 1.5, 30)
    rgb, depth = wifislam.render(a_hall, pose.tolist(), noise=False)
    assert np.array_equal(rgb, wifislam.render(a_hall, pose, noise=False)[0])
    # Images as nested lists of whole numbers: numpy's int64, refused as no image type before.
    assert wifislam.encode_depth_png([[1, 2], [3, 0]]) == wifislam.encode_depth_png(
        np.array([[1.0, 2.0], [3.0, 0.0]]))
    assert wifislam.encode_rgb_png(rgb[:4, :4].tolist()) == wifislam.encode_rgb_png(rgb[:4, :4])
    with pytest.raises(ValueError):
        wifislam.encode_rgb_png([[[300, 0, 0]]])  # no uint8: not taken modulo 256
    with pytest.raises(ValueError):
        wifislam.encode_depth_png(depth.astype(np.int64))  # an array keeps its dtype's check
    for bad in ([["1.5", "2"]], [[None, 1.0]], [[True, False]], [[1.0], [1.0, 2.0]], [[10**400]]):
        with pytest.raises(wifislam.InvalidInputError, match=r"^encode_depth_png\(\): depth"):
            wifislam.encode_depth_png(bad)


def test_whole_numbers_outside_what_the_module_holds_name_the_range(tmp_path, a_hall,
                                                                    small_dataset):
    # pybind11 refused these with its list of the internal function's arguments; a negative
    # max_frames other than -1 ran the whole route.
    cases = [
        (lambda: wifislam.Simulator(a_hall, seed=-1),
         r"Simulator\(\): seed takes a whole number from 0 to 2\*\*64 - 1, got -1"),
        (lambda: wifislam.generate(a_hall, tmp_path / "d", seed=2**64),
         r"generate\(\): seed takes a whole number from 0 to 2\*\*64 - 1"),
        (lambda: wifislam.Simulator(a_hall, max_frames=-5, images=False),
         r"max_frames takes -1 \(the whole route\) or a whole number of 1 or more, got -5"),
        (lambda: wifislam.generate(a_hall, tmp_path / "d", max_frames=0),
         r"generate\(\): max_frames takes -1 .* got 0"),
        (lambda: wifislam.slam(small_dataset, tmp_path / "r", max_frames=np.int64(-3)),
         r"slam\(\): max_frames takes -1 .* got -3"),
        (lambda: wifislam.generate(a_hall, tmp_path / "d", threads=2**40),
         r"generate\(\): threads takes 0 \(every core\)"),
        # A float argument given an int past a double: pybind11's TypeError listed the
        # binding's own signatures, and evaluate's float() an OverflowError.
        (lambda: wifislam.camera_pose(a_hall, 10**400, 0.0, 0.0),
         r"camera_pose\(\): x_m takes a number within a float's range .* got 10{19}\.\.\. "
         r"\(401 digits\)"),
        (lambda: wifislam.evaluate(small_dataset, small_dataset, time_offset_s=-10**400),
         r"evaluate\(\): time_offset_s takes a number within a float's range"),
    ]
    for call, message in cases:
        with pytest.raises(wifislam.InvalidInputError, match=message):
            call()
    assert not (tmp_path / "d").exists() and not (tmp_path / "r").exists()
    # -1 is the whole route, as before.
    assert len(wifislam.Simulator(a_hall, fps=0.2, max_frames=-1, images=False)) > 2


def test_numpy_scalars_inside_dicts_pass_as_python_numbers(a_hall):
    met = wifislam.require({"ate_rmse_m": np.float32(0.1), "rpe_trans_m_per_m": [np.inf]},
                           "ate_rmse_m <= 0.5")
    assert len(met) == 1 and met[0].startswith("met")
    scene = wifislam.Scene.load(a_hall).to_dict()
    scene["seed"] = np.arange(3)[2]  # a seed swept with numpy
    assert wifislam.Scene.from_dict(scene).to_dict()["seed"] == 2


def test_array_stamps_that_are_no_seconds_are_named(small_dataset):
    truth = wifislam.Dataset(small_dataset).ground_truth
    for bad, message in ((np.nan, r"row 3: t is not a finite number \(nan\)"),
                         (np.inf, r"row 3: t is not a finite number \(inf\)"),
                         (1.7e12, r"row 3: t = 1700000000000 s is out of range .* not millisec")):
        estimate = truth.copy()
        estimate[3, 0] = bad
        with pytest.raises(wifislam.ParseError, match=message):
            wifislam.evaluate(estimate, truth)


def test_evaluate_without_verify_scores_an_edited_ground_truth(tmp_path, small_dataset):
    # verify=False reached the array path only: a run or trajectory file against a dataset
    # folder still compared groundtruth.txt with manifest.json.
    import shutil
    edited = tmp_path / "edited"
    shutil.copytree(small_dataset, edited)
    lines = (edited / "groundtruth.txt").read_text().splitlines(keepends=True)
    row = next(i for i, line in enumerate(lines) if not line.startswith("#"))
    fields = lines[row].split(" ")
    fields[1] = f"{float(fields[1]) + 0.001:.6f}"
    lines[row] = " ".join(fields)
    (edited / "groundtruth.txt").write_text("".join(lines))
    estimate = small_dataset / "groundtruth.txt"
    with pytest.raises(wifislam.ParseError, match="manifest"):
        wifislam.evaluate(estimate, edited)
    metrics = wifislam.evaluate(estimate, edited, verify=False)
    assert 0 < metrics["ate_rmse_m"] < 0.01


def test_a_path_that_is_not_utf8_is_refused_before_any_work(tmp_path, a_hall, small_dataset):
    # generate and slam wrote their whole output into such a folder and then failed to give its
    # path back; the readers failed with a JSON or cast error of the compiled module.
    bad = os.fsencode(str(tmp_path)) + b"/bad\xff"
    calls = [
        lambda: wifislam.generate(a_hall, bad, fps=1, max_frames=2, images=False),
        lambda: wifislam.slam(small_dataset, bad, max_frames=2),
        lambda: wifislam.slam(bad, tmp_path / "r"),
        lambda: wifislam.evaluate(bad, small_dataset),
        lambda: wifislam.Scene.load(bad + b".yaml"),
        lambda: wifislam.Dataset(bad),
        lambda: wifislam.read_trajectory(bad + b"/groundtruth.txt"),
    ]
    for call in calls:
        with pytest.raises(wifislam.InvalidInputError, match="not valid UTF-8"):
            call()
    assert os.listdir(tmp_path) == []


def test_an_empty_path_is_refused_not_taken_for_the_current_folder(small_dataset):
    # Dataset("") opened the current folder (os.path.abspath("") is the current folder).
    for call in (lambda: wifislam.Dataset(""), lambda: wifislam.Scene.load(""),
                 lambda: wifislam.read_trajectory(""), lambda: wifislam.slam(small_dataset, "")):
        with pytest.raises(wifislam.InvalidInputError, match="the path is empty"):
            call()


def test_images_too_big_for_any_camera_and_non_arrays_are_named():
    # A 2**31-wide image reached OpenCV, whose assertion came back as a bare RuntimeError.
    with pytest.raises(wifislam.InvalidInputError, match="rgb: the image is 2147483648 x 1"):
        wifislam.encode_rgb_png(np.zeros((1, 2**31, 3), np.uint8))
    with pytest.raises(wifislam.InvalidInputError, match="depth: the image is 1 x 8193"):
        wifislam.encode_depth_png(np.zeros((8193, 1), np.float32))
    for bad in (None, "abc"):
        with pytest.raises(TypeError, match=r"encode_rgb_png\(\): rgb takes an array"):
            wifislam.encode_rgb_png(bad)
        with pytest.raises(TypeError, match=r"encode_depth_png\(\): depth takes an array"):
            wifislam.encode_depth_png(bad)


def test_numpy_and_whole_float_settings_read_as_the_command_line_spells_them(tmp_path,
                                                                             small_dataset):
    # np.bool_ read as "True", an array as "[1. 2.]" and 70.0 as no integer.
    small = {"max_frames": 3, "frontend": "rgbdslam"}
    run = wifislam.slam(small_dataset, tmp_path / "a", wifi=False, **small,
                        settings={"wifi": np.bool_(True), "min_matches": np.float64(70.0),
                                  "prune_chi2": np.array([1.0, 2.0])})
    assert run["wifi"] is True
    with open(os.path.join(run["run"], "run.json")) as f:
        options = json.load(f)["options"]
    assert options["min_matches"] == 70 and options["prune_chi2"] == "1,2"
    with pytest.raises(wifislam.ParseError, match="min_matches"):
        wifislam.slam(small_dataset, tmp_path / "b", **small, settings={"min_matches": 70.5})
    with pytest.raises(wifislam.ParseError, match="from -2147483648 to 2147483647"):
        wifislam.slam(small_dataset, tmp_path / "b", **small,
                      settings={"optimizer_threads": 2**40})
    assert not (tmp_path / "b").exists()


def test_a_whole_number_beyond_64_bits_in_metrics_is_no_json_error():
    met = wifislam.require({"ate_rmse_m": 0.1, "x": 10**400, "y": 2**70}, "ate_rmse_m <= 1")
    assert met[0].startswith("met")
    with pytest.raises(wifislam.RequirementNotMetError, match="not available"):
        wifislam.require({"ate_rmse_m": 10**400}, "ate_rmse_m <= 1")


def test_a_settings_key_holding_an_equals_sign_is_that_key(small_dataset):
    # evaluate split "a=b" into the key "a" and the value "b=c".
    with pytest.raises(wifislam.ParseError, match="settings: key 'a=b'"):
        wifislam.evaluate(small_dataset, small_dataset, settings={"a=b": "c"})
    with pytest.raises(wifislam.ParseError, match="settings: unknown evaluation threshold"):
        wifislam.evaluate(small_dataset, small_dataset, settings={"": "c"})


def test_a_band_given_as_a_number_is_the_band_in_ghz(a_hall):
    # band=5.0 was passed on as the text "5.0", which no band is called.
    for number, text in ((5.0, "5"), (2.4, "2.4"), (np.float32(5), "5"), (np.float32(2.4), "2.4"),
                         (5, "5")):
        as_number = wifislam.radio_map(a_hall, resolution_m=5, band=number)
        as_text = wifislam.radio_map(a_hall, resolution_m=5, band=text)
        assert np.array_equal(as_number.rssi_dbm, as_text.rssi_dbm, equal_nan=True)
    # A number near a band is not that band (2.40000001 was read as "2.4").
    for number in (2.40000001, 5.0000001, np.float64(np.float32(2.4)), float("nan")):
        with pytest.raises(wifislam.InvalidInputError, match=r"band '.*': expected '2.4', '5'"):
            wifislam.radio_map(a_hall, resolution_m=5, band=number)


def test_output_folders_are_named_back_without_a_trailing_slash(tmp_path, a_hall, small_dataset):
    made = wifislam.generate(a_hall, str(tmp_path / "d") + "/.", fps=1, max_frames=2,
                             images=False)
    assert made["dataset"] == str(tmp_path / "d")
    run = wifislam.slam(small_dataset, str(tmp_path / "r") + "/", max_frames=2)
    assert run["run"] == str(tmp_path / "r")
