#!/usr/bin/env python3
"""ct-track against damaged files: a fixed-seed stream of mutations of a
small Y4M video, of a detections file and of parameters (bytes changed, cut
or repeated; numbers made NaN, infinite, huge, negative or empty; header
fields broken). Each run must end with status 0 (done), 1 (a bad input,
with a message) or 2 (bad usage, with a message): never a signal, a hang
or another status. Under `make sanitize` every run is also a memory and
undefined-behaviour check.

    mutated_inputs.py CT_TRACK [RUNS]

Prints one line per failure and a summary; exits 1 if any run failed.
Standard library only.
"""
import os
import random
import re
import subprocess
import sys
import tempfile

TOKENS = [b"9999999999", b"-1", b"nan", b"inf", b"1e308", b" ", b",", b"\n", b"0", b"W0",
          b"H0", b"F0:0", b"C422", b"X", b"FRAME\n", b"\0", b"-9223372036854775808",
          b"4294967296"]
NUMBERS = [b"nan", b"-inf", b"1e39", b"-5", b"0", b"65536", b"2147483648",
           b"18446744073709551616", b"1e-45", b"0x10", b""]
PARAMS = ["high_score", "low_score", "match_iou", "min_hits", "lost_lifetime", "motion_noise",
          "max_tracks", "mean_shift_max_time", "model_learning_rate", "candidate_min_score",
          "appearance_weight", "reid_max_speed", "verify_detections", "mean_shift_coarse_below"]
VALUES = ["nan", "inf", "-1", "0", "1e30", "1e-30", "3", "abc", "", "2147483648", "-0"]


def video(w=64, h=48, frames=4):
    out = bytearray(b"YUV4MPEG2 W%d H%d F7:1 Ip A1:1 C420jpeg\n" % (w, h))
    for k in range(frames):
        out += b"FRAME\n" + bytes((k * 7 + i) % 256 for i in range(w * h))
        out += b"\x80" * (2 * ((w + 1) // 2) * ((h + 1) // 2))
    return bytes(out)


def mutate(rng, data):
    if rng.random() < 0.05:  # next to nothing left
        return rng.choice([b"", b"#\n", b"\n\n", data[:data.find(b"\n") + 1]])
    b = bytearray(data)
    for _ in range(rng.randrange(1, 6)):
        if not b:
            b = bytearray(b"x")
        i = rng.randrange(len(b))
        op = rng.randrange(6)
        if op == 0:
            b[i] = rng.randrange(256)
        elif op == 1:
            del b[i:i + rng.randrange(1, 20)]
        elif op == 2:
            b[i:i] = rng.choice(TOKENS)
        elif op == 3:
            del b[i:]
        elif op == 4:
            b[i:i] = b[i:i + rng.randrange(1, 64)]
        else:
            numbers = list(re.finditer(rb"-?[0-9.]+", bytes(b)))
            if numbers:
                m = rng.choice(numbers)
                b[m.start():m.end()] = rng.choice(NUMBERS)
    return bytes(b)


def main():
    ct = sys.argv[1]
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 300
    rng = random.Random(2026)
    base_video = video()
    base_det = b"".join(b"%d,-1,%d,%d,12,30,0.9,-1,-1,-1\n" % (f, 10 + f, 5 + f)
                        for f in range(1, 5))
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        vpath, dpath = os.path.join(tmp, "in.y4m"), os.path.join(tmp, "det.txt")
        for run in range(runs):
            kind = rng.randrange(4)
            v = mutate(rng, base_video) if kind in (0, 1) else base_video
            d = None if kind == 0 else (base_det if kind == 1 else mutate(rng, base_det))
            with open(vpath, "wb") as f:
                f.write(v)
            cmd = [ct, "-q"]
            if kind == 3:
                cmd += ["-p", "%s=%s" % (rng.choice(PARAMS), rng.choice(VALUES))]
            if d is not None:
                with open(dpath, "wb") as f:
                    f.write(d)
                cmd += ["-d", dpath]
            if rng.random() < 0.3:
                cmd += ["--overlay", os.devnull, "--overlay-candidates"]
            stdin = None
            if rng.random() < 0.2:
                cmd.append("-")
                stdin = open(vpath, "rb")
            else:
                cmd.append(vpath)
            try:
                r = subprocess.run(cmd, stdin=stdin or subprocess.DEVNULL, capture_output=True,
                                   timeout=120)
            except subprocess.TimeoutExpired:
                failed += 1
                print("FAIL run %d: no end after 120 s: %s" % (run, " ".join(cmd[1:])))
                continue
            finally:
                if stdin:
                    stdin.close()
            err = r.stderr.decode(errors="replace")
            if "runtime error:" in err or "Sanitizer" in err:
                failed += 1
                print("FAIL run %d: a sanitizer's report: %s\n%s" % (run, " ".join(cmd[1:]),
                                                                   err[-2000:]))
            elif r.returncode not in (0, 1, 2):
                failed += 1
                print("FAIL run %d: status %d: %s\n%s" % (run, r.returncode, " ".join(cmd[1:]),
                                                          err[-2000:]))
            elif r.returncode != 0 and not err.startswith("ct-track"):
                failed += 1
                print("FAIL run %d: status %d without a message: %r" % (run, r.returncode,
                                                                        err[:300]))
    print("%d runs on damaged inputs, %d failed" % (runs, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
