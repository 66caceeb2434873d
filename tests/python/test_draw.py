"""ctrack.draw() draws what ct-track --overlay draws: TUD-Campus's first
frames, tracked with their detections and pixels by ct-track (with an
overlay) and by the binding (drawn by ctrack.draw on the BGR frames), give
the same picture up to the colour conversions; and the detection adapters
(from_xyxy, a supervision.Detections) give feed() the boxes they stand
for."""
import os
import subprocess

import numpy as np
import pytest

import ctrack
from conftest import DATA

TUD = os.path.join(DATA, "TUD-Campus")
W, H, FRAMES = 640, 480, 12


def y4m_planes(path):
    with open(path, "rb") as f:
        data = f.read()
    _, _, rest = data.partition(b"\n")
    size = W * H * 3 // 2
    return [np.frombuffer(c[:size], np.uint8).reshape(H * 3 // 2, W)
            for c in rest.split(b"FRAME\n")[1:]]


def i420_to_bgr(a):
    """BT.601 limited range back to BGR, each chroma sample over its 2x2."""
    y = a[:H].astype(np.float64) - 16
    u = a[H:H + H // 4].reshape(H // 2, W // 2).repeat(2, 0).repeat(2, 1) - 128.0
    v = a[H + H // 4:].reshape(H // 2, W // 2).repeat(2, 0).repeat(2, 1) - 128.0
    r = 1.164 * y + 1.596 * v
    g = 1.164 * y - 0.392 * u - 0.813 * v
    b = 1.164 * y + 2.017 * u
    return np.clip(np.round(np.dstack([b, g, r])), 0, 255).astype(np.uint8)


def luma(bgr):
    b, g, r = (bgr[..., i].astype(np.int32) for i in range(3))
    return ((66 * r + 129 * g + 25 * b + 128) >> 8) + 16


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    d = tmp_path_factory.mktemp("draw")
    y4m, overlay, tracks = str(d / "tud.y4m"), str(d / "overlay.y4m"), str(d / "tracks.txt")
    subprocess.run(["ffmpeg", "-v", "error", "-i", os.path.join(TUD, "video.mp4"), "-frames:v",
                    str(FRAMES), "-f", "yuv4mpegpipe", "-pix_fmt", "yuv420p", y4m], check=True)
    det = os.path.join(TUD, "det", "det.txt")
    subprocess.run([os.environ["CTRACK_CT_TRACK"], "-q", "-d", det, "--overlay", overlay,
                    "-o", tracks, y4m], check=True)
    with open(tracks) as f:
        ct_lines = f.read().splitlines()
    return y4m_planes(y4m), y4m_planes(overlay), ct_lines, np.loadtxt(det, delimiter=",")


def test_draw_matches_the_overlay(run):
    frames, overlay, ct_lines, det = run
    trails = ctrack.Trails()
    lines, drawn_pixels, agree = [], 0, 0
    with ctrack.Tracker(fps=25) as t:
        for k, (frame, ov) in enumerate(zip(frames, overlay), 1):
            tracks = t.feed(frame, det[det[:, 0] == k][:, 2:7], timestamp=(k - 1) / 25,
                            format="i420")
            lines += ctrack.mot_lines(k, tracks)
            trails.update(tracks)
            bgr = i420_to_bgr(frame)
            assert ctrack.draw(bgr, tracks, trails) is bgr
            mine, theirs, plain = luma(bgr), ov[:H].astype(np.int32), frame[:H].astype(np.int32)
            drawn = theirs != plain  # what the overlay drew on the frame
            drawn_pixels += int(drawn.sum())
            agree += int((np.abs(mine - theirs)[drawn] <= 6).sum())
            # Off the drawing, the picture is the frame (up to the round trip).
            assert np.mean(np.abs(mine - theirs)[~drawn] <= 3) > 0.99
    assert lines == ct_lines  # the same tracks
    assert drawn_pixels > 5000
    assert agree / drawn_pixels > 0.97, "%d of %d drawn pixels agree" % (agree, drawn_pixels)


def test_draw_in_rgb_and_grey(run):
    frames, _, _, det = run
    with ctrack.Tracker(fps=25) as t:
        tracks = t.feed(frames[0], det[det[:, 0] == 1][:, 2:7], format="i420")
    assert len(tracks) > 0
    bgr = ctrack.draw(i420_to_bgr(frames[0]), tracks)
    rgb = ctrack.draw(np.ascontiguousarray(i420_to_bgr(frames[0])[..., ::-1]), tracks,
                      format="rgb")
    assert np.array_equal(bgr, rgb[..., ::-1])
    grey = ctrack.draw(frames[0][:H].copy(), tracks)
    assert grey.shape == (H, W) and not np.array_equal(grey, frames[0][:H])
    with pytest.raises(ValueError, match="read-only"):
        ro = i420_to_bgr(frames[0])
        ro.flags.writeable = False
        ctrack.draw(ro, tracks)
    with pytest.raises(ValueError, match="format"):
        ctrack.draw(i420_to_bgr(frames[0]), tracks, format="yuv")


def test_from_xyxy_and_supervision(run):
    import supervision as sv
    xyxy = np.array([[10, 20, 50, 120, 0.9], [100.5, 40, 130.5, 110, 0.7]])
    want = np.array([[10, 20, 40, 100, 0.9], [100.5, 40, 30, 70, 0.7]])
    assert np.allclose(ctrack.from_xyxy(xyxy), want)
    with_class = ctrack.from_xyxy(np.hstack([xyxy, [[1], [3]]]))
    assert np.allclose(with_class[:, 5], [1, 3])
    with pytest.raises(ValueError, match="x1, y1, x2, y2"):
        ctrack.from_xyxy([[1, 2, 3]])
    frames, _, _, det = run
    rows = det[det[:, 0] == 1][:, 2:7]
    corners = np.hstack([rows[:, :2], rows[:, :2] + rows[:, 2:4]])
    d = sv.Detections(xyxy=corners, confidence=rows[:, 4], class_id=np.zeros(len(rows), int))
    with ctrack.Tracker(fps=25) as a, ctrack.Tracker(fps=25) as b:
        ta = a.feed(frames[0], rows, format="i420")
        tb = b.feed(frames[0], d, format="i420")
    assert len(ta) > 0
    assert np.array_equal(ta, tb)
