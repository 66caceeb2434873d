#!/usr/bin/env python3
"""Sweeps one tracker parameter at a time around the defaults on the
MOTChallenge public detections and prints MOTA / IDF1 per sequence.

    sweep.py BUILD_DIR DATA_DIR NAME=V1,V2,... [NAME=...] [--base NAME=V ...]
             [--pixels | --pixels-only] [--steps 1,2,3]

DATA_DIR holds <SEQ>/det/det.txt, <SEQ>/gt/gt.txt and <SEQ>/seqinfo.ini.
The same parameters are used for every sequence: the choice is made on the
mean over sequences (docs/tuning.md). With --steps, each sequence is also
run at 1/k of its frame rate for each k given, from every offset (as make
eval's lower-rate table), and its cell is the mean over those runs.
"""
import argparse
import os
import shutil
import subprocess
import tempfile

from cteval.data import ct_track, seqinfo, subsampled, video
from cteval.score import score


def sequences(data_dir):
    for name in sorted(os.listdir(data_dir)):
        if os.path.exists(os.path.join(data_dir, name, "seqinfo.ini")):
            i = seqinfo(name, data_dir)
            yield name, i["width"], i["height"], i["fps"]


def variants(data_dir, steps, pixels, tmp):
    """Per sequence, the runs that make its cell: (size, fps, det, gt,
    video or None). Step 1 is the sequence itself; the others are made once
    in tmp (cteval.data.subsampled)."""
    out = {}
    for name, w, h, fps in sequences(data_dir):
        runs = []
        for k in steps:
            for offset in range(k):
                if k == 1:
                    det = os.path.join(data_dir, name, "det", "det.txt")
                    gt = os.path.join(data_dir, name, "gt", "gt.txt")
                    y4m = None
                    if pixels:
                        y4m = video(name)
                else:
                    y4m, gt, det, _ = subsampled(name, seqinfo(name),
                                                 video(name) if pixels else None, k, offset,
                                                 tmp, data=data_dir)
                runs.append(((w, h), fps / k, det, gt, y4m))
        out[name] = runs
    return out


def run(build, runs, params, detections=True):
    out = {}
    for name, seq_runs in runs.items():
        scores = []
        for (w, h), fps, det, gt, y4m in seq_runs:
            with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
                tracks = f.name
            cmd = [ct_track(build), "-q",
                   "-s", "%dx%d" % (w, h), "-r", str(fps), "-o", tracks]
            if detections:
                cmd += ["-d", det]
            for p in params:
                cmd += ["-p", p]
            if y4m:
                cmd.append(y4m)
            subprocess.run(cmd, check=True)
            scores.append(score(gt, tracks))
            os.unlink(tracks)
        out[name] = {m: sum(r[m] for r in scores) / len(scores) for m in ("MOTA", "IDF1", "IDsw")}
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("data")
    ap.add_argument("sweeps", nargs="*")
    ap.add_argument("--base", action="append", default=[])
    ap.add_argument("--pixels", action="store_true",
                    help="give ct-track the frames too (cached Y4M, as make eval makes them)")
    ap.add_argument("--pixels-only", action="store_true",
                    help="the frames without the detections: ctrack finds the people itself")
    ap.add_argument("--steps", default="1",
                    help="comma-separated k: also run every sequence at 1/k of its frame "
                    "rate, from every offset (default 1: the sequences as they are)")
    a = ap.parse_intermixed_args()
    dets = not a.pixels_only
    steps = [int(k) for k in a.steps.split(",")]
    if any(k < 1 for k in steps):
        ap.error("--steps: each k must be at least 1")
    tmp = tempfile.mkdtemp(prefix="ct-sweep-")
    runs = variants(a.data, steps, a.pixels or a.pixels_only, tmp)
    names = [n for n, *_ in sequences(a.data)]
    print("%-34s" % "parameter" + "".join("%22s" % n for n in names) + "%14s" % "mean")
    def line(label, r):
        mota = sum(r[n]["MOTA"] for n in names) / len(names)
        idf1 = sum(r[n]["IDF1"] for n in names) / len(names)
        cells = "".join("%10.1f/%5.1f/%3.0f  " % (r[n]["MOTA"], r[n]["IDF1"], r[n]["IDsw"])
                        for n in names)
        print("%-34s%s%7.1f/%5.1f" % (label, cells, mota, idf1), flush=True)
    line("base " + " ".join(a.base), run(a.build, runs, a.base, dets))
    for sw in a.sweeps:
        name, values = sw.split("=", 1)
        for v in values.split(","):
            line("%s=%s" % (name, v), run(a.build, runs, a.base + ["%s=%s" % (name, v)], dets))
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
