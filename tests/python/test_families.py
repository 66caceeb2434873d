"""make eval's condition families (eval/cteval/families.py): each variant's
ground truth and detections are moved as its ffmpeg filter moves the
frames, so a variant scores as the frames as they are do."""
import os

import pytest

from cteval.data import moved_boxes
from cteval.families import FAMILIES, half_mirrored, run_variant

from conftest import TOP

CT_TRACK = os.environ.get("CTRACK_CT_TRACK", os.path.join(TOP, "build", "tools", "ct-track"))
BUILD = os.path.dirname(os.path.dirname(CT_TRACK))


def test_boxes_move_with_the_frames(tmp_path):
    # TUD-Campus is 640 x 480: a box at (100, 50), 40 x 120, at half size
    # and mirrored is at ((640 - 100 - 40) / 2, 25), 20 x 60.
    assert half_mirrored((100, 50, 40, 120), 640, 480) == (250, 25, 20, 60)
    path = moved_boxes("TUD-Campus", "gt", half_mirrored, str(tmp_path / "gt.txt"))
    with open(path) as f:
        first = [float(v) for v in f.readline().split(",")]
    with open(os.path.join(os.path.dirname(__file__), "..", "data", "mot15", "TUD-Campus",
                           "gt", "gt.txt")) as f:
        src = [float(v) for v in f.readline().split(",")]
    assert first[2:6] == pytest.approx(list(half_mirrored(src[2:6], 640, 480)), abs=1e-3)
    assert first[:2] == src[:2] and first[6:] == src[6:]


def test_a_moved_variant_scores_as_the_frames_do(tmp_path):
    # From the pixels alone (the frames are what moved), TUD-Campus at half
    # size and mirrored tracks about as well as the frames as they are (30
    # MOTA); scored against boxes left where they were it falls below -30.
    label, vf, move = FAMILIES["half size"][1]
    assert "mirrored" in label
    s = run_variant(BUILD, "TUD-Campus", vf, move, str(tmp_path / "tracks.txt"))
    assert s["MOTA"] > 10 and s["IDF1"] > 30, s
