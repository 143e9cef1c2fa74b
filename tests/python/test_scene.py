"""Scene.load and Scene.from_dict: the loader's own checks and located errors."""

import os

import pytest

import wifislam


def test_load_gives_the_scene_file(c_hall):
    scene = wifislam.Scene.load(c_hall)
    assert scene.name == "c_hall"
    assert scene.source_path == c_hall
    assert "c_hall" in repr(scene)


def test_a_dict_round_trip_gives_the_same_resolved_scene(c_hall):
    scene = wifislam.Scene.load(c_hall)
    as_dict = scene.to_dict()
    assert as_dict["version"] == 1
    assert isinstance(as_dict["corridors"], list)
    again = wifislam.Scene.from_dict(as_dict)
    assert again.to_yaml() == scene.to_yaml()


def test_a_changed_dict_changes_the_scene(c_hall):
    as_dict = wifislam.Scene.load(c_hall).to_dict()
    as_dict["seed"] = 12345
    as_dict["appearance"]["aliasing"] = 0.25
    scene = wifislam.Scene.from_dict(as_dict)
    assert scene.seed == 12345
    assert scene.to_dict()["appearance"]["aliasing"] == 0.25


def test_a_bad_key_is_a_value_error_naming_the_key_path(c_hall):
    as_dict = wifislam.Scene.load(c_hall).to_dict()
    as_dict["corridors"][0]["width_m"] = -1.0
    with pytest.raises(ValueError, match=r"corridors\[0\]\.width_m"):
        wifislam.Scene.from_dict(as_dict, source_name="sweep.py")
    as_dict = wifislam.Scene.load(c_hall).to_dict()
    as_dict["no_such_key"] = 1
    with pytest.raises(wifislam.ParseError, match="no_such_key"):
        wifislam.Scene.from_dict(as_dict)


def test_a_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(OSError, match="missing.yaml"):
        wifislam.Scene.load(str(tmp_path / "missing.yaml"))


def test_not_a_dict_is_a_type_error():
    with pytest.raises(TypeError):
        wifislam.Scene.from_dict(["version", 1])


def test_text_that_looks_like_a_number_stays_text_through_a_dict(c_hall):
    # to_dict typed every plain scalar: a name "007" came back as the number 7, "1e5" as 100000.0.
    for text in ("007", "1e5", "0x1F", "5.5", "nan", "true", "1"):
        d = wifislam.Scene.load(c_hall).to_dict()
        d["name"] = text
        d["description"] = "." + text
        scene = wifislam.Scene.from_dict(d)
        again = scene.to_dict()
        assert again["name"] == text and again["description"] == "." + text
        assert wifislam.Scene.from_dict(again).to_yaml() == scene.to_yaml()


def test_a_source_name_labels_messages_and_is_no_input(tmp_path, c_hall):
    # generate refused an output inside a folder named as the scene's source_name, as if that
    # label were the scene file.
    text = wifislam.Scene.load(c_hall).to_yaml()
    scene = wifislam.Scene.from_yaml(text, str(tmp_path / "experiment"))
    info = wifislam.generate(scene, tmp_path / "experiment" / "run1", fps=1, max_frames=2,
                             images=False)
    assert os.path.isdir(info["dataset"])
    info = wifislam.generate(wifislam.Scene.from_dict(scene.to_dict()), tmp_path / "<dict>",
                             fps=1, max_frames=2, images=False)
    assert os.path.isdir(info["dataset"])
