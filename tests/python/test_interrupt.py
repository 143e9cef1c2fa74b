"""Ctrl-C stops long work at the next frame: `generate` runs Python's signal handlers after each
frame it writes, so KeyboardInterrupt (or any handler's exception) ends it there, and the folder
it was writing is removed as on any error. Before, the call ran to its end and the exception came
after, with the whole dataset written.

The signal is sent by a thread that watches the staging folder: once a frame is there, the work
is under way. No timer: the test controls when the signal comes."""

import contextlib
import os
import signal
import threading

import pytest

import wifislam


@contextlib.contextmanager
def signal_once_a_frame_is_written(staging, signum):
    """Sends `signum` to this process once staging/rgb holds a file, while the block runs."""
    rgb = staging / "rgb"
    stop = threading.Event()
    sent = threading.Event()

    def watch():
        while not stop.is_set():  # the call releases the GIL: this loop runs beside it
            if rgb.is_dir() and any(rgb.iterdir()):
                os.kill(os.getpid(), signum)
                sent.set()
                return

    watcher = threading.Thread(target=watch, daemon=True)
    watcher.start()
    try:
        yield sent
    finally:
        stop.set()
        watcher.join()


def test_ctrl_c_stops_generate_and_leaves_no_folder(tmp_path, c_hall):
    out = tmp_path / "d"
    # 300 frames at 3 fps, with images: far longer than the first frame takes.
    with signal_once_a_frame_is_written(tmp_path / "d.partial", signal.SIGINT) as sent:
        with pytest.raises(KeyboardInterrupt):
            wifislam.generate(c_hall, out, fps=3, max_frames=300, threads=1)
    assert sent.is_set()
    assert not out.exists()
    assert not (tmp_path / "d.partial").exists()


def test_a_signal_handlers_exception_reaches_the_caller(tmp_path, c_hall):
    class Stop(Exception):
        pass

    def handler(signum, frame):
        raise Stop()

    previous = signal.signal(signal.SIGUSR1, handler)
    try:
        out = tmp_path / "d"
        with signal_once_a_frame_is_written(tmp_path / "d.partial", signal.SIGUSR1) as sent:
            with pytest.raises(Stop):
                wifislam.generate(c_hall, out, fps=3, max_frames=300, threads=1)
        assert sent.is_set()
        assert not out.exists() and not (tmp_path / "d.partial").exists()
    finally:
        signal.signal(signal.SIGUSR1, previous)
