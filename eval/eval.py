#!/usr/bin/env python3
"""make eval: ctrack and its peers on every real sequence the project has,
scored with py-motmetrics and TrackEval; writes docs/results.md,
docs/img/scores.png and docs/img/rates.png.

    eval.py BUILD_DIR [--out DOCS_DIR]

Needs the eval venv (scripts/venv.sh eval), ffmpeg, and the PETS09-S2L1 frames
(scripts/fetch-pets09.sh, cached).
"""
import argparse
import datetime
import json
import os
import sys
import textwrap
import tempfile

import numpy as np

from cteval import barycenter, counting, detectors, peers
from cteval.data import (CONDITIONS, DATA, TOP, conditioned, ctrack_version,
                         has_video, load_dets, run_ctrack, seqinfo, sequences, subsampled, video,
                         write_rows)
from cteval.families import FAMILIES, RATE_STEPS, run_all
from cteval.score import score, score_overall
from cteval.y4m import i420_planes, open_y4m


def trackeval_scores(seqs, trackers_dir, names):
    """HOTA, MOTA and IDF1 from TrackEval for every tracker and sequence, and
    over all of them together (key "COMBINED_SEQ")."""
    import trackeval
    ev_cfg = trackeval.Evaluator.get_default_eval_config()
    ev_cfg.update({"USE_PARALLEL": False, "PRINT_RESULTS": False, "PRINT_CONFIG": False,
                   "OUTPUT_SUMMARY": False, "OUTPUT_DETAILED": False, "PLOT_CURVES": False,
                   "TIME_PROGRESS": False, "DISPLAY_LESS_PROGRESS": True,
                   "OUTPUT_EMPTY_CLASSES": False, "PRINT_ONLY_COMBINED": True})
    ds_cfg = trackeval.datasets.MotChallenge2DBox.get_default_dataset_config()
    ds_cfg.update({"GT_FOLDER": DATA, "TRACKERS_FOLDER": trackers_dir, "BENCHMARK": "MOT15",
                   "SKIP_SPLIT_FOL": True, "TRACKERS_TO_EVAL": names, "PRINT_CONFIG": False,
                   "SEQ_INFO": {s: seqinfo(s)["frames"] for s in seqs},
                   "OUTPUT_FOLDER": os.path.join(trackers_dir, "_out")})
    metrics = [trackeval.metrics.HOTA(), trackeval.metrics.CLEAR({"PRINT_CONFIG": False}),
               trackeval.metrics.Identity({"PRINT_CONFIG": False})]
    res, _ = trackeval.Evaluator(ev_cfg).evaluate(
        [trackeval.datasets.MotChallenge2DBox(ds_cfg)], metrics)
    out = {}
    for name in names:
        for s in list(seqs) + ["COMBINED_SEQ"]:
            r = res["MotChallenge2DBox"][name][s]["pedestrian"]
            out[(name, s)] = {"HOTA": 100 * float(np.mean(r["HOTA"]["HOTA"])),
                              "LocA": 100 * float(np.mean(r["HOTA"]["LocA"])),
                              "MOTA": 100 * float(r["CLEAR"]["MOTA"]),
                              "IDF1": 100 * float(r["Identity"]["IDF1"])}
    return out


# The seconds ct-track primes on in the look-ahead rows (CT_PRIME_SECONDS).
PRIME = 3.0
PRIMED_LABEL = "ctrack, primed, a look-ahead"


def label_for(key, label, frames, fps):
    """A run's label for a clip of `frames` at `fps`: a primed run on a clip
    no longer than the priming is primed on the whole clip, and says so."""
    if key.endswith("-primed") and frames / fps <= PRIME:
        return label.replace("primed", "primed on the whole clip")
    return label


TRACKERS = [
    # key, label, input
    ("ctrack-det", "ctrack", "detections"),
    ("ctrack-detpix", "ctrack", "detections + pixels"),
    ("ctrack-detpix-noms", "ctrack, mean shift off (ablation)", "detections + pixels"),
    ("ctrack-detpix-noapp", "ctrack, DDIS off (ablation)", "detections + pixels"),
    ("ctrack-detpix-verify", "ctrack, detections verified by the contour template",
     "detections + pixels"),
    ("ctrack-pix", "ctrack", "pixels"),
    ("ctrack-pix-primed", PRIMED_LABEL, "pixels"),
    ("ctrack-pix-size", "ctrack, size and aspect instead of the contour template (ablation)",
     "pixels"),
    ("bytetrack", "ByteTrack (supervision 0.30.9)", "detections"),
    ("sort", "SORT (trackers 2.6.1)", "detections"),
    ("ocsort", "OC-SORT (trackers 2.6.1)", "detections"),
    ("norfair", "norfair 2.3.0 (IoU)", "detections"),
    ("opencv-kcf", "OpenCV KCF per person + IoU", "detections + pixels"),
    ("opencv-csrt", "OpenCV CSRT per person + IoU", "detections + pixels"),
    ("mog2-iou", "OpenCV MOG2 + blobs + IoU tracker", "pixels"),
]
# ctrack's runs: (pixels, detections, parameters). Every run is online but
# the primed one, a look-ahead (ct_tracker_prime() on the first PRIME
# seconds).
CTRACK_RUNS = {
    "ctrack-det": (False, True, []),
    "ctrack-detpix": (True, True, []),
    "ctrack-detpix-noms": (True, True, ["mean_shift=0"]),
    "ctrack-detpix-noapp": (True, True, ["appearance=0"]),
    "ctrack-detpix-verify": (True, True, ["verify_detections=1"]),
    "ctrack-pix": (True, False, []),
    "ctrack-pix-primed": (True, False, ["--prime=%g" % PRIME]),
    "ctrack-pix-size": (True, False, ["pedestrian_test=1"]),
}
# OpenCV's single-object trackers, one per person (peers.OpenCVTrackers).
OPENCV_TRACKERS = {"opencv-kcf": "KCF", "opencv-csrt": "CSRT"}


