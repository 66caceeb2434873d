"""make eval's condition families (eval/cteval/families.py): each variant's
ground truth and detections are moved as its ffmpeg filter moves the
frames, so a variant scores as the frames as they are do."""
import os
import subprocess
from fractions import Fraction

import pytest

from cteval.data import moved_boxes, video
from cteval.families import (FAMILIES, RATE_FAMILY, SCALE_FAMILY, Coded, half_mirrored,
                             run_variant, shifted, variant_stream)
from cteval.y4m import i420_planes, open_y4m

from conftest import TOP

CT_TRACK = os.environ.get("CTRACK_CT_TRACK", os.path.join(TOP, "build", "tools", "ct-track"))
BUILD = os.path.dirname(os.path.dirname(CT_TRACK))


def first_luma(y4m):
    """The luma plane of a Y4M file's first frame."""
    w, h, _, frames = open_y4m(y4m)
    return i420_planes(frames[0], w, h)[0]


def stream_to(seq, vf, out):
    """The variant's frames (variant_stream()) written to the Y4M file out;
    every ffmpeg process of it must succeed."""
    pipeline = variant_stream(seq, vf)
    with open(out, "wb") as f:
        f.write(pipeline[-1].stdout.read())
    pipeline[-1].stdout.close()
    assert [p.wait() for p in pipeline] == [0] * len(pipeline)
    return out


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


def test_a_cut_variant_scores_as_the_frames_do(tmp_path):
    # The frames cut by 4 pixels from the top left corner: every box moves
    # by (-4, -4) and the tracks score about as the frames as they are
    # (TUD-Campus 27.3 / 40.4 MOTA / IDF1); the boxes left where they were
    # would lose most matches at IoU 0.5 only for small people, so the move
    # itself is checked too.
    assert shifted(4, 4)((100, 50, 40, 120), 640, 480) == (96, 46, 40, 120)
    label, vf, move = FAMILIES["shift"][-1]
    assert label == "cut at 4, 4" and vf.endswith("crop=iw-4:ih-4:4:4")
    s = run_variant(BUILD, "TUD-Campus", vf, move, str(tmp_path / "tracks.txt"))
    assert s["MOTA"] > 10 and s["IDF1"] > 30, s


def test_every_cut_moves_the_picture_by_its_offset(tmp_path):
    # The shift family is there to move each pixel to another place of the
    # working scale's blocks: an odd offset must cut an odd number of
    # columns and rows. (ffmpeg's crop on 4:2:0 frames rounds an odd offset
    # down to an even one: the family would read five pictures, every pixel
    # in the same place of its block.) Each variant's first frame is
    # TUD-Campus's first frame moved by its offset, luma byte for byte.
    src = video("TUD-Campus")
    first = first_luma(src)
    h, w = first.shape
    for label, vf, move in FAMILIES["shift"]:
        dx, dy = (int(v) for v in label[len("cut at "):].split(", "))
        assert move((100, 50, 40, 120), w, h) == (100 - dx, 50 - dy, 40, 120)
        out = str(tmp_path / "cut.y4m")
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", src, "-frames:v", "1", "-vf", vf,
                        "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", out], check=True)
        cut = first_luma(out)
        assert cut.shape == (h - 4, w - 4), label
        assert (cut == first[dy:dy + h - 4, dx:dx + w - 4]).all(), label


def test_a_lower_rate_scores_the_frames_it_keeps(tmp_path):
    # Every second frame from the second: ffmpeg keeps frames 2, 4, ...,
    # numbered again from 1, and the ground truth of those frames is the
    # one scored (TUD-Campus 20.3 / 45.1); against every frame's ground
    # truth the tracks would miss half the boxes and match the rest to the
    # wrong frames.
    label, vf, move = RATE_FAMILY[1]
    assert label == "1/2 of the frame rate, from frame 2"
    s = run_variant(BUILD, "TUD-Campus", vf, move, str(tmp_path / "tracks.txt"))
    assert s["MOTA"] > 10 and s["IDF1"] > 30, s
    with open(str(tmp_path / "tracks.txt")) as f:
        frames = {int(line.split(",")[0]) for line in f}
    assert max(frames) <= 36


def test_each_scale_moves_the_boxes_as_the_frames(tmp_path):
    # The scale family's boxes are moved by its factor, so the frames must
    # be scaled by exactly that factor: ffmpeg's size is rounded to even
    # numbers, which for both sequences with frames is the exact size. The
    # first frame of each variant is checked at its size.
    src = video("TUD-Campus")
    h, w = first_luma(src).shape
    for label, vf, move in SCALE_FAMILY:
        f = float(label[len("scaled by "):])
        assert move((100, 50, 40, 120), w, h) == pytest.approx((100 * f, 50 * f, 40 * f, 120 * f))
        for sw, sh in ((640, 480), (768, 576)):
            assert (sw * f) % 2 == 0 and (sh * f) % 2 == 0, (label, sw, sh)
        out = str(tmp_path / "scaled.y4m")
        subprocess.run(["ffmpeg", "-v", "error", "-y", "-i", src, "-frames:v", "1", "-vf", vf,
                        "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", out], check=True)
        assert first_luma(out).shape == (round(h * f), round(w * f)), label


