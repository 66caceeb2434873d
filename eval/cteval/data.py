"""The repository's sequences (tests/data/mot15), their videos decoded to
Y4M and cached, and ct-track runs over them."""
import configparser
import os
import re
import subprocess
import time

import numpy as np

from .y4m import open_y4m

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA = os.path.join(TOP, "tests", "data", "mot15")
SCRIPTS = os.path.join(TOP, "scripts")
CLASSIFIER_PARAMS = os.path.join(TOP, "lib", "template", "classifier_params.inc")
# (MOTA, IDF1) floors of the single runs from the pixels alone, online (every
# output for frame k from frames 1..k, ct-track's default), as
# tests/replay.sh checks them (and reads them from here); eval/vote.py and
# eval/search.py hold their choices to them.
PIXEL_FLOORS = {"PETS09-S2L1": (71.5, 78.0), "PETS09-S2L1 at half size": (68.0, 77.0),
                "TUD-Campus": (32.0, 49.0)}


def classifier_params():
    """The contour template's eleven values in lib/template/classifier_params.inc, in
    order: the nine regions' thresholds (head, neck, shoulders, chest, back,
    abdomen, buttocks, upper limbs, lower limbs), the largest part of its
    convex hull a pedestrian's blob fills, the widest top against the body."""
    with open(CLASSIFIER_PARAMS) as f:
        text = f.read()
    values = [float(v) for v in re.findall(r"([0-9.]+)f", text[text.index("kDefaultParams"):])]
    if len(values) != 11:
        raise SystemExit("%s has %d values, not 11" % (CLASSIFIER_PARAMS, len(values)))
    return values


def seqinfo(seq, data=DATA):
    c = configparser.ConfigParser()
    c.read(os.path.join(data, seq, "seqinfo.ini"))
    s = c["Sequence"]
    return {"frames": int(s["seqLength"]), "fps": float(s["frameRate"]),
            "width": int(s["imWidth"]), "height": int(s["imHeight"])}


def sequences(data=DATA):
    """Every sequence of the data folder (a folder with a seqinfo.ini), by
    name."""
    return sorted(s for s in os.listdir(data)
                  if os.path.exists(os.path.join(data, s, "seqinfo.ini")))


def has_video(seq):
    """Whether the sequence's frames can be had: PETS09-S2L1's from Debian's
    opencv-doc, the others' from a video.mp4 beside their ground truth."""
    return seq == "PETS09-S2L1" or os.path.exists(os.path.join(DATA, seq, "video.mp4"))


def cache_dir():
    """Where decoded videos are kept: $CT_CACHE, as scripts/fetch-pets09.sh."""
    d = os.environ.get("CT_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "ctrack")
    os.makedirs(d, exist_ok=True)
    return d


def video(seq):
    """A cached Y4M of the sequence's frames."""
    if seq == "PETS09-S2L1":
        return subprocess.run([os.path.join(SCRIPTS, "fetch-pets09.sh")], check=True,
                              capture_output=True, text=True).stdout.strip()
    out = os.path.join(cache_dir(), seq.lower() + ".y4m")
    if not os.path.exists(out):
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i",
                        os.path.join(DATA, seq, "video.mp4"), "-f", "yuv4mpegpipe",
                        "-pix_fmt", "yuv420p", out + ".part"], check=True)
        os.replace(out + ".part", out)
    return out


# Camera conditions made from a video by an ffmpeg filter, with what the
# filter does to a box (left, top, width, height) of a width x height image.
CONDITIONS = {
    "half size": ("scale=iw/2:ih/2", lambda b, w, h: (b[0] / 2, b[1] / 2, b[2] / 2, b[3] / 2)),
    # A camera of twice the resolution: TUD-Campus's nearest people over
    # 500 pixels tall, past the people's size's prior of 400.
    "twice the size": ("scale=iw*2:ih*2",
                       lambda b, w, h: (b[0] * 2, b[1] * 2, b[2] * 2, b[3] * 2)),
    "sensor noise": ("noise=alls=14:allf=t", None),
    "darker, lower contrast": ("eq=brightness=-0.12:contrast=0.55", None),
    "mirrored": ("hflip", lambda b, w, h: (w - b[0] - b[2], b[1], b[2], b[3])),
    # An auto-exposure or a cloud: brighter and more contrasted, in steps,
    # for frames 30 to 59 and 300 to 399 (from 0).
    "exposure steps": ("eq=brightness=0.08:contrast=1.2:"
                       "enable='between(n,30,59)+between(n,300,399)'", None),
}


