"""Tracks many recordings at once, each with its own tracker, on this
machine's cores or on a Ray cluster.

    python -m ctrack.batch INPUT... -o OUTDIR [--workers N] [--ray ADDRESS]

Each INPUT is one of:
- a video file ffmpeg reads (.mp4, .mkv, .avi, .mov, .webm, .y4m, ...): the
  tracker finds people in the pixels, with detections beside it when there
  are some: NAME.det.txt next to NAME.EXT, or det/det.txt in the video's
  folder (MOTChallenge's layout); --pixels-only ignores them;
- a detections file (MOTChallenge's frame,id,left,top,width,height,score,...,
  frames from 1): tracked from the detections alone, the image's size and
  rate from a seqinfo.ini beside it or in its parent folder (MOTChallenge's
  SEQ/det/det.txt and SEQ/seqinfo.ini), else from --size and --fps;
- a folder: a MOTChallenge sequence (it holds seqinfo.ini or det/det.txt:
  its video if it has one, else its detections), or else every video and
  .txt file directly inside it.

OUTDIR gets one MOTChallenge file per input, NAME.txt, written as ct-track
writes it (the same lines for the same input), and summary.csv: input,
output, status (ok, skipped, failed), frames, tracks, seconds,
frames_per_second, error. An output is written under a temporary name and
renamed when complete, so a run stopped half way leaves no partial file, and
a rerun skips the inputs whose output is there (--force tracks them again).
A failed input (unreadable, truncated, bad detections) is reported in the
summary and the others go on. Ctrl-C (SIGINT, to the process group or to
this process) stops the run within seconds: queued inputs are cancelled,
running ones stop at their next frame, no partial file is left, and
summary.csv marks them "interrupted"; the exit status is then 130. An
OUTDIR that cannot be made or written in is refused before anything runs
(exit status 2).

Every input is tracked online, as a camera's stream is: the tracks of frame
k come from frames 1 to k. --prime SECONDS asks for a look-ahead for
recorded files, as ct-track --prime does: where the tracker reads a
background (from the pixels alone, or with verify_detections), it first
learns it from each video's first SECONDS (ct_tracker_prime(); 3 is a usual
length), so that the people there from the first frame are found from it,
and frame 1's tracks then depend on later frames. The frames are kept in
memory for it: at most 65536, and as many as fit in 512 MiB.

From Python:

    from ctrack.batch import run
    results = run(["a.mp4", "b.mp4"], "out", workers=2)

With --ray (or run(..., ray=ADDRESS)) the same tasks run on Ray: "auto"
joins the cluster this machine belongs to, "local" starts one here, any
other value is ray.init's address. Only file names and the results' small
dicts travel between tasks: on a cluster of several machines the inputs,
OUTDIR and libctrack must be at the same paths on every node (shared
storage), and ctrack must be importable there. Ray is an optional
dependency (pip install ray).
"""
import argparse
import configparser
import csv
import math
import os
import sys
import time

import numpy as np

from . import PRIME_SECONDS, _number

VIDEO_EXTENSIONS = {".mp4", ".mkv", ".avi", ".mov", ".webm", ".y4m", ".mpg", ".mpeg", ".ts",
                    ".m4v", ".mts", ".flv", ".wmv", ".ogv", ".h264", ".h265", ".hevc", ".mjpeg"}
SUMMARY_FIELDS = ["input", "output", "status", "frames", "tracks", "seconds",
                  "frames_per_second", "error"]

# Set in a pool's worker processes (_worker_init) and in a Ray task
# (_ray_task): once set, the input in progress stops at its next frame
# (Ctrl-C in the main process; on Ray, SIGINT or ray.cancel()).
_STOP = None


class _Interrupted(Exception):
    """The run was interrupted: the input in progress stops."""


class BatchError(Exception):
    """A problem with the whole run (not with one input)."""


# -- what each input is ------------------------------------------------------
def _seqinfo(folder):
    """imWidth, imHeight and frameRate of folder/seqinfo.ini, or None."""
    path = os.path.join(folder, "seqinfo.ini")
    if not os.path.isfile(path):
        return None
    ini = configparser.ConfigParser()
    try:
        ini.read(path)
        s = ini["Sequence"]
        return {"width": int(s["imWidth"]), "height": int(s["imHeight"]),
                "fps": float(s["frameRate"])}
    except (configparser.Error, KeyError, ValueError) as e:
        raise ValueError("%s: not a MOTChallenge seqinfo.ini (%s)" % (path, e))


