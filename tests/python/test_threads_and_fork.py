"""One object shared by threads, and processes forked from one that rendered.

Long calls release the GIL, so two threads can be inside one Renderer or one Simulator at once:
they take turns (each view equals the one-thread view, each frame goes to exactly one thread),
where they crashed the interpreter before. OSMesa's rendering threads do not survive fork()
(Python's multiprocessing forks by default on Linux): a forked child of a process that rendered
gets FacilityError, where it waited for ever.
"""

import multiprocessing
import os
import threading

import numpy as np
import pytest

import wifislam


@pytest.fixture(scope="module")
def a_hall(scenes_dir):
    return os.path.join(scenes_dir, "a_hall.yaml")


def test_one_renderer_in_two_threads_gives_each_view_as_one_thread_does(a_hall):
    renderer = wifislam.Renderer(a_hall)
    poses = [renderer.camera_pose(2.0 + i, 1.5, 30.0 * i) for i in range(3)]
    expected = [renderer.render(p) for p in poses]
    results = {}

    def work(name):
        results[name] = [renderer.render(p) for p in poses for _ in range(2)]

    threads = [threading.Thread(target=work, args=(n,)) for n in ("a", "b")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for name in ("a", "b"):
        for i, (rgb, depth) in enumerate(results[name]):
            assert np.array_equal(rgb, expected[i // 2][0]), (name, i)
            assert np.array_equal(depth, expected[i // 2][1], equal_nan=True), (name, i)


def test_one_simulator_in_two_threads_hands_each_frame_to_one_of_them(a_hall):
    simulator = wifislam.Simulator(a_hall, fps=2, max_frames=20)
    frames = iter(simulator)  # one iteration, shared: each `for` over the simulator starts anew
    seen = {"a": [], "b": []}

    def work(name):
        for frame in frames:
            seen[name].append(frame.index)

    threads = [threading.Thread(target=work, args=(n,)) for n in seen]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert sorted(seen["a"] + seen["b"]) == list(range(20))


def _render_in_child(renderer, pose, scene_path, answers):
    for attempt in ("inherited renderer", "new renderer"):
        try:
            if attempt == "inherited renderer":
                renderer.render(pose)
            else:
                wifislam.Renderer(scene_path).render(pose)
            answers.put((attempt, "rendered"))
        except wifislam.FacilityError as e:
            answers.put((attempt, str(e)))


def test_a_child_forked_after_rendering_gets_an_error_not_a_hang(a_hall):
    renderer = wifislam.Renderer(a_hall)
    pose = renderer.camera_pose(2.0, 1.5, 0.0)
    renderer.render(pose)
    context = multiprocessing.get_context("fork")
    answers = context.Queue()
    child = context.Process(target=_render_in_child, args=(renderer, pose, a_hall, answers))
    child.start()
    child.join(120)
    if child.is_alive():
        child.kill()
        child.join()
        pytest.fail("the forked child hung")
    assert child.exitcode == 0
    got = dict(answers.get(timeout=10) for _ in range(2))
    for attempt in ("inherited renderer", "new renderer"):
        assert "forked" in got[attempt] and "spawn" in got[attempt], got
    # The parent renders on, and a child started afresh renders as it does.
    rgb, _ = renderer.render(pose)
    spawned = multiprocessing.get_context("spawn")
    with spawned.Pool(1) as pool:
        rgb_spawned, _ = pool.apply(wifislam.render, (a_hall, pose))
    assert np.array_equal(rgb, rgb_spawned)
