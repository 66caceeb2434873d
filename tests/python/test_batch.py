"""python -m ctrack.batch: many inputs, each with its own tracker, on a
process pool or on Ray, give ct-track's output for each; a broken input is
reported and the others complete; a rerun skips what is done."""
import csv
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

from conftest import DATA, TOP
from ctrack import batch

CT_TRACK = os.environ.get("CTRACK_CT_TRACK", os.path.join(TOP, "build", "tools", "ct-track"))
SEQUENCES = sorted(os.listdir(DATA))


def seqinfo(seq):
    info = {}
    with open(os.path.join(DATA, seq, "seqinfo.ini")) as f:
        for line in f:
            if "=" in line:
                k, v = line.strip().split("=", 1)
                info[k] = v
    return info


@pytest.fixture(scope="module")
def expected(tmp_path_factory):
    """ct-track's output for each sequence: from the detections alone, and
    TUD-Campus from its video (decoded to Y4M by ffmpeg) with its
    detections, and from the pixels alone."""
    tmp = tmp_path_factory.mktemp("ct-track")
    out = {}
    for seq in SEQUENCES:
        det = os.path.join(DATA, seq, "det", "det.txt")
        path = str(tmp / (seq + ".txt"))
        video = os.path.join(DATA, seq, "video.mp4")
        if os.path.exists(video):
            y4m = str(tmp / (seq + ".y4m"))
            subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", video, "-f", "yuv4mpegpipe",
                            y4m], check=True)
            subprocess.run([CT_TRACK, "-q", "-d", det, "-o", path, y4m], check=True)
            pixels = str(tmp / (seq + "-pixels.txt"))
            subprocess.run([CT_TRACK, "-q", "-o", pixels, y4m], check=True)
            out[seq + " pixels"] = pixels
        else:
            info = seqinfo(seq)
            subprocess.run([CT_TRACK, "-q", "-d", det, "-s",
                            "%sx%s" % (info["imWidth"], info["imHeight"]), "-r",
                            info["frameRate"], "-o", path], check=True)
        out[seq] = path
    return out


def read(path):
    with open(path, "rb") as f:
        return f.read()


def summary(outdir):
    with open(os.path.join(outdir, "summary.csv")) as f:
        return {os.path.basename(r["input"].rstrip(os.sep)): r for r in csv.DictReader(f)}


def test_each_sequence_as_ct_track(tmp_path, expected):
    folders = [os.path.join(DATA, s) for s in SEQUENCES]
    rows = batch.run(folders, str(tmp_path), workers=2, progress=False)
    assert [r["input"] for r in rows] == folders
    for seq, row in zip(SEQUENCES, rows):
        assert row["status"] == "ok", row
        assert read(row["output"]) == read(expected[seq]), seq
        assert row["frames"] > 0 and row["tracks"] > 0 and row["frames_per_second"] > 0
    s = summary(str(tmp_path))
    assert set(s) == set(SEQUENCES) and all(r["status"] == "ok" for r in s.values())
    # No temporary file is left.
    assert sorted(os.listdir(tmp_path)) == sorted([q + ".txt" for q in SEQUENCES] +
                                                  ["summary.csv"])
    # The pixels alone, through the command.
    out = tmp_path / "pixels"
    r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-q", "--pixels-only", "-o",
                        str(out), os.path.join(DATA, "TUD-Campus", "video.mp4")],
                       capture_output=True, text=True, env=env())
    assert r.returncode == 0, r.stderr
    assert read(str(out / "TUD-Campus.txt")) == read(expected["TUD-Campus pixels"])


def env():
    e = dict(os.environ)
    e["PYTHONPATH"] = os.path.join(TOP, "python") + os.pathsep + e.get("PYTHONPATH", "")
    return e


