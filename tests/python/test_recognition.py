"""The recognition measure's labels (eval/recognition.py): a blob on a
person the ground truth lacks, listed in gt-omissions.txt, is an uncertain
negative, not a false positive of the contour template."""
import os
import sys

import numpy as np

from conftest import TOP

sys.path.insert(0, os.path.join(TOP, "eval"))
import recognition  # noqa: E402


def blob(frame, cx, cy, w=20, h=50):
    """A candidate row (frame, left, top, width, height, then the file's
    other columns, unread here)."""
    return [frame, cx - w / 2, cy - h / 2, w, h] + [0.0] * 14


def test_a_blob_on_the_man_by_the_parked_cars_is_uncertain():
    # PETS09-S2L1's gt-omissions.txt: frames 660-795, 60 pixels about
    # (740, 73). The same place before he comes, or another place with no
    # one, is a negative.
    c = np.array([blob(700, 745, 80), blob(600, 745, 80), blob(700, 520, 60)])
    assert list(recognition.in_omissions(c, "PETS09-S2L1")) == [True, False, False]
    labels, why = recognition.label(c, "PETS09-S2L1")
    assert labels[0] == recognition.UNCERTAIN and why[3][0]
    assert not why[3][1] and not why[3][2]


def test_a_sequence_without_omissions_has_none():
    c = np.array([blob(10, 300, 300)])
    assert not recognition.in_omissions(c, "TUD-Campus").any()
