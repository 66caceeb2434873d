#!/usr/bin/env python3
"""Where the barycenter error comes from, by how much of a person another covers.

    barycenter_breakdown.py BUILD_DIR [SEQUENCE] [--mode detections+pixels|pixels]
                            [--picture PNG]

Tracks a sequence with a video online as make eval does, matches its boxes
to the ground truth's as the barycenter error is measured (py-motmetrics,
IoU >= 0.5; cteval.score) and splits the error of the matched pairs:
- by the share of the ground-truth box that another ground-truth person's
  box covers (none, under a sixth, more);
- for the covered ones, whether the person is in front (feet lower in the
  image than the other's) or behind, with the mean offset of the box's top
  and bottom from the ground truth's in heights of the ground truth;
- for the covered ones, whether ctrack reported another box over this one
  (more than a sixth of it covered, the rule under which the library fits
  a detector's box only from the rows its person has alone, in front or
  behind) or none: one box where there are two people;
- what the total would be if the covered pairs' centres were right (an
  oracle: the share of the error the occlusions hold).
With --picture, a sheet of the uncovered pairs whose error is over 10%:
the ground truth's box green, ctrack's red. Prints Markdown
(docs/notes/barycenter.md, "Where the error is").
"""
import argparse
import os
import sys
import tempfile

import numpy as np

from cteval import score
from cteval.data import DATA, run_ctrack, seqinfo, video
from cteval.y4m import open_y4m

COVER = 1.0 / 6  # the library's kMaxCovered (lib/track/engine.cc)


def covered_by_other(boxes, frames):
    """For each row of boxes (left, top, width, height), the
    largest share of it another box of the same frame covers, and whether
    that other box's bottom is above this one's (this one in front)."""
    share = np.zeros(len(boxes))
    front = np.zeros(len(boxes), bool)
    for f in np.unique(frames):
        rows = np.where(frames == f)[0]
        b = boxes[rows]
        ix = np.clip(np.minimum.outer(b[:, 0] + b[:, 2], b[:, 0] + b[:, 2]) -
                     np.maximum.outer(b[:, 0], b[:, 0]), 0, None)
        iy = np.clip(np.minimum.outer(b[:, 1] + b[:, 3], b[:, 1] + b[:, 3]) -
                     np.maximum.outer(b[:, 1], b[:, 1]), 0, None)
        inter = ix * iy
        np.fill_diagonal(inter, 0)
        j = inter.argmax(axis=1)
        share[rows] = inter[np.arange(len(rows)), j] / (b[:, 2] * b[:, 3])
        front[rows] = b[:, 1] + b[:, 3] > b[j, 1] + b[j, 3]
    return share, front