def test_online_by_default_and_priming_as_ct_track(tmp_path):
    """A video from the pixels is tracked online unless asked: without
    prime as with prime=0, and as ct-track tracks it (without --prime);
    prime=3 is ct-track --prime 3's look-ahead, which differs; a duration
    that is not one is refused before anything runs."""
    video = os.path.join(DATA, "TUD-Campus", "video.mp4")
    y4m = str(tmp_path / "tud.y4m")
    subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", video, "-f", "yuv4mpegpipe", y4m],
                   check=True)
    online = subprocess.run([CT_TRACK, "-q", y4m], check=True, capture_output=True).stdout
    primed = subprocess.run([CT_TRACK, "-q", "--prime", "3", y4m], check=True,
                            capture_output=True).stdout
    assert online != primed
    for name, prime, want in (("default", None, online), ("zero", 0, online),
                              ("three", 3, primed)):
        rows = batch.run([video], str(tmp_path / name), workers=1, progress=False,
                         pixels_only=True, prime=prime)
        assert rows[0]["status"] == "ok", rows[0]
        assert read(rows[0]["output"]) == want, name
    r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-q", "--pixels-only", "-o",
                        str(tmp_path / "cli"), video], capture_output=True, text=True, env=env())
    assert r.returncode == 0, r.stderr
    outs = [f for f in os.listdir(str(tmp_path / "cli")) if f.endswith(".txt")]
    assert len(outs) == 1, outs
    assert read(str(tmp_path / "cli" / outs[0])) == online
    for bad in (-1, float("nan"), "3", True):
        with pytest.raises(batch.BatchError, match="prime"):
            batch.run([video], str(tmp_path / "bad"), workers=1, progress=False, prime=bad)
    r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-q", "--prime", "x", "-o",
                        str(tmp_path / "bad"), video], capture_output=True, text=True, env=env())
    assert r.returncode == 2 and "--prime" in r.stderr


def test_priming_is_capped_as_ct_track_caps_it():
    """The frames kept for a priming: at most PRIME_MAX_FRAMES whatever the
    seconds asked, and as many as fit in the memory cap, which says so in
    ct-track's words; a frame larger than the cap primes nothing."""
    import ctrack
    from ctrack.video import primed

    class Primes:
        def __init__(self):
            self.n = None

        def prime(self, frames, timestamps, format=None):
            assert len(frames) == len(timestamps)
            self.n = len(frames)

    frames = [np.zeros((3, 2), np.uint8)] * (ctrack.PRIME_MAX_FRAMES + 100)
    t = Primes()
    assert len(list(primed(t, frames, (25, 1), 1e6))) == len(frames)
    assert t.n == ctrack.PRIME_MAX_FRAMES
    notes = []
    t = Primes()
    big = [np.zeros((720, 640), np.uint8)] * 50  # 460,800 bytes each
    assert len(list(primed(t, big, (25, 1), 3, note=notes.append, max_bytes=10 << 20))) == 50
    assert t.n == (10 << 20) // 460800
    assert notes == ["--prime: 22 frames fit in 10 MiB, 0.88 s"]
    t = Primes()
    assert len(list(primed(t, big, (25, 1), 3, max_bytes=1000))) == 50
    assert t.n is None
    assert ctrack.PRIME_MAX_BYTES == 512 << 20


def test_broken_inputs_are_reported_and_the_rest_complete(tmp_path, expected):
    src = tmp_path / "in"
    src.mkdir()
    # A video cut short, a detections file with a NaN box, a path that is
    # not there, beside two good inputs.
    with open(os.path.join(DATA, "TUD-Campus", "video.mp4"), "rb") as f:
        data = f.read()
    (src / "cut.mp4").write_bytes(data[: len(data) // 3])
    (src / "nan.txt").write_text("1,-1,10,20,30,NaN,0.9\n")
    good = os.path.join(DATA, "PETS09-S2L1")
    out = tmp_path / "out"
    r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-o", str(out), "-j", "2",
                        str(src / "cut.mp4"), str(src / "nan.txt"), str(src / "missing.mp4"),
                        good, os.path.join(DATA, "KITTI-13")],
                       capture_output=True, text=True, env=env())
    assert r.returncode == 1, r.stderr
    s = summary(str(out))
    for name, words in (("cut.mp4", "cut.mp4"), ("nan.txt", "nan.txt:1"),
                        ("missing.mp4", "no such file")):
        assert s[name]["status"] == "failed" and words in s[name]["error"], s[name]
        assert "ctrack.batch: %s" % str(src / name) in r.stderr
    assert s["PETS09-S2L1"]["status"] == "ok" and s["KITTI-13"]["status"] == "ok"
    assert read(str(out / "PETS09-S2L1.txt")) == read(expected["PETS09-S2L1"])
    assert sorted(os.listdir(out)) == ["KITTI-13.txt", "PETS09-S2L1.txt", "summary.csv"]
    assert "2 tracked, 0 skipped, 3 failed" in r.stderr


