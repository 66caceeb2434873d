#!/usr/bin/env python3
"""Cuts small real test clips from PETS09-S2L1 for the unit tests, chosen
from the ground truth by rule (never by hand), into tests/data/pets09-crops/.

    .venv-eval/bin/python tests/data/make-test-crops.py
        (the eval venv, scripts/venv.sh eval, has the harness; needs
        scripts/fetch-pets09.sh's cached frames)

Mean shift clips ("walk-*"): one person with no other ground-truth box near,
at least 70 pixels tall and 40 pixels inside the image, in frame f and f+2;
the first such person in each 100-frame stretch. Each clip is a two-frame Y4M
of the person's box grown by 40 pixels (even-aligned), and crops.csv gives
the box in both frames in clip coordinates.

Appearance clips ("cross-*"): two people whose boxes overlap (IoU > 0.2) in
frame f, and are apart (no overlap) and at least 60 pixels tall in frames
f - 6 and f + 6, inside the image; the first such pair in each 100-frame
stretch. The clip holds frames f - 6 and f + 6 of both boxes' union grown by
20 pixels; crossings.csv gives both people's boxes in both frames.
"""
import os
import subprocess

import numpy as np

from cteval.data import TOP
from cteval.y4m import i420_planes, open_y4m

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


def iou(a, b):
    x0, y0 = max(a[0], b[0]), max(a[1], b[1])
    x1, y1 = min(a[0] + a[2], b[0] + b[2]), min(a[1] + a[3], b[1] + b[3])
    inter = max(0, x1 - x0) * max(0, y1 - y0)
    return inter / (a[2] * a[3] + b[2] * b[3] - inter)


def box_of(gt, f, pid):
    r = gt[(gt[:, 0] == f) & (gt[:, 1] == pid)]
    return r[0, 2:6] if len(r) == 1 else None


def crossings(gt, frames, W, H):
    """The crossing clips; returns their crossings.csv lines."""
    lines = ["# name,frame,a_before(l,t,w,h),b_before(l,t,w,h),a_after(l,t,w,h),"
             "b_after(l,t,w,h) (clip coordinates; the clip's frames are PETS09-S2L1's "
             "frame - 6 and frame + 6, frame 1-based)"]
    gap = 6
    for start in range(1 + gap, 795 - gap, 100):
        found = False
        for f in range(start, min(start + 100, 795 - gap)):
            ids = boxes_at(gt, f)[:, 1]
            for ai, a in enumerate(ids):
                for b in ids[ai + 1:]:
                    now = (box_of(gt, f, a), box_of(gt, f, b))
                    if now[0] is None or now[1] is None or iou(*now) <= 0.2:
                        continue
                    bx = [box_of(gt, g, p) for g in (f - gap, f + gap) for p in (a, b)]
                    if any(x is None or x[3] < 60 or x[0] < 0 or x[1] < 0 or
                           x[0] + x[2] > W or x[1] + x[3] > H for x in bx):
                        continue
                    if iou(bx[0], bx[1]) > 0 or iou(bx[2], bx[3]) > 0:
                        continue
                    x0 = max(0, int(min(x[0] for x in bx) - 20)) // 2 * 2
                    y0 = max(0, int(min(x[1] for x in bx) - 20)) // 2 * 2
                    x1 = min(W, (int(max(x[0] + x[2] for x in bx) + 20) + 1) // 2 * 2)
                    y1 = min(H, (int(max(x[1] + x[3] for x in bx) + 20) + 1) // 2 * 2)
                    name = "cross-%03d-%d-%d" % (f, a, b)
                    write_clip(os.path.join(OUT, name + ".y4m"),
                               [frames[f - gap - 1], frames[f + gap - 1]], x0, y0, x1, y1, W, H)
                    cells = []
                    for x in bx:
                        cells += [x[0] - x0, x[1] - y0, x[2], x[3]]
                    lines.append(name + ",%d," % f + ",".join("%.2f" % v for v in cells))
                    found = True
                    break
                if found:
                    break
            if found:
                break
    return lines


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
    pets = subprocess.run([os.path.join(TOP, "scripts", "fetch-pets09.sh")], check=True,
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
    cross = crossings(gt, frames, W, H)
    with open(os.path.join(OUT, "crossings.csv"), "w") as fo:
        fo.write("\n".join(cross) + "\n")
    print("wrote %d walking and %d crossing clips to %s" % (len(lines) - 1, len(cross) - 1, OUT))


if __name__ == "__main__":
    main()