PEERS_ON_DETECTIONS = {"bytetrack": peers.bytetrack, "sort": peers.sort, "ocsort": peers.ocsort,
                       "norfair": peers.norfair_iou}


def run_tracker(build, key, seq, info, y4m, dets, path):
    """One tracker of TRACKERS over one sequence into path; returns its
    time in seconds."""
    n, fps = info["frames"], info["fps"]
    if key in CTRACK_RUNS:
        pixels, detections, params = CTRACK_RUNS[key]
        if seq in counting.LINES:  # the tracks are the same with counting on
            params = params + counting.ct_track_args(seq, counting.events_path(path, seq))
        return run_ctrack(build, seq, info, y4m, path, pixels=pixels, detections=detections,
                          params=params)
    if key in PEERS_ON_DETECTIONS:
        rows, seconds = PEERS_ON_DETECTIONS[key](dets, n, fps)
    elif key in OPENCV_TRACKERS:
        rows, seconds = peers.opencv_trackers(OPENCV_TRACKERS[key], y4m, dets, n)
    else:
        rows, seconds = peers.mog2_iou(y4m, n)
    write_rows(path, rows)
    return seconds


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--out", default=os.path.join(TOP, "docs"))
    a = ap.parse_args()
    seqs = sequences()
    tmp = tempfile.mkdtemp(prefix="ct-eval-")
    results = []
    for seq in seqs:
        info = seqinfo(seq)
        y4m = video(seq) if has_video(seq) else None
        dets = load_dets(seq)
        for key, label, mode in TRACKERS:
            if y4m is None and mode != "detections":
                continue
            d = os.path.join(tmp, key, "data")
            os.makedirs(d, exist_ok=True)
            path = os.path.join(d, seq + ".txt")
            print("eval: %s: %s (%s)" % (seq, label, mode), file=sys.stderr, flush=True)
            seconds = run_tracker(a.build, key, seq, info, y4m, dets, path)
            r = score(os.path.join(DATA, seq, "gt", "gt.txt"), path)
            r.update({"sequence": seq, "key": key,
                      "tracker": label_for(key, label, info["frames"], info["fps"]),
                      "input": mode,
                      "seconds": seconds,
                      "fps": info["frames"] / seconds if seconds > 0 else float("inf"),
                      "fps_native": info["fps"]})
            results.append(r)
    lower = lower_rates(a.build, seqs, tmp)
    conditions = camera_conditions(a.build, seqs, tmp)
    families = condition_families(a.build, seqs, tmp)
    detector_family = other_detectors(a.build, seqs, tmp)
    # TrackEval wants every tracker on every sequence it is given: those on
    # detections over all of them (and their combined scores), the others
    # over the sequences with a video.
    det_keys = [k for k, _, m in TRACKERS if m == "detections"]
    video_seqs = [s for s in seqs if has_video(s)]
    te = trackeval_scores(seqs, tmp, det_keys)
    te.update(trackeval_scores(video_seqs, tmp, [k for k, _, m in TRACKERS if m != "detections"]))
    worst = 0.0
    for r in results:
        t = te[(r["key"], r["sequence"])]
        r["HOTA"], r["LocA"] = t["HOTA"], t["LocA"]
        r["trackeval_MOTA"], r["trackeval_IDF1"] = t["MOTA"], t["IDF1"]
        worst = max(worst, abs(t["MOTA"] - r["MOTA"]), abs(t["IDF1"] - r["IDF1"]))
    overall = []
    for key, label, mode in TRACKERS:
        if mode != "detections":
            continue
        r = score_overall([(os.path.join(DATA, s, "gt", "gt.txt"),
                            os.path.join(tmp, key, "data", s + ".txt")) for s in seqs])
        r.update({"key": key, "tracker": label, "input": mode,
                  "HOTA": te[(key, "COMBINED_SEQ")]["HOTA"]})
        overall.append(r)
    counts = counting.evaluate(tmp, DATA, has_video)
    floors = {s: barycenter.floor(a.build, s, video(s), tmp) for s in seqs if has_video(s)}
    write_report(a.out, results, seqs, worst, lower, overall, conditions, families, counts,
                 detector_family, floors)
    with open(os.path.join(a.build, "eval.json"), "w") as f:
        json.dump({"sequences": results, "overall": overall, "lower_rates": lower,
                   "conditions": conditions, "families": families, "counting": counts,
                   "detector_family": detector_family, "barycenter_floors": floors}, f,
                  indent=1)
    print("eval: wrote %s/results.md, %s/img/scores.png, rates.png, conditions.png, %s/eval.json"
          % (a.out, a.out, a.build), file=sys.stderr)