def _is_sequence(folder):
    return (os.path.isfile(os.path.join(folder, "seqinfo.ini")) or
            os.path.isfile(os.path.join(folder, "det", "det.txt")))


def _videos_in(folder):
    return sorted(os.path.join(folder, f) for f in os.listdir(folder)
                  if os.path.splitext(f)[1].lower() in VIDEO_EXTENSIONS and
                  os.path.isfile(os.path.join(folder, f)))


def _job(path, pixels_only=False, size=None, fps=None):
    """One input as a task: a dict of plain values (it travels to workers)."""
    job = {"input": path, "video": None, "detections": None, "size": size, "fps": fps}
    if os.path.isdir(path):
        folder = path.rstrip(os.sep) or path
        videos = _videos_in(folder)
        job["name"] = os.path.basename(os.path.abspath(folder))
        if videos:
            job["video"] = videos[0]
        det = os.path.join(folder, "det", "det.txt")
        if os.path.isfile(det) and not (pixels_only and videos):
            job["detections"] = det
        if not videos and not job["detections"]:
            job["error"] = "%s: holds no video and no det/det.txt" % path
        info_dir = folder
    else:
        stem, ext = os.path.splitext(path)
        folder = os.path.dirname(os.path.abspath(path))
        # A MOTChallenge sequence's files take the sequence's name.
        if os.path.basename(folder) == "det" and os.path.isfile(
                os.path.join(os.path.dirname(folder), "seqinfo.ini")):
            job["name"] = os.path.basename(os.path.dirname(folder))
            info_dir = os.path.dirname(folder)
        elif os.path.isfile(os.path.join(folder, "seqinfo.ini")):
            job["name"] = os.path.basename(folder)
            info_dir = folder
        else:
            job["name"] = os.path.basename(stem)
            info_dir = folder
        if ext.lower() in VIDEO_EXTENSIONS:
            job["video"] = path
            if not pixels_only:
                for det in (stem + ".det.txt", os.path.join(folder, "det", "det.txt")):
                    if os.path.isfile(det):
                        job["detections"] = det
                        break
        else:
            job["detections"] = path
    if job["video"] is None and job["detections"] and "error" not in job:
        try:
            info = _seqinfo(info_dir)
        except ValueError as e:
            info, job["error"] = None, str(e)
        if info:
            job["size"] = job["size"] or (info["width"], info["height"])
            job["fps"] = job["fps"] or info["fps"]
    return job


def find_jobs(inputs, pixels_only=False, size=None, fps=None):
    """The tasks for INPUT...: folders that are no sequence expand into the
    videos and .txt files inside them. Two inputs that would write the same
    output name are an error of the run."""
    jobs = []
    for path in inputs:
        if os.path.isdir(path) and not _is_sequence(path):
            inside = _videos_in(path) + sorted(
                os.path.join(path, f) for f in os.listdir(path)
                if f.endswith(".txt") and not f.endswith(".det.txt") and
                os.path.isfile(os.path.join(path, f)))
            jobs += [_job(p, pixels_only, size, fps) for p in inside]
        elif not os.path.exists(path):
            jobs.append({"input": path, "name": os.path.basename(path.rstrip(os.sep)) or path,
                         "video": None, "detections": None, "size": size, "fps": fps,
                         "error": "%s: no such file or folder" % path})
        else:
            jobs.append(_job(path, pixels_only, size, fps))
    seen = {}
    for j in jobs:
        if j["name"] in seen:
            raise BatchError("%s and %s would both write %s.txt: give them different names"
                             % (seen[j["name"]], j["input"], j["name"]))
        seen[j["name"]] = j["input"]
    return jobs


