#!/usr/bin/env python3
"""The paper's "feature recognition accuracy", under the label rule of
docs/algorithm.md ("What the paper measures"), and the thresholds of the
contour template's regions.

    recognition.py BUILD_DIR [--write] [--report]

1. Runs ct-track from the pixels alone on PETS09-S2L1 and TUD-Campus and
   collects every blob the background model gave (--candidates), with eq.
   (1)'s distance per region.
2. Labels the blobs against the ground truth, never by hand: positive when a
   blob matches one person (IoU >= 0.5, or it lies inside one person's box,
   80% of its area, and covers at least 40% of their height); negative when
   it overlaps no one (IoU < 0.1 with every box, and no box holds a tenth of
   its area: a small blob between a person's legs has a tiny IoU with their
   box but is on them); the others (parts of people, groups) are left out
   and counted apart. The people are the ground-truth rows the scoring
   keeps (7th column not 0). A negative is uncertain, left out and counted
   apart too, when it touches the image's edge (within 2 pixels), when a
   public detection of its frame covers it (IoU >= 0.4), when it lies on
   a row the scoring ignores (7th column 0), or when its centre lies in a
   region the sequence's gt-omissions.txt lists (a person seen on the
   frames whom gt.txt lacks; tests/data/README.md).
3. Reports the balanced accuracy of the library's region vote, as built (a
   blob is a pedestrian when more than half the voting regions say yes), on
   frames 1-400, 401-795 and on TUD-Campus, beside a size-and-aspect-ratio
   filter whose bounds are chosen on frames 1-400, and the candidates'
   recall and precision; where the negatives the vote accepts lie; and the
   same figures under a stricter rule that counts every negative.
4. Chooses each region's threshold again on PETS09-S2L1 frames 1-400, blob
   by blob, for comparison: the one that best separates positives from
   negatives by that region's own vote (balanced accuracy); then the
   largest part of its convex hull a pedestrian's blob may fill. The
   shipped thresholds (lib/template/classifier_params.inc) are chosen by tracking
   instead (eval/vote.py): chosen blob by blob, they rejected more small
   people than they spared (docs/notes/pixels.md).

With --write it rewrites tests/data/blobs/labelled.bin: the masks of
held-out blobs (every negative of PETS09-S2L1 frames 401-795 and of
TUD-Campus, and as many positives drawn at random with a fixed seed) for the
contour template's unit test, taken by eval/dump-blobs from the same run.
With --report it rewrites docs/notes/recognition.md.
"""
import argparse
import datetime
import os
import subprocess
import sys

import numpy as np

from cteval.data import DATA, TOP, classifier_params, ct_track, seqinfo, video
REGIONS = ["head", "neck", "shoulders", "chest", "back", "abdomen", "buttocks",
           "upper limbs", "lower limbs"]


def iou(a, b):
    """IoU of box a against boxes b (N, 4), left, top, width, height."""
    x0 = np.maximum(a[0], b[:, 0])
    y0 = np.maximum(a[1], b[:, 1])
    x1 = np.minimum(a[0] + a[2], b[:, 0] + b[:, 2])
    y1 = np.minimum(a[1] + a[3], b[:, 1] + b[:, 3])
    inter = np.clip(x1 - x0, 0, None) * np.clip(y1 - y0, 0, None)
    return inter / (a[2] * a[3] + b[:, 2] * b[:, 3] - inter), inter


def candidates(build, seq):
    fps = "%g" % seqinfo(seq)["fps"]
    path = os.path.join(build, "recognition-%s.txt" % seq)
    subprocess.run([ct_track(build), "-q", "-r", fps, "-o", os.devnull,
                    "--candidates", path, video(seq)], check=True)
    return np.loadtxt(path, delimiter=",", comments="#", ndmin=2)