LOWER_RATES = [
    # key, label, input, ct-track parameters (None: a peer)
    ("ctrack-det", "ctrack", "detections", []),
    ("ctrack-detpix", "ctrack", "detections + pixels", []),
    ("ctrack-detpix-noms", "ctrack, mean shift off", "detections + pixels", ["mean_shift=0"]),
    ("ctrack-pix", "ctrack", "pixels", []),
    ("ctrack-pix-primed", PRIMED_LABEL, "pixels", ["--prime=%g" % PRIME]),
    ("bytetrack", "ByteTrack (supervision 0.30.9)", "detections", None),
    ("sort", "SORT (trackers 2.6.1)", "detections", None),
]


def lower_rates(build, seqs, tmp):
    """Every sequence at a half and a third of its frame rate (a camera that
    keeps every k-th frame), from each offset: frames 1, 3, 5, ... and
    2, 4, 6, ... at half the rate. ctrack in each input mode the sequence
    has and two peers, scored with py-motmetrics against the ground truth of
    the frames kept. One offset alone is a small sample: on TUD-Campus a
    tracker's IDF1 moves by up to 10 points from one offset to the other.
    Returns one result per sequence, step and tracker, with the scores of
    each offset."""
    results = []
    for seq in seqs:
        info = seqinfo(seq)
        src = video(seq) if has_video(seq) else None
        trackers = [t for t in LOWER_RATES if src is not None or t[2] == "detections"]
        for k in RATE_STEPS:
            runs = {}
            for offset in range(k):
                y4m, gt, det, sub = subsampled(seq, info, src, k, offset, tmp)
                for key, label, mode, params in trackers:
                    print("eval: %s at 1/%d of its frame rate, from frame %d: %s (%s)"
                          % (seq, k, offset + 1, label, mode), file=sys.stderr, flush=True)
                    path = os.path.join(tmp, "rate-%s-%s-%dof%d.txt" % (key, seq, offset + 1, k))
                    if params is None:
                        rows, _ = PEERS_ON_DETECTIONS[key](load_dets(seq, det), sub["frames"],
                                                           sub["fps"])
                        write_rows(path, rows)
                    else:
                        run_ctrack(build, seq, sub, y4m, path, pixels=mode != "detections",
                                   params=params, detections=mode != "pixels", det=det)
                    runs.setdefault(key, []).append(score(gt, path))
                if y4m:
                    os.remove(y4m)
            for key, label, mode, _ in trackers:
                results.append({"sequence": seq, "step": k, "fps": info["fps"] / k, "key": key,
                                "tracker": label_for(key, label, info["frames"] // k,
                                                     info["fps"] / k),
                                "input": mode, "runs": runs[key]})
    return results


# The runs in each camera condition: key, label, input, ct-track parameters
# (None: the MOG2 baseline).
CONDITION_RUNS = [
    ("ctrack-pix", "ctrack", "pixels", []),
    ("ctrack-pix-primed", PRIMED_LABEL, "pixels", ["--prime=%g" % PRIME]),
    ("ctrack-pix-size", "ctrack, size and aspect alone (ablation)", "pixels",
     ["pedestrian_test=1"]),
    ("ctrack-detpix", "ctrack", "detections + pixels", []),
    ("mog2-iou", "OpenCV MOG2 + blobs + IoU tracker", "pixels", None),
]


def camera_conditions(build, seqs, tmp):
    """Each sequence with a video in each camera condition (CONDITIONS: half
    and twice the size, sensor noise, darker and lower in contrast, mirrored,
    exposure steps), ctrack from
    the pixels alone and with the detections, and the MOG2 baseline, scored
    against the ground truth moved to match. Returns one result a sequence,
    condition and run, with its frames per second."""
    results = []
    for seq in seqs:
        if not has_video(seq):
            continue
        for cond in CONDITIONS:
            y4m, gt, det, info = conditioned(seq, cond, tmp)
            for key, label, mode, params in CONDITION_RUNS:
                print("eval: %s, %s: %s (%s)" % (seq, cond, label, mode), file=sys.stderr,
                      flush=True)
                path = os.path.join(tmp, "cond-%s-%s.txt" % (key, seq))
                if params is None:
                    rows, seconds = peers.mog2_iou(y4m, info["frames"])
                    write_rows(path, rows)
                else:
                    seconds = run_ctrack(build, seq, info, y4m, path, pixels=True,
                                         detections=mode != "pixels", params=params, det=det)
                r = score(gt, path)
                r.update({"sequence": seq, "condition": cond, "key": key, "tracker": label,
                          "input": mode, "fps": info["frames"] / seconds})
                results.append(r)
    return results


# ctrack's runs over the condition families (cteval.families): key, label,
# input.
FAMILY_RUNS = [
    ("ctrack-pix", "ctrack", "pixels", []),
    ("ctrack-pix-primed", PRIMED_LABEL, "pixels", ["--prime=%g" % PRIME]),
    ("ctrack-detpix", "ctrack", "detections + pixels", []),
]


