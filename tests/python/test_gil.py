"""Long calls release the GIL: another Python thread keeps running while they work.

The main thread records when each of its loop iterations ran while a worker thread is inside
the call. Holding the GIL, the call would stop the main thread for its whole length; released,
the longest gap is scheduling noise. The bound (half the call's length) leaves a wide margin
either way.
"""

import threading
import time

import wifislam


def longest_gap_while(call):
    done = threading.Event()
    span = {}

    def work():
        start = time.monotonic()
        call()
        span["s"] = time.monotonic() - start
        done.set()

    worker = threading.Thread(target=work)
    last = time.monotonic()
    gap = 0.0
    worker.start()
    while not done.is_set():
        now = time.monotonic()
        gap = max(gap, now - last)
        last = now
    worker.join()
    return gap, span["s"]


def test_generate_releases_the_gil(tmp_path, c_hall):
    gap, span = longest_gap_while(
        lambda: wifislam.generate(c_hall, tmp_path / "d", fps=2, max_frames=6, threads=1))
    assert span > 0.3
    assert gap < 0.5 * span, (gap, span)


def test_simulator_frames_release_the_gil(c_hall):
    frames = []
    scene = wifislam.Scene.load(c_hall)
    gap, span = longest_gap_while(
        lambda: frames.extend(wifislam.Simulator(scene, fps=2, max_frames=6)))
    assert len(frames) == 6
    assert gap < 0.5 * span, (gap, span)