def blob_masks(build, seq, cands):
    """The masks of the candidates (eval/dump-blobs runs the same tracker
    and must find the same blobs): (frame, x0, y0, w, h, mask) in working
    pixels, one per candidate row, and the working scale of each."""
    path = os.path.join(build, "recognition-%s.blobs" % seq)
    subprocess.run([os.path.join(build, "eval", "dump-blobs"), video(seq), path], check=True)
    data = open(path, "rb").read()
    out, scales, i = [], [], 0
    while i < len(data):
        f, x, y, w, h, s = (int(v) for v in np.frombuffer(data, "<i4", 6, i))
        i += 24
        out.append((f, x, y, w, h, np.frombuffer(data, np.uint8, w * h, i).reshape(h, w)))
        scales.append(s)
        i += w * h
    boxes = np.array([[b[0], s * b[1], s * b[2], s * b[3], s * b[4]]
                      for b, s in zip(out, scales)])
    if boxes.shape != (len(cands), 5) or not (boxes == cands[:, :5]).all():
        sys.exit("recognition: dump-blobs and ct-track found different blobs on %s" % seq)
    return out


# What made the file, in its first lines (each starts with '#', which no
# record's first byte is).
BLOBS_HEADER = (
    "# tests/data/blobs/labelled.bin, written by `eval/recognition.py BUILD --write`\n"
    "# from the pixels-only blobs (eval/dump-blobs) of PETS09-S2L1 frames 401-795\n"
    "# (scripts/fetch-pets09.sh) and TUD-Campus (tests/data/mot15/TUD-Campus/video.mp4),\n"
    "# labelled against their gt/gt.txt. After these lines, records: int32 label,\n"
    "# sequence, frame, width, height (little-endian), then the mask, 1 bit a pixel.\n")


def write_test_blobs(build, sets):
    """tests/data/blobs/labelled.bin: BLOBS_HEADER, then records of little-endian int32 label (1
    person, 0 not), sequence (0 PETS09-S2L1, 1 TUD-Campus), frame, width,
    height, then the mask, one bit a pixel, rows in order, most significant
    bit first (numpy.packbits of the flattened mask)."""
    rng = np.random.default_rng(2026)
    out = bytearray()
    counts = []
    for k, (seq, first) in enumerate((("PETS09-S2L1", 401), ("TUD-Campus", 1))):
        c, lab = sets[seq]
        masks = blob_masks(build, seq, c)
        held = c[:, 0] >= first
        neg = np.flatnonzero(held & (lab == 0))
        pos = np.flatnonzero(held & (lab == 1))
        pos = np.sort(rng.choice(pos, min(len(pos), len(neg)), replace=False))
        counts.append((seq, len(pos), len(neg)))
        for i in np.concatenate([pos, neg]):
            f, _, _, w, h, m = masks[i]
            out += np.array([int(lab[i]), k, f, w, h], "<i4").tobytes()
            out += np.packbits((m.ravel() != 0).astype(np.uint8)).tobytes()
    d = os.path.join(TOP, "tests", "data", "blobs")
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, "labelled.bin"), "wb") as f:
        f.write(BLOBS_HEADER.encode())
        f.write(bytes(out))
    for seq, p, n in counts:
        print("test blobs: %s %d positives, %d negatives" % (seq, p, n))


UNCERTAIN = -2  # a negative the rule leaves out and counts apart


def label(cands, seq):
    """The label of every candidate row (docs/algorithm.md's rule): +1
    positive, 0 negative, -1 left out (a part of a
    person, a group), UNCERTAIN a negative left out of the accuracy and
    counted apart. Returns the labels and, for the uncertain ones, why:
    (at the image's edge, under a public detection, on an ignored person,
    on a person the ground truth lacks), four boolean arrays (a blob may
    have several reasons)."""
    gt = np.loadtxt(os.path.join(DATA, seq, "gt", "gt.txt"), delimiter=",")
    labels = np.full(len(cands), -1)
    ignored = np.zeros(len(cands), bool)
    for i, row in enumerate(cands):
        rows = gt[gt[:, 0] == row[0]]
        people, skip = rows[rows[:, 6] != 0][:, 2:6], rows[rows[:, 6] == 0][:, 2:6]
        box = row[1:5]
        if len(skip):  # on a person MOTChallenge ignores (flag 0)
            o, inter = iou(box, skip)
            ignored[i] = o.max() >= 0.1 or (inter / (box[2] * box[3])).max() >= 0.1
        if len(people) == 0:
            labels[i] = 0
            continue
        o, inter = iou(box, people)
        held = inter / (box[2] * box[3])  # the part of the blob each box holds
        if o.max() >= 0.5:
            labels[i] = 1
        elif o.max() < 0.1 and held.max() < 0.1:
            labels[i] = 0
        else:
            inside = held >= 0.8
            tall = box[3] >= 0.4 * people[:, 3]
            labels[i] = 1 if np.sum(inside & tall) == 1 else -1
    neg = labels == 0
    why = (neg & at_border(cands, seq), neg & under_detection(cands, seq), neg & ignored,
           neg & in_omissions(cands, seq))
    labels[why[0] | why[1] | why[2] | why[3]] = UNCERTAIN
    return labels, why


