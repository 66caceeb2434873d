#!/usr/bin/env python3
"""Sweeps an internal constant over a family of camera conditions
(cteval.families: many variants of one condition, levels and seeds), on
every sequence that has frames, so that a choice does not rest on one noise
pattern or one contrast.

    families.py TUNING_BUILD FAMILY [CTRACK_NAME=V1,V2,...@SHIPPED] [--jobs 2]
                [--each] [--detections] [-p NAME=VALUE ...]

FAMILY is one of cteval.families.FAMILIES ("half size" needs its quotes),
"conditions": the frames as they are and make eval's camera conditions,
"frame rate": a half and a third of the frame rate, from each offset, or
"noise seeds": sensor noise of three strengths, ten seeds each (not one of
make eval's: one seed is one draw, and TUD-Campus's swing by 20 MOTA), or
"scale": the frames scaled from 0.75 to 3 times (not make eval's either). A
tuning build (meson -Dtuning=true) reads CTRACK_NAME from the environment;
without a sweep, any build is scored with its defaults.
Pixels only, or with --detections each sequence's public detections too
(moved with the frames); -p passes ct-track a parameter (-p
verify_detections=1). For each value, each sequence's mean and lowest MOTA /
IDF1 over the family's variants, and its mean and highest barycenter error
(with --each, every variant's MOTA / IDF1 too); then,
leaving each sequence out in turn, the value with the best mean MOTA + IDF1
on the others, and the one left out scored with it beside the shipped value
(docs/tuning.md).
"""
import argparse
import sys
import tempfile

import numpy as np

from cteval.data import has_video, sequences
from cteval.families import (CONDITIONS_FAMILY, FAMILIES, NOISE_SEEDS_FAMILY, RATE_FAMILY,
                              SCALE_FAMILY, run_all)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("family",
                    choices=sorted(FAMILIES) + ["conditions", "frame rate", "noise seeds",
                                                "scale"])
    ap.add_argument("sweep", nargs="?",
                    help="CTRACK_NAME=V1,V2,...@SHIPPED (none: the build's defaults alone)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--each", action="store_true", help="also print every variant's score")
    ap.add_argument("--detections", action="store_true")
    ap.add_argument("-p", dest="params", action="append", default=[])
    a = ap.parse_args()
    if a.sweep is None:
        name, values, shipped = "defaults", ["as built"], None
    else:
        name, rest = a.sweep.split("=", 1)
        values, shipped = rest.split("@") if "@" in rest else (rest, None)
        values = values.split(",")
        if shipped is not None and shipped not in values:
            values.append(shipped)
    seqs = [s for s in sequences() if has_video(s)]
    variants = dict(FAMILIES, conditions=CONDITIONS_FAMILY,
                    **{"frame rate": RATE_FAMILY, "noise seeds": NOISE_SEEDS_FAMILY,
                       "scale": SCALE_FAMILY})[a.family]
    keys = [(seq, label, v) for v in values for seq in seqs for label, _, _ in variants]
    jobs = [dict(build=a.build, seq=seq, vf=vf, move=move,
                 env={name: v} if a.sweep is not None else None,
                 detections=a.detections, params=a.params)
            for v in values for seq in seqs for _, vf, move in variants]
    with tempfile.TemporaryDirectory() as tmp:
        scores = run_all(jobs, tmp, a.jobs, lambda k, n: print(
            "families: %d/%d runs" % (k, n), file=sys.stderr, flush=True))
    results = {k: (s["MOTA"], s["IDF1"]) for k, s in zip(keys, scores)}
    bary = {k: s["barycenter_error"] for k, s in zip(keys, scores)}

    def per_seq(seq, v):
        return np.array([results[(seq, label, v)] for label, _, _ in variants])

    mode = "detections + pixels" if a.detections else "pixels only"
    print("%s over the %s family (%d variants a sequence), %s%s: mean (lowest) "
          "MOTA / IDF1\n" % (name, a.family, len(variants), mode,
                              "".join(", " + p for p in a.params)))
    print("| %s | %s |" % (name, " | ".join(seqs)))
    print("|---|%s" % ("---|" * len(seqs)))
    for v in values:
        cells = ["%.1f / %.1f (%.1f / %.1f)" % (*per_seq(s, v).mean(0), *per_seq(s, v).min(0))
                 for s in seqs]
        print("| %s%s | %s |" % (v, " (shipped)" if v == shipped else "", " | ".join(cells)))
    print("\nThe barycenter error, mean (highest) over the variants:\n")
    print("| %s | %s |" % (name, " | ".join(seqs)))
    print("|---|%s" % ("---|" * len(seqs)))
    for v in values:
        errs = [np.array([bary[(s, label, v)] for label, _, _ in variants]) for s in seqs]
        print("| %s%s | %s |" % (v, " (shipped)" if v == shipped else "", " | ".join(
            "%.2f%% (%.2f%%)" % (e.mean(), e.max()) for e in errs)))
    if a.each:
        print("\n| %s | variant | %s |" % (name, " | ".join(seqs)))
        print("|---|---|%s" % ("---|" * len(seqs)))
        for v in values:
            for label, _, _ in variants:
                print("| %s | %s | %s |" % (v, label, " | ".join(
                    "%.1f / %.1f" % results[(s, label, v)] for s in seqs)))
    if a.sweep is None:
        return
    print("\nLeave one sequence out (the value with the best mean MOTA + IDF1 on the "
          "others):\n")
    print("| left out | chosen | its score | shipped's |")
    print("|---|---|---|---|")
    for out in seqs:
        others = [s for s in seqs if s != out]
        best = max(values, key=lambda v: sum(per_seq(s, v).mean(0).sum() for s in others))
        ref = "%.1f / %.1f" % tuple(per_seq(out, shipped).mean(0)) if shipped else "-"
        print("| %s | %s | %.1f / %.1f | %s |" % (out, best, *per_seq(out, best).mean(0), ref))


if __name__ == "__main__":
    main()
