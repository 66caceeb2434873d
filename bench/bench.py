#!/usr/bin/env python3
"""make bench: ctrack's speed and memory on one core, each figure beside a
baseline measured in the same run (these shared machines drift by a third
from one minute to the next, so only the ratios compare across runs).

    bench.py BUILD_DIR [--out DOCS_DIR] [--quick]

Prints the tables, writes BUILD_DIR/bench.json and DOCS_DIR/bench.md.
"""
import argparse
import datetime
import json
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
from cteval import peers
from cteval.data import cache_dir, conditioned, load_dets, video
from cteval.y4m import open_y4m

DATA = os.path.join(TOP, "tests", "data", "mot15")
PETS_DET = os.path.join(DATA, "PETS09-S2L1", "det", "det.txt")
CORE = 0


def pets_hd(src):
    """PETS09-S2L1 scaled to 1920x1080, and its detections scaled the same."""
    y4m = os.path.join(cache_dir(), "pets09-s2l1-1080p.y4m")
    det = os.path.join(cache_dir(), "pets09-s2l1-1080p-det.txt")
    if not os.path.exists(y4m):
        print("bench: scaling PETS09-S2L1 to 1920x1080 (once, cached)", file=sys.stderr)
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", src, "-vf", "scale=1920:1080",
                        "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", y4m + ".part"], check=True)
        os.replace(y4m + ".part", y4m)
    if not os.path.exists(det):
        d = np.loadtxt(PETS_DET, delimiter=",", ndmin=2)
        d[:, [2, 4]] *= 1920 / 768
        d[:, [3, 5]] *= 1080 / 576
        np.savetxt(det, d, delimiter=",", fmt="%.3f")
    return y4m, det


def warm(path):
    """Puts the file in the page cache the same way whatever made it: its
    cached pages are dropped, then read back (the kernel's readahead fills
    the cache in large folios; the small writes of the ffmpeg that made the
    file leave it in 4 KiB pages, over which ct-track's reads cost some 20%
    more at 768x576, the kernel's copy and page lookups). Without
    posix_fadvise, or where the kernel ignores it, the file is read as it
    is."""
    with open(path, "rb") as f:
        if hasattr(os, "posix_fadvise"):
            os.posix_fadvise(f.fileno(), 0, 0, os.POSIX_FADV_DONTNEED)
        while f.read(1 << 24):
            pass


