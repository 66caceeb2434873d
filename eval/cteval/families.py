"""Families of camera conditions: many variants of one condition (levels and
random seeds), made by ffmpeg from a sequence's frames, so that a score, or
the choice of a constant, does not rest on one noise pattern, one contrast
or one picture size. make eval reports ctrack's mean over each family;
eval/families.py sweeps a tuning build's constants over one."""
import concurrent.futures
import os
import subprocess

from .data import CONDITIONS, moved_boxes, run_ctrack, seqinfo, subsampled, video
from .score import score

half = CONDITIONS["half size"][1]


def scaled(f, mirrored=False):
    """A box of frames scaled by f (after make eval's mirror image when
    asked)."""
    mirror = CONDITIONS["mirrored"][1]

    def move(b, w, h):
        x, y, bw, bh = mirror(b, w, h) if mirrored else b[:4]
        return (x * f, y * f, bw * f, bh * f)
    return move


half_mirrored = scaled(0.5, mirrored=True)


def shifted(dx, dy):
    """A box of frames whose first dx columns and dy rows were cut off."""
    return lambda b, w, h: (b[0] - dx, b[1] - dy, b[2], b[3])


class Coded:
    """Not a filter but a camera's stream: the frames encoded by x264 (H.264)
    at a constant rate factor, a keyframe every `gop` frames, and decoded
    again. One encoder thread, so that every machine decodes the same
    pixels (x264's output depends on its threads)."""

    def __init__(self, crf, gop):
        self.crf, self.gop = crf, gop

    def __str__(self):
        return "H.264 crf %d, keyframe every %d" % (self.crf, self.gop)

    def encoder(self):
        """ffmpeg's output options for the encoding."""
        return ["-c:v", "libx264", "-threads", "1", "-preset", "veryfast",
                "-crf", str(self.crf), "-g", str(self.gop)]


# Each family: (label, ffmpeg filter or Coded, what it does to a box or
# None) per variant.
FAMILIES = {
    # Temporal sensor noise at three strengths (make eval's condition is
    # 14), two seeds each.
    "noise": [("alls=%d seed %d" % (a, s), "noise=alls=%d:allf=t:all_seed=%d" % (a, s), None)
              for a in (8, 14, 20) for s in (1, 2)],
    # make eval's sensor noise (14) at three seeds: one noise pattern is one
    # draw, which moves TUD-Campus's MOTA by 12 points from seed to seed.
    "sensor noise, 3 seeds": [("alls=14 seed %d" % s, "noise=alls=14:allf=t:all_seed=%d" % s,
                               None) for s in (1, 2, 3)],
    # Lower contrast, darker (make eval's condition is 0.55 / -0.12) or
    # washed out as in haze, where the black level rises; the first is the
    # frames as they are.
    "contrast": [("contrast %g brightness %+g" % (c, b), "eq=contrast=%g:brightness=%g" % (c, b),
                  None)
                 for c, b in ((1, 0), (0.4, -0.15), (0.55, -0.12), (0.7, -0.06), (1, 0.08),
                              (0.55, 0.1), (0.7, 0.08))],
    # Half size (make eval's condition), and with small changes a camera
    # makes anyway: mirrored, a little brighter or darker, less contrast, a
    # little noise.
    "half size": [("half size" + label, "scale=iw/2:ih/2" + vf, move)
                  for label, vf, move in (("", "", half), (", mirrored", ",hflip", half_mirrored),
                                          (", brightness +0.04", ",eq=brightness=0.04", half),
                                          (", brightness -0.04", ",eq=brightness=-0.04", half),
                                          (", contrast 0.9", ",eq=contrast=0.9", half),
                                          (", noise 4", ",noise=alls=4:allf=t", half))],
    # The same camera a few pixels off: the frames cut by 4 pixels in each
    # direction, at eight offsets (the first is the top left corner). The
    # picture is the same; what moves is where each pixel falls in the
    # working scale's blocks, so the spread is the tracker's luck. The cut
    # is made on full-resolution chroma: on 4:2:0 frames ffmpeg's crop
    # rounds an odd offset down to an even one, and the odd offsets would
    # repeat the even ones.
    "shift": [("cut at %d, %d" % (dx, dy), "format=yuv444p,crop=iw-4:ih-4:%d:%d" % (dx, dy),
               shifted(dx, dy))
              for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1), (2, 2), (3, 1), (1, 3), (4, 4))],
    # What a network camera sends: H.264 from x264's default quality (a
    # constant rate factor of 23) down to a low bitrate's (38), with a
    # keyframe every 25 frames (a second at 25 frames/s, as such cameras
    # send them) and every 250 (x264's default): blocks, smoothed texture
    # and colour, and no sensor noise left.
    "compression": [(str(Coded(crf, gop)), Coded(crf, gop), None)
                    for crf in (23, 28, 33, 38) for gop in (25, 250)],
    # A moving person's trail: each frame blended with the ones before it,
    # as a camera's temporal noise filter leaves it in dim light, or a slow
    # shutter smears it. The frame before at a quarter, a third and a half
    # of the picture, and the two before at a seventh and two sevenths (a
    # fading trail). tmix takes the oldest frame's weight first; the first
    # frame is left as it is.
    "ghosting": [(label, "tmix=frames=%d:weights=%s" % (len(w.split()), w), None)
                 for label, w in (("the frame before at 1/4", "1 3"),
                                  ("the frame before at 1/3", "1 2"),
                                  ("the frame before at 1/2", "1 1"),
                                  ("the frames before at 1/7 and 2/7", "1 2 4"))],
}


