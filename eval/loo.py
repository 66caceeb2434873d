#!/usr/bin/env python3
"""Leave one sequence out: does a default chosen on the other sequences hold
on the one left out?

    loo.py BUILD_DIR NAME=V1,V2,... [NAME=...] [--base NAME=V ...]

For each parameter, detections only, every sequence of tests/data/mot15 is
tracked with every value (the others at their defaults, or --base). A NAME
in capitals starting CTRACK_ is an internal constant that a tuning build
(meson -Dtuning=true) reads from the environment; give its shipped value
after an @ (CTRACK_SCENE_TIME=0.1,0.3,1@0.3). Then
for each sequence in turn the value with the best MOTA + IDF1 over the
other sequences together (py-motmetrics' OVERALL) is chosen, and the
sequence left out is scored with it, beside the shipped default's score.
Prints a Markdown table a parameter (docs/tuning.md).
"""
import argparse
import os
import subprocess
import sys
import tempfile

import motmetrics as mm

from cteval.data import DATA, ct_track, sequences, seqinfo


def track(build, seq, params, out, env=None):
    i = seqinfo(seq)
    cmd = [ct_track(build), "-q", "-d", os.path.join(DATA, seq, "det", "det.txt"),
           "-s", "%dx%d" % (i["width"], i["height"]), "-r", str(i["fps"]), "-o", out]
    for p in params:
        cmd += ["-p", p]
    subprocess.run(cmd, check=True, env=dict(os.environ, **(env or {})))
    gt = mm.io.loadtxt(os.path.join(DATA, seq, "gt", "gt.txt"), fmt="mot15-2D",
                       min_confidence=1)
    return mm.utils.compare_to_groundtruth(gt, mm.io.loadtxt(out, fmt="mot15-2D"), "iou",
                                           distth=0.5)


def scores(accs, names):
    """(MOTA, IDF1) in percent over the accumulators together."""
    r = mm.metrics.create().compute_many(accs, names=names, metrics=["mota", "idf1"],
                                         generate_overall=True)
    return 100 * r.loc["OVERALL", "mota"], 100 * r.loc["OVERALL", "idf1"]


def default_of(build, name):
    """The shipped default of a parameter, from ct-track --help."""
    out = subprocess.run([ct_track(build), "--help"], check=True, capture_output=True,
                         text=True).stdout
    for line in out.splitlines():
        f = line.split()
        if len(f) >= 2 and f[0] == name:
            return f[1]
    sys.exit("loo: no parameter %s" % name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("sweeps", nargs="+")
    ap.add_argument("--base", action="append", default=[])
    a = ap.parse_args()
    seqs = sequences()
    tmp = tempfile.mkdtemp(prefix="ct-loo-")
    for sw in a.sweeps:
        name, values = sw.split("=", 1)
        internal = name.startswith("CTRACK_")
        if internal:
            values, default = values.split("@")
        else:
            default = default_of(a.build, name)
        values = values.split(",")
        if default not in values:
            values.append(default)
        accs = {}
        for v in values:
            for s in seqs:
                out = os.path.join(tmp, "%s.txt" % s)
                if internal:
                    accs[(v, s)] = track(a.build, s, a.base, out, env={name: v})
                else:
                    accs[(v, s)] = track(a.build, s, a.base + ["%s=%s" % (name, v)], out)
        print("\n%s (default %s; tried %s)\n" % (name, default, ", ".join(values)))
        print("| left out | chosen on the others | its MOTA / IDF1 there | the default's |")
        print("|---|---|---|---|")
        for out in seqs:
            rest = [s for s in seqs if s != out]

            def on_rest(v):
                m, i = scores([accs[(v, s)] for s in rest], rest)
                return m + i
            best = max(values, key=on_rest)
            chosen = scores([accs[(best, out)]], [out])
            shipped = scores([accs[(default, out)]], [out])
            print("| %s | %s | %.1f / %.1f | %.1f / %.1f |" % (out, best, *chosen, *shipped),
                  flush=True)


if __name__ == "__main__":
    main()