# -- one input ---------------------------------------------------------------
def load_detections(path):
    """A MOTChallenge detections file as {frame: (N, 5) float array of left,
    top, width, height, score}, file order within a frame, and the last
    frame. Checks what ct-track checks: numbers, frames from 1, finite
    boxes with positive sizes."""
    with open(path, "rb") as f:
        data = f.read()
    if b"\0" in data:
        raise ValueError("%s: holds a NUL byte: not a text file" % path)
    rows = []
    for n, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        try:
            v = [float(x) for x in line.split(",")[:7]]
        except ValueError:
            raise ValueError("%s:%d: not a detection (frame,id,left,top,width,height,"
                             "score,...): '%.60s'" % (path, n, line))
        if len(v) < 7:
            raise ValueError("%s:%d: %d fields, a detection has at least 7" % (path, n, len(v)))
        with np.errstate(over="ignore"):  # past a float: infinite, refused below
            box = np.array(v[2:7], dtype=np.float32)
        if (not 1 <= v[0] <= 10000000 or v[0] != math.floor(v[0]) or
                not np.all(np.isfinite(box)) or box[2] <= 0 or box[3] <= 0):
            raise ValueError("%s:%d: frame %g, box %s: frames are whole numbers from 1, boxes "
                             "finite with positive sizes" % (path, n, v[0], v[2:6]))
        rows.append([v[0]] + v[2:7])
    if not rows:
        return {}, 0
    a = np.array(rows, dtype=np.float64)
    order = np.argsort(a[:, 0], kind="stable")
    a = a[order]
    frames = a[:, 0].astype(np.int64)
    cuts = np.flatnonzero(np.diff(frames)) + 1
    out = {int(chunk[0, 0]): chunk[:, 1:6] for chunk in np.split(a, cuts)}
    return out, int(frames[-1])


def _summary_of(path):
    """Frames and tracks of a finished output (a rerun's skipped input)."""
    frames, ids = 0, set()
    with open(path) as f:
        for line in f:
            parts = line.split(",", 2)
            if len(parts) >= 2:
                frames = max(frames, int(parts[0]))
                ids.add(parts[1])
    return frames, len(ids)


def track_one(job, outdir, params=None, library=None, force=False):
    """Tracks one input (a dict from find_jobs()) into OUTDIR/NAME.txt and
    returns its summary row. Never raises for a bad input: its error goes
    in the row."""
    import ctrack
    from ctrack.video import Video, frame_time, primed

    out = os.path.join(outdir, job["name"] + ".txt")
    row = {"input": job["input"], "output": out, "status": "failed", "frames": 0,
           "tracks": 0, "seconds": 0.0, "frames_per_second": 0.0, "error": ""}
    if job.get("error"):
        row["error"] = job["error"]
        return row
    if not force and os.path.isfile(out):
        row["status"] = "skipped"
        try:
            row["frames"], row["tracks"] = _summary_of(out)
        except (OSError, ValueError):  # not ct-track's lines: counted as none
            pass
        return row
    tmp = _partial(outdir, job["name"], os.getpid())
    t0 = time.perf_counter()
    ids = set()
    frames = 0
    video = None
    try:
        dets, last = load_detections(job["detections"]) if job["detections"] else ({}, 0)
        params = dict(params or {})
        if job["video"]:
            video = Video(job["video"])
            rate = (job["fps"], 1) if job["fps"] else video.rate
            frame_iter = iter(video)
            image_size = None
        else:
            rate = (job["fps"] or 25.0, 1)
            frame_iter = (None for _ in range(last))
            image_size = tuple(job["size"]) if job["size"] else None
        if not job["detections"]:
            params.setdefault("source", ctrack.SOURCE_PIXELS)
        with ctrack.Tracker(fps=rate[0] / rate[1], library=library, image_size=image_size,
                            **params) as t, open(tmp, "w") as f:
            if job["video"] and (t.config["source"] == ctrack.SOURCE_PIXELS or
                                 t.config["verify_detections"]):
                frame_iter = primed(t, frame_iter, rate, job.get("prime", 0),
                                    note=lambda m: print("ctrack.batch: %s: %s"
                                                         % (job["input"], m), file=sys.stderr))
            for k, frame in enumerate(frame_iter, 1):
                if _STOP is not None and _STOP.is_set():
                    raise _Interrupted()
                tracks = t.feed(frame, dets.get(k), timestamp=frame_time(k, rate),
                                format="i420" if frame is not None else None)
                for line in ctrack.mot_lines(k, tracks):
                    f.write(line + "\n")
                ids.update(int(i) for i in tracks["id"])
                frames = k
        os.replace(tmp, out)
    except _Interrupted:
        _remove(tmp)
        row.update(status="interrupted", frames=frames, error="interrupted")
        return row
    except Exception as e:  # one input's failure is its row's, not the run's
        row["error"] = str(e) or type(e).__name__
        _remove(tmp)
        return row
    except BaseException:  # KeyboardInterrupt, a Ray worker's exit: no partial left
        _remove(tmp)
        raise
    finally:
        if video is not None:
            video.close()
    seconds = time.perf_counter() - t0
    row.update(status="ok", frames=frames, tracks=len(ids), seconds=round(seconds, 3),
               frames_per_second=round(frames / seconds, 1) if seconds > 0 else 0.0)
    return row