def test_a_rerun_skips_completed_inputs(tmp_path, expected):
    folders = [os.path.join(DATA, s) for s in ("KITTI-13", "Venice-2")]
    batch.run(folders, str(tmp_path), workers=1, progress=False)
    done = tmp_path / "KITTI-13.txt"
    before = done.stat().st_mtime_ns
    os.remove(tmp_path / "Venice-2.txt")  # as if the first run stopped there
    rows = batch.run(folders, str(tmp_path), workers=1, progress=False)
    assert [r["status"] for r in rows] == ["skipped", "ok"]
    assert done.stat().st_mtime_ns == before
    assert rows[0]["frames"] == 340 and rows[0]["tracks"] > 0
    assert read(str(tmp_path / "Venice-2.txt")) == read(expected["Venice-2"])
    rows = batch.run(folders, str(tmp_path), workers=1, progress=False, force=True)
    assert [r["status"] for r in rows] == ["ok", "ok"]
    assert read(str(done)) == read(expected["KITTI-13"])


def test_inputs_and_options(tmp_path, expected):
    # A detections file alone takes its size and rate from the seqinfo.ini
    # of its sequence, and the sequence's name; elsewhere, from the options
    # (KITTI-13's tracks depend on the image's size: boxes leaving it).
    det = os.path.join(DATA, "KITTI-13", "det", "det.txt")
    rows = batch.run([det], str(tmp_path / "a"), workers=1, progress=False)
    assert rows[0]["output"].endswith("KITTI-13.txt")
    assert read(rows[0]["output"]) == read(expected["KITTI-13"])
    loose = tmp_path / "loose.txt"
    shutil.copy(det, loose)
    info = seqinfo("KITTI-13")
    rows = batch.run([str(loose)], str(tmp_path / "b"), workers=1, progress=False,
                     size=(int(info["imWidth"]), int(info["imHeight"])),
                     fps=float(info["frameRate"]))
    assert read(rows[0]["output"]) == read(expected["KITTI-13"])
    rows = batch.run([str(loose)], str(tmp_path / "b2"), workers=1, progress=False,
                     fps=float(info["frameRate"]))
    assert rows[0]["status"] == "ok" and read(rows[0]["output"]) != read(expected["KITTI-13"])
    # Two inputs with one output name are refused before anything runs.
    with pytest.raises(batch.BatchError, match="would both write"):
        batch.run([det, str(tmp_path / "x" / "KITTI-13")], str(tmp_path / "c"))
    r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-o", str(tmp_path / "d"), det,
                        det], capture_output=True, text=True, env=env())
    assert r.returncode == 2 and "would both write" in r.stderr
    for bad in (["-j", "0"], ["-r", "nan"], ["-s", "10"], ["-p", "min_hits"]):
        r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-o", str(tmp_path / "e")] +
                           bad + [det], capture_output=True, text=True, env=env())
        assert r.returncode == 2, (bad, r.stderr)
    # A bad tracker parameter fails each input with the library's message.
    rows = batch.run([det], str(tmp_path / "f"), params={"min_hits": -1}, progress=False)
    assert rows[0]["status"] == "failed" and "min_hits" in rows[0]["error"]