# Not make eval's: sensor noise at its three strengths with ten seeds each,
# for sweeps of what the noise moves. On TUD-Campus's 71 frames one seed is
# one draw, and make eval's three seeds of alls=14 scored 7.6 MOTA above the
# mean of fifteen (docs/tuning.md, "Mean shift on the background").
NOISE_SEEDS_FAMILY = [("alls=%d seed %d" % (a, s), "noise=alls=%d:allf=t:all_seed=%d" % (a, s),
                       None) for a in (8, 14, 20) for s in range(1, 11)]

# Not make eval's either: the frames scaled from three quarters to three
# times their size (the boxes with them), for the claims of how one clip
# holds as its people's size in pixels changes (README.md, docs/tuning.md,
# "The people's size: its bound"). Three times PETS09-S2L1 is 2304x1728.
SCALE_FAMILY = [("scaled by %g" % f, "scale=trunc(iw*%g/2)*2:trunc(ih*%g/2)*2" % (f, f), scaled(f))
                for f in (0.75, 1.25, 1.5, 2, 2.5, 3)]

# Conditions that no default is chosen on: eval/vote.py reports its choice
# over them beside the shipped one's, as a check of how it transfers.
HELD_OUT_FAMILY = [
    ("three quarters size", "scale=trunc(iw*0.375)*2:trunc(ih*0.375)*2", scaled(0.75)),
    ("0.625 size, mirrored", "hflip,scale=trunc(iw*0.3125)*2:trunc(ih*0.3125)*2",
     scaled(0.625, True)),
    ("gamma 1.5", "eq=gamma=1.5", None),
    ("blurred (sigma 1.2)", "gblur=sigma=1.2", None),
    ("hue +30, saturation 0.4", "hue=h=30:s=0.4", None),
    ("darker by 0.06, noise 10", "eq=brightness=-0.06,noise=alls=10:allf=t:all_seed=7", None),
]

# Not a family of make eval's (it reports these runs one by one, "Camera
# conditions"), but one to sweep over: the frames as they are and in each
# of make eval's camera conditions.
CONDITIONS_FAMILY = [("as it is", "null", None)] + [(name, vf, move)
                                                     for name, (vf, move) in CONDITIONS.items()]


