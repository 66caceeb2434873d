"""A family of detectors: each sequence's public detections as another
detector would give them, so that "any detector" is measured and not only
the one the defaults were chosen with.

- scores on another scale: times 0.8, and squared (a detector whose
  scores are spread lower, as many are);
- a detector that misses more: 20% of the boxes dropped at random, three
  seeds;
- a looser one: each box edge moved by up to 5% of the box's height, at
  random (uniform), one seed.

Every variant is written once per run into a temporary folder; the ground
truth is the sequence's own.
"""
import os

import numpy as np

from cteval.data import DATA

# name, the change to the rows of a det.txt (frame, -1, left, top, width,
# height, score, ...), and its seed.
VARIANTS = [
    ("scores x 0.8", "scale", 0),
    ("scores squared", "square", 0),
    ("20% dropped, seed 1", "drop", 1),
    ("20% dropped, seed 2", "drop", 2),
    ("20% dropped, seed 3", "drop", 3),
    ("edges jittered by 5% of the height", "jitter", 1),
]


def changed(rows, how, seed):
    """The detections' rows changed as the variant says."""
    rows = rows.copy()
    rng = np.random.default_rng(seed)
    if how == "scale":
        rows[:, 6] *= 0.8
    elif how == "square":
        rows[:, 6] = rows[:, 6] ** 2
    elif how == "drop":
        rows = rows[rng.random(len(rows)) >= 0.2]
    elif how == "jitter":
        h = rows[:, 5].copy()
        x0, y0 = rows[:, 2].copy(), rows[:, 3].copy()
        x1, y1 = x0 + rows[:, 4], y0 + rows[:, 5]
        d = rng.uniform(-0.05, 0.05, size=(len(rows), 4)) * h[:, None]
        x0, y0, x1, y1 = x0 + d[:, 0], y0 + d[:, 1], x1 + d[:, 2], y1 + d[:, 3]
        rows[:, 2], rows[:, 3] = x0, y0
        rows[:, 4] = np.maximum(1.0, x1 - x0)
        rows[:, 5] = np.maximum(1.0, y1 - y0)
    else:
        raise ValueError(how)
    return rows


def variant_path(seq, name, how, seed, tmp):
    """The sequence's detections as the variant gives them, written in tmp."""
    src = np.loadtxt(os.path.join(DATA, seq, "det", "det.txt"), delimiter=",", ndmin=2)
    path = os.path.join(tmp, "det-%s-%s-%d.txt" % (seq, how, seed))
    if not os.path.exists(path):
        np.savetxt(path, changed(src, how, seed), delimiter=",", fmt="%.6g")
    return path
