"""eval/barycenter_breakdown.py's split of the barycenter error: how much of
a box another box of its frame covers, and which of the two is in front."""
import os
import sys

import numpy as np

from conftest import TOP

sys.path.insert(0, os.path.join(TOP, "eval"))
import barycenter_breakdown  # noqa: E402


def test_cover_and_front():
    # Frame 1: a person (0) half covered by one in front of them (1, feet
    # lower), and a third far away (2). Frame 2: the first one alone.
    boxes = np.array([[100, 100, 20, 60], [110, 120, 20, 60], [300, 100, 20, 60],
                      [100, 100, 20, 60]], dtype=float)
    frames = np.array([1, 1, 1, 2])
    share, front = barycenter_breakdown.covered_by_other(boxes, frames)
    assert share[0] == (10 * 40) / (20 * 60)
    assert share[1] == (10 * 40) / (20 * 60)
    assert share[2] == 0 and share[3] == 0
    assert front[1] and not front[0]


def test_lookup_finds_rows_by_frame_and_id():
    table = np.array([[1, 5, 0, 0, 1, 1], [1, 7, 0, 0, 1, 1], [2, 5, 0, 0, 1, 1]])
    assert list(barycenter_breakdown.lookup(table, [2, 1], [5, 7])) == [2, 1]
