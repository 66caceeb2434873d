#!/usr/bin/env python3
"""Coordinate search for the defaults of tracking from detections, under the
floors of the modes where ctrack must not lose ground.

    search.py BUILD_DIR '{"NAME": [V1, V2, ...], ...}' [--base '{"NAME": V}']
              [--rounds N] [--no-modes]

Each round tries, parameter by parameter, every value given with the others
at the best so far, and keeps a value that raises the objective: MOTA +
IDF1 over every sequence of tests/data/mot15 together, detections only
(py-motmetrics' OVERALL), less 100 for each point under a floor. The
floors are the replay test's: PETS09-S2L1 and TUD-Campus from detections,
and (unless --no-modes) with their frames and from the pixels alone. A NAME
starting CTRACK_ is set in the environment (a tuning build, meson
-Dtuning=true). Two processes run at once. Prints each step and the best.
"""
import argparse
import json
import multiprocessing
import os
import subprocess
import tempfile

import motmetrics as mm

from cteval.data import DATA, PIXEL_FLOORS, ct_track, seqinfo, sequences, video

# (MOTA, IDF1) floors, as tests/replay.sh checks them.
FLOORS = {"PETS09-S2L1": (68.0, 68.5), "TUD-Campus": (74.0, 81.0),
          "ADL-Rundle-8": (31.0, 38.5), "ETH-Bahnhof": (45.0, 55.0),
          "KITTI-13": (27.0, 49.0), "Venice-2": (20.0, 43.5)}
MODE_FLOORS = {("PETS09-S2L1", "detections + pixels"): (70.0, 75.0),
               ("TUD-Campus", "detections + pixels"): (75.5, 80.5),
               ("PETS09-S2L1", "pixels"): PIXEL_FLOORS["PETS09-S2L1"],
               ("TUD-Campus", "pixels"): PIXEL_FLOORS["TUD-Campus"]}

BUILD = None
_GT = {}


def gt(seq):
    if seq not in _GT:
        _GT[seq] = mm.io.loadtxt(os.path.join(DATA, seq, "gt", "gt.txt"), fmt="mot15-2D",
                                 min_confidence=1)
    return _GT[seq]


def accumulate(seq, cfg, mode, tmp):
    info = seqinfo(seq)
    env, cmd = dict(os.environ), [ct_track(BUILD), "-q", "-r", str(info["fps"])]
    for k, v in cfg.items():
        if k.startswith("CTRACK_"):
            env[k] = str(v)
        else:
            cmd += ["-p", "%s=%s" % (k, v)]
    if mode != "pixels":
        cmd += ["-d", os.path.join(DATA, seq, "det", "det.txt")]
    if mode == "detections":
        cmd += ["-s", "%dx%d" % (info["width"], info["height"])]
    else:
        cmd.append(video(seq))
    out = os.path.join(tmp, "t.txt")
    subprocess.run(cmd + ["-o", out], check=True, env=env)
    return mm.utils.compare_to_groundtruth(gt(seq), mm.io.loadtxt(out, fmt="mot15-2D"), "iou",
                                           distth=0.5)


def evaluate(args):
    cfg, modes = args
    seqs = sequences()
    with tempfile.TemporaryDirectory() as tmp:
        accs = [accumulate(s, cfg, "detections", tmp) for s in seqs]
        r = mm.metrics.create().compute_many(accs, names=seqs, metrics=["mota", "idf1"],
                                             generate_overall=True)
        out = {n: (100 * r.loc[n, "mota"], 100 * r.loc[n, "idf1"]) for n in r.index}
        if modes:
            for (seq, mode) in MODE_FLOORS:
                acc = accumulate(seq, cfg, mode, tmp)
                m = mm.metrics.create().compute(acc, metrics=["mota", "idf1"], name="x")
                out["%s, %s" % (seq, mode)] = (100 * m.loc["x", "mota"], 100 * m.loc["x", "idf1"])
    return out


def objective(r):
    j = r["OVERALL"][0] + r["OVERALL"][1]
    floors = dict(FLOORS)
    floors.update({"%s, %s" % k: v for k, v in MODE_FLOORS.items()})
    for name, (m, i) in floors.items():
        if name in r:
            j -= 100 * (max(0.0, m - r[name][0]) + max(0.0, i - r[name][1]))
    return j


def line(r):
    return "  ".join("%s %.1f/%.1f" % (n, *v) for n, v in r.items())


def main():
    global BUILD
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("space", help="JSON: each parameter's values (null: its default)")
    ap.add_argument("--base", default="{}", help="JSON: the starting point")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--no-modes", action="store_true",
                    help="detections only: no floors with the frames")
    a = ap.parse_args()
    BUILD = a.build
    space, best = json.loads(a.space), json.loads(a.base)
    modes = not a.no_modes
    cache = {}
    with multiprocessing.Pool(2, initializer=globals().update, initargs=({"BUILD": BUILD},)) as pool:
        def run(cfgs):
            todo = [c for c in cfgs if json.dumps(c, sort_keys=True) not in cache]
            for c, r in zip(todo, pool.map(evaluate, [(c, modes) for c in todo])):
                cache[json.dumps(c, sort_keys=True)] = r
            return [cache[json.dumps(c, sort_keys=True)] for c in cfgs]
        br = run([best])[0]
        bj = objective(br)
        print("start %s: %.2f  %s" % (json.dumps(best), bj, line(br)), flush=True)
        for rnd in range(a.rounds):
            improved = False
            for name, values in space.items():
                cands = []
                for v in values:
                    c = dict(best)
                    if v is None:
                        c.pop(name, None)
                    else:
                        c[name] = v
                    cands.append(c)
                for c, r in zip(cands, run(cands)):
                    if objective(r) > bj + 0.05:
                        best, br, bj, improved = c, r, objective(r), True
                print("round %d, %s = %s: %.2f  %s" % (rnd + 1, name, best.get(name), bj, line(br)),
                      flush=True)
            if not improved:
                break
    print("best %s: %.2f  %s" % (json.dumps(best), bj, line(br)))


if __name__ == "__main__":
    main()