def timed_child(cmd):
    """Runs ct-track on one core; returns (wall seconds, peak RSS KiB as
    ct-track reports it, mean shift us per person per frame from the
    library's timers or None)."""
    t0 = time.perf_counter()
    p = subprocess.run(["taskset", "-c", str(CORE)] + cmd + ["--progress", "--stats"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise SystemExit("bench: %s failed: %s" % (" ".join(cmd), p.stderr))
    m = re.search(r"peak memory ([0-9.]+) MiB", p.stderr)
    ms = re.search(r"mean shift ([0-9.]+) us per person", p.stderr)
    return (wall, float(m.group(1)) * 1024 if m else float("nan"),
            float(ms.group(1)) if ms else None)


def best_of(n, cmd):
    """The fastest of n runs (its mean shift figure too) and the largest RSS."""
    runs = sorted(timed_child(cmd) for _ in range(n))
    return runs[0][0], max(r[1] for r in runs), runs[0][2]


def median_of(n, cmd):
    """The median of n runs' wall times (its mean shift figure too), and the
    largest RSS."""
    runs = sorted(timed_child(cmd) for _ in range(n))
    mid = runs[len(runs) // 2]
    return mid[0], max(r[1] for r in runs), mid[2]


def memcpy_us(width, height, n=2000):
    """The memory-bandwidth floor: one I420 frame copied (numpy's copyto is
    a memcpy), median microseconds over n copies between two buffers larger
    than the caches together (so each copy reads memory, as a frame read
    from the page cache does)."""
    size = width * height * 3 // 2
    k = max(2, (64 << 20) // size)
    src = np.random.default_rng(1).integers(0, 256, size * k, dtype=np.uint8)
    dst = np.empty(size, np.uint8)
    times = []
    for i in range(n):
        a = src[(i % k) * size:(i % k + 1) * size]
        t0 = time.perf_counter()
        np.copyto(dst, a)
        times.append(time.perf_counter() - t0)
    return 1e6 * float(np.median(times))


def mog2_ms(y4m, frames):
    """OpenCV MOG2 alone, ms per frame on one thread (apply() only)."""
    import cv2
    cv2.setNumThreads(1)
    w, h, _, rows = open_y4m(y4m)
    sub = cv2.createBackgroundSubtractorMOG2()
    spent = 0.0
    n = min(frames, len(rows))
    for k in range(n):
        bgr = cv2.cvtColor(np.asarray(rows[k]).reshape(h * 3 // 2, w), cv2.COLOR_YUV2BGR_I420)
        t0 = time.perf_counter()
        sub.apply(bgr)
        spent += time.perf_counter() - t0
    return 1e3 * spent / n


def opencv_follow_us(y4m, kind, people=10, frames=50):
    """OpenCV's single-object trackers following one person: microseconds per
    update() on one thread. Each of the first `people` PETS09-S2L1
    ground-truth people seen in at least `frames` frames is taken from its
    first box, then followed over its next `frames` frames (init() not
    counted)."""
    import cv2
    cv2.setNumThreads(1)
    make = {"KCF": cv2.TrackerKCF_create, "CSRT": cv2.TrackerCSRT_create,
            "MIL": cv2.TrackerMIL_create}[kind]
    w, h, _, rows = open_y4m(y4m)

    def bgr(k):
        return cv2.cvtColor(np.asarray(rows[k - 1]).reshape(h * 3 // 2, w),
                            cv2.COLOR_YUV2BGR_I420)
    gt = np.loadtxt(os.path.join(DATA, "PETS09-S2L1", "gt", "gt.txt"), delimiter=",")
    spent, n = 0.0, 0
    for pid in [i for i in np.unique(gt[:, 1]) if (gt[:, 1] == i).sum() > frames][:people]:
        track = gt[gt[:, 1] == pid]
        first = int(track[:, 0].min())
        box = track[track[:, 0] == first][0, 2:6]
        t = make()
        t.init(bgr(first), tuple(int(round(v)) for v in box))
        for k in range(first + 1, first + 1 + frames):
            img = bgr(k)
            t0 = time.perf_counter()
            t.update(img)
            spent += time.perf_counter() - t0
            n += 1
    return 1e6 * spent / n


def colour_conversion_us(y4m, frames):
    """OpenCV's and numpy's BGR to I420 on the first frames of y4m, us a
    frame (the frames made BGR by OpenCV first, not counted)."""
    import cv2
    from ctrack import bgr_to_i420  # the binding in python/ (make bench's PYTHONPATH)
    cv2.setNumThreads(1)
    w, h, _, rows = open_y4m(y4m)
    bgr = [cv2.cvtColor(np.asarray(rows[k]).reshape(h * 3 // 2, w), cv2.COLOR_YUV2BGR_I420)
           for k in range(frames)]
    out = {}
    for name, convert in (("opencv", lambda b: cv2.cvtColor(b, cv2.COLOR_BGR2YUV_I420)),
                          ("numpy", bgr_to_i420)):
        t0 = time.perf_counter()
        for b in bgr:
            convert(b)
        out[name] = 1e6 * (time.perf_counter() - t0) / frames
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--out", default=os.path.join(TOP, "docs"))
    ap.add_argument("--quick", action="store_true", help="fewer repeats (for a smoke test)")
    a = ap.parse_args()
    os.sched_setaffinity(0, {CORE})
    reps = 1 if a.quick else 3
    ct = os.path.join(a.build, "tools", "ct-track")
    report = {"date": datetime.datetime.now().isoformat(timespec="seconds"), "core": CORE}
    lines = []

    def say(s=""):
        print(s, flush=True)
        lines.append(s)

    # 1. The library alone, per stage, memory, allocations (ct-bench).
    with tempfile.NamedTemporaryFile(suffix=".json") as tj:
        pets = video("PETS09-S2L1")
        hd, hd_det = pets_hd(pets)
        out = subprocess.run(["taskset", "-c", str(CORE), os.path.join(a.build, "bench", "ct-bench"),
                              "--passes", "3" if a.quick else "15", "--json", tj.name,
                              "--video", pets, "--video-hd", hd, DATA],
                             check=True, capture_output=True, text=True).stdout
        report["library"] = json.load(open(tj.name))
    say("## The library (ct-bench, one core)")
    say("")
    say("Detections only, then with the real frames held in memory (the first 200 at "
        "768x576, 60 at 1920x1080; each frame is cold in the cache when the tracker "
        "reads it, so this is the slow case for mean shift).")
    say("")
    say("```")
    for l in out.rstrip().splitlines():
        say(l)
    say("```")

    # 1b. DDIS and template builds (ddis-bench), on the real crossing clips.
    with tempfile.NamedTemporaryFile(suffix=".json") as tj:
        out = subprocess.run(["taskset", "-c", str(CORE), os.path.join(a.build, "bench", "ddis-bench"),
                              "--json", tj.name, os.path.join(TOP, "tests", "data")],
                             check=True, capture_output=True, text=True).stdout
        report["ddis"] = json.load(open(tj.name))
    say("")
    say("## Appearance: DDIS, all pairs against FLANN's kd-tree (ddis-bench, one core)")
    say("")
    say("```")
    for l in out.rstrip().splitlines():
        say(l)
    say("```")

    lib = {r["name"]: r for r in report["library"]["runs"]}

    # 1c. Colour frames: the library's own conversion of packed BGR (0.8.0),
    # beside OpenCV's and the Python binding's numpy one on the same frames.
    colour = colour_conversion_us(pets, 30 if a.quick else 100)
    rb, ri = lib["pixels only 768x576 BGR24"], lib["pixels only 768x576"]
    colour.update({"ctrack": rb["stages_us"]["convert"],
                   "pixels_only_i420_us": ri["us_per_frame"],
                   "pixels_only_bgr24_us": rb["us_per_frame"]})
    report["colour_conversion_us"] = colour
    say("")
    say("## Colour frames: packed BGR to planes (768x576, one core)")
    say("")
    say("A host that has BGR (OpenCV, many cameras) hands it over as `CT_FORMAT_BGR24`, "
        "and the library converts it (the stage `convert` above). Beside it, on the same "
        "PETS09-S2L1 frames in the same run: OpenCV's `cvtColor(COLOR_BGR2YUV_I420)` on "
        "one thread, and the numpy conversion the Python binding used before 0.8.0 "
        "(`ctrack.bgr_to_i420`, still used with an older library).")
    say("")
    say("| conversion | us per frame | against ctrack's |")
    say("|---|---|---|")
    for name, key in (("ctrack (in the library)", "ctrack"),
                      ("OpenCV cvtColor", "opencv"), ("numpy (bgr_to_i420)", "numpy")):
        say("| %s | %.0f | %.1fx |" % (name, colour[key], colour[key] / colour["ctrack"]))
    say("")
    say("The whole pixels-only step took %.0f us a frame from BGR24 and %.0f from I420 "
        "in the runs above." % (colour["pixels_only_bgr24_us"], colour["pixels_only_i420_us"]))

    # 2. Peers on the same detections, in this run.
    dets = load_dets("PETS09-S2L1")
    us = lib["detections 768x576"]["us_per_frame"]
    peers_us = {name: 1e6 * run(dets, 795, 7)[1] / 795 for name, run in (
        ("ByteTrack (supervision 0.30.9)", peers.bytetrack),
        ("SORT (trackers 2.6.1)", peers.sort),
        ("OC-SORT (trackers 2.6.1)", peers.ocsort),
        ("norfair 2.3.0 (IoU)", peers.norfair_iou))}
    report["peers_us_per_frame"] = peers_us
    say("")
    say("## Against the peers, same detections (PETS09-S2L1, 768x576), same run")
    say("")
    say("| tracker | us/frame | frames/s | ctrack is faster by |")
    say("|---|---|---|---|")
    say("| ctrack | %.2f | %.0f | 1.0x |" % (us, 1e6 / us))
    for name, p in peers_us.items():
        say("| %s | %.1f | %.0f | %.0fx |" % (name, p, 1e6 / p, p / us))

    # 3. The whole pipeline: ct-track reading Y4M from the page cache.
    whole = {}
    for label, y4m, det, size in (("768x576", pets, PETS_DET, "768x576"),
                                  ("1920x1080", hd, hd_det, "1920x1080")):
        warm(y4m)
        runs = 1 if a.quick else 5  # the speed targets are medians of 5
        wall, rss, ms_us = median_of(runs, [ct, "-q", "-d", det, "-r", "7", "-o", "/dev/null",
                                            y4m])
        wall_det, rss_det, _ = median_of(runs, [ct, "-q", "-d", det, "-s", size, "-r", "7",
                                                "-o", "/dev/null"])
        # The boxes' fit to the silhouettes keeps a background model with
        # detections: its cost, from the same runs without it.
        wall_nofit, _, _ = median_of(runs, [ct, "-q", "-d", det, "-r", "7", "-p", "refine_boxes=0",
                                            "-o", "/dev/null", y4m])
        wall_pix, rss_pix, _ = median_of(runs, [ct, "-q", "-r", "7", "-o", "/dev/null", y4m])
        mog = mog2_ms(y4m, 100 if a.quick else 300)
        w_px, h_px = (int(v) for v in size.split("x"))
        floor_us = memcpy_us(w_px, h_px)
        whole[label] = {"detections_pixels_fps": 795 / wall, "detections_pixels_rss_kib": rss,
                        "detections_pixels_unfitted_fps": 795 / wall_nofit,
                        "detections_fps": 795 / wall_det, "detections_rss_kib": rss_det,
                        "pixels_fps": 795 / wall_pix, "pixels_rss_kib": rss_pix,
                        "mog2_ms_per_frame": mog, "mog2_fps": 1e3 / mog,
                        "mean_shift_us_per_person": ms_us, "memcpy_us_per_frame": floor_us}
    report["whole_pipeline"] = whole
    say("")
    say("## The whole pipeline: ct-track reading Y4M from the page cache, one core")
    say("")
    say("ct-track over all 795 PETS09-S2L1 frames with the public detections, output "
        "discarded, median of %d runs; beside it OpenCV's MOG2 alone (`apply()` on one "
        "thread) on the same frames in the same run, and the memory-bandwidth floor: one "
        "frame copied (a memcpy, measured in the same run). The file's cached pages are "
        "dropped and read back first, so that the kernel holds it the same way whoever "
        "wrote it (the small writes of ffmpeg, which made it, leave 4 KiB pages, which make "
        "ct-track's reads some 20%% dearer at 768x576). Every run is online, as ct-track "
        "runs by default (no priming)."
        % (1 if a.quick else 5))
    say("")
    say("| resolution | ct-track, pixels only | ct-track, detections + pixels | "
        "ct-track, detections only | MOG2 alone | pixels only / MOG2 | "
        "detections + pixels / MOG2 | memcpy of a frame | pixels only's frame / memcpy | "
        "mean shift per person | peak RSS |")
    say("|---|---|---|---|---|---|---|---|---|---|---|")
    for label, w in whole.items():
        say("| %s | %.0f frames/s | %.0f frames/s | %.0f frames/s | %.0f frames/s (%.2f ms) | "
            "%.1fx | %.1fx | %.0f us | %.1fx | %.1f us (%.2f%% of MOG2's frame) | %.1f MiB |"
            % (label, w["pixels_fps"], w["detections_pixels_fps"], w["detections_fps"],
               w["mog2_fps"], w["mog2_ms_per_frame"], w["pixels_fps"] / w["mog2_fps"],
               w["detections_pixels_fps"] / w["mog2_fps"], w["memcpy_us_per_frame"],
               1e6 / w["pixels_fps"] / w["memcpy_us_per_frame"],
               w["mean_shift_us_per_person"],
               100 * w["mean_shift_us_per_person"] / (1e3 * w["mog2_ms_per_frame"]),
               w["detections_pixels_rss_kib"] / 1024))
    say("")
    say("Detections + pixels reads the background to fit the boxes to the silhouettes "
        "(`refine_boxes`, on by default); without it (`-p refine_boxes=0`), in the same "
        "run: %s."
        % "; ".join("%s %.0f frames/s, the fit %.2f ms a frame"
                    % (label, w["detections_pixels_unfitted_fps"],
                       1e3 / w["detections_pixels_fps"] - 1e3 / w["detections_pixels_unfitted_fps"])
                    for label, w in whole.items()))
    say("")
    say("Mean shift per person: the library's mean shift stage (model learning, refining "
        "the prediction, following and scale) divided by the confirmed tracks it served, "
        "from `ct-track --stats` in the same runs.")

    # 3a. Sensor noise (make eval's condition): the pixels-only pipeline must
    # not slow down with a noisy mask.
    noisy = conditioned("PETS09-S2L1", "sensor noise", tempfile.mkdtemp(prefix="ct-bench-"))[0]
    warm(noisy)
    wall_n, _, _ = best_of(reps, [ct, "-q", "-r", "7", "-o", "/dev/null", noisy])
    mog_n = mog2_ms(noisy, 100 if a.quick else 300)
    report["sensor_noise"] = {"pixels_fps": 795 / wall_n, "mog2_fps": 1e3 / mog_n}
    say("")
    say("With sensor noise (`noise=alls=14:allf=t`, make eval's condition) on the same "
        "frames, pixels only: ct-track %.0f frames/s, MOG2 alone %.0f frames/s (%.2f ms): "
        "%.1fx. On the clean frames: %.1fx."
        % (795 / wall_n, 1e3 / mog_n, mog_n, (795 / wall_n) / (1e3 / mog_n),
           whole["768x576"]["pixels_fps"] / whole["768x576"]["mog2_fps"]))

    # 3b. Following one person: OpenCV's single-object trackers beside mean
    # shift (opencv-contrib-python in the eval venv).
    ms_us = whole["768x576"]["mean_shift_us_per_person"]
    follow_frames = 20 if a.quick else 50
    follow = {kind: opencv_follow_us(pets, kind, frames=follow_frames)
              for kind in ("KCF", "CSRT", "MIL")}
    report["follow_one_person_us"] = dict(follow, ctrack_mean_shift=ms_us)
    say("")
    say("## Following one person: OpenCV's trackers beside ctrack's mean shift (768x576)")
    say("")
    say("OpenCV 4.10's single-object trackers, `update()` on one thread, following each of "
        "the first 10 PETS09-S2L1 ground-truth people for %d frames from their first box "
        "(`init()` not counted); ctrack's mean shift per person per frame from the run "
        "above." % follow_frames)
    say("")
    say("| follower | us per person per frame | ctrack's mean shift is faster by |")
    say("|---|---|---|")
    say("| ctrack mean shift | %.1f | 1.0x |" % ms_us)
    for kind, us_ in follow.items():
        say("| OpenCV %s | %.0f | %.0fx |" % (kind, us_, us_ / ms_us))

    # 3c. Bounded work: a flood of overlapping detections (ct-bench).
    flood = report["library"]["flood_ms"]
    say("")
    say("## Bounded work: a flood of overlapping detections")
    say("")
    say("One feed of overlapping detections (a detector without non-maximum suppression) "
        "into a tracker holding 1,000 live tracks, median of 5 (ct-bench, one core, "
        "`tests/flood.h`): 5,000 detections in %.1f ms, 50,000 in %.1f ms. The targets are "
        "100 ms and 2 s (docs/API.md, \"Work per call\")." % (flood["5000"], flood["50000"]))

    # 4. Memory and allocations.
    r = lib["detections 768x576"]
    say("")
    say("## Memory")
    say("")
    rp = lib.get("detections+pixels 768x576", r)
    say("- A new tracker: %d bytes on the heap; after PETS09-S2L1: %d bytes with detections "
        "only, %d with pixels (a colour model is 2 KiB a track)."
        % (r["tracker_bytes_created"], r["tracker_bytes_after"], rp["tracker_bytes_after"]))
    rx = lib.get("pixels only 768x576", rp)
    say("- Heap allocations per frame in steady state (second and later passes, every "
        "malloc of the process counted by ct-bench's interposed allocator): %.2f with "
        "detections only; %.2f with detections and pixels; %.2f from the pixels alone."
        % (r["allocs_per_frame"], rp["allocs_per_frame"], rx["allocs_per_frame"]))
    d = report["ddis"]
    say("- FLANN: appearance templates (%d points) are searched by comparing all pairs, "
        "which allocates nothing (%.1f allocations a DDIS, %.1f a template build); FLANN's "
        "kd-tree, kept for sets of more than 128 points, allocates %.0f a DDIS (one a query, "
        "in `findNeighbors`) and %.0f a build, and is never called at the default template. "
        "OpenCV is no longer called: the mask's closing and outer regions are the "
        "library's own." % (d["points"], d["ddis_allocs"], d["build_allocs"],
                            d["flann_ddis_allocs"], d["flann_build_allocs"]))
    say("- Peak RSS of ct-bench: %d KiB." % report["library"]["peak_rss_kib"])

    with open(os.path.join(a.build, "bench.json"), "w") as f:
        json.dump(report, f, indent=1)
    if not a.quick:
        with open(os.path.join(a.out, "bench.md"), "w") as f:
            f.write("# Benchmarks\n\nMade by `make bench` (`bench/bench.py`) on %s, ctrack %s, "
                    "on one core (`taskset -c 0`) of a 2-core machine. Absolute figures drift "
                    "by up to a third between runs on shared machines; the ratios to the "
                    "baselines measured in the same run are the figures to compare. The JSON "
                    "is written to `build/bench.json`.\n\n"
                    % (report["date"][:10], report["library"]["ctrack"]))
            f.write("\n".join(lines) + "\n")
    print("bench: wrote %s/bench.json%s" % (a.build, "" if a.quick else
                                             " and %s/bench.md" % a.out), file=sys.stderr)


if __name__ == "__main__":
    main()
