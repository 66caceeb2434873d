#!/usr/bin/env python3
"""Tracks the pedestrians of any video from Python, with ctrack.

    track_video.py VIDEO [--detections det.txt] [--fps RATE] [--prime SECONDS]
                   [-o tracks.txt]

ffmpeg decodes VIDEO (any format it reads) to I420 frames on a pipe
(ctrack.video.Video); each frame goes to ctrack.Tracker.feed() as a numpy
array. Without --detections ctrack finds the people in the pixels itself;
with a MOTChallenge detections file (frame,-1,left,top,width,height,score,...;
frames 1-based) it tracks them with the pixels' help. The tracks are written
as MOTChallenge lines (frame,id,left,top,width,height,confidence,-1,-1,-1),
as ct-track writes them, online: frame k's tracks from frames 1 to k. With
--prime, a look-ahead for recorded files, the tracker first learns the
background from the video's first seconds (Tracker.prime()), as ct-track
--prime does, so that the people there from its first frame are found from
it.
Needs numpy and ffmpeg; run it from a source
checkout after `make` (the ctrack package is in python/, the library in
build/lib/), or with ctrack installed. For many videos at once, see
`python -m ctrack.batch`.
"""
import argparse
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
import ctrack  # noqa: E402
from ctrack.video import Video, frame_time, primed  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("video")
    ap.add_argument("--detections", help="MOTChallenge detections, frames 1-based")
    ap.add_argument("--fps", type=float, help="frame rate (default: the video's)")
    ap.add_argument("--prime", type=float, default=0, metavar="SECONDS",
                    help="a look-ahead: learn the background from the first SECONDS before "
                         "tracking (default 0: online)")
    ap.add_argument("-o", "--output", help="tracks file (default: standard output)")
    a = ap.parse_args()
    dets = None
    if a.detections:
        dets = np.loadtxt(a.detections, delimiter=",", ndmin=2)
    try:
        video = Video(a.video)
    except ValueError as e:
        raise SystemExit("track_video: %s" % e)
    rate = (a.fps, 1) if a.fps else video.rate
    source = ctrack.SOURCE_DETECTIONS if a.detections else ctrack.SOURCE_PIXELS
    out = open(a.output, "w") if a.output else sys.stdout
    with video, ctrack.Tracker(fps=rate[0] / rate[1], source=source) as tracker:
        try:
            # With --prime, from the pixels: the background learnt from the
            # first seconds (Tracker.prime()), which are then fed again.
            frames = primed(tracker, video, rate,
                            a.prime if source == ctrack.SOURCE_PIXELS else 0,
                            note=lambda m: print("track_video: " + m, file=sys.stderr))
            for k, frame in enumerate(frames, start=1):
                d = dets[dets[:, 0] == k][:, 2:7] if dets is not None else None
                tracks = tracker.feed(frame, d, timestamp=frame_time(k, rate), format="i420")
                for line in ctrack.mot_lines(k, tracks):
                    out.write(line + "\n")
        except ValueError as e:
            raise SystemExit("track_video: %s" % e)
        finally:
            if out is not sys.stdout:
                out.close()


if __name__ == "__main__":
    main()
