#!/usr/bin/env python3
"""The counting lines' hysteresis, chosen with one sequence left out.

    counting_loo.py BUILD_DIR [H1,H2,...]

For each hysteresis, ct-track counts on make eval's lines (cteval.counting)
of every sequence that has them, with detections (and the pixels where
there is a video) and from the pixels alone online, and the ground truth
is counted by the same rule and hysteresis. Then for each sequence in turn
the value with the least counting error over the others (both modes
together) is chosen and the sequence left out is scored with it, beside
the shipped default. Prints a Markdown table (docs/tuning.md).
"""
import argparse
import os
import sys
import tempfile

from cteval import counting
from cteval.data import DATA, has_video, run_ctrack, seqinfo, video

MODES = ("detections (+ pixels)", "pixels, online")


def counted(build, seq, mode, h, tmp):
    info = seqinfo(seq)
    events = os.path.join(tmp, "events.jsonl")
    pixels = has_video(seq)
    if mode == MODES[1] and not pixels:
        return None
    run_ctrack(build, seq, info, video(seq) if pixels else None, os.path.join(tmp, "t.txt"),
               pixels=pixels, detections=mode == MODES[0],
               params=counting.ct_track_args(seq, events, h))
    return counting.count_events(seq, events)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("values", nargs="?", default="0,0.05,0.1,0.2,0.3,0.5")
    a = ap.parse_args()
    values = [float(v) for v in a.values.split(",")]
    if counting.HYSTERESIS not in values:
        values.append(counting.HYSTERESIS)
    seqs = list(counting.LINES)
    tmp = tempfile.mkdtemp(prefix="ct-count-loo-")
    err = {}  # (h, seq, mode) -> (error, true)
    for h in values:
        for seq in seqs:
            true = {seq: counting.count_rows(seq, counting.ground_truth(seq, DATA), h)}
            for mode in MODES:
                c = counted(a.build, seq, mode, h, tmp)
                if c is not None:
                    err[(h, seq, mode)] = counting.error({seq: c}, true)
        print("counting_loo: hysteresis %g done" % h, file=sys.stderr, flush=True)

    def rate(h, among):
        e = [err[(h, s, m)] for s in among for m in MODES if (h, s, m) in err]
        return sum(x for x, _ in e) / max(1, sum(t for _, t in e))

    print("\nhysteresis (default %g; tried %s)\n" % (counting.HYSTERESIS,
                                                   ", ".join("%g" % v for v in values)))
    print("| left out | chosen on the others | its counting error there | the default's |")
    print("|---|---|---|---|")
    for out in seqs:
        rest = [s for s in seqs if s != out]
        best = min(values, key=lambda h: (rate(h, rest), abs(h - counting.HYSTERESIS)))
        print("| %s | %g | %.1f%% | %.1f%% |" % (out, best, 100 * rate(best, [out]),
                                                100 * rate(counting.HYSTERESIS, [out])))
    print("\n| hysteresis | " + " | ".join(seqs) + " | all |")
    print("|---" * (len(seqs) + 2) + "|")
    for h in values:
        print("| %g | " % h + " | ".join("%.1f%%" % (100 * rate(h, [s])) for s in seqs) +
              " | %.1f%% |" % (100 * rate(h, seqs)))


if __name__ == "__main__":
    main()
