"""One ctrack.Tracker shared between threads: ctypes lets the other threads
run while the library works, so every call holds the tracker's lock. Four
threads feed one tracker TUD-Campus's frames at once (from the pixels
alone, where a step writes the background model's rows) and it steps once
a call, in some order, as a tracker fed by one thread; close() from one
thread while the others feed waits for the call in flight, and the calls
after it raise. Under make sanitize (AddressSanitizer preloaded), a call
that ran beside another would be a reported heap error."""
import os
import subprocess
import threading

import numpy as np
import pytest

import ctrack
from conftest import DATA

W, H = 640, 480


@pytest.fixture(scope="module")
def frames():
    video = os.path.join(DATA, "TUD-Campus", "video.mp4")
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", video, "-frames:v", "40", "-f",
                          "rawvideo", "-pix_fmt", "yuv420p", "-"], check=True,
                         capture_output=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(-1, H * 3 // 2, W)


def hammer(t, frames, errors, stop=None):
    try:
        for f in frames:
            if stop is not None and stop.is_set():
                return
            t.feed(f, format="i420")  # no timestamp: one period after the last
            t.tracks()
            t.stats()
            t.person_size()
    except ValueError as e:  # closed under us: the one error allowed
        errors.append(e)


def test_threads_feeding_one_tracker(frames):
    with ctrack.Tracker(source=ctrack.SOURCE_PIXELS) as t:
        errors = []
        threads = [threading.Thread(target=hammer, args=(t, frames, errors)) for _ in range(4)]
        for th in threads:
            th.start()
        for th in threads:
            th.join()
        assert errors == []
        assert t.stats()["steps"] == 4 * len(frames)
        # Fed in order, the steps' timestamps followed one another: the time
        # stepped one period each call, from 0.
        t.feed(frames[0], format="i420", timestamp=4 * len(frames) / t.fps)
        with pytest.raises(ctrack.CtrackError, match="does not increase"):
            t.feed(frames[0], format="i420", timestamp=(4 * len(frames) - 1) / t.fps)


def test_close_while_others_feed(frames):
    for _ in range(3):
        t = ctrack.Tracker(source=ctrack.SOURCE_PIXELS)
        errors = []
        threads = [threading.Thread(target=hammer, args=(t, frames, errors)) for _ in range(3)]
        for th in threads:
            th.start()
        t.close()
        for th in threads:
            th.join()
        for e in errors:
            assert "closed" in str(e)
        with pytest.raises(ValueError, match="closed"):
            t.feed(frames[0], format="i420")
        with pytest.raises(ValueError, match="closed"):
            t.tracks()
        t.close()  # again: nothing