def start_ray(ray):
    """A local Ray of two CPUs whose workers import ctrack from the tree.
    Under make sanitize, only the workers, which load the sanitized
    libctrack, get the sanitizers' runtimes: Ray's own servers (GCS, raylet)
    are not ctrack, and with the runtimes preloaded on a loaded 2-core
    machine the raylet once missed Ray's fixed 30 s to register. A start
    that still times out is retried once; a second failure fails the test."""
    env_vars = {"PYTHONPATH": os.path.join(TOP, "python"),
                "CTRACK_LIBRARY": os.environ["CTRACK_LIBRARY"]}
    preload = os.environ.pop("LD_PRELOAD", None)
    if preload:
        env_vars["LD_PRELOAD"] = preload
    try:
        for attempt in (1, 2):
            try:
                ray.init(num_cpus=2, object_store_memory=80 * 1024 * 1024,
                         include_dashboard=False, log_to_driver=False,
                         runtime_env={"env_vars": env_vars})
                return
            except Exception as e:
                ray.shutdown()
                if attempt == 2 or "timed out during startup" not in str(e):
                    raise
                print("ray did not start, once more:", e, file=sys.stderr)
    finally:
        if preload is not None:
            os.environ["LD_PRELOAD"] = preload


def test_on_ray(tmp_path, expected):
    import ray
    start_ray(ray)
    try:
        folders = [os.path.join(DATA, s) for s in SEQUENCES]
        rows = batch.run(folders, str(tmp_path), ray=True, progress=False)
        for seq, row in zip(SEQUENCES, rows):
            assert row["status"] == "ok", row
            assert read(row["output"]) == read(expected[seq]), seq
        # The tasks ran in Ray's worker processes, not here.
        def pid():
            return os.getpid()
        pids = ray.get([ray.remote(pid).remote() for _ in range(4)])
        assert os.getpid() not in pids
    finally:
        ray.shutdown()


@pytest.fixture(scope="module")
def long_videos(tmp_path_factory):
    """Six inputs of some seconds' work each: TUD-Campus looped eight times
    (568 frames), by six names."""
    d = tmp_path_factory.mktemp("long")
    first = str(d / "v0.y4m")
    subprocess.run(["ffmpeg", "-v", "error", "-stream_loop", "7", "-i",
                    os.path.join(DATA, "TUD-Campus", "video.mp4"), "-f", "yuv4mpegpipe",
                    "-pix_fmt", "yuv420p", first], check=True)
    paths = [first]
    for i in range(1, 6):
        paths.append(str(d / ("v%d.y4m" % i)))
        os.link(first, paths[-1])
    return paths


# The batch's main on a local Ray started as start_ray() starts it (so that
# under make sanitize Ray's servers run without the sanitizers' runtimes).
# CT_TEST_RAY_GRACE, when set, is the seconds the running tasks have to stop
# on their own before they are cancelled.
RAY_MAIN = """
import os
import sys
import ray
from ctrack import batch
from test_batch import start_ray
if "CT_TEST_RAY_GRACE" in os.environ:
    batch._RAY_STOP_GRACE_S = float(os.environ["CT_TEST_RAY_GRACE"])
start_ray(ray)
sys.exit(batch.main(sys.argv[1:]))
"""