# -- many inputs -------------------------------------------------------------
def _write_summary(outdir, rows):
    tmp = os.path.join(outdir, ".summary.csv.partial")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, SUMMARY_FIELDS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, os.path.join(outdir, "summary.csv"))


class _Progress:
    """Inputs done and frames/s on standard error: one line rewritten on a
    terminal, a line every few seconds in a log."""

    def __init__(self, total, stream=None, enabled=None):
        self.stream = stream or sys.stderr
        self.tty = self.stream.isatty()
        self.enabled = self.tty if enabled is None else enabled
        self.total, self.done, self.failed, self.frames = total, 0, 0, 0
        self.t0 = self.last = time.monotonic()

    def update(self, row, final=False):
        self.done += 1
        self.failed += row["status"] == "failed"
        if row["status"] == "ok":
            self.frames += row["frames"]
        now = time.monotonic()
        if not self.enabled or (not self.tty and not final and now - self.last < 5 and
                                self.done < self.total):
            return
        self.last = now
        rate = self.frames / max(1e-9, now - self.t0)
        line = "ctrack.batch: %d/%d inputs, %d failed, %.0f frames/s" % (
            self.done, self.total, self.failed, rate)
        end = "\n" if not self.tty or self.done == self.total else ""
        self.stream.write(("\r" if self.tty else "") + line + end)
        self.stream.flush()


def _partial(outdir, name, pid):
    """Where an input's output is written until it is complete."""
    return os.path.join(outdir, ".%s.txt.%d.partial" % (name, pid))


def _remove(path):
    try:
        os.remove(path)
    except FileNotFoundError:
        pass


def _interrupted_row(job, outdir):
    return {"input": job["input"], "output": os.path.join(outdir, job["name"] + ".txt"),
            "status": "interrupted", "frames": 0, "tracks": 0, "seconds": 0.0,
            "frames_per_second": 0.0, "error": "interrupted before it started"}


def _worker_init(stop):
    """A pool's worker: Ctrl-C is the main process's to handle (it sets
    stop, and the input in progress stops at its next frame)."""
    import signal
    global _STOP
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    _STOP = stop


class _Pool:
    """The inputs on a local process pool (or in this process, with one
    worker)."""

    def __init__(self, jobs, outdir, args, workers):
        import multiprocessing
        from concurrent.futures import ProcessPoolExecutor
        self.jobs, self.outdir, self.args = jobs, outdir, args
        self.workers = workers or os.cpu_count() or 1
        self.pool = self.stop = None
        if self.workers > 1:
            ctx = multiprocessing.get_context()
            self.stop = ctx.Event()
            self.pool = ProcessPoolExecutor(max_workers=self.workers, mp_context=ctx,
                                            initializer=_worker_init, initargs=(self.stop,))
        self.futures = {}

    def results(self):
        """Each input's row, as it completes."""
        from concurrent.futures import as_completed
        if not self.pool:
            for j in self.jobs:
                self.current = j
                yield track_one(j, self.outdir, *self.args)
            return
        self.futures = {self.pool.submit(track_one, j, self.outdir, *self.args): j
                        for j in self.jobs}
        for fut in as_completed(self.futures):
            yield fut.result()

    def interrupt(self, reported):
        """Stops the run: queued inputs cancelled, running ones stopped at
        their next frame; the rows of the inputs not yet reported."""
        if not self.pool:
            return [_interrupted_row(j, self.outdir) for j in self.jobs
                    if j["input"] not in reported]
        from concurrent.futures.process import BrokenProcessPool
        self.stop.set()
        for fut in self.futures:
            fut.cancel()
        rows = []
        for fut, j in self.futures.items():
            if j["input"] in reported:
                continue
            if fut.cancelled():
                rows.append(_interrupted_row(j, self.outdir))
                continue
            try:
                rows.append(fut.result())
            except BrokenProcessPool:
                # Ctrl-C sent to the whole process group (a terminal's) can
                # reach a worker still starting, before _worker_init() has
                # it ignore SIGINT: the worker ends, and with it the pool.
                row = _interrupted_row(j, self.outdir)
                row["error"] = "interrupted; its worker process ended"
                rows.append(row)
        return rows

    def close(self):
        if self.pool:
            self.pool.shutdown(wait=True, cancel_futures=True)


