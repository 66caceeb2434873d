"""ct-track fed live: frames on a pipe and detections on a FIFO, written
slowly, frame by frame, as a camera and a detector write them. Each frame's
tracks must come out (to a pipe; to a file with --flush) before the next
frame is written, and the whole output must be what ct-track writes for the
same files read at once."""
import os
import select
import subprocess
import threading
import time

import numpy as np
import pytest

from conftest import DATA

CT = os.environ.get("CTRACK_CT_TRACK")
TUD = os.path.join(DATA, "TUD-Campus")
FRAMES = 25  # a second of TUD-Campus


@pytest.fixture(scope="module")
def tud(tmp_path_factory):
    d = tmp_path_factory.mktemp("live")
    y4m = str(d / "tud.y4m")
    subprocess.run(["ffmpeg", "-v", "error", "-i", os.path.join(TUD, "video.mp4"), "-frames:v",
                    str(FRAMES), "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", y4m], check=True)
    det = np.loadtxt(os.path.join(TUD, "det", "det.txt"), delimiter=",", ndmin=2)
    det = det[det[:, 0] <= FRAMES]
    det_path = str(d / "det.txt")
    with open(det_path, "w") as f:
        for row in det:
            f.write("%d,-1,%.2f,%.2f,%.2f,%.2f,%.4f,-1,-1,-1\n" % (row[0], *row[2:7]))
    return y4m, det_path


def reference(args):
    return subprocess.run([CT, "-q", *args], check=True, capture_output=True,
                          text=True).stdout.splitlines()


def by_frame(lines):
    out = {}
    for line in lines:
        out.setdefault(int(line.split(",")[0]), []).append(line)
    return out


def y4m_frames(path):
    with open(path, "rb") as f:
        data = f.read()
    header, _, rest = data.partition(b"\n")
    chunks = rest.split(b"FRAME\n")[1:]
    return header + b"\n", [b"FRAME\n" + c for c in chunks]


def det_lines(path):
    out = {}
    with open(path) as f:
        for line in f:
            out.setdefault(int(line.split(",")[0]), []).append(line)
    return out


class Reader:
    """Lines from a pipe or a growing file, as they come."""

    def __init__(self, pipe=None, path=None):
        self.pipe, self.path, self.buf, self.lines, self.pos = pipe, path, b"", [], 0

    def wait_for(self, want, timeout=20.0):
        """Reads until the lines in `want` have all come; fails after
        timeout seconds."""
        end = time.monotonic() + timeout
        while not all(w in self.lines for w in want):
            if time.monotonic() > end:
                raise AssertionError("not out before the next frame: %s (got %d lines)"
                                     % (want[:2], len(self.lines)))
            if self.pipe is not None:
                ready, _, _ = select.select([self.pipe], [], [], 0.05)
                if ready:
                    chunk = os.read(self.pipe.fileno(), 65536)
                    self.buf += chunk
            else:
                time.sleep(0.02)
                with open(self.path, "rb") as f:
                    f.seek(self.pos)
                    chunk = f.read()
                self.pos += len(chunk)
                self.buf += chunk
            *done, self.buf = self.buf.split(b"\n")
            self.lines += [d.decode() for d in done]


def feed_live(tmp_path, tud, out_path=None, video=True, flush=False):
    """Runs ct-track on a pipe of frames and a FIFO of detections, writing
    frame k only once frame k-1's tracks are out; returns all its lines."""
    y4m, det_path = tud
    fifo = str(tmp_path / "det.fifo")
    os.mkfifo(fifo)
    args = [CT, "-q", "-d", fifo] + (["-"] if video else ["-s", "640x480", "-r", "25"])
    if out_path:
        args += ["-o", out_path] + (["--flush"] if flush else [])
    want = by_frame(reference(["-d", det_path] + ([y4m] if video else ["-s", "640x480",
                                                                        "-r", "25"])))
    p = subprocess.Popen(args, stdin=subprocess.PIPE if video else subprocess.DEVNULL,
                         stdout=subprocess.PIPE)
    # A ct-track that stops reading would block these writes for ever: it
    # is killed after a minute, and the writes fail.
    watchdog = threading.Timer(60, p.kill)
    watchdog.start()
    try:
        return run_live(p, fifo, want, tud, out_path, video)
    finally:
        watchdog.cancel()
        p.kill()
        p.wait()


def run_live(p, fifo, want, tud, out_path, video):
    y4m, det_path = tud
    dets = open(fifo, "w")
    reader = Reader(pipe=p.stdout) if not out_path else None
    header, frames = y4m_frames(y4m)
    det = det_lines(det_path)
    if video:
        p.stdin.write(header)
    for k in range(1, FRAMES + 1):
        if video:
            p.stdin.write(frames[k - 1])
            p.stdin.flush()
        dets.write("".join(det.get(k, [])) + "%d\n" % k)  # its lines, then its marker
        dets.flush()
        if reader is None:
            reader = Reader(path=out_path)
        reader.wait_for(want.get(k, []))
    dets.close()
    if video:
        p.stdin.close()
    rest = p.stdout.read()
    assert p.wait(timeout=30) == 0
    if reader.pipe is not None:
        reader.lines += rest.decode().splitlines()
    return reader.lines, [line for k in sorted(want) for line in want[k]]


def test_frames_on_a_pipe_and_detections_on_a_fifo(tmp_path, tud):
    got, want = feed_live(tmp_path, tud)
    assert got == want
    assert len(want) > 50


def test_detections_alone_from_a_fifo(tmp_path, tud):
    got, want = feed_live(tmp_path, tud, video=False)
    assert got == want


def test_flush_writes_each_frame_to_a_file(tmp_path, tud):
    out = str(tmp_path / "tracks.txt")
    got, want = feed_live(tmp_path, tud, out_path=out, flush=True)
    assert got == want


def test_a_stream_out_of_order_is_refused(tmp_path, tud):
    fifo = str(tmp_path / "det.fifo")
    os.mkfifo(fifo)
    p = subprocess.Popen([CT, "-q", "-d", fifo, "-s", "640x480"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    with open(fifo, "w") as f:
        f.write("2,-1,10,10,20,50,0.9,-1,-1,-1\n1,-1,10,10,20,50,0.9,-1,-1,-1\n")
    _, err = p.communicate(timeout=30)
    assert p.returncode == 1
    assert "frame 1 after frame 2" in err, err
