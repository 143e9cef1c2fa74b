"""Scene.load and Scene.from_dict: the loader's own checks and located errors."""

import json
import os
import subprocess
import sys

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


def test_a_scene_is_made_only_by_its_factories():
    # pybind11's own __new__ gave an instance holding no scene, and its first method call crashed
    # the interpreter (SIGSEGV); run in a child so that a crash fails this test, not the suite.
    code = ("import wifislam\n"
            "for make in (lambda: wifislam.Scene.__new__(wifislam.Scene), wifislam.Scene):\n"
            "    try:\n"
            "        make().name\n"
            "    except TypeError as e:\n"
            "        print(e)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert len(lines) == 2, done.stdout
    for line in lines:
        assert "use Scene.load(path), Scene.from_dict(d) or Scene.from_yaml(text)" in line


def test_a_scene_pickles_and_copies_to_the_same_scene(tmp_path, c_hall):
    # multiprocessing's spawn and forkserver workers pickle their arguments.
    import copy
    import pickle

    scene = wifislam.Scene.load(c_hall)
    copies = [pickle.loads(pickle.dumps(scene, protocol))
              for protocol in range(pickle.HIGHEST_PROTOCOL + 1)]
    for again in copies + [copy.copy(scene), copy.deepcopy(scene)]:
        assert again.to_yaml() == scene.to_yaml()
        assert again.source_path == scene.source_path
    built = wifislam.Scene.from_dict(scene.to_dict(), "mine")
    assert pickle.loads(pickle.dumps(built)).to_yaml() == built.to_yaml()
    # The same dataset, bit for bit, from the scene and from its pickled copy.
    small = {"fps": 1, "max_frames": 3}
    wifislam.generate(scene, tmp_path / "a", **small)
    wifislam.generate(pickle.loads(pickle.dumps(scene)), tmp_path / "b", **small)
    for name in ("groundtruth.txt", "wifi.csv", "images.sha256", "scene.yaml"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes(), name


def test_from_yaml_takes_text_and_says_so():
    for call in (lambda: wifislam.Scene.from_yaml(None),
                 lambda: wifislam.Scene.from_yaml("version: 1", source_name=None)):
        with pytest.raises(TypeError,
                           match=r"^Scene\.from_yaml\(\): (text|source_name) takes text"):
            call()


def test_seeds_past_2_to_the_63_stay_whole_numbers_through_a_dict(c_hall):
    # to_dict read the plain scalar with stoll, which stops at 2**63 - 1, and fell back to a
    # float: 2**64 - 1 came back as 1.8446744073709552e+19, which from_dict then refused.
    for seed in (2**63 - 1, 2**63, 2**64 - 1):
        d = wifislam.Scene.load(c_hall).to_dict()
        d["seed"] = seed
        again = wifislam.Scene.from_dict(d).to_dict()
        assert again["seed"] == seed and isinstance(again["seed"], int)
        assert wifislam.Scene.from_dict(again).seed == seed


def test_route_node_names_that_look_like_numbers_stay_names_through_a_dict(c_hall):
    # The route's node list was written unquoted: nodes named "01" and "02" came back as
    # route.nodes [1, 2, ...], which named no node.
    text = json.dumps(wifislam.Scene.load(c_hall).to_dict())
    for old, new in (("A", "01"), ("B", "1e2"), ("C", "0x10"), ("D", "nan")):
        assert f'"{old}"' in text
        text = text.replace(f'"{old}"', f'"{new}"')  # the node, and wherever it is named
    d = json.loads(text)
    scene = wifislam.Scene.from_dict(d)
    again = scene.to_dict()
    assert again["route"]["nodes"] == d["route"]["nodes"]
    assert wifislam.Scene.from_dict(again).to_yaml() == scene.to_yaml()


def test_a_loaded_scene_remembers_its_file_wherever_the_notebook_goes(tmp_path, c_hall,
                                                                     monkeypatch):
    # The scene kept the relative path it was loaded by: after a %cd, generate's check that
    # force=True never replaces a folder holding an input looked elsewhere, and the scene file
    # inside the replaced folder was deleted.
    monkeypatch.chdir(tmp_path)
    small = {"images": False, "fps": 1, "max_frames": 2}
    wifislam.generate(c_hall, "ds", **small)
    (tmp_path / "ds" / "variant.yaml").write_bytes(open(c_hall, "rb").read())
    scene = wifislam.Scene.load("ds/variant.yaml")
    assert scene.source_path == str(tmp_path / "ds" / "variant.yaml")
    (tmp_path / "elsewhere").mkdir()
    monkeypatch.chdir(tmp_path / "elsewhere")
    with pytest.raises(wifislam.InvalidInputError, match="input"):
        wifislam.generate(scene, tmp_path / "ds", force=True, **small)
    assert (tmp_path / "ds" / "variant.yaml").exists()
