#!/usr/bin/env python3
"""Tracks the pedestrians of any video from Python, with ctrack.

    track_video.py VIDEO [--detections det.txt] [--fps RATE] [-o tracks.txt]

ffmpeg decodes VIDEO (any format it reads) to I420 frames on a pipe; each
frame goes to ctrack.Tracker.feed() as a numpy array. Without --detections
ctrack finds the people in the pixels itself; with a MOTChallenge detections
file (frame,-1,left,top,width,height,score,...; frames 1-based) it tracks
them with the pixels' help. The tracks are written as MOTChallenge lines
(frame,id,left,top,width,height,confidence,-1,-1,-1), as ct-track writes
them. Needs numpy and ffmpeg; run it from a source checkout after `make`
(the ctrack package is in python/, the library in build/lib/), or with
ctrack installed.
"""
import argparse
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
import ctrack  # noqa: E402


def y4m_frames(path):
    """Yields (width, height, fps, frame) for each frame of the video, the
    frame an (H*3/2) x W uint8 I420 array, decoded by ffmpeg."""
    cmd = ["ffmpeg", "-v", "error", "-i", path, "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p",
           "-"]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE) as p:
        header = p.stdout.readline().split()
        if not header or header[0] != b"YUV4MPEG2":
            raise SystemExit("track_video: ffmpeg could not decode %s" % path)
        fields = {t[:1]: t[1:] for t in header[1:]}
        w, h = int(fields[b"W"]), int(fields[b"H"])
        num, den = (int(v) for v in fields.get(b"F", b"25:1").split(b":"))
        if w % 2 or h % 2:
            raise SystemExit("track_video: %dx%d: this example reads even sizes only "
                             "(scale the video, or feed BGR frames)" % (w, h))
        size = w * h * 3 // 2
        while p.stdout.readline().startswith(b"FRAME"):
            data = p.stdout.read(size)
            if len(data) < size:
                raise SystemExit("track_video: truncated frame from ffmpeg")
            yield w, h, num / den, np.frombuffer(data, np.uint8).reshape(h * 3 // 2, w)
    if p.returncode:
        raise SystemExit("track_video: ffmpeg failed (exit %d)" % p.returncode)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("video")
    ap.add_argument("--detections", help="MOTChallenge detections, frames 1-based")
    ap.add_argument("--fps", type=float, help="frame rate (default: the video's)")
    ap.add_argument("-o", "--output", help="tracks file (default: standard output)")
    a = ap.parse_args()
    dets = None
    if a.detections:
        dets = np.loadtxt(a.detections, delimiter=",", ndmin=2)
    out = open(a.output, "w") if a.output else sys.stdout
    tracker = None
    try:
        for k, (w, h, fps, frame) in enumerate(y4m_frames(a.video), start=1):
            if tracker is None:
                fps = a.fps or fps
                source = ctrack.SOURCE_DETECTIONS if a.detections else ctrack.SOURCE_PIXELS
                tracker = ctrack.Tracker(fps=fps, source=source)
            d = dets[dets[:, 0] == k][:, 2:7] if dets is not None else None
            # The timestamp of frame k, as ct-track computes it.
            tracks = tracker.feed(frame, d, timestamp=round((k - 1) * 1e6 / fps) / 1e6,
                                  format="i420")
            for line in ctrack.mot_lines(k, tracks):
                out.write(line + "\n")
    finally:
        if tracker is not None:
            tracker.close()
        if out is not sys.stdout:
            out.close()


if __name__ == "__main__":
    main()