def condition_families(build, seqs, tmp):
    """Each sequence with a video over each family of conditions (every
    variant of it), ctrack from the pixels alone and with the detections.
    Returns one result a sequence, family, variant and run."""
    keys, jobs = [], []
    for seq in seqs:
        if not has_video(seq):
            continue
        for fam, variants in FAMILIES.items():
            for label, vf, move in variants:
                for key, _, mode, params in FAMILY_RUNS:
                    keys.append({"sequence": seq, "family": fam, "variant": label, "key": key})
                    jobs.append(dict(build=build, seq=seq, vf=vf, move=move,
                                     detections=mode != "pixels", params=params))
    scores = run_all(jobs, tmp, progress=lambda k, n: print(
        "eval: condition families, %d/%d runs" % (k, n), file=sys.stderr, flush=True))
    return [dict(k, MOTA=s["MOTA"], IDF1=s["IDF1"]) for k, s in zip(keys, scores)]


def mean_and_range(runs, measure):
    v = [r[measure] for r in runs]
    return "%.1f (%.1f-%.1f)" % (sum(v) / len(v), min(v), max(v))


def plot_rates(plt, path, results, seqs, lower):
    """MOTA and IDF1 against the frame rate, one line a tracker of the
    lower-rate table: the native rate from the main runs, then a half and a
    third (the mean over the offsets, the bar from the lowest to the
    highest)."""
    fig, axes = plt.subplots(len(seqs), 2, figsize=(11, 4.2 * len(seqs)))
    # One colour a tracker in every panel, and one legend entry each.
    colour = {key: "C%d" % i for i, (key, _, _, _) in enumerate(LOWER_RATES)}
    legend = {}
    for row, seq in zip(axes, seqs):
        for key, label, mode, _ in LOWER_RATES:
            native = [r for r in results if r["sequence"] == seq and r["key"] == key]
            lows = sorted((r for r in lower if r["sequence"] == seq and r["key"] == key),
                          key=lambda r: r["step"])
            if not native or not lows:
                continue
            fps = [native[0]["fps_native"]] + [r["fps"] for r in lows]
            name = "%s (%s)" % (label.split(" (")[0], mode)
            style = "-" if label.startswith("ctrack") else "--"
            for ax, m in zip(row, ("MOTA", "IDF1")):
                mean = [native[0][m]] + [sum(x[m] for x in r["runs"]) / len(r["runs"])
                                         for r in lows]
                lo = [0] + [mean[i + 1] - min(x[m] for x in r["runs"]) for i, r in enumerate(lows)]
                hi = [0] + [max(x[m] for x in r["runs"]) - mean[i + 1] for i, r in enumerate(lows)]
                line = ax.errorbar(fps, mean, yerr=[lo, hi], linestyle=style, marker="o",
                                   capsize=3, color=colour[key], label=name)
                legend.setdefault(name, line)
        for ax, m in zip(row, ("MOTA", "IDF1")):
            ax.set_title("%s: %s" % (seq, m))
            ax.set_xlabel("frames per second")
            ax.set_ylabel("%s (%%)" % m)
            ax.grid(alpha=0.3)
    fig.legend(list(legend.values()), list(legend.keys()), loc="lower center", ncol=3,
               fontsize=8)
    fig.suptitle("Scores against the frame rate (every k-th frame kept; mean and range "
                 "over the offsets)")
    fig.tight_layout(rect=(0, 0.03, 1, 0.985))
    fig.savefig(path, dpi=100)
    plt.close(fig)


def plot_conditions(plt, path, results, conditions):
    """MOTA by camera condition, one panel a sequence with a video: ctrack
    from the pixels alone and with the detections, and the MOG2 baseline."""
    seqs = sorted(set(r["sequence"] for r in conditions))
    names = ["as shipped"] + list(CONDITIONS)
    fig, axes = plt.subplots(len(seqs), 1, figsize=(12, 4.5 * len(seqs)), sharey=True)
    for ax, seq in zip(np.atleast_1d(axes), seqs):
        x = np.arange(len(names))
        for i, (key, label, mode, _) in enumerate(CONDITION_RUNS):
            base = [r for r in results if r["sequence"] == seq and r["key"] == key]
            v = [base[0]["MOTA"]] + [next(r["MOTA"] for r in conditions if r["sequence"] == seq
                                          and r["key"] == key and r["condition"] == c)
                                     for c in CONDITIONS]
            width = 0.8 / len(CONDITION_RUNS)
            bars = ax.bar(x + (i - (len(CONDITION_RUNS) - 1) / 2) * width,
                          [max(t, -20) for t in v], width,
                          label="%s (%s)" % (label.split(" (")[0], mode))
            ax.bar_label(bars, labels=["%.0f" % t for t in v], fontsize=7)
        ax.set_xticks(x, [textwrap.fill(n, 14) for n in names])
        ax.set_title("%s: MOTA by camera condition" % seq)
        ax.set_ylabel("MOTA (%)")
        ax.axhline(0, color="black", linewidth=0.5)
        ax.set_ylim(-25, 118)  # the legend above the bars; below -20 is cut, labelled
        ax.legend(fontsize=8, loc="upper center", ncol=3)
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def first_frame(seq):
    """A sequence's first frame in grey, or None without a video."""
    if not has_video(seq):
        return None
    w, h, _, frames = open_y4m(video(seq))
    return np.array(i420_planes(frames[0], w, h)[0])


