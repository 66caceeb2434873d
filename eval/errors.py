#!/usr/bin/env python3
"""Where tracking from detections errs: by box size, by how long the person
has been in view, by how long ctrack's track has existed, by camera motion.

    errors.py BUILD_DIR [-p NAME=VALUE ...]

Tracks each sequence of tests/data/mot15 from its detections alone (the
defaults, or -p), matches the boxes to the ground truth as py-motmetrics
scores them (IoU >= 0.5) and splits the outcome:
- by height in pixels: recall by the person's (beside the detector's own
  recall there: the share of the ground truth's boxes that the public
  detections match, one a person, at IoU 0.5, whatever their score),
  precision by ctrack's box's;
- by the time since the person's first ground-truth box (recall, and the
  ID switches py-motmetrics counts);
- by the time since ctrack's track was first reported (precision: the
  share of its boxes that match someone);
- by the image motion of the frame: on the still cameras (PETS09-S2L1,
  TUD-Campus, Venice-2) as one row, on the moving ones by the median
  motion of the frame's people between that frame and the one before, in
  their heights a second (the camera's motion and the people's walk
  together; walking alone is about 0.7).
Then, a sequence a column: the false positives that lie on a person the
ground truth marks 0 (left out of the scores; py-motmetrics and
MOTChallenge's 2015 scoring count a box there as false, for every tracker
alike); the near misses (a person missed while a reported box overlaps
them at IoU 0.3 to 0.5 and a public detection at 0.5 or more), with the
median IoU of that detection with the person and of the reported box with
the detection, and the mean sideways offset of each from the person, in
their heights; and the passes, a track matched to a person other than the
one it last matched, with the median time since it did.
Prints Markdown (docs/tuning.md, "Where tracking from detections errs").
"""
import argparse
import os
import tempfile
from collections import defaultdict

import numpy as np
from scipy.optimize import linear_sum_assignment

from cteval.data import DATA, sequences, seqinfo
from cteval.peers import iou_matrix
from loo import track

# The still cameras of tests/data/README.md's table.
STILL = {"PETS09-S2L1", "TUD-Campus", "Venice-2"}
HEIGHTS = [0, 60, 100, 160, 250, 1e9]
SINCE = [0, 0.5, 1, 2, 4, 1e9]
MOTION = [0, 0.5, 1, 2, 1e9]


def boxes(rows):
    """{(frame, id): (left, top, width, height)} of MOTChallenge rows."""
    return {(int(r[0]), int(r[1])): r[2:6] for r in rows}


def iou(b, d):
    """IoU of box b against the boxes d (N, 4)."""
    return iou_matrix(b[None], d)[0]


def by_frame(boxes):
    out = defaultdict(list)
    for (k, _), b in boxes.items():
        out[k].append(b)
    return {k: np.array(v) for k, v in out.items()}


def frame_motion(gt, fps):
    """Per frame, the median motion of its people's centres since the frame
    before, in their heights a second."""
    by_frame = defaultdict(list)
    for (k, o), b in gt.items():
        p = gt.get((k - 1, o))
        if p is None:
            continue
        d = np.hypot(b[0] + b[2] / 2 - p[0] - p[2] / 2, b[1] + b[3] / 2 - p[1] - p[3] / 2)
        by_frame[k].append(d / b[3] * fps)
    return {k: float(np.median(v)) for k, v in by_frame.items()}


def label(edges, v, unit=""):
    for lo, hi in zip(edges, edges[1:]):
        if lo <= v < hi:
            return ("%g%s or more" % (lo, unit) if hi >= 1e9 else
                    "under %g%s" % (hi, unit) if lo == 0 else "%g-%g%s" % (lo, hi, unit))
    return "?"


def overlapped(boxes, others):
    """The keys of boxes that a box of others in their frame overlaps at
    IoU >= 0.5."""
    frames = by_frame(others)
    return {key for key, b in boxes.items()
            if key[0] in frames and iou(b, frames[key[0]]).max() >= 0.5}