class _Flag:
    """A stop request that a signal handler can set (threading.Event's
    is_set, without its lock, which a handler must not wait on)."""

    def __init__(self):
        self._set = False

    def set(self):
        self._set = True

    def is_set(self):
        return self._set


def _ray_task(job, outdir, *args):
    """track_one as a Ray task. Ctrl-C to the process group and ray.cancel()
    (which Ray delivers as _thread.interrupt_main()) both reach it as
    SIGINT; as in a pool's worker, that stops the input at its next frame
    instead of raising KeyboardInterrupt in it: the signal and then the
    cancel, two interrupts in a row, could abort Ray itself (its task
    manager's check that a task completing was pending)."""
    import signal
    global _STOP
    stop = _Flag()
    previous = signal.signal(signal.SIGINT, lambda signum, frame: stop.set())
    _STOP = stop
    try:
        return track_one(job, outdir, *args)
    finally:
        _STOP = None
        signal.signal(signal.SIGINT, previous)


# Seconds the running tasks have to stop on their own after Ctrl-C, before
# they are cancelled (_Ray.interrupt()).
_RAY_STOP_GRACE_S = 3.0
# How long an interrupted run waits for each task's row once it stopped or
# was cancelled; a task that never answers is reported as such.
_RAY_ANSWER_S = 10.0
# The longest a run waits on Ray before it looks at Ctrl-C again.
_RAY_WAIT_SLICE_S = 0.2


class _Ray:
    """The inputs as Ray tasks, at most as many at once as the cluster has
    CPUs for them: none waits queued in Ray, so Ctrl-C cancels only running
    tasks, and the inputs never submitted are marked interrupted here."""

    def __init__(self, jobs, outdir, args, address, workers):
        import ray  # optional: pip install ray
        self.ray, self.outdir, self.args = ray, outdir, args
        if address is not True and not ray.is_initialized():
            env = {k: os.environ[k] for k in ("CTRACK_LIBRARY",) if k in os.environ}
            if address == "local":
                ray.init(num_cpus=workers or os.cpu_count(), include_dashboard=False,
                         log_to_driver=False, runtime_env={"env_vars": env})
            else:
                ray.init(address=address, log_to_driver=False, runtime_env={"env_vars": env})
        self.task = ray.remote(num_cpus=1)(_ray_task)
        self.at_once = max(1, int(workers or ray.cluster_resources().get("CPU", 1)))
        self.waiting = list(jobs)
        self.refs = {}

    def _submit(self, running):
        while self.waiting and len(running) < self.at_once:
            j = self.waiting.pop(0)
            ref = self.task.remote(j, self.outdir, *self.args)
            self.refs[ref] = j
            running.append(ref)

    def results(self):
        running = []
        self._submit(running)
        while running:
            # In slices: a wait without a timeout holds Ctrl-C (to this
            # process alone) until a task ends, which may be hours away.
            ready, running = self.ray.wait(running, num_returns=1, timeout=_RAY_WAIT_SLICE_S)
            if not ready:
                continue
            self._submit(running)
            yield self.ray.get(ready[0])

    def interrupt(self, reported):
        """Stops every task not reported (a running one stops at its next
        frame, and removes its partial file), cancelling those the signal
        did not reach; their rows, and those of the inputs never submitted."""
        left = {ref: j for ref, j in self.refs.items() if j["input"] not in reported}
        # Ctrl-C to the process group reached the tasks too, and each stops
        # at its next frame: only those still running after a grace are
        # cancelled. A cancel that races a task's own return aborts the
        # driver (Ray's task manager: "Tried to complete task that was not
        # pending"), one interrupted run in some ten on a busy machine.
        running = list(left)
        if running:
            try:
                _, running = self.ray.wait(running, num_returns=len(running),
                                           timeout=_RAY_STOP_GRACE_S)
            except Exception:  # Ray itself went down with the signal
                pass
        for ref in running:
            try:
                self.ray.cancel(ref)
            except Exception:
                pass
        rows = []
        for ref, j in left.items():
            try:
                rows.append(self.ray.get(ref, timeout=_RAY_ANSWER_S))
            except Exception as e:  # cancelled, or its worker gone or stuck
                # Ray's GetTimeoutError is a TimeoutError.
                rows.append(dict(_interrupted_row(j, self.outdir), error=(
                    "interrupted; its task did not stop within %g s" % _RAY_ANSWER_S
                    if isinstance(e, TimeoutError) else "interrupted")))
        rows += [_interrupted_row(j, self.outdir) for j in self.waiting]
        self.waiting = []
        return rows

    def close(self):
        pass