def test_a_coded_variant_is_the_clip_through_a_camera_s_encoder(tmp_path):
    # The compression family's lowest quality: every frame comes back, at
    # the clip's size, and its pixels are the clip's with the encoder's
    # losses (a few grey levels on average, not none and not another
    # picture); the same encoding twice gives the same pixels, so that
    # make eval's scores do not move from one run to the next.
    labels = [label for label, _, _ in FAMILIES["compression"]]
    assert "H.264 crf 38, keyframe every 250" in labels
    vf = Coded(38, 250)
    src = video("TUD-Campus")
    w, h, _, frames = open_y4m(src)
    decoded = []
    for k in range(2):
        decoded.append(open_y4m(stream_to("TUD-Campus", vf, str(tmp_path / ("coded%d.y4m" % k)))))
    cw, ch, _, coded = decoded[0]
    assert (cw, ch) == (w, h) and len(coded) == len(frames) == 71
    assert (coded == decoded[1][3]).all()
    for i in (0, 35, 70):
        a = i420_planes(frames[i], w, h)[0].astype(int)
        b = i420_planes(coded[i], w, h)[0].astype(int)
        assert 0.5 < abs(a - b).mean() < 8, i
    s = run_variant(BUILD, "TUD-Campus", vf, None, str(tmp_path / "tracks.txt"))
    assert s["MOTA"] > 0 and s["IDF1"] > 20, s


def test_a_ghosting_variant_blends_each_frame_with_the_ones_before(tmp_path):
    # Each variant's frame k is its weights' blend of the clip's frames k-n+1
    # .. k, the oldest's weight first: the frame before at a quarter is
    # 1/4 of frame k-1 and 3/4 of frame k (not the other way round, which
    # would be a ghost ahead of the person), within ffmpeg's rounding. The
    # first frame is the clip's own.
    src = video("TUD-Campus")
    w, h, _, frames = open_y4m(src)
    luma = [i420_planes(f, w, h)[0].astype(float) for f in frames[:4]]
    for label, vf, move in FAMILIES["ghosting"]:
        assert move is None
        weights = [float(x) for x in vf.split("weights=")[1].split()]
        # The label's shares are the frames before's, oldest first.
        shares = [Fraction(x) for x in label.split(" at ")[1].split(" and ")]
        assert shares == [Fraction(int(wt), int(sum(weights))) for wt in weights[:-1]], label
        gw, gh, _, ghost = open_y4m(stream_to("TUD-Campus", vf, str(tmp_path / "ghost.y4m")))
        assert (gw, gh) == (w, h) and len(ghost) == len(frames), label
        first = i420_planes(ghost[0], w, h)[0].astype(float)
        assert abs(first - luma[0]).mean() < 0.5, label
        k = 3
        got = i420_planes(ghost[k], w, h)[0].astype(float)
        n = len(weights)
        blend = sum(wt * luma[k - n + 1 + i] for i, wt in enumerate(weights)) / sum(weights)
        backward = sum(wt * luma[k - i] for i, wt in enumerate(weights)) / sum(weights)
        assert abs(got - blend).mean() < 0.75, label
        if weights != weights[::-1]:
            assert abs(got - backward).mean() > 2 * abs(got - blend).mean() + 0.5, label
    s = run_variant(BUILD, "TUD-Campus", FAMILIES["ghosting"][0][1], None,
                    str(tmp_path / "tracks.txt"))
    assert s["MOTA"] > 0 and s["IDF1"] > 20, s


def test_a_walkers_trail_is_left_out_of_the_foreground(tmp_path):
    # PETS09-S2L1's people walk a few working pixels a frame: with each
    # frame blended with the one before at a half, the trail behind each
    # is as wide as a stride. The background model learns the blend's
    # weight and leaves the trail out (lib/pixels/trail.h): 72.3 MOTA from
    # the pixels alone, online, against 68.8 with the trail in the
    # foreground and 75.2 on the clean frames (docs/tuning.md, "A walker's
    # trail").
    half = [vf for label, vf, _ in FAMILIES["ghosting"] if label.endswith(" 1/2")]
    assert half == ["tmix=frames=2:weights=1 1"]
    s = run_variant(BUILD, "PETS09-S2L1", half[0], None, str(tmp_path / "tracks.txt"))
    assert s["MOTA"] >= 71, s
