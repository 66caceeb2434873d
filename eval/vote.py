#!/usr/bin/env python3
"""Chooses the contour template's thresholds (eq. (1) per region, and the
bound on how much of its convex hull a pedestrian's blob fills) by tracking
from the pixels alone, over families of camera conditions of every sequence
with frames.

    vote.py TUNING_BUILD [--rounds N] [--start JSON] [--sequences A,B]
            [--write] [--score]

The region vote decides which blobs are people, which fragments merge and
where a blob is cut between heads, so its thresholds are chosen on what it
serves: each round tries, threshold by threshold, the value 15% lower and
15% higher (8% after the first round; the fill bound 5%) with the others at
the best so far, and keeps one that raises the objective by more than 0.5.
The objective is the sum over the families (make eval's conditions, noise,
half size, contrast and shift; a half and a third of the frame rate) and
sequences of the mean MOTA + IDF1, less 10 for each point under a replay
floor (tests/replay.sh: PETS09-S2L1 as it is and at half size, TUD-Campus
as it is). A tuning build (meson -Dtuning=true) reads the thresholds from
CTRACK_REGION_0..8 and CTRACK_MAX_FILL; the search starts from --start
(JSON of those names) or the shipped values. The widest top against the
body (CTRACK_MAX_TOP) is a design constant, carried over: a T, an H or an S
has a top as wide as its body, a person a head (tests/check_background.cc
holds shapes to it).

--sequences chooses on those sequences only (leave one out: choose on one,
then --score the other with the choice). --score only scores --start, and
the shipped values, over the families and over conditions no threshold is
chosen on (cteval.families.HELD_OUT_FAMILY). --write rewrites
lib/template/classifier_params.inc with the choice. A choice is adopted only when it
loses nothing over the held-out conditions either: on TUD-Campus's 71
frames the objective's noise is as large as what a step gains, and two
rounds can climb on it (docs/tuning.md).
"""
import argparse
import json
import sys
import tempfile

import numpy as np

from cteval.data import CLASSIFIER_PARAMS, PIXEL_FLOORS, classifier_params, has_video, sequences
from cteval.families import CONDITIONS_FAMILY, FAMILIES, HELD_OUT_FAMILY, RATE_FAMILY, run_all

NAMES = ["CTRACK_REGION_%d" % g for g in range(9)] + ["CTRACK_MAX_FILL", "CTRACK_MAX_TOP"]
CHOICE_FAMILIES = {"conditions": CONDITIONS_FAMILY, "noise": FAMILIES["noise"],
                   "half size": FAMILIES["half size"], "contrast": FAMILIES["contrast"],
                   "frame rate": RATE_FAMILY, "shift": FAMILIES["shift"]}
# The replay's floors, on the runs of make eval's conditions that are the
# replay's. The thresholds of 0.9.0 were chosen under the floors before
# them: 69.0 / 78.0, 68.0 / 76.5 and 31.0 / 51.0.
FLOORS = {("conditions", "PETS09-S2L1", "as it is"): PIXEL_FLOORS["PETS09-S2L1"],
          ("conditions", "PETS09-S2L1", "half size"): PIXEL_FLOORS["PETS09-S2L1 at half size"],
          ("conditions", "TUD-Campus", "as it is"): PIXEL_FLOORS["TUD-Campus"]}


def shipped():
    """The thresholds lib/template/classifier_params.inc holds, by name."""
    return dict(zip(NAMES, classifier_params()))


def evaluate(build, params, families, seqs, workers):
    """{(family, sequence): [(MOTA, IDF1, variant label), ...]}."""
    env = {k: "%.4f" % v for k, v in params.items()}
    keys, jobs = [], []
    for fam, variants in families.items():
        for seq in seqs:
            for label, vf, move in variants:
                keys.append((fam, seq, label))
                jobs.append(dict(build=build, seq=seq, vf=vf, move=move, env=env))
    with tempfile.TemporaryDirectory() as tmp:
        scores = run_all(jobs, tmp, workers)
    out = {}
    for (fam, seq, label), s in zip(keys, scores):
        out.setdefault((fam, seq), []).append((s["MOTA"], s["IDF1"], label))
    return out


def objective(out):
    """The objective, and a line of its parts."""
    total, parts, shortfall = 0.0, [], 0.0
    for (fam, seq), runs in sorted(out.items()):
        m = np.array([r[:2] for r in runs]).mean(0)
        total += m.sum()
        parts.append("%s, %s %.1f / %.1f" % (fam, seq, *m))
        for mota, idf1, label in runs:
            floor = FLOORS.get((fam, seq, label))
            if floor:
                shortfall += max(0, floor[0] - mota) + max(0, floor[1] - idf1)
                parts.append("[%s %s %.1f / %.1f]" % (seq, label, mota, idf1))
    return total - 10 * shortfall, "; ".join(parts)


