#!/usr/bin/env python3
"""Scores MOTChallenge track files against ground truth with py-motmetrics.

    mot_score.py GT.txt TRACKS.txt [--min-mota X] [--min-idf1 Y] [--json]

Prints MOTA, IDF1, ID switches, precision and recall (in percent). With
--min-mota / --min-idf1 it exits 1 when a score is below its threshold, so a
test can use it.
"""
import argparse
import json
import sys

import motmetrics as mm


def score(gt_path, tracks_path):
    gt = mm.io.loadtxt(gt_path, fmt="mot15-2D", min_confidence=1)
    ts = mm.io.loadtxt(tracks_path, fmt="mot15-2D")
    acc = mm.utils.compare_to_groundtruth(gt, ts, "iou", distth=0.5)
    mh = mm.metrics.create()
    names = ["mota", "motp", "idf1", "num_switches", "precision", "recall",
             "num_false_positives", "num_misses", "mostly_tracked", "num_unique_objects"]
    s = mh.compute(acc, metrics=names, name="seq")
    row = s.loc["seq"]
    return {
        "MOTA": 100.0 * float(row["mota"]),
        "IDF1": 100.0 * float(row["idf1"]),
        "IDsw": int(row["num_switches"]),
        "precision": 100.0 * float(row["precision"]),
        "recall": 100.0 * float(row["recall"]),
        "FP": int(row["num_false_positives"]),
        "FN": int(row["num_misses"]),
        "MT": int(row["mostly_tracked"]),
        "GT": int(row["num_unique_objects"]),
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("gt")
    ap.add_argument("tracks")
    ap.add_argument("--min-mota", type=float)
    ap.add_argument("--min-idf1", type=float)
    ap.add_argument("--json", action="store_true", help="print the scores as JSON")
    args = ap.parse_args()
    r = score(args.gt, args.tracks)
    if args.json:
        print(json.dumps(r))
    else:
        print("MOTA %.1f  IDF1 %.1f  IDsw %d  precision %.1f  recall %.1f  FP %d  FN %d  MT %d/%d"
              % (r["MOTA"], r["IDF1"], r["IDsw"], r["precision"], r["recall"],
                 r["FP"], r["FN"], r["MT"], r["GT"]))
    bad = []
    if args.min_mota is not None and r["MOTA"] < args.min_mota:
        bad.append("MOTA %.1f < %.1f" % (r["MOTA"], args.min_mota))
    if args.min_idf1 is not None and r["IDF1"] < args.min_idf1:
        bad.append("IDF1 %.1f < %.1f" % (r["IDF1"], args.min_idf1))
    if bad:
        print("below threshold: " + ", ".join(bad), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