def _check_outdir(outdir):
    """Makes OUTDIR if need be and checks that files can be written in it;
    a BatchError says why not."""
    try:
        os.makedirs(outdir, exist_ok=True)
    except OSError as e:
        raise BatchError("%s: cannot make the output folder: %s" % (outdir, e.strerror or e))
    if not os.path.isdir(outdir):
        raise BatchError("%s: not a folder" % outdir)
    probe = os.path.join(outdir, ".ctrack-batch.%d.probe" % os.getpid())
    try:
        with open(probe, "w"):
            pass
        os.remove(probe)
    except OSError as e:
        raise BatchError("%s: cannot write in the output folder: %s"
                         % (outdir, e.strerror or e))


def run(inputs, outdir, workers=None, ray=None, params=None, library=None, force=False,
        pixels_only=False, size=None, fps=None, progress=None, prime=None):
    """Tracks every input into outdir (see the module's help) and returns
    the summary rows, in the inputs' order. workers: processes (default:
    the cores); ray: None for a local process pool, True to use the Ray
    session this process already opened, or an address for ray.init
    ("auto", "local", "ray://host:10001"); params: ct_config fields;
    progress: None (on a terminal), True or False; prime: a look-ahead for
    recorded files, the seconds of each video a tracker that reads a
    background learns it from first (default 0: online; 3,
    ctrack.PRIME_SECONDS, is a usual length). A KeyboardInterrupt stops the
    run (queued inputs cancelled, running ones stopped, their partial files
    removed), writes summary.csv with them "interrupted", and is raised
    again."""
    jobs = find_jobs(inputs, pixels_only=pixels_only, size=size, fps=fps)
    if prime is not None:
        if not (_number(prime) and math.isfinite(prime) and prime >= 0):
            raise BatchError("prime: %r is not a duration in seconds" % (prime,))
        for j in jobs:
            j["prime"] = float(prime)
    _check_outdir(outdir)
    args = (params, library, force)
    runner = _Ray(jobs, outdir, args, ray, workers) if ray else _Pool(jobs, outdir, args, workers)
    prog = _Progress(len(jobs), enabled=progress)
    order = {j["input"]: i for i, j in enumerate(jobs)}
    rows = []

    def record(row):
        rows.append(row)
        rows.sort(key=lambda r: order[r["input"]])
        _write_summary(outdir, rows)
        prog.update(row, final=len(rows) == len(jobs))

    try:
        for row in runner.results():
            record(row)
    except KeyboardInterrupt:
        for row in runner.interrupt({r["input"] for r in rows}):
            record(row)
        # A worker that died with its input (a Ray worker killed by the
        # signal) leaves its partial file: none stays.
        for j in jobs:
            for name in os.listdir(outdir):
                if name.startswith(".%s.txt." % j["name"]) and name.endswith(".partial"):
                    _remove(os.path.join(outdir, name))
        raise
    finally:
        runner.close()
        if not jobs:
            _write_summary(outdir, rows)
    return rows


