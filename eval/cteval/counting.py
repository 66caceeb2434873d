"""Counting people on lines: the lines make eval counts on, the counting
rule applied to any tracker's rows (the ground truth's, a peer's), and the
counting error.

The rule is the library's (docs/API.md, "Counting"): a track's point is the
bottom centre of its box; its starting side of a line is that of its first
box; a crossing counts when the point is past the line by the hysteresis
(in heights of the box) and its path from where it was last on its side
went through the segment, not around its ends. ctrack's own counts come
from the library (ct-track --line --events); the ground truth's, SORT's
and ByteTrack's from their tracks by this rule, every track of theirs
counting from its first row.
"""
import json
import os

import numpy as np

from cteval.data import seqinfo

# The library's default hysteresis (ct_line_default();
# tests/python/test_counting.py checks it is the library's).
HYSTERESIS = 0.1

# Two or three lines across each sequence's walkable area (x1, y1, x2, y2),
# drawn in docs/img/counting-lines.png: where people walk, across the
# direction they walk in, not where ctrack does well.
LINES = {
    "PETS09-S2L1": [("west", (300, 150, 300, 520)), ("centre", (450, 150, 450, 520)),
                    ("east", (600, 120, 600, 480))],
    "TUD-Campus": [("left", (200, 300, 200, 480)), ("right", (420, 300, 420, 480))],
    "Venice-2": [("left", (700, 450, 700, 1080)), ("right", (1300, 450, 1300, 1080))],
}
DIRECTIONS = ("in", "out")


def ct_track_args(seq, events_path, hysteresis=None):
    """ct-track's options that count on seq's lines into events_path."""
    args = ["--line=%g,%g,%g,%g,%s" % (*seg, name) for name, seg in LINES[seq]]
    if hysteresis is not None:
        args.append("--hysteresis=%g" % hysteresis)
    return args + ["--events=" + events_path]


def _signed_distance(a, b, p):
    return ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / np.hypot(
        b[0] - a[0], b[1] - a[1])


def _crossing_fraction(a, b, p, q):
    dp, dq = _signed_distance(a, b, p), _signed_distance(a, b, q)
    s = dp / (dp - dq)
    m = (p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1]))
    dx, dy = b[0] - a[0], b[1] - a[1]
    return ((m[0] - a[0]) * dx + (m[1] - a[1]) * dy) / (dx * dx + dy * dy)


def crossings(rows, seg, hysteresis=HYSTERESIS):
    """The crossings of the segment seg by rows' tracks (frame, id, left,
    top, width, height, ...): a list of (frame, id, "in" or "out")."""
    a, b = seg[:2], seg[2:]
    rows = np.asarray(rows, dtype=float)
    out = []
    if rows.size == 0:
        return out
    for tid in np.unique(rows[:, 1]):
        r = rows[rows[:, 1] == tid]
        r = r[np.argsort(r[:, 0], kind="stable")]
        side, on = 0, None
        for frame, _, left, top, w, h in r[:, :6]:
            p = (left + w / 2, top + h)
            d = _signed_distance(a, b, p)
            s = int(np.sign(d))
            if side == 0 or s == side:
                if s != 0:
                    side, on = s, p
                continue
            if s == 0 or abs(d) < hysteresis * h:
                continue
            if 0 <= _crossing_fraction(a, b, on, p) <= 1:
                out.append((int(frame), int(tid), "in" if s > 0 else "out"))
            side, on = s, p
    return out


def count_rows(seq, rows, hysteresis=HYSTERESIS):
    """{line name: {"in": n, "out": n}} from a tracker's rows."""
    out = {}
    for name, seg in LINES[seq]:
        c = {d: 0 for d in DIRECTIONS}
        for _, _, d in crossings(rows, seg, hysteresis):
            c[d] += 1
        out[name] = c
    return out


def count_events(seq, events_path):
    """{line name: {"in": n, "out": n}} from ct-track's --events file."""
    out = {name: {d: 0 for d in DIRECTIONS} for name, _ in LINES[seq]}
    with open(events_path) as f:
        for line in f:
            e = json.loads(line)
            if "line" in e:
                out[e["line"]][e["direction"]] += 1
    return out


def ground_truth(seq, data):
    """The ground truth's rows (those it scores: confidence 1)."""
    g = np.loadtxt(os.path.join(data, seq, "gt", "gt.txt"), delimiter=",", ndmin=2)
    return g[g[:, 6] != 0]


def error(counted, true):
    """(sum of |counted - true|, sum of true) over the lines and both
    directions of {seq: {line: {direction: n}}} dicts."""
    err = total = 0
    for seq, lines in true.items():
        for name, c in lines.items():
            for d in DIRECTIONS:
                err += abs(counted[seq][name][d] - c[d])
                total += c[d]
    return err, total


def events_path(tracks_path, seq):
    """Where a ctrack run writing tracks_path (.../KEY/data/SEQ.txt) writes
    its counting events."""
    d = os.path.join(os.path.dirname(os.path.dirname(tracks_path)), "events")
    os.makedirs(d, exist_ok=True)
    return os.path.join(d, seq + ".jsonl")


# The runs whose counts make eval reports: make eval's tracker keys.
COUNTED = [("ctrack-det", "ctrack, detections"),
           ("ctrack-detpix", "ctrack, detections + pixels"),
           ("ctrack-pix", "ctrack, pixels, online"),
           ("ctrack-pix-primed", "ctrack, pixels, primed (a look-ahead)"),
           ("sort", "SORT, detections"),
           ("bytetrack", "ByteTrack, detections")]