def detected(gt, dets):
    """The keys of the ground truth's boxes that a public detection of their
    frame matches, one detection a person (the most matched at IoU >= 0.5,
    as py-motmetrics matches a tracker's boxes)."""
    frames = by_frame(dets)
    out = set()
    people = defaultdict(list)
    for key, b in gt.items():
        people[key[0]].append((key, b))
    for k, rows in people.items():
        if k not in frames:
            continue
        o = iou_matrix(np.array([b for _, b in rows]), frames[k])
        r, c = linear_sum_assignment(np.where(o >= 0.5, 1 - o, 2))
        out.update(rows[i][0] for i, j in zip(r, c) if o[i, j] >= 0.5)
    return out


def near_misses(ev, gt, hyp, dets):
    """(count, median IoU of the detection with the person, median IoU of
    the reported box with the detection, mean sideways offset of the box and
    of the detection in the person's heights) of the near misses."""
    hyps, detections = by_frame(hyp), by_frame(dets)
    rows = []
    for (k, _), o in ev[ev.Type == "MISS"].OId.items():
        k, g = int(k), gt[(int(k), int(o))]
        if k not in hyps or k not in detections:
            continue
        on_d, on_t = iou(g, detections[k]), iou(g, hyps[k])
        d, t = detections[k][on_d.argmax()], hyps[k][on_t.argmax()]
        if on_d.max() < 0.5 or not 0.3 <= on_t.max() < 0.5:
            continue
        cx = g[0] + g[2] / 2
        rows.append((on_d.max(), iou(d, t[None])[0],
                     abs(t[0] + t[2] / 2 - cx) / g[3], abs(d[0] + d[2] / 2 - cx) / g[3]))
    r = np.array(rows).reshape(-1, 4)
    if not len(r):
        return (0, np.nan, np.nan, np.nan, np.nan)
    return (len(r), np.median(r[:, 0]), np.median(r[:, 1]), r[:, 2].mean(), r[:, 3].mean())


def passes(ev, fps):
    """(count, median seconds since the track last matched the other
    person) of the tracks matched to another person than their last."""
    last, gaps = {}, []
    for (k, _), r in ev[ev.Type.isin(["MATCH", "SWITCH"])].iterrows():
        h, o = int(r.HId), int(r.OId)
        if h in last and last[h][1] != o:
            gaps.append((int(k) - last[h][0]) / fps)
        last[h] = (int(k), o)
    return (len(gaps), float(np.median(gaps)) if gaps else np.nan)


def outcomes(acc, gt, hyp, fps, still, found):
    """(kind, bin, outcome) triples: outcome 'tp', 'fn', 'fp' or 'sw'."""
    first_gt, first_hyp = {}, {}
    for k, o in sorted(gt):
        first_gt.setdefault(o, k)
    for k, h in sorted(hyp):
        first_hyp.setdefault(h, k)
    motion = {} if still else frame_motion(gt, fps)
    out = []
    ev = acc.mot_events
    for (k, _), r in ev.iterrows():
        kind = r.Type
        if kind not in ("MATCH", "SWITCH", "MISS", "FP"):
            continue
        k = int(k)
        cam = "still camera" if still else label(MOTION, motion.get(k, 0.0))
        if kind == "FP":
            h = int(r.HId)
            out.append(("box height", label(HEIGHTS, hyp[(k, h)][3], " px"), "fp"))
            out.append(("track age", label(SINCE, (k - first_hyp[h]) / fps, " s"), "fp"))
            out.append(("motion", cam, "fp"))
            continue
        o = int(r.OId)
        res = "fn" if kind == "MISS" else "tp"
        bins = [("height", label(HEIGHTS, gt[(k, o)][3], " px")),
                ("in view", label(SINCE, (k - first_gt[o]) / fps, " s")),
                ("motion", cam)]
        for b in bins:
            out.append(b + (res,))
            if (k, o) in found:
                out.append(b + ("det",))
        if kind == "SWITCH":
            out.append(("in view", bins[1][1], "sw"))
        if res == "tp":
            h = int(r.HId)
            out.append(("track age", label(SINCE, (k - first_hyp[h]) / fps, " s"), "tp"))
            out.append(("box height", label(HEIGHTS, hyp[(k, h)][3], " px"), "tp"))
    return out


