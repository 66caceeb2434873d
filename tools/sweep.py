#!/usr/bin/env python3
"""Sweeps one tracker parameter at a time around the defaults on the
MOTChallenge public detections and prints MOTA / IDF1 per sequence.

    sweep.py BUILD_DIR DATA_DIR NAME=V1,V2,... [NAME=...] [--base NAME=V ...]
             [--pixels | --pixels-only]

DATA_DIR holds <SEQ>/det/det.txt, <SEQ>/gt/gt.txt and <SEQ>/seqinfo.ini.
The same parameters are used for every sequence: the choice is made on the
mean over sequences (docs/tuning.md).
"""
import argparse
import configparser
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mot_score import score  # noqa: E402


def sequences(data_dir):
    for name in sorted(os.listdir(data_dir)):
        ini = os.path.join(data_dir, name, "seqinfo.ini")
        if os.path.exists(ini):
            c = configparser.ConfigParser()
            c.read(ini)
            s = c["Sequence"]
            yield name, int(s["imWidth"]), int(s["imHeight"]), float(s["frameRate"])


def run(build, data_dir, params, pixels=False, detections=True):
    out = {}
    for name, w, h, fps in sequences(data_dir):
        with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as f:
            tracks = f.name
        cmd = [os.path.join(build, "tools", "ct-track"), "-q",
               "-s", "%dx%d" % (w, h), "-r", str(fps), "-o", tracks]
        if detections:
            cmd += ["-d", os.path.join(data_dir, name, "det", "det.txt")]
        for p in params:
            cmd += ["-p", p]
        if pixels or not detections:
            from eval import video
            cmd.append(video(name))
        subprocess.run(cmd, check=True)
        out[name] = score(os.path.join(data_dir, name, "gt", "gt.txt"), tracks)
        os.unlink(tracks)
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
    a = ap.parse_intermixed_args()
    dets = not a.pixels_only
    names = [n for n, *_ in sequences(a.data)]
    print("%-28s" % "parameter" + "".join("%22s" % n for n in names) + "%14s" % "mean")
    def line(label, r):
        mota = sum(r[n]["MOTA"] for n in names) / len(names)
        idf1 = sum(r[n]["IDF1"] for n in names) / len(names)
        cells = "".join("%10.1f/%5.1f/%3d  " % (r[n]["MOTA"], r[n]["IDF1"], r[n]["IDsw"])
                        for n in names)
        print("%-28s%s%7.1f/%5.1f" % (label, cells, mota, idf1), flush=True)
    line("base " + " ".join(a.base), run(a.build, a.data, a.base, a.pixels, dets))
    for sw in a.sweeps:
        name, values = sw.split("=", 1)
        for v in values.split(","):
            line("%s=%s" % (name, v),
                 run(a.build, a.data, a.base + ["%s=%s" % (name, v)], a.pixels, dets))


if __name__ == "__main__":
    main()