class Every:
    """Not a move of boxes but of frames: every k-th frame kept, from frame
    offset + 1 (the filter of such a variant is every(k, offset))."""

    def __init__(self, k, offset):
        self.k, self.offset = k, offset


def every(k, offset):
    """The ffmpeg filter keeping frames offset + 1, offset + 1 + k, ..."""
    return "trim=start_frame=%d,setpts=PTS-STARTPTS,framestep=%d" % (offset, k)


# A camera that keeps every k-th frame: a half and a third of the frame
# rate (make eval reports these runs one by one, "At lower frame rates"),
# and as a family from each offset, which eval/vote.py chooses over.
RATE_STEPS = (2, 3)
RATE_FAMILY = [("1/%d of the frame rate, from frame %d" % (k, o + 1), every(k, o), Every(k, o))
               for k in RATE_STEPS for o in range(k)]


def run_variant(build, seq, vf, move, out, env=None, detections=False, params=()):
    """ct-track over the sequence's frames through the filter, piped from
    ffmpeg (nothing but the tracks is written), with its detections if
    asked; returns py-motmetrics' scores (cteval.score). A move that is an
    Every keeps the ground truth's and detections' frames that the filter
    keeps."""
    info = seqinfo(seq)
    if isinstance(move, Every):
        os.makedirs(out + ".d", exist_ok=True)
        _, gt, det, info = subsampled(seq, info, None, move.k, move.offset, out + ".d")
    else:
        gt = moved_boxes(seq, "gt", move, out + ".gt")
        det = moved_boxes(seq, "det", move, out + ".det") if detections else None
    pipeline = variant_stream(seq, vf)
    try:
        run_ctrack(build, seq, info, "-", out, pixels=True, params=params,
                   detections=detections, det=det,
                   stdin=pipeline[-1].stdout, env=env)
    finally:
        # A ct-track that failed leaves ffmpeg writing to a closed pipe:
        # its error is the one to report.
        pipeline[-1].stdout.close()
        status = [p.wait() for p in pipeline]
    if any(status):
        raise RuntimeError("ffmpeg failed on %s (%s)" % (seq, vf))
    return score(gt, out)


def variant_stream(seq, vf):
    """The ffmpeg processes that give the sequence's frames through the
    variant's filter, or encoded and decoded again (Coded), as Y4M on the
    last one's stdout; the caller closes it and waits for each."""
    pipeline = []
    if isinstance(vf, Coded):
        pipeline.append(subprocess.Popen(
            ["ffmpeg", "-v", "error", "-i", video(seq), "-pix_fmt", "yuv420p"] + vf.encoder() +
            ["-f", "matroska", "-"], stdout=subprocess.PIPE))
        src = ["-i", "-"]
    else:
        src = ["-i", video(seq), "-vf", vf]
    stdin = pipeline[0].stdout if pipeline else None
    pipeline.append(subprocess.Popen(["ffmpeg", "-v", "error"] + src +
                                     ["-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", "-"],
                                     stdin=stdin, stdout=subprocess.PIPE))
    if stdin:
        stdin.close()  # the decoder holds it now
    return pipeline


def run_all(jobs, tmp, workers=2, progress=None):
    """Runs run_variant() for each job, a dict of its keyword arguments
    (build, seq, vf, move, env, detections, params), `workers` at a time;
    returns the scores in the jobs' order. progress(done, total) is called
    after each."""
    out = [None] * len(jobs)
    with concurrent.futures.ThreadPoolExecutor(workers) as pool:
        futs = {pool.submit(run_variant, out=os.path.join(tmp, "family-%d.txt" % i), **j): i
                for i, j in enumerate(jobs)}
        for done, f in enumerate(concurrent.futures.as_completed(futs), 1):
            out[futs[f]] = f.result()
            if progress:
                progress(done, len(jobs))
    return out