def balanced(pred, lab):
    pos, neg = lab == 1, lab == 0
    tpr = (pred & pos).sum() / max(1, pos.sum())
    tnr = (~pred & neg).sum() / max(1, neg.sum())
    return 0.5 * (tpr + tnr), tpr, tnr


def votes(dist, th):
    """The region vote with thresholds th: pedestrian when yes > half the
    voters, at least 5 vote, and the head, the neck or the shoulders among
    them (the library's veto of a blob with no upper body)."""
    voting = dist >= 0
    yes = (voting & (dist <= th)).sum(axis=1)
    voters = voting.sum(axis=1)
    return (voters >= 5) & (2 * yes > voters) & voting[:, :3].any(axis=1)


def choose_max_fill(dist, fill, th, lab):
    """The largest fill of its convex hull a pedestrian's blob may have: the
    best balanced accuracy of the vote with thresholds th, the smallest of
    equals."""
    v = votes(dist, th)
    k = lab >= 0
    best, best_f = -1, 1.0
    for f in FILL_BOUNDS:
        b = balanced((v & (fill <= f))[k], lab[k])[0]
        if b > best + 1e-12:
            best, best_f = b, f
    return best_f


FILL_BOUNDS = np.round(np.arange(0.75, 1.0001, 0.025), 3)


def choose_thresholds(dist, lab):
    th = np.zeros(dist.shape[1])
    for r in range(dist.shape[1]):
        d = dist[:, r]
        ok = (d >= 0) & (lab >= 0)
        best, best_t = -1, 0.15
        for t in np.linspace(0.01, 0.4, 79):
            b = balanced(d[ok] <= t, lab[ok])[0]
            if b > best:
                best, best_t = b, t
        th[r] = best_t
    return th


def size_filter(box, lo_a, hi_a, lo_h):
    aspect = box[:, 3] / np.maximum(box[:, 2], 1)
    return (aspect >= lo_a) & (aspect <= hi_a) & (box[:, 3] >= lo_h)


def choose_size_filter(box, lab):
    best = (-1, None)
    for lo_a in np.arange(1.0, 3.01, 0.1):
        for hi_a in np.arange(2.0, 6.01, 0.25):
            for lo_h in (0, 20, 30, 40, 50, 60, 80):
                b = balanced(size_filter(box, lo_a, hi_a, lo_h), lab)[0]
                if b > best[0]:
                    best = (b, (lo_a, hi_a, lo_h))
    return best[1]


def recall_precision(cands, pred, seq, first, last):
    """Candidates the vote keeps against the ground truth (IoU >= 0.5) in
    frames first..last: recall of the boxes the scoring considers, precision
    against every box."""
    gt = np.loadtxt(os.path.join(DATA, seq, "gt", "gt.txt"), delimiter=",")
    gt = gt[(gt[:, 0] >= first) & (gt[:, 0] <= last)]
    found, kept_ok = 0, 0
    kept = cands[pred]
    for f in np.unique(gt[:, 0]):
        rows = gt[gt[:, 0] == f]
        boxes = rows[:, 2:6]
        c = kept[kept[:, 0] == f][:, 1:5]
        for b in boxes[rows[:, 6] != 0]:
            if len(c) and iou(b, c)[0].max() >= 0.5:
                found += 1
        for b in c:
            if iou(b, boxes)[0].max() >= 0.5:
                kept_ok += 1
    return 100.0 * found / (gt[:, 6] != 0).sum(), 100.0 * kept_ok / max(1, len(kept))