# The summary rows: a label, and the run counted on each sequence (None: not
# counted there). "detections (+ pixels)" reads the pixels where there is a
# video.
SUMMARY = [
    ("ctrack, detections + pixels where there is a video, else detections",
     lambda seq, video: "ctrack-detpix" if video else "ctrack-det"),
    ("ctrack, detections", lambda seq, video: "ctrack-det"),
    ("ctrack, pixels alone, online", lambda seq, video: "ctrack-pix" if video else None),
    ("ctrack, pixels alone, primed (a look-ahead)",
     lambda seq, video: "ctrack-pix-primed" if video else None),
    ("SORT, detections", lambda seq, video: "sort"),
    ("ByteTrack, detections", lambda seq, video: "bytetrack"),
]


def evaluate(tmp, data, has_video):
    """The true counts and every COUNTED run's, from make eval's outputs in
    tmp (TRACKERS' layout); and the SUMMARY rows' errors."""
    true = {seq: count_rows(seq, ground_truth(seq, data)) for seq in LINES}
    counted = {}
    for key, _ in COUNTED:
        for seq in LINES:
            tracks = os.path.join(tmp, key, "data", seq + ".txt")
            if not os.path.exists(tracks):
                continue
            if key.startswith("ctrack"):
                c = count_events(seq, events_path(tracks, seq))
            else:
                c = count_rows(seq, np.loadtxt(tracks, delimiter=",", ndmin=2))
            counted.setdefault(key, {})[seq] = c
    summary = []
    for label, run_on in SUMMARY:
        runs = {seq: run_on(seq, has_video(seq)) for seq in LINES}
        runs = {s: k for s, k in runs.items() if k and s in counted.get(k, {})}
        err, total = error({s: counted[k][s] for s, k in runs.items()},
                           {s: true[s] for s in runs})
        summary.append({"label": label, "sequences": sorted(runs), "error": err,
                        "true": total, "rate": 100.0 * err / max(1, total)})
    return {"true": true, "counted": counted, "summary": summary}


HEAD = """## Counting

People crossing lines, each way (`ct-track --line`, `ct_tracker_add_line()`):
two or three lines across each sequence's walkable area
(`eval/cteval/counting.py`, drawn below), counted by ctrack as it tracks
(`--events`), and from the ground truth's, SORT's and ByteTrack's tracks by
the same rule (`eval/cteval/counting.py`). The counting error is the sum
over lines and directions of |counted - true| over the sum of the true
counts. Venice-2 has no video: detections only there.

![the counting lines](img/counting-lines.png)

"""


def write_report(f, c):
    """The Counting section of docs/results.md."""
    f.write(HEAD)
    f.write("| counted by | sequences | counting error |\n|---|---|---|\n")
    for r in c["summary"]:
        f.write("| %s | %s | %.1f%% (%d of %d) |\n" % (r["label"], ", ".join(r["sequences"]),
                                                    r["rate"], r["error"], r["true"]))
    keys = [(k, label) for k, label in COUNTED if k in c["counted"]]
    f.write("\nEach line's crossings, in / out:\n\n")
    f.write("| line | true | " + " | ".join(label for _, label in keys) + " |\n")
    f.write("|---|---|" + "---|" * len(keys) + "\n")
    for seq, lines in LINES.items():
        for name, _ in lines:
            t = c["true"][seq][name]
            cells = []
            for k, _ in keys:
                got = c["counted"][k].get(seq, {}).get(name)
                cells.append("%d / %d" % (got["in"], got["out"]) if got else "")
            f.write("| %s, %s | %d / %d | %s |\n" % (seq, name, t["in"], t["out"],
                                                    " | ".join(cells)))
    f.write("\n")


def plot_lines(plt, path, data, frame_of):
    """docs/img/counting-lines.png: each sequence's lines, on its first
    frame (frame_of(seq): a grey image, or None) or else on the ground
    truth's paths, with an arrow to each line's "in" side."""
    fig, axes = plt.subplots(1, len(LINES), figsize=(6 * len(LINES), 4.2))
    for ax, (seq, lines) in zip(axes, LINES.items()):
        img = frame_of(seq)
        info = seqinfo(seq, data)
        w = info["width"]
        if img is not None:
            ax.imshow(img, cmap="gray")
        else:
            g = ground_truth(seq, data)
            for tid in np.unique(g[:, 1]):
                r = g[g[:, 1] == tid]
                r = r[np.argsort(r[:, 0])]
                ax.plot(r[:, 2] + r[:, 4] / 2, r[:, 3] + r[:, 5], lw=0.7, color="grey")
            ax.set_xlim(0, w)
            ax.set_ylim(info["height"], 0)
            ax.set_aspect("equal")
        for name, (x1, y1, x2, y2) in lines:
            ax.plot([x1, x2], [y1, y2], color="orange", lw=2.5)
            mx, my = (x1 + x2) / 2, (y1 + y2) / 2
            n = np.hypot(x2 - x1, y2 - y1)
            nx, ny = -(y2 - y1) / n, (x2 - x1) / n  # the "in" side, as the image shows it
            ax.annotate("", (mx + 40 * nx * w / 768, my + 40 * ny * w / 768), (mx, my),
                        arrowprops={"arrowstyle": "->", "color": "orange", "lw": 2})
            ax.text(x1, y1, " " + name, color="orange", fontsize=10, va="bottom")
        ax.set_title(seq + ("" if img is not None else " (no video: the ground truth's paths)"))
    fig.suptitle("make eval's counting lines; the arrow points to each line's \"in\" side")
    fig.tight_layout()
    fig.savefig(path, dpi=80)