def _size(text):
    try:
        w, h = (int(v) for v in text.lower().split("x"))
        if w > 0 and h > 0:
            return (w, h)
    except ValueError:
        pass
    raise argparse.ArgumentTypeError("%r is not WIDTHxHEIGHT" % text)


def _param(text):
    name, sep, value = text.partition("=")
    if not sep:
        raise argparse.ArgumentTypeError("%r is not NAME=VALUE" % text)
    try:
        return name, int(value)
    except ValueError:
        try:
            return name, float(value)
        except ValueError:
            raise argparse.ArgumentTypeError("%s: %r is not a number" % (name, value))


def main(argv=None):
    doc = __doc__.split("\n\n")
    ap = argparse.ArgumentParser(
        prog="python -m ctrack.batch", description=doc[0],
        epilog="\n\n".join(doc[1:]), formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="+", metavar="INPUT",
                    help="videos, detections files or folders")
    ap.add_argument("-o", "--output", required=True, metavar="OUTDIR")
    ap.add_argument("-j", "--workers", type=int, metavar="N",
                    help="tasks at once (default: the cores; with --ray local, its CPUs)")
    ap.add_argument("--ray", metavar="ADDRESS",
                    help="run on Ray: auto, local, or ray.init's address")
    ap.add_argument("-p", "--param", type=_param, action="append", default=[],
                    metavar="NAME=VALUE", help="a ct_config field, as ct-track -p")
    ap.add_argument("--pixels-only", action="store_true",
                    help="ignore detections files beside the videos")
    ap.add_argument("-s", "--size", type=_size, metavar="WxH",
                    help="image size of detections files without a seqinfo.ini")
    ap.add_argument("-r", "--fps", type=float, metavar="RATE",
                    help="frame rate: of detections files without a seqinfo.ini, and "
                         "instead of each video's own")
    ap.add_argument("--prime", type=float, metavar="SECONDS",
                    help="a look-ahead for recorded files: learn the background from each "
                         "video's first SECONDS before tracking it from its first frame "
                         "(default 0: online; %g is a usual length)" % PRIME_SECONDS)
    ap.add_argument("--force", action="store_true",
                    help="track again the inputs whose output is already there")
    ap.add_argument("-q", "--quiet", action="store_true", help="no progress")
    ap.add_argument("--progress", action="store_true",
                    help="progress even when standard error is not a terminal")
    a = ap.parse_args(argv)
    if a.workers is not None and a.workers < 1:
        ap.error("--workers: %d is not a positive count" % a.workers)
    if a.fps is not None and not (math.isfinite(a.fps) and a.fps > 0):
        ap.error("--fps: %r is not a positive rate" % a.fps)
    progress = False if a.quiet else (True if a.progress else None)
    try:
        rows = run(a.inputs, a.output, workers=a.workers, ray=a.ray, params=dict(a.param),
                   force=a.force, pixels_only=a.pixels_only, size=a.size, fps=a.fps,
                   progress=progress, prime=a.prime)
    except BatchError as e:
        print("ctrack.batch: %s" % e, file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("ctrack.batch: interrupted; summary in %s"
              % os.path.join(a.output, "summary.csv"), file=sys.stderr)
        return 130
    except ImportError as e:
        if a.ray:
            print("ctrack.batch: --ray needs Ray: pip install ray (%s)" % e, file=sys.stderr)
            return 2
        raise
    failed = [r for r in rows if r["status"] == "failed"]
    for r in failed:
        print("ctrack.batch: %s: %s" % (r["input"], r["error"]), file=sys.stderr)
    if not a.quiet:
        ok = sum(r["status"] == "ok" for r in rows)
        skipped = sum(r["status"] == "skipped" for r in rows)
        print("ctrack.batch: %d tracked, %d skipped, %d failed; summary in %s"
              % (ok, skipped, len(failed), os.path.join(a.output, "summary.csv")),
              file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