def picture_of_false_positives(cands, lab, accepted, seq, path, first=401, n=18):
    """A contact sheet of the blobs on no one that the vote accepts (frames
    from `first` on):
    the frame around each, the blob in red, the ground-truth boxes in green."""
    import cv2  # the eval venv's; only --report needs it
    from cteval.y4m import open_y4m
    w, h, _, frames = open_y4m(video(seq))
    gt = np.loadtxt(os.path.join(DATA, seq, "gt", "gt.txt"), delimiter=",")
    idx = np.flatnonzero(accepted & (lab == 0) & (cands[:, 0] >= first))
    idx = evenly(idx, n)
    tiles = []
    for i in idx:
        f, x, y, bw, bh = (int(v) for v in cands[i, :5])
        img = cv2.cvtColor(np.ascontiguousarray(frames[f - 1]).reshape(h * 3 // 2, w),
                           cv2.COLOR_YUV2BGR_I420)
        for g in gt[gt[:, 0] == f]:
            cv2.rectangle(img, (int(g[2]), int(g[3])), (int(g[2] + g[4]), int(g[3] + g[5])),
                          (0, 255, 0), 1)
        cv2.rectangle(img, (x, y), (x + bw, y + bh), (0, 0, 255), 2)
        cx, cy, m = x + bw // 2, y + bh // 2, 100
        crop = cv2.copyMakeBorder(img, m, m, m, m, cv2.BORDER_CONSTANT)[cy:cy + 2 * m,
                                                                         cx:cx + 2 * m]
        crop = cv2.resize(crop, (160, 160), interpolation=cv2.INTER_AREA)
        cv2.putText(crop, "frame %d" % f, (4, 14), cv2.FONT_HERSHEY_SIMPLEX, 0.45,
                    (0, 255, 255), 1)
        tiles.append(crop)
    return write_sheet(tiles, 6, path, [cv2.IMWRITE_JPEG_QUALITY, 85])


def evenly(idx, n):
    """At most n of the indices idx, evenly spread."""
    return idx[np.linspace(0, len(idx) - 1, min(n, len(idx))).astype(int)] if len(idx) else idx


def write_sheet(tiles, per_row, path, params=()):
    """The tiles (images of one size) in rows of per_row, written to path;
    False when there are none."""
    import cv2
    if not tiles:
        return False
    tiles = tiles + [np.zeros_like(tiles[0])] * (-len(tiles) % per_row)
    rows = [np.hstack(tiles[k:k + per_row]) for k in range(0, len(tiles), per_row)]
    cv2.imwrite(path, np.vstack(rows), list(params))
    return True


def picture_of_shape_rejections(build, sets, rejected, column, path, n=24):
    """A sheet of the blobs that a shape test (rejected[seq]) turns down
    although their regions vote for them (PETS09-S2L1 frames 401-795, then
    TUD-Campus): each mask in white with its convex hull, framed in green on
    a person, red on no one, grey when left out, with the value of the
    candidates' column that the test reads (the fill or the top's width)."""
    import cv2  # the eval venv's; only --report needs it
    tiles = []
    for seq, first in (("PETS09-S2L1", 401), ("TUD-Campus", 1)):
        c, lab = sets[seq]
        idx = evenly(np.flatnonzero(rejected[seq] & (c[:, 0] >= first)), n // 2)
        if not len(idx):
            continue
        masks = blob_masks(build, seq, c)
        for i in idx:
            m = masks[i][5]
            scale = min(112.0 / m.shape[0], 72.0 / m.shape[1])
            size = (max(1, int(m.shape[1] * scale)), max(1, int(m.shape[0] * scale)))
            big = cv2.resize((m != 0).astype(np.uint8) * 255, size,
                             interpolation=cv2.INTER_NEAREST)
            tile = np.zeros((128, 80, 3), np.uint8)
            y, x = (128 - size[1]) // 2, (80 - size[0]) // 2
            tile[y:y + size[1], x:x + size[0]] = big[:, :, None]
            pts = cv2.findNonZero(tile[:, :, 0])
            cv2.polylines(tile, [cv2.convexHull(pts)], True, (0, 160, 255), 1)
            colour = {1: (0, 200, 0), 0: (0, 0, 255)}.get(int(lab[i]), (128, 128, 128))
            cv2.rectangle(tile, (0, 0), (79, 127), colour, 2)
            cv2.putText(tile, "%.2f" % c[i, column], (4, 124), cv2.FONT_HERSHEY_SIMPLEX, 0.4,
                        (0, 255, 255), 1)
            tiles.append(tile)
    return write_sheet(tiles, 12, path)


def shipped_params():
    """The classifier's parameters the library is built with
    (lib/template/classifier_params.inc): the regions' thresholds, the largest fill
    of the convex hull and the widest top against the body (all chosen by
    tracking, eval/vote.py)."""
    values = classifier_params()
    return np.array(values[:len(REGIONS)]), values[-2], values[-1]


def at_border(c, seq):
    """Candidates touching the image's edge (within 2 pixels)."""
    info = seqinfo(seq)
    w, h = info["width"], info["height"]
    return ((c[:, 1] <= 2) | (c[:, 2] <= 2) | (c[:, 1] + c[:, 3] >= w - 2) |
            (c[:, 2] + c[:, 4] >= h - 2))


def in_omissions(c, seq):
    """Candidates whose centre lies in a region of the sequence's
    gt-omissions.txt (first frame, last frame, centre x, centre y, radius
    a line): a person seen on the frames whom gt.txt lacks."""
    path = os.path.join(DATA, seq, "gt-omissions.txt")
    out = np.zeros(len(c), bool)
    if not os.path.exists(path):
        return out
    cx, cy = c[:, 1] + c[:, 3] / 2, c[:, 2] + c[:, 4] / 2
    for first, last, x, y, r in np.loadtxt(path, delimiter=",", comments="#", ndmin=2):
        out |= (c[:, 0] >= first) & (c[:, 0] <= last) & (np.hypot(cx - x, cy - y) <= r)
    return out


def under_detection(c, seq, min_iou=0.4):
    """Candidates that a public detection of their frame covers (IoU >=
    min_iou): as negatives, mostly people the ground truth lacks."""
    det = np.loadtxt(os.path.join(DATA, seq, "det", "det.txt"), delimiter=",", ndmin=2)
    out = np.zeros(len(c), bool)
    for i, row in enumerate(c):
        boxes = det[det[:, 0] == row[0]][:, 2:6]
        out[i] = len(boxes) > 0 and iou(row[1:5], boxes)[0].max() >= min_iou
    return out


def accepted_negatives(c, l, v):
    """Where the negatives the vote accepts lie: None when it accepts none,
    else a dict of their count, the frames they span, their median centre,
    and the indices (into c) of those within 60 pixels of it (one place:
    usually one person the ground truth lacks)."""
    idx = np.flatnonzero(v & (l == 0))
    if len(idx) == 0:
        return None
    cx = c[idx, 1] + c[idx, 3] / 2
    cy = c[idx, 2] + c[idx, 4] / 2
    mx, my = np.median(cx), np.median(cy)
    return {"count": len(idx), "first": int(c[idx, 0].min()), "last": int(c[idx, 0].max()),
            "centre": (mx, my), "near": idx[np.hypot(cx - mx, cy - my) <= 60]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--write", action="store_true",
                    help="rewrite tests/data/blobs/labelled.bin")
    ap.add_argument("--report", action="store_true", help="rewrite docs/notes/recognition.md")
    a = ap.parse_args()
    sets, reasons = {}, {}
    for seq in ("PETS09-S2L1", "TUD-Campus"):
        c = candidates(a.build, seq)
        lab, why = label(c, seq)
        sets[seq] = (c, lab)
        reasons[seq] = why
    pc, pl = sets["PETS09-S2L1"]
    train = pc[:, 0] <= 400
    th = choose_thresholds(pc[train][:, 8:17], pl[train])
    max_fill = choose_max_fill(pc[train][:, 8:17], pc[train][:, 17], th, pl[train])
    shipped, shipped_fill, max_top = shipped_params()
    size = choose_size_filter(pc[train][:, 1:5], pl[train])
    rows = []
    parts = [("PETS09-S2L1 frames 1-400 (\"re-chosen\" on these)", train, "PETS09-S2L1",
              (1, 400)),
             ("PETS09-S2L1 frames 401-795", ~train, "PETS09-S2L1",
              (401, seqinfo("PETS09-S2L1")["frames"])),
             ("TUD-Campus", np.ones(len(sets["TUD-Campus"][0]), bool), "TUD-Campus",
              (1, seqinfo("TUD-Campus")["frames"]))]
    alone = []  # each part's vote of the regions alone, without the shape tests
    uncertain, older, where = [], [], []
    for name, part, seq, frames in parts:
        c, l = sets[seq][0][part], sets[seq][1][part]
        why = [w[part] for w in reasons[seq]]
        keep = l >= 0
        v = c[:, 5] > 0.5  # the library's own vote: more than half the voters say yes
        s = size_filter(c[:, 1:5], *size)
        alone.append(votes(c[:, 8:17], shipped))
        no_top = alone[-1] & (c[:, 17] <= shipped_fill)  # the vote without the top's test
        rows.append((name, (l == 1).sum(), (l == 0).sum(), (l == UNCERTAIN).sum(),
                     (l == -1).sum(), balanced(v[keep], l[keep]), balanced(s[keep], l[keep]),
                     recall_precision(c, v, seq, *frames),
                     balanced((votes(c[:, 8:17], th) & (c[:, 17] <= max_fill) &
                               (c[:, 18] <= max_top))[keep], l[keep]),
                     balanced(alone[-1][keep], l[keep]), balanced(no_top[keep], l[keep])))
        uncertain.append((name, *(int(w.sum()) for w in why)))
        # The stricter rule: every negative counts.
        l_old = np.where(l == UNCERTAIN, 0, l)
        k_old = l_old >= 0
        older.append((name, balanced(v[k_old], l_old[k_old]), balanced(s[k_old], l_old[k_old])))
        acc = accepted_negatives(c, l, v)
        if acc:
            # The vote's balanced accuracy without the negatives at that one place.
            l_wo = l.copy()
            l_wo[acc["near"]] = UNCERTAIN
            k_wo = l_wo >= 0
            acc["without"] = balanced(v[k_wo], l_wo[k_wo])
        where.append((name, acc))
    print("thresholds in use:", " ".join("%s %.3f" % (n, t) for n, t in zip(REGIONS, shipped)),
          "fill %.3f" % shipped_fill)
    print("thresholds chosen now:", " ".join("%s %.3f" % (n, t) for n, t in zip(REGIONS, th)),
          "fill %.3f" % max_fill)
    print("size filter: aspect %.1f-%.2f, height >= %d" % size)
    for r, u in zip(rows, uncertain):
        print("%-38s pos %5d neg %5d uncertain %4d (edge %d, detection %d, ignored %d, "
              "omitted %d) out %5d  "
              "vote %.1f%% (TPR %.1f TNR %.1f)  size %.1f%%  recall %.1f precision %.1f  "
              "re-chosen %.1f%%  regions alone %.1f%%  no top test %.1f%%"
              % (r[0][:38], r[1], r[2], r[3], u[1], u[2], u[3], u[4], r[4], 100 * r[5][0],
                 100 * r[5][1], 100 * r[5][2], 100 * r[6][0], r[7][0], r[7][1], 100 * r[8][0],
                 100 * r[9][0], 100 * r[10][0]))
    for name, acc in where:
        if acc:
            print("%-38s the vote accepts %d negatives, frames %d-%d, %d of them within 60 px "
                  "of (%.0f, %.0f); without those: %.1f%%"
                  % (name[:38], acc["count"], acc["first"], acc["last"], len(acc["near"]),
                     *acc["centre"], 100 * acc["without"][0]))
    if a.write:
        write_test_blobs(a.build, sets)
    if not a.report:
        return
    picture = picture_of_false_positives(pc, pl, pc[:, 5] > 0.5, "PETS09-S2L1",
                                         os.path.join(TOP, "docs", "img",
                                                      "recognition-false-positives.jpg"))
    regions_vote = {seq: votes(sets[seq][0][:, 8:17], shipped) for seq in sets}
    fill_picture = picture_of_shape_rejections(
        a.build, sets, {seq: regions_vote[seq] & (sets[seq][0][:, 17] > shipped_fill)
                        for seq in sets}, 17,
        os.path.join(TOP, "docs", "img", "recognition-fill.png"))
    top_picture = picture_of_shape_rejections(
        a.build, sets, {seq: regions_vote[seq] & (sets[seq][0][:, 17] <= shipped_fill) &
                        (sets[seq][0][:, 18] > max_top) for seq in sets}, 18,
        os.path.join(TOP, "docs", "img", "recognition-top.png"))
    with open(os.path.join(TOP, "docs", "notes", "recognition.md"), "w") as f:
        f.write(RECOGNITION_HEAD % datetime.date.today().isoformat())
        f.write("| set | positives | negatives | uncertain (edge / detection / ignored / "
                "omitted) | left "
                "out | region vote: balanced accuracy (TPR / TNR) | size and aspect filter | "
                "regions alone, no shape test | region vote without the top's test | "
                "candidates kept: recall / precision |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        for r, u in zip(rows, uncertain):
            f.write("| %s | %d | %d | %d (%d / %d / %d / %d) | %d | %.1f%% (%.1f / %.1f) | %.1f%% "
                    "(%.1f / %.1f) | %.1f%% | %.1f%% (%.1f / %.1f) | %.1f / %.1f |\n"
                    % (r[0], r[1], r[2], r[3], u[1], u[2], u[3], u[4], r[4], 100 * r[5][0],
                       100 * r[5][1], 100 * r[5][2], 100 * r[6][0], 100 * r[6][1],
                       100 * r[6][2], 100 * r[9][0], 100 * r[10][0], 100 * r[10][1],
                       100 * r[10][2], r[7][0], r[7][1]))
        f.write(RECOGNITION_WHERE)
        for name, acc in where:
            if acc:
                b = acc["without"]
                f.write("- %s: %d, in frames %d to %d; %d of them within 60 pixels of (%.0f, "
                        "%.0f). Without those, the vote's balanced accuracy is %.1f%% "
                        "(%.1f / %.1f).\n" % (name, acc["count"], acc["first"], acc["last"],
                                               len(acc["near"]), *acc["centre"], 100 * b[0],
                                               100 * b[1], 100 * b[2]))
            else:
                f.write("- %s: none.\n" % name)
        f.write("\nThe thresholds in use (box heights): %s; a blob that fills more than %.3f "
                "of its convex hull is no pedestrian, nor one whose top is wider than %.2f of "
                "its body. They were chosen by tracking from the pixels alone (`eval/vote.py`, "
                "docs/tuning.md); chosen blob by blob on this run's PETS09-S2L1 frames 1-400 "
                "under this rule they would be %s, and %.3f (the column "
                "\"re-chosen\" of `recognition.py`'s output). The size and aspect filter's "
                "bounds, chosen on frames 1-400 of this run: height over width %.1f to %.2f, "
                "height at least %d pixels.\n"
                % (", ".join("%s %.3f" % (n, t) for n, t in zip(REGIONS, shipped)), shipped_fill,
                   max_top, ", ".join("%.3f" % t for t in th), max_fill, *size))
        f.write("\nThe bound on the fill, against the vote's balanced accuracy with the "
                "thresholds in use (chosen on frames 1-400; 1.000 turns the test off):\n\n")
        f.write("| fill at most | " + " | ".join(r[0] for r in rows) + " |\n")
        f.write("|---|" + "---|" * len(rows) + "\n")
        for bound in FILL_BOUNDS:
            cells = []
            for (_, part, seq, _), regions in zip(parts, alone):
                c, l = sets[seq][0][part], sets[seq][1][part]
                k = l >= 0
                pred = regions & (c[:, 17] <= bound) & (c[:, 18] <= max_top)
                cells.append("%.1f%%" % (100 * balanced(pred[k], l[k])[0]))
            f.write("| %.3f | %s |\n" % (bound, " | ".join(cells)))
        if fill_picture:
            f.write(RECOGNITION_FILL_PICTURE)
        if top_picture:
            f.write(RECOGNITION_TOP_PICTURE)
        f.write(RECOGNITION_OLDER)
        f.write("| set | region vote (TPR / TNR) | size and aspect filter (TPR / TNR) |\n"
                "|---|---|---|\n")
        for name, vb, sb in older:
            f.write("| %s | %.1f%% (%.1f / %.1f) | %.1f%% (%.1f / %.1f) |\n"
                    % (name, 100 * vb[0], 100 * vb[1], 100 * vb[2], 100 * sb[0],
                       100 * sb[1], 100 * sb[2]))
        f.write(RECOGNITION_TAIL)
        if picture:
            f.write(RECOGNITION_PICTURE)


RECOGNITION_HEAD = """# Feature recognition: the contour template's region vote

Made by `eval/recognition.py build --report` on %s, with the thresholds
the library is built with (chosen by tracking, `eval/vote.py`). The blobs are those
the background model finds when ct-track tracks from the pixels alone; each is
labelled against the ground truth by rule (docs/algorithm.md, "What the
paper measures"):

- **positive** when it matches one person (IoU >= 0.5, or it lies inside
  one person's box and covers at least 40%% of their height);
- **negative** when it overlaps no one (IoU < 0.1 with every box, and no box
  holds a tenth of its area: a small blob between a person's legs has a
  tiny IoU with their box, yet it is on them);
- **left out** otherwise (parts of people, groups), counted apart;
- a negative is **uncertain**, left out of the accuracy and counted apart,
  when it touches the image's edge (within 2 pixels: people coming in or
  going out, whom the ground truth lacks while they are partly outside),
  when a public detection of the same frame covers it (IoU >= 0.4 with a
  box of `det/det.txt`: a detector saw a person there), when it lies on
  a ground-truth row whose 7th column is 0 (people the MOTChallenge scoring
  ignores: PETS09-S2L1's far off in the top right corner), or when its
  centre lies in a region of the sequence's `gt-omissions.txt` (a person
  seen on the frames whom `gt.txt` lacks: PETS09-S2L1's man by the parked
  cars, frames 660-795; tests/data/README.md).

The blobs are the online model's: ct-track from frame 1, no priming.

The people are the rows the scoring keeps. Balanced accuracy is the mean of
the true positive and true negative rates. The shipped thresholds were
chosen by tracking both sequences (`eval/vote.py`, docs/tuning.md), so no
frame here is held out from them; the thresholds chosen blob by blob
(below, for comparison) are chosen on PETS09-S2L1 frames 1-400. A
blob is a pedestrian when more than half of the regions that vote say yes,
it fills no more of its convex hull than a walking person does, its top
is narrower than its body (0.7.0: a person has a head;
docs/notes/pixels.md), its head, neck or shoulders vote (0.10.0: a blob
whose box's top quarter is mostly empty rows, a speck above a gap, shows no
upper body; docs/tuning.md, "No upper body"), and no shape a person is not (two walkers side by
side) fits it better than every silhouette (0.9.0) unless its top edge
shows one head (0.10.0: it is then a pedestrian scoring at most 0.75,
which starts no track; docs/tuning.md, "Shapes a person is not"). The column "regions
alone" leaves the shape tests out, the column "without the top's test"
keeps the fill's alone; neither weighs the pairs, which need the blob's
outline (the candidates' file holds its distances to the closest
silhouette only).

"""

RECOGNITION_WHERE = """
Where the negatives the vote accepts lie (all the vote's false positives
that count), per set. Many at one place over consecutive frames are one
thing the vote keeps accepting, most often a person the ground truth lacks
(no row, not even one the scoring ignores, and no public detection): the
contact sheet at the end shows those of frames 401-795.

"""

RECOGNITION_OLDER = """
With every negative counted (none left out as uncertain), for comparison:

"""

RECOGNITION_TAIL = """
Recall and precision: of the ground-truth boxes the scoring considers, those
a kept candidate matches (IoU >= 0.5); of the kept candidates, those that
match a box.

`--write` keeps held-out blobs of its run (every negative of PETS09-S2L1
frames 401-795 and of TUD-Campus, as many positives) in
`tests/data/blobs/labelled.bin`; `tests/check_background.cc` checks the
vote's rates on them.
"""

RECOGNITION_FILL_PICTURE = """
Blobs whose regions vote for them but which fill too much of their convex
hull (orange), so the vote turns them down: up to 12 from PETS09-S2L1 frames
401-795, then up to 12 from TUD-Campus, evenly spread. The frame is green on
a person, red on no one, grey when the blob is left out of the accuracy;
the number is the fill.

![rejected for their fill](../img/recognition-fill.png)
"""

RECOGNITION_TOP_PICTURE = """
Blobs whose regions vote for them, which do not fill too much of their hull,
but whose top (the head's rows) is as wide as their body, so the vote turns
them down (0.7.0): up to 12 from PETS09-S2L1 frames 401-795, then up to 12
from TUD-Campus, framed as above; the number is the top's width over the
body's.

![rejected for their top](../img/recognition-top.png)
"""

RECOGNITION_PICTURE = """
The blobs on no one that the vote accepts in PETS09-S2L1 frames 401-795 (at
most 18, evenly spread; the blob in red, the ground truth's boxes in green).
Look at them before reading the accuracy as the classifier's alone: many are
people the ground truth lacks, near the edges of the image or by the parked
cars.

![false positives](../img/recognition-false-positives.jpg)
"""


if __name__ == "__main__":
    main()