def lookup(table, frames, ids):
    """Rows of a MOTChallenge array (frame, id, box...) at (frame, id) pairs."""
    where = {(int(r[0]), int(r[1])): i for i, r in enumerate(table)}
    return np.array([where[(int(f), int(i))] for f, i in zip(frames, ids)])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("sequence", nargs="?", default="PETS09-S2L1")
    ap.add_argument("--mode", choices=("detections+pixels", "pixels"),
                    default="detections+pixels")
    ap.add_argument("--picture", help="write a sheet of the uncovered pairs over 10%%")
    a = ap.parse_args()
    seq = a.sequence
    gt_path = os.path.join(DATA, seq, "gt", "gt.txt")
    with tempfile.TemporaryDirectory() as tmp:
        tracks_path = os.path.join(tmp, "tracks.txt")
        run_ctrack(a.build, seq, seqinfo(seq), video(seq), tracks_path, pixels=True,
                   detections=a.mode == "detections+pixels")
        acc, _, _ = score._accumulate(gt_path, tracks_path)
        tracks = np.loadtxt(tracks_path, delimiter=",", ndmin=2)
    gt = np.loadtxt(gt_path, delimiter=",", ndmin=2)
    gt = gt[gt[:, 6] != 0]
    ev = acc.mot_events
    ev = ev[ev["Type"].isin(["MATCH", "SWITCH"])]
    frames = ev.index.get_level_values("FrameId").values
    g_rows = lookup(gt, frames, ev["OId"].values)
    t_rows = lookup(tracks, frames, ev["HId"].values)
    g, t = gt[g_rows, 2:6], tracks[t_rows, 2:6]
    h = g[:, 3]
    dx = (t[:, 0] + t[:, 2] / 2 - g[:, 0] - g[:, 2] / 2) / h
    dy = (t[:, 1] + t[:, 3] / 2 - g[:, 1] - g[:, 3] / 2) / h
    err = 100 * np.hypot(dx, dy)
    top = (t[:, 1] - g[:, 1]) / h
    bottom = (t[:, 1] + t[:, 3] - g[:, 1] - g[:, 3]) / h
    gt_share, gt_front = covered_by_other(gt[:, 2:6], gt[:, 0])
    gt_share, gt_front = gt_share[g_rows], gt_front[g_rows]
    our_share, _ = covered_by_other(tracks[:, 2:6], tracks[:, 0])
    our_share = our_share[t_rows]

    total = err.sum()
    print("%s, %s, online: barycenter error %.2f%% over %d matched pairs\n"
          % (seq, a.mode.replace("+", " + "), err.mean(), len(err)))
    print("| pairs | count | error | share of the total | top | bottom |")
    print("|---|---|---|---|---|---|")

    def row(name, m):
        if m.any():
            print("| %s | %d | %.2f%% | %.0f%% | %+.3f | %+.3f |"
                  % (name, m.sum(), err[m].mean(), 100 * err[m].sum() / total,
                     top[m].mean(), bottom[m].mean()))
    covered = gt_share > COVER
    row("not covered by another person", gt_share == 0)
    row("covered, under a sixth", (gt_share > 0) & ~covered)
    row("covered, more than a sixth", covered)
    row("... in front", covered & gt_front)
    row("... behind", covered & ~gt_front)
    row("... ctrack reported no other box over it", covered & (our_share == 0))
    row("... ctrack's boxes overlap, under a sixth", covered & (our_share > 0) &
        (our_share <= COVER))
    row("... ctrack's boxes overlap, more (fitted in front and behind)", covered & (our_share > COVER))
    uncovered = gt_share == 0
    print("\nThe uncovered pairs: median %.2f%%, %.1f%% of them over 10%% holding %.2f "
          "points of the mean; with the covered pairs' centres right in height: %.2f%%."
          % (np.median(err[uncovered]), 100 * (err[uncovered] > 10).mean(),
             (err * (uncovered & (err > 10))).sum() / len(err),
             100 * np.where(covered, np.abs(dx), np.hypot(dx, dy)).mean()))
    if a.picture:
        picture(a.picture, seq, frames, g, t, err, uncovered & (err > 10))


def picture(path, seq, frames, g, t, err, m, n=12):
    """A sheet of n pairs drawn from m (the same ones each run)."""
    import cv2
    rows = np.random.default_rng(1).choice(np.where(m)[0], min(n, m.sum()), replace=False)
    want = {int(frames[i]) for i in rows}
    w, h, _, data = open_y4m(video(seq))
    images = {k: cv2.cvtColor(np.asarray(data[k - 1]).reshape(h * 3 // 2, w),
                              cv2.COLOR_YUV2BGR_I420) for k in want}
    tiles = []
    for i in rows:
        im = images[int(frames[i])].copy()
        for b, colour in ((g[i], (0, 200, 0)), (t[i], (0, 0, 255))):
            cv2.rectangle(im, (int(b[0]), int(b[1])), (int(b[0] + b[2]), int(b[1] + b[3])),
                          colour, 1)
        cx, cy, s = int(g[i, 0] + g[i, 2] / 2), int(g[i, 1] + g[i, 3] / 2), int(g[i, 3])
        crop = im[max(0, cy - s):cy + s, max(0, cx - s):cx + s]
        crop = cv2.resize(crop, (200, 200))
        cv2.putText(crop, "frame %d, %.0f%%" % (frames[i], err[i]), (4, 16),
                    cv2.FONT_HERSHEY_SIMPLEX, 0.45, (255, 255, 255), 1)
        tiles.append(crop)
    while len(tiles) % 4:
        tiles.append(np.zeros_like(tiles[0]))
    sheet = np.vstack([np.hstack(tiles[r:r + 4]) for r in range(0, len(tiles), 4)])
    cv2.imwrite(path, sheet)


if __name__ == "__main__":
    sys.exit(main())
