"""Scores MOTChallenge track files against ground truth with py-motmetrics.

    python -m cteval.score GT.txt TRACKS.txt [--min-mota X] [--min-idf1 Y] [--json]

Prints MOTA, IDF1, ID switches, precision and recall (in percent). With
--min-mota / --min-idf1 it exits 1 when a score is below its threshold, so a
test can use it.
"""
import argparse
import json
import sys

import motmetrics as mm


def barycenter_error(acc, gt, ts):
    """The paper's barycenter error as docs/algorithm.md defines it: over the
    matched track/ground-truth pairs, the mean distance between the box
    centres divided by the ground-truth box height, in percent."""
    ev = acc.mot_events
    ev = ev[ev["Type"].isin(["MATCH", "SWITCH"])]
    if len(ev) == 0:
        return float("nan")
    frames = ev.index.get_level_values("FrameId")
    g = gt.loc[list(zip(frames, ev["OId"]))]
    t = ts.loc[list(zip(frames, ev["HId"]))]
    gx = g["X"].values + g["Width"].values / 2
    gy = g["Y"].values + g["Height"].values / 2
    tx = t["X"].values + t["Width"].values / 2
    ty = t["Y"].values + t["Height"].values / 2
    return float(100.0 * (((gx - tx) ** 2 + (gy - ty) ** 2) ** 0.5 / g["Height"].values).mean())


NAMES = ["mota", "motp", "idf1", "num_switches", "precision", "recall",
         "num_false_positives", "num_misses", "mostly_tracked", "num_unique_objects"]


def _row(row):
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


def _accumulate(gt_path, tracks_path):
    gt = mm.io.loadtxt(gt_path, fmt="mot15-2D", min_confidence=1)
    ts = mm.io.loadtxt(tracks_path, fmt="mot15-2D")
    return mm.utils.compare_to_groundtruth(gt, ts, "iou", distth=0.5), gt, ts


def score(gt_path, tracks_path):
    """py-motmetrics' scores of one track file (IoU >= 0.5, ground-truth rows
    with flag 0 dropped) and the paper's barycenter error."""
    acc, gt, ts = _accumulate(gt_path, tracks_path)
    s = mm.metrics.create().compute(acc, metrics=NAMES, name="seq")
    r = _row(s.loc["seq"])
    r["barycenter_error"] = barycenter_error(acc, gt, ts)
    return r


def score_overall(pairs):
    """py-motmetrics' OVERALL over several sequences, [(gt, tracks), ...]:
    every sequence's events pooled, as MOTChallenge sums them."""
    accs = [_accumulate(g, t)[0] for g, t in pairs]
    names = [str(i) for i in range(len(accs))]
    s = mm.metrics.create().compute_many(accs, names=names, metrics=NAMES,
                                         generate_overall=True)
    return _row(s.loc["OVERALL"])


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
              "  barycenter error %.2f%%"
              % (r["MOTA"], r["IDF1"], r["IDsw"], r["precision"], r["recall"],
                 r["FP"], r["FN"], r["MT"], r["GT"], r["barycenter_error"]))
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