def search(build, start, seqs, rounds, workers):
    cur = dict(start)
    searched = [n for n in NAMES if n != "CTRACK_MAX_TOP"]
    best, line = objective(evaluate(build, cur, CHOICE_FAMILIES, seqs, workers))
    print("start %.1f: %s" % (best, line), flush=True)
    for r in range(rounds):
        for name in searched:
            steps = ((0.85, 1.15) if r == 0 else (0.92, 1.08)) if "REGION" in name else (0.95, 1.05)
            for f in steps:
                trial = dict(cur)
                trial[name] = round(min(cur[name] * f, 1.0), 4)
                if trial[name] == cur[name]:
                    continue
                t, line = objective(evaluate(build, trial, CHOICE_FAMILIES, seqs, workers))
                print("%s = %.4f: %.1f: %s" % (name, trial[name], t, line), flush=True)
                if t > best + 0.5:
                    best, cur = t, trial
                    print("kept", json.dumps(cur), flush=True)
                    break
    return cur, best


def table(build, params, seqs, workers):
    """Mean (lowest) MOTA / IDF1 over each family, these thresholds beside
    the shipped ones, and the held-out conditions."""
    fams = dict(CHOICE_FAMILIES, **{"held out": HELD_OUT_FAMILY})
    res = {name: evaluate(build, p, fams, seqs, workers)
           for name, p in (("chosen", params), ("shipped", shipped()))}
    print("| family | sequence | chosen | shipped |")
    print("|---|---|---|---|")
    for fam in fams:
        for seq in seqs:
            cells = []
            for name in ("chosen", "shipped"):
                a = np.array([r[:2] for r in res[name][(fam, seq)]])
                cells.append("%.1f / %.1f (%.1f / %.1f)" % (*a.mean(0), *a.min(0)))
            print("| %s | %s | %s |" % (fam, seq, " | ".join(cells)))
    print("\n| variant | sequence | chosen | shipped |")
    print("|---|---|---|---|")
    for fam in fams:
        for seq in seqs:
            for c, s in zip(res["chosen"][(fam, seq)], res["shipped"][(fam, seq)]):
                print("| %s: %s | %s | %.1f / %.1f | %.1f / %.1f |"
                      % (fam, c[2], seq, c[0], c[1], s[0], s[1]))


def write(params):
    th = [params[n] for n in NAMES]
    with open(CLASSIFIER_PARAMS, "w") as f:
        f.write("// Generated by `eval/vote.py BUILD --write`: do not edit. Chosen by tracking\n"
                "// from the pixels alone (PETS09-S2L1 and TUD-Campus under make eval's\n"
                "// camera conditions and three families of conditions; docs/tuning.md,\n"
                "// \"The contour template's thresholds\").\n"
                "// Eq. (1)'s threshold per region (box heights), in region order: head,\n"
                "// neck, shoulders, chest, back, abdomen, buttocks, upper limbs, lower limbs;\n"
                "// then the vetoes: the largest part of its convex hull a pedestrian's blob\n"
                "// fills, and the widest top against the body.\n"
                "constexpr ClassifierParams kDefaultParams = {\n"
                "    {%s}, {%.4ff, %.4ff}};\n"
                % (", ".join("%.4ff" % t for t in th[:9]), th[9], th[10]))
    print("wrote", CLASSIFIER_PARAMS)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--start", help="JSON: the thresholds to start from (others shipped)")
    ap.add_argument("--sequences", help="choose on these only (comma-separated)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--write", action="store_true", help="rewrite lib/template/classifier_params.inc")
    ap.add_argument("--score", action="store_true", help="only score --start beside the shipped")
    a = ap.parse_args()
    start = shipped()
    start.update({k: float(v) for k, v in json.loads(a.start or "{}").items()})
    seqs = [s for s in sequences() if has_video(s)]
    if a.sequences:
        seqs = [s for s in seqs if s in a.sequences.split(",")]
    if a.score:
        table(a.build, start, seqs, a.jobs)
        return 0
    chosen, best = search(a.build, start, seqs, a.rounds, a.jobs)
    print("chosen (%.1f): %s" % (best, json.dumps(chosen)))
    if a.write:
        write(chosen)
    return 0


if __name__ == "__main__":
    sys.exit(main())
