#!/usr/bin/env python3
"""How python -m ctrack.batch scales with its workers on this machine:
frames per second over a batch of recordings, with 1 and 2 workers, on a
process pool and on a local Ray.

    PYTHONPATH=python .venv-eval/bin/python eval/batch_throughput.py BUILD_DIR \
        [--inputs N] [--repeats R] [--png PATH]

(the binding in python/ on the path, as make bench puts it there; the eval
venv, scripts/venv.sh eval, has Ray and the harness).

Each configuration runs R times, interleaved with the others (the machine's
speed drifts), and its median is kept. The batch is N copies of PETS09-S2L1 (768x576, 795 frames; links to the
cached Y4M under different names), tracked from the pixels alone. Prints a
Markdown table and draws it into PATH (default docs/img/batch-throughput.png).
"""
import argparse
import os
import sys
import tempfile
import time

from cteval.data import TOP, video


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("build")
    ap.add_argument("--inputs", type=int, default=8)
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--png", default=os.path.join(TOP, "docs", "img", "batch-throughput.png"))
    a = ap.parse_args()
    # The library of the build; Ray's workers and the pool's find the
    # binding as this process does, on PYTHONPATH.
    os.environ["CTRACK_LIBRARY"] = os.path.abspath(os.path.join(a.build, "lib", "libctrack.so"))
    try:
        from ctrack import batch
    except ImportError:
        raise SystemExit("batch_throughput: put the binding on the path: PYTHONPATH=python ...")

    src = video("PETS09-S2L1")
    tmp = tempfile.mkdtemp(prefix="ctrack-batch-")
    inputs = []
    for i in range(a.inputs):
        p = os.path.join(tmp, "pets-%02d.y4m" % i)
        os.symlink(src, p)
        inputs.append(p)
    runs = {}
    configs = [(mode, workers) for mode in ("processes", "ray") for workers in (1, 2)]
    for rep in range(a.repeats):
        for mode, workers in configs:
            out = os.path.join(tmp, "%s-%d-%d" % (mode, workers, rep))
            if mode == "ray":
                import ray
                ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
            t0 = time.perf_counter()
            rows = batch.run(inputs, out, workers=workers, ray=mode == "ray" or None,
                             progress=False)
            wall = time.perf_counter() - t0
            if mode == "ray":
                ray.shutdown()
            bad = [r for r in rows if r["status"] != "ok"]
            if bad:
                sys.exit("batch_throughput: %s" % bad[0])
            frames = sum(r["frames"] for r in rows)
            runs.setdefault((mode, workers), []).append(wall)
            print("%-9s %d worker(s): %d frames in %.1f s, %.0f frames/s"
                  % (mode, workers, frames, wall, frames / wall), file=sys.stderr)
    results = []
    for mode, workers in configs:
        wall = sorted(runs[(mode, workers)])[len(runs[(mode, workers)]) // 2]
        results.append((mode, workers, frames / wall, wall))
    print("| run on | workers | frames/s (median of %d) | seconds for %d recordings | "
          "against 1 worker |" % (a.repeats, a.inputs))
    print("|---|---|---|---|---|")
    for mode, workers, fps, wall in results:
        one = [r[2] for r in results if r[0] == mode and r[1] == 1][0]
        print("| %s | %d | %.0f | %.1f | %.2f |" % (mode, workers, fps, wall, fps / one))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 3.2))
    for mode, marker in (("processes", "o"), ("ray", "s")):
        pts = [(w, f) for m, w, f, _ in results if m == mode]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], marker=marker,
                label="process pool" if mode == "processes" else "Ray (local)")
    ax.set_xticks([1, 2])
    ax.set_xlabel("workers")
    ax.set_ylabel("frames/s, whole batch")
    ax.set_ylim(bottom=0)
    ax.set_title("ctrack.batch: %d x PETS09-S2L1, pixels only" % a.inputs, fontsize=10)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.png, dpi=100)


if __name__ == "__main__":
    main()