def write_report(out, results, seqs, worst, lower, overall, conditions, families, counts,
                 detector_family, floors):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    os.makedirs(os.path.join(out, "img"), exist_ok=True)
    # All the sequences together first, then one sequence a row, so that
    # every tracker's label has room.
    panels = [("Over all %d sequences, detections only" % len(seqs), overall)]
    panels += [(seq, [r for r in results if r["sequence"] == seq]) for seq in seqs]
    fig, axes = plt.subplots(len(panels), 1, figsize=(12, 4.0 * len(panels)), sharey=True)
    measures = ["HOTA", "MOTA", "IDF1"]
    for ax, (title, rows) in zip(axes, panels):
        x = np.arange(len(rows))
        for i, m in enumerate(measures):
            # Bars stop at -20 so that one very negative MOTA does not squash
            # the rest; the labels give the true values.
            bars = ax.bar(x + (i - 1) * 0.27, [max(r[m], -20) for r in rows], 0.27, label=m)
            ax.bar_label(bars, labels=["%.0f" % r[m] for r in rows], fontsize=7)
        ax.set_xticks(x, ["%s\n(%s)" % (r["tracker"].split(" (")[0], r["input"])
                          for r in rows], fontsize=7, rotation=25, ha="right",
                      rotation_mode="anchor")
        ax.set_title(title)
        ax.axhline(0, color="black", linewidth=0.5)
    for ax in axes:
        ax.set_ylabel("score (%)")
    axes[0].legend(loc="upper right", fontsize=8)
    fig.suptitle("ctrack and its peers, MOTChallenge 2015 public detections (online)")
    fig.tight_layout(rect=(0, 0, 1, 0.985))
    fig.savefig(os.path.join(out, "img", "scores.png"), dpi=110)
    plot_rates(plt, os.path.join(out, "img", "rates.png"), results, seqs, lower)
    plot_conditions(plt, os.path.join(out, "img", "conditions.png"), results, conditions)
    counting.plot_lines(plt, os.path.join(out, "img", "counting-lines.png"), DATA, first_frame)
    barycenter.plot(plt, os.path.join(out, "img", "barycenter.png"), results, floors)

    with open(os.path.join(out, "results.md"), "w") as f:
        f.write("# Results\n\n")
        f.write("Made by `make eval` (`eval/eval.py`) on %s, ctrack %s. Every run is "
                "online (the output for frame k from frames 1 to k) but those labelled "
                "a look-ahead: ctrack primed on the first %g seconds (`ct-track --prime`, "
                "`ct_tracker_prime()`), which stand beside the online row of the same "
                "input, never in its place; on a clip shorter than that, primed on the "
                "whole clip. One set of defaults serves every sequence, and every "
                "tracker has the same input. HOTA from TrackEval 1.3.0; MOTA, IDF1, ID switches, "
                "precision, recall and the barycenter error from py-motmetrics 1.4.0 "
                "(IoU >= 0.5). TrackEval's MOTA and IDF1 agree with py-motmetrics' "
                "within %.2f points here. Time is wall time for the whole sequence "
                "(ctrack: the ct-track process, reading the video included; peers: "
                "their update calls only).\n\n"
                % (datetime.date.today().isoformat(), ctrack_version(), PRIME, worst))
        f.write("![scores](img/scores.png)\n\n")
        f.write("![barycenter error](img/barycenter.png)\n\n")
        f.write("## Over all %d sequences, detections only\n\n" % len(seqs))
        f.write(OVERALL_HEAD)
        f.write("| tracker | HOTA | MOTA | IDF1 | ID sw. | precision | recall | FP | FN "
                "| MOTA above on |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        for r in overall:
            f.write("| %s | %.1f | %.1f | %.1f | %d | %.1f | %.1f | %d | %d | %s |\n"
                    % (r["tracker"], r["HOTA"], r["MOTA"], r["IDF1"], r["IDsw"],
                       r["precision"], r["recall"], r["FP"], r["FN"],
                       beaten_on(results, seqs, "ctrack-det", r["key"])))
        f.write("\n")
        for seq in seqs:
            info = seqinfo(seq)
            f.write("## %s (%d frames, %dx%d, %g fps)\n\n" % (
                seq, info["frames"], info["width"], info["height"], info["fps"]))
            if seq in floors:
                f.write("The ground truth's own boxes sit %.2f%% of a person's height from "
                        "the silhouettes the tracker finds (%.0f%% of them fitted; the "
                        "barycenter error's floor, `eval/cteval/barycenter.py`).\n\n"
                        % (floors[seq][0], 100 * floors[seq][1]))
            f.write("| tracker | input | HOTA | LocA | MOTA | IDF1 | ID sw. | precision "
                    "| recall | barycenter error | time (s) | frames/s |\n")
            f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
            for r in results:
                if r["sequence"] != seq:
                    continue
                f.write("| %s | %s | %.1f | %.1f | %.1f | %.1f | %d | %.1f | %.1f | %.2f%% "
                        "| %.3f | %.0f |\n"
                        % (r["tracker"], r["input"], r["HOTA"], r["LocA"], r["MOTA"],
                           r["IDF1"], r["IDsw"], r["precision"], r["recall"],
                           r["barycenter_error"], r["seconds"], r["fps"]))
            f.write("\n")
        counting.write_report(f, counts)
        write_conditions(f, results, conditions)
        write_families(f, families)
        write_detector_family(f, detector_family)
        f.write(LOWER_RATES_HEAD)
        f.write("![scores against the frame rate](img/rates.png)\n\n")
        f.write("| sequence | tracker | input | MOTA: mean (range) | IDF1: mean (range) "
                "| ID sw. (sum) |\n")
        f.write("|---|---|---|---|---|---|\n")
        for r in lower:
            f.write("| %s at 1/%d (%.3g fps) | %s | %s | %s | %s | %d |\n"
                    % (r["sequence"], r["step"], r["fps"], r["tracker"], r["input"],
                       mean_and_range(r["runs"], "MOTA"), mean_and_range(r["runs"], "IDF1"),
                       sum(x["IDsw"] for x in r["runs"])))
        f.write("\n")
        f.write(NOTES)


def write_conditions(f, results, conditions):
    """The camera conditions' table: per sequence and condition, each run's
    MOTA / IDF1 and frames per second, then the mean over the sequences."""
    f.write(CONDITIONS_HEAD)
    f.write("![MOTA by camera condition](img/conditions.png)\n\n")
    f.write("| sequence | condition | %s |\n" % " | ".join(
        "%s (%s)" % (label.split(" (")[0], mode) for _, label, mode, _ in CONDITION_RUNS))
    f.write("|---|---|%s\n" % ("---|" * len(CONDITION_RUNS)))
    seqs = sorted(set(r["sequence"] for r in conditions))
    cell = "%.1f / %.1f, %.0f fps"
    for seq in seqs:
        row = ["%s" % seq, "as shipped"]
        for key, _, _, _ in CONDITION_RUNS:
            r = next(r for r in results if r["sequence"] == seq and r["key"] == key)
            row.append(cell % (r["MOTA"], r["IDF1"], r["fps"]))
        f.write("| %s |\n" % " | ".join(row))
        for c in CONDITIONS:
            row = ["", c]
            for key, _, _, _ in CONDITION_RUNS:
                r = next(r for r in conditions if r["sequence"] == seq and r["key"] == key
                         and r["condition"] == c)
                row.append(cell % (r["MOTA"], r["IDF1"], r["fps"]))
            f.write("| %s |\n" % " | ".join(row))
    for c in CONDITIONS:
        row = ["mean of the %d" % len(seqs), c]
        for key, _, _, _ in CONDITION_RUNS:
            rs = [r for r in conditions if r["key"] == key and r["condition"] == c]
            row.append("%.1f / %.1f" % (np.mean([r["MOTA"] for r in rs]),
                                        np.mean([r["IDF1"] for r in rs])))
        f.write("| %s |\n" % " | ".join(row))
    f.write("\n")


# The trackers run on each member of the detector family: key, label.
DETECTOR_FAMILY_RUNS = [("ctrack-det", "ctrack"), ("sort", "SORT (trackers 2.6.1)"),
                        ("bytetrack", "ByteTrack (supervision 0.30.9)")]


# Detectors of another kind, where the sequence has frames to run them on
# (eval/hog_detections.py): the member's name and its file in det/.
OTHER_KINDS = [("OpenCV's HOG people detector", "hog.txt"),
               ("the same, its low scores too (SVM margin from -0.5)", "hog-low.txt")]


def detector_members(seqs, tmp):
    """(member, sequence, detections) for every member of the detector
    family: the public detections' variants on every sequence, then the
    detectors of another kind where their files are."""
    for name, how, seed in detectors.VARIANTS:
        for seq in seqs:
            yield name, seq, detectors.variant_path(seq, name, how, seed, tmp)
    for name, fname in OTHER_KINDS:
        for seq in seqs:
            det = os.path.join(DATA, seq, "det", fname)
            if os.path.exists(det):
                yield name, seq, det


def other_detectors(build, seqs, tmp):
    """Every sequence's detections as other detectors would give them
    (cteval.detectors), and other detectors' own (OTHER_KINDS), ctrack from
    the detections and two peers on each. Returns one result a sequence,
    member and tracker."""
    results = []
    for name, seq, det in detector_members(seqs, tmp):
        info = seqinfo(seq)
        gt = os.path.join(DATA, seq, "gt", "gt.txt")
        print("eval: %s, %s" % (seq, name), file=sys.stderr, flush=True)
        for key, label in DETECTOR_FAMILY_RUNS:
            path = os.path.join(tmp, "detfam-%s-%s.txt" % (key, seq))
            if key in CTRACK_RUNS:
                run_ctrack(build, seq, info, None, path, pixels=False, det=det)
            else:
                rows, _ = PEERS_ON_DETECTIONS[key](load_dets(seq, det), info["frames"],
                                                   info["fps"])
                write_rows(path, rows)
            r = score(gt, path)
            r.update({"sequence": seq, "variant": name, "key": key, "tracker": label})
            results.append(r)
    return results


def write_detector_family(f, results):
    """The detector family's table: each variant's MOTA / IDF1 per sequence
    and tracker, and how often ctrack's MOTA is above both peers'."""
    f.write(DETECTOR_FAMILY_HEAD)
    above = total = 0
    f.write("| detections | sequence | %s |\n" % " | ".join(l for _, l in DETECTOR_FAMILY_RUNS))
    f.write("|---|---|%s\n" % ("---|" * len(DETECTOR_FAMILY_RUNS)))
    last = None
    # Each member's rows in the order they ran, its name on its first.
    for name, seq in dict.fromkeys((r["variant"], r["sequence"]) for r in results):
        rs = {r["key"]: r for r in results if r["variant"] == name and r["sequence"] == seq}
        f.write("| %s | %s | %s |\n" % (name if name != last else "", seq, " | ".join(
            "%.1f / %.1f" % (rs[k]["MOTA"], rs[k]["IDF1"]) for k, _ in DETECTOR_FAMILY_RUNS)))
        last = name
        total += 1
        above += rs["ctrack-det"]["MOTA"] > max(rs[k]["MOTA"] for k, _ in DETECTOR_FAMILY_RUNS[1:])
    f.write("\nctrack's MOTA is above SORT's and ByteTrack's on %d of the %d.\n\n"
            % (above, total))


DETECTOR_FAMILY_HEAD = """## Other detectors

A user's detector is not the one these detections came from. Each
sequence's public detections are also given as other detectors would give
them (`eval/cteval/detectors.py`): scores on another scale (times 0.8, and
squared), a detector that misses more (20% of the boxes dropped at random,
three seeds), and a looser one (each box edge moved at random by up to 5%
of the box's height). The sequences with frames also have a detector of
another kind: OpenCV's HOG people detector, as its sample peopledetect.py
runs it, its SVM margin through a logistic for a score
(`eval/hog_detections.py`, `tests/data/README.md`), with its own threshold
and with its low scores too. ctrack runs with the same defaults on each,
and the peers with their libraries' defaults, which start tracks from
every box scoring over 0.25 (SORT) or 0.35 (ByteTrack): all of HOG's,
hence their scores under zero on HOG's low scores. Each cell is MOTA /
IDF1, detections only.

"""


def write_families(f, families):
    """The condition families' table: per sequence and family, ctrack's mean
    and lowest MOTA / IDF1 over the variants, in each input."""
    f.write(FAMILIES_HEAD)
    f.write("| sequence | family | %s |\n" % " | ".join(
        "%s (%s): mean (lowest)" % (label, mode) for _, label, mode, _ in FAMILY_RUNS))
    f.write("|---|---|%s\n" % ("---|" * len(FAMILY_RUNS)))
    seqs = sorted(set(r["sequence"] for r in families))
    for seq in seqs:
        for fam, variants in FAMILIES.items():
            row = [seq if fam == next(iter(FAMILIES)) else "",
                   "%s (%d)" % (fam, len(variants))]
            for key, _, _, _ in FAMILY_RUNS:
                rs = [r for r in families
                      if r["sequence"] == seq and r["family"] == fam and r["key"] == key]
                row.append("%.1f / %.1f (%.1f / %.1f)" % (
                    np.mean([r["MOTA"] for r in rs]), np.mean([r["IDF1"] for r in rs]),
                    min(r["MOTA"] for r in rs), min(r["IDF1"] for r in rs)))
            f.write("| %s |\n" % " | ".join(row))
    f.write("\n")


FAMILIES_HEAD = """## Condition families

One run in a condition is one draw: on TUD-Campus's 71 frames, a little
noise, a mirror or a small change of brightness moves ctrack's pixels-only
MOTA by 10 points either way. So each sequence with frames is also run over
families of variants (`eval/cteval/families.py`): sensor noise of three
strengths with two seeds each, and at the camera conditions' strength with
three seeds (one noise pattern is one draw); contrast from 0.4 to 1 with the black level
lowered or raised (haze, a washed-out picture), the frames as they are
first; and half size as it is, mirrored, a little brighter or darker, with
less contrast and with a little noise; and the frames cut by 4 pixels at
eight offsets, the same picture with each pixel in another place of the
working scale's blocks (its spread is the tracker's luck, not the
camera's); and the stream a network camera sends, H.264 (x264) from its
default quality (a constant rate factor of 23) to a low bitrate's (38),
with a keyframe every 25 and every 250 frames; and a moving person's
trail, as a camera's temporal noise filter or a slow shutter leaves it:
each frame blended with the frame before at a quarter, a third and a half
of the picture, and with the two before at a seventh and two sevenths.
Each cell is the mean over the family's variants (how many in brackets)
and, in brackets, the lowest MOTA / IDF1 among them. The background
model's constants for noise, contrast and black level, and the size
model's, were chosen on these means (docs/tuning.md) but for compression's
and ghosting's, which came after them and on which no default was chosen
but the trail's own (docs/tuning.md, "A walker's trail").
The primed column is a look-ahead beside the online one; TUD-Campus's
variants are primed on their whole clip.

"""


CONDITIONS_HEAD = """## Camera conditions

Each sequence with frames, as a camera user meets it: made half its size
(`scale=iw/2:ih/2`: PETS09-S2L1's people about 40 pixels tall) and twice
its size (`scale=iw*2:ih*2`: TUD-Campus's nearest people over 500 pixels
tall, a high-definition camera's), with sensor
noise (`noise=alls=14:allf=t`), darker and lower in contrast
(`eq=brightness=-0.12:contrast=0.55`), mirrored (`hflip`), and with steps
of exposure (brighter by 0.08 with 20% more contrast for frames 30-59 and
300-399: an auto-exposure, a cloud), by ffmpeg on the decoded frames, the
ground truth and the detections moved to match (`eval/cteval/data.py`,
`CONDITIONS`).
Each cell is MOTA / IDF1 and the frames per second of the run (ctrack: the
ct-track process; MOG2: its update calls). The defaults are the same in
every condition. A primed run (a look-ahead) stands beside the online one;
TUD-Campus is primed on its whole clip.

"""


def beaten_on(results, seqs, ours, peer):
    """On how many sequences ctrack's MOTA is above the peer's (detections
    only), for the peers' rows of the overall table."""
    if peer == ours:
        return ""
    mota = {(r["key"], r["sequence"]): r["MOTA"] for r in results}
    won = sum(mota[(ours, s)] > mota[(peer, s)] for s in seqs)
    return "%d of %d" % (won, len(seqs))


OVERALL_HEAD = """Every sequence's events pooled (py-motmetrics' OVERALL; TrackEval's
combined HOTA), as MOTChallenge sums a benchmark: the large sequences
weigh most. The last column counts the sequences on which ctrack's MOTA is
above the peer's.

"""


LOWER_RATES_HEAD = """## At lower frame rates

A camera that keeps every second or every third frame: each sequence with
frames 1, 3, 5, ... kept, then 2, 4, 6, ... (a half of its rate), and from
each of frames 1, 2 and 3 at a third, numbered again from 1 and scored by
py-motmetrics against the ground truth of the frames kept. The defaults are
the same; only the frame rate given changes. Each row gives the mean over
the offsets and, in brackets, the lowest and highest: one offset alone is a
small sample, and a single decision of the tracker moves TUD-Campus's IDF1
by several points. The primed rows are a look-ahead beside the online ones.

"""

NOTES = """## Notes

- **Input.** "detections": the MOTChallenge public detections (already cut at
  score 0.5). "detections + pixels": the same with the frames (ct-track reading
  the Y4M): each confirmed track keeps a colour model, multiscale mean shift refines
  its predicted box before association and follows it through missing detections
  (docs/notes/meanshift.md). "pixels": no detections at all; ctrack finds people with
  its background model and contour template (docs/notes/pixels.md), like the MOG2
  baseline, online as a camera's stream is tracked. "primed, a look-ahead" is the
  same run with `--prime 3`: ct-track first learns the background from the video's
  first 3 seconds (`ct_tracker_prime()`), so that frame 1's tracks depend on later
  frames; on TUD-Campus (2.84 s) and its variants that is the whole clip, which no
  camera has.
- **Ablations.** "mean shift off" is the same run with `mean_shift=0` and every
  other parameter equal, the lost-track lifetime and the reporting of lost tracks
  included: what mean shift adds comes from following the pixels, not from
  coasting longer. "DDIS off" is the same run with `appearance=0`: no appearance
  term in the association cost and no re-identification of lost tracks, the
  lost-track lifetime unchanged (docs/notes/appearance.md).
- **Size and aspect instead of the contour template.** The "pixels" run
  with `pedestrian_test=1`: each candidate scores 1 when its height over
  width is 1 to 4.25 and its height half to one and a half times the learnt
  person's at its feet, else 0; the blobs, their merging and splitting
  (which consult the template) and everything else are the same. It asks
  whether the template earns its place in tracking, not blob by blob
  (docs/notes/recognition.md measures that).
- **Verified detections.** The "detections + pixels" run with
  `verify_detections=1`: the contour template votes on the foreground inside
  each detection's box, and a detection it rejects can no longer start a track
  (docs/notes/pixels.md). An option, off by default.
- **Barycenter error** (the paper's measure, docs/algorithm.md): over the matched pairs,
  the distance between the track's and the ground truth's box centres divided by the
  ground-truth box height.
- **Feature recognition accuracy** (the paper's third measure) is in
  docs/notes/recognition.md (`eval/recognition.py`).

## Peers

ByteTrack as supervision 0.30.9 ships it (defaults, `frame_rate` set
to the sequence's); SORT and OC-SORT as Roboflow's trackers 2.6.1 ships them
(defaults, `frame_rate` set to the sequence's; boxes reported once a track is
confirmed); norfair 2.3.0 with IoU distance, threshold 0.7; the pixels-only
baseline is OpenCV's MOG2 (defaults, shadows dropped), a 3x3 opening and a 7x7
closing, contours of at least 400 pixels as boxes, and an IoU tracker (IoU >= 0.3,
3 hits to confirm, 3 frames kept). "OpenCV KCF / CSRT per person" is
tracking by detection as people build it from OpenCV's own trackers
(opencv-contrib-python 4.10): the same IoU tracker on the public
detections, where each track runs OpenCV's tracker on every frame, is
matched by the box that tracker gives, is started again on each matched
detection's box, and between detections is reported where the tracker
follows the person, while the tracker says it holds them. Their time
includes OpenCV's trackers, not the conversion of the frames to BGR.
`eval/cteval/peers.py` has them.
"""


if __name__ == "__main__":
    main()
