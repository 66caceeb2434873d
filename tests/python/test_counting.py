"""Counting from Python: Tracker.add_line, add_zone, events() and counts()."""
import os

import numpy as np
import pytest

import ctrack
from conftest import DATA


def walker(tracker, points, t0=0.0):
    """Feeds one person 100 px tall whose feet follow `points`, a step each
    tenth of a second; returns every step's events, concatenated."""
    events = []
    for k, (x, y) in enumerate(points):
        tracker.feed(detections=[[x - 20, y - 100, 40, 100, 0.97]], timestamp=t0 + 0.1 * k)
        events.append(tracker.events())
    return np.concatenate(events)


def test_a_line_and_a_zone():
    with ctrack.Tracker(min_hits=3) as t:
        t.feed(timestamp=0.0)
        door = t.add_line((100, 300), (540, 300), name="door")
        shop = t.add_zone([(250, 320), (400, 320), (400, 460), (250, 460)], name="shop")
        assert (door, shop) == (0, 0)
        ev = walker(t, [(320, 200 + 10 * k) for k in range(21)], t0=0.1)
        assert ev.dtype == ctrack.EVENT_DTYPE
        kinds = list(ev["kind"])
        assert kinds == [ctrack.EVENT_LINE_IN, ctrack.EVENT_ZONE_ENTER]
        assert list(ev["track_id"]) == [1, 1]
        c = t.counts()
        assert c["lines"] == {"door": {"in": 1, "out": 0}}
        z = c["zones"]["shop"]
        assert (z["entered"], z["exited"], z["inside"]) == (1, 0, 1)
        assert list(z["occupants"]) == [1]
        assert z["occupants"][1] >= 0


def test_bad_lines_and_zones_raise_and_add_nothing():
    with ctrack.Tracker() as t:
        t.add_line((0, 0), (10, 0), name="taken")
        for args, kw in [(((0, 0), (0, 0)), {}),
                         (((float("nan"), 0), (10, 0)), {}),
                         (((0, 0), (10, float("inf"))), {}),
                         (((0, 0), (10, 0)), {"name": "taken"}),
                         (((0, 0), (10, 0)), {"name": "x" * 40}),
                         (((0, 0), (10, 0)), {"hysteresis": -1})]:
            with pytest.raises(ValueError):
                t.add_line(*args, **kw)
        for a in [(0,), (True, 0), ("0", "0"), "ab", 5]:  # float() would take the second and third
            with pytest.raises(ValueError, match="not a point"):
                t.add_line(a, (10, 0))
        with pytest.raises(ValueError, match="not a point"):
            t.add_zone([(0, 0), (10, 0), (10, False)])
        for h in (True, "0.2"):
            with pytest.raises(TypeError, match="hysteresis"):
                t.add_line((0, 0), (10, 0), hysteresis=h)
        with pytest.raises(TypeError):
            t.add_line((0, 0), (10, 0), name=5)
        for pts in [[(0, 0), (10, 10), (10, 0), (0, 10)],  # crosses itself
                    [(0, 0), (5, 5), (10, 10)],            # no area
                    [(0, 0), (1, 1)],                       # two corners
                    [(np.cos(a), np.sin(a)) for a in np.linspace(0, 6, 65)]]:
            with pytest.raises(ValueError):
                t.add_zone(pts)
        assert list(t.counts()["lines"]) == ["taken"]
        assert t.counts()["zones"] == {}


def test_crossings_on_pets_detections_equal_the_counts():
    """On PETS09-S2L1's detections, a line across the square: every step's
    events add up to the counts, and people cross it both ways."""
    path = os.path.join(DATA, "PETS09-S2L1", "det", "det.txt")
    det = np.loadtxt(path, delimiter=",")
    with ctrack.Tracker(fps=7) as t:
        t.add_line((0, 400), (768, 400), name="middle")
        seen = {ctrack.EVENT_LINE_IN: 0, ctrack.EVENT_LINE_OUT: 0}
        for frame in range(1, int(det[:, 0].max()) + 1):
            rows = det[det[:, 0] == frame]
            t.feed(detections=rows[:, 2:7], timestamp=(frame - 1) / 7)
            for e in t.events():
                seen[int(e["kind"])] += 1
        c = t.counts()["lines"]["middle"]
        assert (c["in"], c["out"]) == (seen[ctrack.EVENT_LINE_IN], seen[ctrack.EVENT_LINE_OUT])
        assert c["in"] >= 3 and c["out"] >= 3


@pytest.mark.parametrize("struct", ["ct_line", "ct_zone"])
def test_header_states_the_hysteresis_the_library_has(struct):
    """ct_line's and ct_zone's hysteresis: the default and range the header
    states are ct_*_default()'s and what ct_tracker_add_*() takes; make
    eval counts the ground truth with the same default."""
    import ctypes
    import re
    from conftest import TOP
    from ctrack import _abi
    from cteval import counting
    with open(os.path.join(TOP, "include", "ctrack", "ctrack.h")) as f:
        text = f.read()
    body = text[text.index("typedef struct %s {" % struct):text.index("} %s;" % struct)]
    m = re.search(r"Default ([0-9.]+), range \[([0-9.]+), ([0-9.]+)\]", body)
    default, lo, hi = (float(v) for v in m.groups())
    lib = ctrack.load()
    cls = _abi.Line if struct == "ct_line" else _abi.Zone
    s = cls()
    getattr(lib, struct + "_default")(ctypes.byref(s), ctypes.sizeof(s))
    assert s.hysteresis == pytest.approx(default)
    assert counting.HYSTERESIS == pytest.approx(default)
    square = [(0, 0), (100, 0), (100, 100), (0, 100)]
    with ctrack.Tracker() as t:
        for h, ok in [(lo, True), (hi, True), (lo - 1e-3, False), (hi + 1e-3, False)]:
            add = (lambda: t.add_line((0, 0), (10, 0), hysteresis=h)) if struct == "ct_line" \
                else (lambda: t.add_zone(square, hysteresis=h))
            if ok:
                add()
            else:
                with pytest.raises(ValueError, match="hysteresis"):
                    add()


def test_eval_counts_by_the_library_s_rule():
    """eval/cteval/counting.py's rule, on the tracks ct-track reports,
    counts what the library counts as it tracks, on PETS09-S2L1's
    detections (the library may count a little more: it knows where a
    track was before it was confirmed)."""
    import json
    import subprocess
    import tempfile
    from cteval import counting
    ct = os.environ["CTRACK_CT_TRACK"]
    with tempfile.TemporaryDirectory() as tmp:
        tracks, events = os.path.join(tmp, "t.txt"), os.path.join(tmp, "e.jsonl")
        subprocess.run([ct, "-q", "-d", os.path.join(DATA, "PETS09-S2L1", "det", "det.txt"),
                        "-s", "768x576", "-r", "7", "-o", tracks]
                       + counting.ct_track_args("PETS09-S2L1", events),
                       check=True, capture_output=True)
        lib = counting.count_events("PETS09-S2L1", events)
        rule = counting.count_rows("PETS09-S2L1", np.loadtxt(tracks, delimiter=","))
        with open(events) as f:
            assert all(json.loads(line)["kind"] == "cross" for line in f)
    total = sum(c[d] for c in lib.values() for d in counting.DIRECTIONS)
    differ = sum(abs(lib[n][d] - rule[n][d]) for n in lib for d in counting.DIRECTIONS)
    assert total > 50
    assert differ <= 0.05 * total, (lib, rule)
