"""The barycenter error's floor and picture (make eval).

The floor: how far the ground truth's own boxes sit from the people's
silhouettes. eval/fit-floor.cc fits each ground-truth box of a sequence with
a video to the silhouette in the pixels-alone tracker's foreground, all
the way (the library's fit, lib/pixels/box_fit.cc), and the floor is the
mean distance between the two boxes' centres over the ground truth's
height, as the barycenter error is measured: annotators' boxes jitter
about the silhouettes, and a tracker whose boxes sat on the silhouettes
exactly would still score this.
"""
import os
import subprocess

import numpy as np

from cteval.data import DATA


def floor(build, seq, y4m, tmp):
    """(floor in percent, share of the ground truth's boxes fitted)."""
    gt_path = os.path.join(DATA, seq, "gt", "gt.txt")
    out = os.path.join(tmp, "floor-%s.txt" % seq)
    subprocess.run([os.path.join(build, "eval", "fit-floor"), y4m, gt_path, out], check=True)
    gt = np.loadtxt(gt_path, delimiter=",", ndmin=2)
    gt = gt[gt[:, 6] != 0]
    fitted = np.loadtxt(out, delimiter=",", ndmin=2)
    by_key = {(int(r[0]), int(r[1])): r[2:6] for r in gt}
    errors = []
    for r in fitted:
        g = by_key[(int(r[0]), int(r[1]))]
        d = np.hypot(r[2] + r[4] / 2 - (g[0] + g[2] / 2), r[3] + r[5] / 2 - (g[1] + g[3] / 2))
        errors.append(d / g[3])
    return 100.0 * float(np.mean(errors)), len(fitted) / len(gt)


def plot(plt, path, results, floors):
    """docs/img/barycenter.png: the barycenter error of every run on each
    sequence with a video, the floor drawn across."""
    seqs = list(floors)
    fig, axes = plt.subplots(1, len(seqs), figsize=(7 * len(seqs), 4.5), sharey=True)
    for ax, seq in zip(np.atleast_1d(axes), seqs):
        rows = [r for r in results if r["sequence"] == seq]
        x = np.arange(len(rows))
        colours = ["tab:orange" if r["tracker"].startswith("ctrack") else "tab:grey"
                   for r in rows]
        bars = ax.bar(x, [r["barycenter_error"] for r in rows], color=colours)
        ax.bar_label(bars, labels=["%.1f" % r["barycenter_error"] for r in rows], fontsize=7)
        ax.axhline(floors[seq][0], color="black", linestyle="--", linewidth=1)
        ax.text(len(rows) - 0.5, floors[seq][0], " floor %.1f%%" % floors[seq][0], fontsize=8,
                va="bottom", ha="right")
        ax.set_xticks(x, ["%s\n(%s)" % (r["tracker"].split(" (")[0], r["input"]) for r in rows],
                      fontsize=6, rotation=30, ha="right", rotation_mode="anchor")
        ax.set_title(seq)
    np.atleast_1d(axes)[0].set_ylabel("barycenter error (% of the person's height)")
    fig.suptitle("Barycenter error: box centre to the ground truth's, over its height "
                 "(lower is better)")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