def table(rows, kind, edges, unit, what, seqs):
    """One row a bin: recall (kinds binned by the ground truth) or
    precision (binned by ctrack's boxes) over the six, then each sequence's."""
    counts = defaultdict(lambda: defaultdict(int))
    for seq, k, b, res in rows:
        if k == kind:
            counts[b][res] += 1
            counts[b][seq + res] += 1
    order = [label(edges, (lo + hi) / 2 if hi < 1e9 else lo, unit)
             for lo, hi in zip(edges, edges[1:])]
    if kind == "motion":
        order = ["still camera"] + order
    precision = kind in ("track age", "box height")

    def cell(c, p=""):
        if precision:
            n = c[p + "tp"] + c[p + "fp"]
            return "%.1f (%d)" % (100.0 * c[p + "tp"] / n, n) if n else "-"
        n = c[p + "tp"] + c[p + "fn"]
        return ("%.1f of %.1f (%d)" % (100.0 * c[p + "tp"] / n, 100.0 * c[p + "det"] / n, n)
                if n else "-")
    print("\n%s, %s (boxes):\n" % (what, "precision" if precision else "recall"))
    print("| %s | over the six | %s |%s" % (what, " | ".join(seqs),
                                           " ID switches |" if kind == "in view" else ""))
    print("|---|---|%s%s" % ("---|" * len(seqs), "---|" if kind == "in view" else ""))
    for b in order:
        c = counts.get(b)
        if not c:
            continue
        print("| %s | %s | %s |%s" % (b, cell(c), " | ".join(cell(c, s) for s in seqs),
                                      " %d |" % c["sw"] if kind == "in view" else ""))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("-p", "--param", action="append", default=[])
    a = ap.parse_args()
    tmp = tempfile.mkdtemp(prefix="ct-errors-")
    rows, ignored = [], []
    seqs = sequences()
    for seq in seqs:
        out = os.path.join(tmp, seq + ".txt")
        acc = track(a.build, seq, a.param, out)
        fps = float(seqinfo(seq)["fps"])
        rows_gt = np.loadtxt(os.path.join(DATA, seq, "gt", "gt.txt"), delimiter=",", ndmin=2)
        scored = rows_gt[:, 6] != 0  # the rows the scoring keeps
        gt, ignored_gt = boxes(rows_gt[scored]), boxes(rows_gt[~scored])
        hyp = boxes(np.loadtxt(out, delimiter=",", ndmin=2))
        dets = {(k, i): b for i, (k, b) in enumerate(
            (int(r[0]), r[2:6]) for r in np.loadtxt(
                os.path.join(DATA, seq, "det", "det.txt"), delimiter=",", ndmin=2))}
        found = detected(gt, dets)
        rows += [(seq,) + r for r in outcomes(acc, gt, hyp, fps, seq in STILL, found)]
        ev = acc.mot_events
        fp = {(int(k), int(h)) for (k, _), h in ev[ev.Type == "FP"].HId.items()}
        on_ignored = overlapped({key: hyp[key] for key in fp}, ignored_gt)
        ignored.append((seq, len(fp), len(on_ignored)) + near_misses(ev, gt, hyp, dets)
                       + passes(ev, fps))
    print("Over the six sequences, detections only. Each cell a percentage and, in "
          "brackets, how many boxes it is of; recall is given as ctrack's of the "
          "detector's (the share the public detections match, one a person, at IoU "
          "0.5, whatever their score).")
    table(rows, "height", HEIGHTS, " px", "the person's height", seqs)
    table(rows, "box height", HEIGHTS, " px", "ctrack's box's height", seqs)
    table(rows, "in view", SINCE, " s", "the person in view for", seqs)
    table(rows, "track age", SINCE, " s", "ctrack's track reported for", seqs)
    table(rows, "motion", MOTION, "", "the people's image motion (heights/s)", seqs)
    print("\nA sequence a column:\n")
    print("| | %s |" % " | ".join(r[0] for r in ignored))
    print("|---|%s" % ("---|" * len(ignored)))
    for i, (name, fmt) in enumerate((
            ("false positives", "%d"), ("... on a person marked 0", "%d"),
            ("near misses", "%d"), ("... the detection's IoU with the person", "%.2f"),
            ("... the reported box's IoU with the detection", "%.2f"),
            ("... the reported box's sideways offset", "%.3f"),
            ("... the detection's sideways offset", "%.3f"),
            ("passes to another person", "%d"), ("... seconds after the last match", "%.2f"))):
        print("| %s | %s |" % (name, " | ".join(fmt % r[i + 1] for r in ignored)))


if __name__ == "__main__":
    main()
