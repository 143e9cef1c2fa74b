"""Every iteration of a Dataset or Simulator starts at the first frame, as a list's does, and two
iterations never interleave silently: the frames have one read position."""

import numpy as np
import pytest

import wifislam


def same_frames(a, b):
    assert [f.index for f in a] == [f.index for f in b]
    assert [f.stamp_ns for f in a] == [f.stamp_ns for f in b]
    for x, y in zip(a, b):
        assert (x.rgb is None) == (y.rgb is None)
        if x.rgb is not None:
            assert np.array_equal(x.rgb, y.rgb)
            assert np.array_equal(x.depth, y.depth, equal_nan=True)
        assert np.array_equal(x.pose, y.pose)
        assert x.scans == y.scans


def test_a_dataset_iterated_twice_gives_every_frame_twice(small_dataset):
    dataset = wifislam.Dataset(small_dataset)
    first = list(dataset)
    second = list(dataset)
    assert len(first) == len(dataset) > 0
    same_frames(first, second)


def test_a_simulator_iterated_twice_gives_the_same_frames(c_hall):
    simulator = wifislam.Simulator(c_hall, fps=1.0, max_frames=4)
    first = list(simulator)
    second = list(simulator)
    assert len(first) == 4
    assert first[0].rgb is not None
    same_frames(first, second)


def test_a_loop_after_a_break_starts_at_the_first_frame(small_dataset, c_hall):
    for source in (wifislam.Dataset(small_dataset),
                   wifislam.Simulator(c_hall, fps=1.0, max_frames=6, images=False)):
        for frame in source:
            if frame.index == 2:
                break
        assert [f.index for f in source] == list(range(len(source)))


def test_an_iterator_holds_its_place_until_another_iteration_begins(small_dataset):
    dataset = wifislam.Dataset(small_dataset, load_images=False)
    frames = iter(dataset)
    assert [next(frames).index for _ in range(3)] == [0, 1, 2]
    assert next(frames).index == 3
    again = iter(dataset)
    assert next(again).index == 0
    with pytest.raises(RuntimeError, match="another iteration"):
        next(frames)
    assert next(again).index == 1
    dataset.rewind()
    with pytest.raises(RuntimeError, match="another iteration"):
        next(again)


def test_zip_of_a_source_with_itself_is_an_error_not_wrong_pairs(small_dataset):
    dataset = wifislam.Dataset(small_dataset, load_images=False)
    with pytest.raises(RuntimeError, match="another iteration"):
        list(zip(dataset, dataset))


def test_an_iterator_at_its_end_stays_there(c_hall):
    simulator = wifislam.Simulator(c_hall, fps=1.0, max_frames=2, images=False)
    frames = iter(simulator)
    assert len(list(frames)) == 2
    assert list(frames) == []
    with pytest.raises(StopIteration):
        next(frames)


# Threads sharing one iterator: test_threads_and_fork.py.


def test_a_dataset_opened_by_a_relative_path_keeps_reading_it_after_a_chdir(
        tmp_path, monkeypatch, small_dataset):
    # Each pass reads the files again: a relative path once read another folder's after a
    # notebook's %cd, with len() and ground_truth still the first folder's.
    monkeypatch.chdir(small_dataset.parent)
    dataset = wifislam.Dataset(small_dataset.name)
    first = list(dataset)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    same_frames(first, list(dataset))
    assert dataset.path == str(small_dataset)


def test_a_dataset_replaced_or_removed_since_it_was_opened_is_refused(tmp_path, small_dataset,
                                                                        c_hall):
    # A pass read the new folder's frames while len() and ground_truth were the old one's.
    import shutil
    folder = tmp_path / "ds"
    shutil.copytree(small_dataset, folder)
    dataset = wifislam.Dataset(folder)
    assert len(list(dataset)) == len(dataset)
    wifislam.generate(c_hall, folder, fps=1.0, max_frames=4, images=False, force=True)
    with pytest.raises(wifislam.InvalidInputError, match="changed since it was opened"):
        list(dataset)
    shutil.rmtree(folder)
    with pytest.raises(wifislam.InvalidInputError, match="changed since it was opened"):
        list(dataset)
    # Opened again: the folder as it is now.
    wifislam.generate(c_hall, folder, fps=1.0, max_frames=4)
    assert len(list(wifislam.Dataset(folder))) == 4