def conditioned(seq, name, tmp):
    """The sequence in a camera condition: its video through the condition's
    ffmpeg filter (cached beside the decoded videos), and its ground truth
    and detections with their boxes moved to match (in tmp). Returns
    (y4m, gt, det, info)."""
    vf, move = CONDITIONS[name]
    info = seqinfo(seq)
    tag = "%s-%s" % (seq.lower(), name.split(",")[0].replace(" ", "-"))
    out = os.path.join(cache_dir(), tag + ".y4m")
    if not os.path.exists(out):
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", video(seq), "-vf", vf,
                        "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", out + ".part"], check=True)
        os.replace(out + ".part", out)
    gt, det = (moved_boxes(seq, kind, move, os.path.join(tmp, "%s-%s.txt" % (tag, kind)))
               for kind in ("gt", "det"))
    w, h, _, _ = open_y4m(out)
    return out, gt, det, dict(info, width=w, height=h)


def moved_boxes(seq, kind, move, path):
    """The sequence's ground truth or detections (kind "gt" or "det") with
    their boxes moved as a filter moves the frames (move(box, width, height),
    written to path), or as they are when move is None."""
    src = os.path.join(DATA, seq, kind, kind + ".txt")
    if move is None:
        return src
    info = seqinfo(seq)
    a = np.loadtxt(src, delimiter=",", ndmin=2)
    for row in a:
        row[2:6] = move(row[2:6], info["width"], info["height"])
    np.savetxt(path, a, delimiter=",", fmt="%.6g")
    return path


def load_dets(seq, path=None):
    d = np.loadtxt(path or os.path.join(DATA, seq, "det", "det.txt"), delimiter=",", ndmin=2)
    return {int(k): d[d[:, 0] == k][:, 2:7] for k in np.unique(d[:, 0])}


def subsampled(seq, info, y4m, k, offset, tmp, data=DATA):
    """The sequence at 1/k of its frame rate: frames offset+1, offset+1+k,
    ... kept and numbered again from 1. Writes a Y4M of the video y4m (none
    when y4m is None) and the ground truth and detections of those frames
    into tmp; returns (y4m or None, gt, det, info)."""
    tag = "%s-%dof%d" % (seq, offset + 1, k)
    out = None
    if y4m is not None:
        w, h, (num, den), frames = open_y4m(y4m)
        out = os.path.join(tmp, tag + ".y4m")
        with open(out, "wb") as f:
            f.write(b"YUV4MPEG2 W%d H%d F%d:%d Ip A1:1 C420jpeg\n" % (w, h, num, den * k))
            for row in frames[offset::k]:
                f.write(b"FRAME\n")
                f.write(row.tobytes())
    paths = []
    for kind in ("gt", "det"):
        a = np.loadtxt(os.path.join(data, seq, kind, kind + ".txt"), delimiter=",", ndmin=2)
        a = a[(a[:, 0] - 1 - offset) % k == 0]
        a[:, 0] = (a[:, 0] - 1 - offset) // k + 1
        paths.append(os.path.join(tmp, "%s-%s.txt" % (tag, kind)))
        np.savetxt(paths[-1], a, delimiter=",", fmt="%.6g")
    sub = dict(info, fps=info["fps"] / k, frames=len(range(offset, info["frames"], k)))
    return out, paths[0], paths[1], sub


def write_rows(path, rows):
    """MOTChallenge lines of (frame, id, left, top, width, height) rows."""
    with open(path, "w") as f:
        for k, tid, x, y, w, h in rows:
            f.write("%d,%d,%.2f,%.2f,%.2f,%.2f,1,-1,-1,-1\n" % (k, tid, x, y, w, h))


def ct_track(build):
    return os.path.join(build, "tools", "ct-track")


def run_ctrack(build, seq, info, y4m, out, pixels, params=(), detections=True, det=None,
               stdin=None, env=None):
    """ct-track over a sequence: its detections (or det), its frames when
    pixels (y4m "-": from stdin, a pipe), with env added to the environment;
    returns the wall time in seconds."""
    cmd = [ct_track(build), "-q", "-o", out]
    if detections:
        cmd += ["-d", det or os.path.join(DATA, seq, "det", "det.txt")]
    for p in params:  # ct_config fields, or ct-track's own options ("--prime=0")
        cmd += [p] if p.startswith("--") else ["-p", p]
    if pixels:
        cmd += ["-r", str(info["fps"]), y4m]
    else:
        cmd += ["-s", "%dx%d" % (info["width"], info["height"]), "-r", str(info["fps"])]
    t0 = time.perf_counter()
    subprocess.run(cmd, check=True, stdin=stdin, env=dict(os.environ, **env) if env else None)
    return time.perf_counter() - t0


def ctrack_version():
    """MAJOR.MINOR.PATCH from include/ctrack/ctrack.h."""
    return subprocess.run([os.path.join(SCRIPTS, "version.sh")], check=True,
                          capture_output=True, text=True).stdout.strip()
