#!/usr/bin/env python3
"""A detector of another kind for the sequences with frames: OpenCV's HOG
people detector (Dalal and Triggs' histograms of oriented gradients with
its default linear SVM), as OpenCV's sample peopledetect.py runs it.

    hog_detections.py [SEQUENCE ...]

Writes tests/data/mot15/<SEQ>/det/hog.txt and hog-low.txt (frame,-1,left,
top,width,height,score,-1,-1,-1, frames 1-based) for each sequence with
frames (by default both). make eval's "Other detectors" runs ctrack and the peers on them
beside the public detections' variants: those are one detector's boxes
changed, this is another detector, with its own misses, false boxes, box
shapes and scale of scores.

As the sample does: windows every 8 pixels, 32 pixels of padding, a
pyramid step of 1.05, the detector's own threshold (an SVM margin of 0;
hog-low.txt: -0.5, its boxes of low scores too, as docs/API.md asks a
host to give) and grouping; each window shrunk to the person it holds (15% of its
width off each side, 5% of its height off the top and the bottom). The
score is the SVM's margin through a logistic, 1 / (1 + exp(-margin)), as
docs/API.md ("Detector scores") asks of a host whose scores are logits.
The window is 64 x 128 pixels for a person some 96 tall: PETS09-S2L1's
people (60 to 120 pixels) are found in its frames read at twice their
size, TUD-Campus's (150 to 350) at their own.

The frames are the luma of the Y4M files make eval decodes
(cteval.data.video()); OpenCV's HOG is deterministic, so the files are
made once and kept (some 10 minutes for PETS09-S2L1 on one core).
"""
import os
import sys

import cv2
import numpy as np

from cteval.data import DATA, video
from cteval.y4m import i420_planes, open_y4m

UPSCALE = {"PETS09-S2L1": 2.0, "TUD-Campus": 1.0}
# The files, and the SVM margin from which each keeps a window.
THRESHOLDS = {"hog": 0.0, "hog-low": -0.5}


def detect(y4m, upscale, threshold):
    """MOTChallenge detection lines for every frame of the Y4M file."""
    w, h, _, rows = open_y4m(y4m)
    hog = cv2.HOGDescriptor()
    hog.setSVMDetector(cv2.HOGDescriptor_getDefaultPeopleDetector())
    lines = []
    for k in range(len(rows)):
        y, _, _ = i420_planes(rows[k], w, h)
        img = cv2.cvtColor(np.ascontiguousarray(y), cv2.COLOR_GRAY2BGR)
        if upscale != 1.0:
            img = cv2.resize(img, None, fx=upscale, fy=upscale)
        boxes, margins = hog.detectMultiScale(img, hitThreshold=threshold, winStride=(8, 8),
                                              padding=(32, 32), scale=1.05)
        for (x, t, bw, bh), m in zip(boxes, np.ravel(margins) if len(boxes) else []):
            x, t, bw, bh = x / upscale, t / upscale, bw / upscale, bh / upscale
            # The window holds a margin around the person.
            x, t, bw, bh = x + 0.15 * bw, t + 0.05 * bh, 0.7 * bw, 0.9 * bh
            lines.append("%d,-1,%.1f,%.1f,%.1f,%.1f,%.4f,-1,-1,-1"
                         % (k + 1, x, t, bw, bh, 1 / (1 + np.exp(-m))))
        if (k + 1) % 100 == 0:
            print("hog: frame %d of %d" % (k + 1, len(rows)), file=sys.stderr, flush=True)
    return lines


def main():
    cv2.setNumThreads(1)
    for seq in sys.argv[1:] or sorted(UPSCALE):
        for name, threshold in THRESHOLDS.items():
            lines = detect(video(seq), UPSCALE[seq], threshold)
            out = os.path.join(DATA, seq, "det", name + ".txt")
            with open(out + ".part", "w") as f:
                f.write("".join(line + "\n" for line in lines))
            os.replace(out + ".part", out)
            print("hog: %s, %d boxes -> %s" % (seq, len(lines), out), file=sys.stderr)


if __name__ == "__main__":
    main()
