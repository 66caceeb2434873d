#!/usr/bin/env python3
"""Cuts small real test clips from PETS09-S2L1 for the unit tests, chosen
from the ground truth by rule (never by hand), into tests/data/pets09-crops/.

    make-test-crops.py            (needs tools/fetch-pets09.sh's cached frames)

Mean shift clips ("walk-*"): one person with no other ground-truth box near,
at least 70 pixels tall and 40 pixels inside the image, in frame f and f+2;
the first such person in each 100-frame stretch. Each clip is a two-frame Y4M
of the person's box grown by 40 pixels (even-aligned), and crops.csv gives
the box in both frames in clip coordinates.
"""
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.dirname(HERE)
sys.path.insert(0, HERE)
from y4m import open_y4m, i420_planes  # noqa: E402

OUT = os.path.join(TOP, "tests", "data", "pets09-crops")
GT = os.path.join(TOP, "tests", "data", "mot15", "PETS09-S2L1", "gt", "gt.txt")
MARGIN = 40
STEP = 2


def boxes_at(gt, f):
    return gt[gt[:, 0] == f]


def near(a, b, margin):
    """Do boxes a and b (left, top, w, h) come within margin of each other?"""
    return not (a[0] + a[2] + margin < b[0] or b[0] + b[2] + margin < a[0] or
                a[1] + a[3] + margin < b[1] or b[1] + b[3] + margin < a[1])


def isolated(gt, f, pid, W, H):
    rows = boxes_at(gt, f)
    me = rows[rows[:, 1] == pid]
    if len(me) != 1:
        return None
    b = me[0, 2:6]
    if b[3] < 70 or b[0] < MARGIN or b[1] < MARGIN or b[0] + b[2] > W - MARGIN or \
            b[1] + b[3] > H - MARGIN:
        return None
    for o in rows[rows[:, 1] != pid]:
        if near(b, o[2:6], MARGIN):
            return None
    return b


def write_clip(path, frames, x0, y0, x1, y1, W, H):
    w, h = x1 - x0, y1 - y0
    with open(path, "wb") as f:
        f.write(b"YUV4MPEG2 W%d H%d F7:1 Ip A1:1 C420jpeg\n" % (w, h))
        for row in frames:
            y, u, v = i420_planes(np.asarray(row), W, H)
            f.write(b"FRAME\n")
            f.write(np.ascontiguousarray(y[y0:y1, x0:x1]).tobytes())
            f.write(np.ascontiguousarray(u[y0 // 2:y1 // 2, x0 // 2:x1 // 2]).tobytes())
            f.write(np.ascontiguousarray(v[y0 // 2:y1 // 2, x0 // 2:x1 // 2]).tobytes())


def main():
    pets = subprocess.run([os.path.join(HERE, "fetch-pets09.sh")], check=True,
                          capture_output=True, text=True).stdout.strip()
    W, H, _, frames = open_y4m(pets)
    gt = np.loadtxt(GT, delimiter=",")
    os.makedirs(OUT, exist_ok=True)
    lines = ["# name,frame,left0,top0,width0,height0,left1,top1,width1,height1 "
             "(box in the clip's first and second frame; frame is PETS09-S2L1's, 1-based)"]
    for start in range(1, 795 - STEP, 100):
        done = False
        for f in range(start, min(start + 100, 795 - STEP)):
            for pid in boxes_at(gt, f)[:, 1]:
                b0 = isolated(gt, f, pid, W, H)
                b1 = isolated(gt, f + STEP, pid, W, H) if b0 is not None else None
                if b1 is None:
                    continue
                x0 = int(min(b0[0], b1[0]) - MARGIN) // 2 * 2
                y0 = int(min(b0[1], b1[1]) - MARGIN) // 2 * 2
                x1 = (int(max(b0[0] + b0[2], b1[0] + b1[2]) + MARGIN) + 1) // 2 * 2
                y1 = (int(max(b0[1] + b0[3], b1[1] + b1[3]) + MARGIN) + 1) // 2 * 2
                name = "walk-%03d-%d" % (f, pid)
                write_clip(os.path.join(OUT, name + ".y4m"),
                           [frames[f - 1], frames[f + STEP - 1]], x0, y0, x1, y1, W, H)
                lines.append("%s,%d,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f,%.2f" % (
                    name, f, b0[0] - x0, b0[1] - y0, b0[2], b0[3],
                    b1[0] - x0, b1[1] - y0, b1[2], b1[3]))
                done = True
                break
            if done:
                break
    with open(os.path.join(OUT, "crops.csv"), "w") as fo:
        fo.write("\n".join(lines) + "\n")
    print("wrote %d clips to %s" % (len(lines) - 1, OUT))


if __name__ == "__main__":
    main()