def interrupt_batch(tmp_path, videos, to_group, ray=False, grace=5.0, ray_grace=None):
    """Runs python -m ctrack.batch over the videos (on two workers, or on a
    local Ray), sends SIGINT (to its process group, as a terminal's Ctrl-C
    does, or to it alone) once an input is being written, and returns (exit
    status, seconds from the signal to the exit, the output folder's files,
    its standard error)."""
    import signal
    import time
    out = tmp_path / "out"
    args = ["-q", "-o", str(out)] + (["--ray", "auto"] if ray else ["-j", "2"]) + list(videos)
    cmd = [sys.executable, "-c", RAY_MAIN] if ray else [sys.executable, "-m", "ctrack.batch"]
    e = env()
    e["PYTHONPATH"] += os.pathsep + os.path.dirname(os.path.abspath(__file__))
    if ray_grace is not None:
        e["CT_TEST_RAY_GRACE"] = str(ray_grace)
    p = subprocess.Popen(cmd + args, env=e, start_new_session=True, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    t0 = time.monotonic()
    while time.monotonic() - t0 < 120:
        if out.is_dir() and any(n.endswith(".partial") for n in os.listdir(out)):
            break
        if p.poll() is not None:
            raise AssertionError("the batch ended before it was interrupted: %s"
                                 % p.stderr.read())
        time.sleep(0.05)
    signaled = time.monotonic()
    if to_group:
        os.killpg(p.pid, signal.SIGINT)
    else:
        p.send_signal(signal.SIGINT)
    try:
        p.wait(timeout=grace + 30)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
    return p.returncode, time.monotonic() - signaled, sorted(os.listdir(out)), p.stderr.read()


@pytest.mark.parametrize("to_group", [True, False], ids=["to the group", "to the main process"])
def test_ctrl_c_stops_the_run_cleanly(tmp_path, long_videos, to_group):
    """Ctrl-C: exit status 130 within 5 s, queued inputs cancelled, running
    ones stopped, no partial file left, and summary.csv with a row for every
    input, those not done "interrupted"."""
    status, seconds, files, err = interrupt_batch(tmp_path, long_videos, to_group)
    assert status == 130, err
    assert seconds < 5.0, "%.1f s from the signal to the exit" % seconds
    assert not [f for f in files if f.endswith(".partial")], files
    rows = list(summary(str(tmp_path / "out")).values())
    assert len(rows) == len(long_videos)
    interrupted = [r for r in rows if r["status"] == "interrupted"]
    assert len(interrupted) >= 4, rows  # two workers: at most two had finished
    for r in rows:
        assert r["status"] in ("ok", "interrupted"), r
        assert (os.path.basename(r["output"]) in files) == (r["status"] == "ok"), (r, files)


@pytest.mark.parametrize("to_group", [True, False], ids=["to the group", "to the main process"])
def test_ctrl_c_on_ray(tmp_path, long_videos, to_group):
    """The same on Ray: exit status 130 within 15 s, no partial file. To the
    group, the tasks stop on their own; to the main process alone, they are
    cancelled (at once here: these inputs end within the usual grace) and
    stop part way."""
    status, seconds, files, err = interrupt_batch(tmp_path, long_videos[:4], to_group, ray=True,
                                                  grace=15.0,
                                                  ray_grace=None if to_group else 0)
    assert status == 130, err
    assert seconds < 15.0, "%.1f s from the signal to the exit" % seconds
    assert not [f for f in files if f.endswith(".partial")], files
    rows = list(summary(str(tmp_path / "out")).values())
    assert len(rows) == 4 and any(r["status"] == "interrupted" for r in rows), rows
    if not to_group:
        # Cancelled: a running input stopped part way (without the cancel
        # the running ones run to their end, or say in their error that
        # they did not stop; the inputs never started say so). Only one is
        # asked for: on a loaded machine a task can end in the moment
        # before the cancel reaches it.
        assert any(r["status"] == "interrupted" and r["error"] == "interrupted" and
                   int(r["frames"]) < 568 for r in rows), rows


def test_a_ray_task_that_does_not_answer_is_marked(tmp_path, monkeypatch):
    """After Ctrl-C, a Ray task whose row does not come within the wait is
    marked as such in its row; one cancelled, or whose worker is gone, is
    "interrupted" as those stopped at their next frame."""
    class FakeRay:
        def wait(self, refs, num_returns, timeout):
            return [], refs

        def cancel(self, ref):
            pass

        def get(self, ref, timeout):
            raise TimeoutError() if ref == "stuck" else RuntimeError("cancelled")

    monkeypatch.setattr(batch, "_RAY_STOP_GRACE_S", 0)
    r = object.__new__(batch._Ray)
    r.ray, r.outdir, r.waiting = FakeRay(), str(tmp_path), []
    r.refs = {"stuck": {"input": "a.y4m", "name": "a"}, "gone": {"input": "b.y4m", "name": "b"}}
    rows = {row["input"]: row for row in r.interrupt(set())}
    assert rows["a.y4m"]["status"] == "interrupted"
    assert rows["a.y4m"]["error"] == "interrupted; its task did not stop within 10 s"
    assert rows["b.y4m"]["error"] == "interrupted"


def test_a_worker_ended_by_ctrl_c_is_marked_interrupted(tmp_path):
    """After Ctrl-C to the process group, a pool worker the signal reached
    before it ignored SIGINT has ended, and the pool is broken: its input's
    row is "interrupted" like the others, not the run's crash."""
    from concurrent.futures import Future
    from concurrent.futures.process import BrokenProcessPool

    class Stop:
        def set(self):
            pass

    done, broken, queued = Future(), Future(), Future()
    done.set_result({"input": "a.y4m", "status": "interrupted", "error": "interrupted"})
    broken.set_running_or_notify_cancel()
    broken.set_exception(BrokenProcessPool("a process in the pool was terminated"))
    p = object.__new__(batch._Pool)
    p.pool, p.stop, p.outdir = object(), Stop(), str(tmp_path)
    p.futures = {done: {"input": "a.y4m", "name": "a"}, broken: {"input": "b.y4m", "name": "b"},
                 queued: {"input": "c.y4m", "name": "c"}}
    rows = {row["input"]: row for row in p.interrupt(set())}
    assert rows["a.y4m"]["error"] == "interrupted"
    assert rows["b.y4m"]["status"] == "interrupted"
    assert rows["b.y4m"]["error"] == "interrupted; its worker process ended"
    assert rows["c.y4m"]["error"] == "interrupted before it started"


@pytest.mark.parametrize("how", ["signal", "interrupt_main"])
def test_a_ray_task_stops_on_sigint_without_raising(tmp_path, long_videos, how, monkeypatch):
    """A Ray task (batch._ray_task, run here in the main thread as Ray runs
    it) meets Ctrl-C as SIGINT and ray.cancel() as _thread.interrupt_main():
    either stops its input at the next frame with an "interrupted" row and
    no partial file, with no KeyboardInterrupt (two in a row could abort
    Ray), and the handler before it is back after it."""
    import _thread
    import signal
    from ctrack import video
    (job,) = batch.find_jobs(long_videos[:1])
    before = signal.getsignal(signal.SIGINT)
    send = ((lambda: os.kill(os.getpid(), signal.SIGINT)) if how == "signal"
            else _thread.interrupt_main)

    # The interrupt arrives while the task reads its 20th frame, whatever
    # the machine's speed (a timer can come after the last frame).
    class Interrupting(video.Video):
        def __iter__(self):
            for k, frame in enumerate(super().__iter__(), 1):
                if k == 20:
                    send()
                yield frame

    monkeypatch.setattr(video, "Video", Interrupting)
    row = batch._ray_task(job, str(tmp_path))
    assert row["status"] == "interrupted", row
    assert 0 < row["frames"] < 568, row
    assert not [f for f in os.listdir(tmp_path) if f.endswith(".partial")]
    assert signal.getsignal(signal.SIGINT) is before


def test_a_bad_output_folder_is_one_line(tmp_path):
    """An output folder that is a file, or that cannot be written in: one
    line, exit status 2, no traceback, nothing tracked."""
    det = os.path.join(DATA, "TUD-Campus", "det", "det.txt")
    afile = tmp_path / "a-file"
    afile.write_text("x")
    for outdir in (str(afile), str(afile / "below"), "/proc/1"):
        r = subprocess.run([sys.executable, "-m", "ctrack.batch", "-q", "-o", outdir, det],
                           capture_output=True, text=True, env=env())
        assert r.returncode == 2, (outdir, r.stderr)
        assert r.stderr.count("\n") == 1 and "Traceback" not in r.stderr, r.stderr
        assert r.stderr.startswith("ctrack.batch: %s" % outdir), r.stderr
