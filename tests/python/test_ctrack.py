"""The Python binding through the real shared library."""
import configparser
import math
import os
import subprocess

import numpy as np
import pytest

import ctrack
from conftest import DATA


def load_dets(seq):
    d = np.loadtxt(os.path.join(DATA, seq, "det", "det.txt"), delimiter=",", ndmin=2)
    return {int(k): d[d[:, 0] == k][:, 2:7] for k in np.unique(d[:, 0])}


def seqinfo(seq):
    c = configparser.ConfigParser()
    c.read(os.path.join(DATA, seq, "seqinfo.ini"))
    s = c["Sequence"]
    return int(s["seqLength"]), float(s["frameRate"]), int(s["imWidth"]), int(s["imHeight"])


def test_version():
    assert ctrack.version().count(".") == 2
    assert ctrack.abi_version() == 1
    major, minor, patch = map(int, ctrack.version().split("."))
    assert ctrack.version_number() == (major << 16) | (minor << 8) | patch


def test_track_fields_are_those_of_ct_track():
    for name in ("id", "left", "top", "width", "height", "barycenter_x", "barycenter_y",
                 "velocity_x", "velocity_y", "confidence", "state", "age", "hits",
                 "time_since_update", "detection_index", "class_id"):
        assert name in ctrack.TRACK_DTYPE.names


def test_parameters_reach_the_library():
    t = ctrack.Tracker(min_hits=5, lost_lifetime=3.5)
    assert t.config["min_hits"] == 5
    assert t.config["lost_lifetime"] == 3.5
    t.close()


def test_bad_parameters_raise_with_the_library_message():
    with pytest.raises(ctrack.CtrackError, match="config.lost_lifetime"):
        ctrack.Tracker(lost_lifetime=-1)
    with pytest.raises(ctrack.CtrackError, match="config.high_score") as e:
        ctrack.Tracker(high_score=float("nan"))
    assert e.value.status == -1
    with pytest.raises(ctrack.CtrackError, match="config.candidate_min_score"):
        ctrack.Tracker(candidate_min_score=0.01)
    with pytest.raises(ctrack.CtrackError, match="config.verify_detections"):
        ctrack.Tracker(verify_detections=2)
    with pytest.raises(TypeError, match="unknown parameter 'bogus'"):
        ctrack.Tracker(bogus=1)
    with pytest.raises(TypeError):
        ctrack.Tracker(min_hits="three")
    with pytest.raises(ValueError, match="fps"):
        ctrack.Tracker(fps=0)
    with pytest.raises(ValueError, match="fps"):
        ctrack.Tracker(fps=True)
    with ctrack.Tracker(fps=np.float32(12.5)) as t:
        assert t.fps == 12.5


def test_integer_parameters_are_taken_whole_and_never_wrapped():
    # ctypes alone would store max_tracks=2**32 + 5 as 5 and refuse 2.0.
    with pytest.raises(ValueError, match="max_tracks=4294967301 is out of the range"):
        ctrack.Tracker(max_tracks=2**32 + 5)
    with pytest.raises(ValueError, match="min_hits=-2147483649 is out of the range"):
        ctrack.Tracker(min_hits=-2**31 - 1)
    with pytest.raises(ValueError, match="min_hits=2.5 is not a whole number"):
        ctrack.Tracker(min_hits=2.5)
    with pytest.raises(ValueError, match="min_hits=inf is not a whole number"):
        ctrack.Tracker(min_hits=float("inf"))
    with pytest.raises(TypeError, match="high_score=True is not a number"):
        ctrack.Tracker(high_score=True)
    with pytest.raises(ValueError, match="high_score=1e\\+300 is past the range of a float"):
        ctrack.Tracker(high_score=1e300)
    with ctrack.Tracker(min_hits=2.0, refine_boxes=0.0, mean_shift=False,
                        max_tracks=np.int64(7), high_score=np.float32(0.5)) as t:
        assert (t.config["min_hits"], t.config["refine_boxes"], t.config["mean_shift"],
                t.config["max_tracks"]) == (2, 0, 0, 7)
        assert t.config["high_score"] == 0.5


def test_replay_equals_ct_track(tmp_path):
    """The binding on TUD-Campus gives exactly what ct-track writes."""
    n, fps, w, h = seqinfo("TUD-Campus")
    dets = load_dets("TUD-Campus")
    lines = []
    with ctrack.Tracker(fps=fps) as t:
        for k in range(1, n + 1):
            lines += ctrack.mot_lines(k, t.feed(None, dets.get(k)))
    ct = os.environ.get("CTRACK_CT_TRACK")
    assert ct, "CTRACK_CT_TRACK must name ct-track (meson test sets it)"
    out = subprocess.run([ct, "-q", "-d", os.path.join(DATA, "TUD-Campus", "det", "det.txt"),
                          "-r", str(fps)], check=True, capture_output=True, text=True).stdout
    assert len(lines) > 200
    assert lines == out.splitlines()


def test_frames_of_every_kind():
    h, w = 48, 64
    rng = np.random.default_rng(1)
    grey = rng.integers(0, 255, (h, w), dtype=np.uint8)
    i420 = rng.integers(0, 255, (h * 3 // 2, w), dtype=np.uint8)
    bgr = rng.integers(0, 255, (h, w, 3), dtype=np.uint8)
    det = [[10, 5, 12, 30, 0.9]]
    with ctrack.Tracker() as t:
        assert len(t.feed(grey, det)) == 1
        assert len(t.feed(i420, det, format="i420")) == 1
        assert len(t.feed(i420, det, format="nv12")) == 1
        assert len(t.feed(bgr, det)) == 1
        assert len(t.feed(bgr[:47, :63], det)) == 1          # odd size
        assert len(t.feed(grey[:, ::1][::2], det)) == 1      # a strided view
        assert len(t.feed(None, det)) == 1


def test_bgr_conversion_matches_bt601():
    bgr = np.zeros((4, 4, 3), np.uint8)
    bgr[:] = (255, 255, 255)
    out = ctrack.bgr_to_i420(bgr)
    assert out.shape == (6, 4)
    assert out[0, 0] == 235 and out[4, 0] == 128
    bgr[:] = (0, 0, 0)
    assert ctrack.bgr_to_i420(bgr)[0, 0] == 16


@pytest.fixture(scope="module")
def tud_bgr():
    """TUD-Campus's frames as ffmpeg decodes them to BGR (once for the
    module), and its frame rate."""
    n, fps, w, h = seqinfo("TUD-Campus")
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i",
                          os.path.join(DATA, "TUD-Campus", "video.mp4"), "-f", "rawvideo",
                          "-pix_fmt", "bgr24", "-"], check=True, capture_output=True).stdout
    return np.frombuffer(raw, np.uint8).reshape(-1, h, w, 3), fps


def test_colour_frames_are_converted_by_the_library(tud_bgr):
    """BGR frames go to the library packed (0.8.0), which converts them as
    bgr_to_i420 does: on TUD-Campus from the pixels alone, every step's
    tracks and candidates are those of the I420 frames bgr_to_i420 makes,
    and the same pictures in RGB order (format='rgb') give them too, as do
    rows with padding between them; upside down, as their I420 does."""
    frames, fps = tud_bgr
    assert len(frames) == 71
    runs = {name: ctrack.Tracker(fps=fps, source=ctrack.SOURCE_PIXELS)
            for name in ("bgr", "i420", "rgb", "view", "flipped", "flipped i420")}
    assert runs["bgr"]._packed
    seen = 0
    for bgr in frames:
        out = {}
        for name, t in runs.items():
            if name == "bgr":
                tracks = t.feed(bgr)
            elif name == "i420":
                tracks = t.feed(ctrack.bgr_to_i420(bgr), format="i420")
            elif name == "rgb":  # a view whose channels run backwards: copied first
                tracks = t.feed(bgr[..., ::-1], format="rgb")
            elif name == "view":  # rows with padding between them: read through their stride
                padded = np.zeros((bgr.shape[0], bgr.shape[1] + 7, 3), np.uint8)
                padded[:, :bgr.shape[1]] = bgr
                tracks = t.feed(padded[:, :bgr.shape[1]], format="bgr")
            elif name == "flipped":  # upside down, rows running backwards: copied first
                tracks = t.feed(bgr[::-1])
            else:
                tracks = t.feed(ctrack.bgr_to_i420(bgr[::-1]), format="i420")
            out[name] = (tracks.tobytes(), t.candidates().tobytes())
        assert out["bgr"] == out["i420"] == out["rgb"] == out["view"]
        assert out["flipped"] == out["flipped i420"]
        seen += len(out["bgr"][0])
    assert seen > 100
    assert runs["bgr"].stats()["stages"]["convert"] > 0
    assert runs["i420"].stats()["stages"]["convert"] == 0
    for t in runs.values():
        t.close()


def test_odd_colour_frames_match_bgr_to_i420(tud_bgr):
    """Odd sizes: the library repeats the last row and column, as the padding
    of bgr_to_i420 does."""
    frames, _ = tud_bgr
    with ctrack.Tracker(source=ctrack.SOURCE_PIXELS) as a, \
            ctrack.Tracker(source=ctrack.SOURCE_PIXELS) as b:
        b._packed = False  # this package's own conversion, as with a library before 0.8.0
        for bgr in frames[:30]:
            odd = bgr[:479, :639]
            a.feed(odd)
            b.feed(odd)
            assert a.candidates().tobytes() == b.candidates().tobytes()
            assert a.tracks().tobytes() == b.tracks().tobytes()


def test_bad_colour_frames():
    bgr = np.zeros((48, 64, 3), np.uint8)
    with ctrack.Tracker() as t:
        with pytest.raises(ValueError, match="'bgr' or 'rgb'"):
            t.feed(bgr, format="i420")
        with pytest.raises(ValueError, match="HxWx3"):
            t.feed(np.zeros((48, 64, 4), np.uint8))
        with pytest.raises(ctrack.CtrackError, match="frame.width"):
            t.feed(np.zeros((0, 64, 3), np.uint8))


def test_timestamps():
    with ctrack.Tracker(fps=10) as t:
        t.feed(None, [[10, 10, 20, 40, 0.9]], timestamp=5.0)
        tr = t.feed(None, [[12, 10, 20, 40, 0.9]])            # 5.1 s
        assert tr["velocity_x"][0] > 0
        with pytest.raises(ctrack.CtrackError, match="timestamp_us") as e:
            t.feed(None, None, timestamp=5.0)
        assert e.value.status == -5
        with pytest.raises(ValueError, match="timestamp"):
            t.feed(None, None, timestamp=float("nan"))
        for far in (1e13, -1e13):  # beyond int64 microseconds: refused, not wrapped
            with pytest.raises(ValueError, match="outside int64"):
                t.feed(None, None, timestamp=far)
        t.feed(None, None, timestamp=9.2e12)  # the largest that fits, nearly
        for bad in (True, "9.21e12", 1j):  # float() would take the first two as seconds
            with pytest.raises(TypeError, match="timestamp"):
                t.feed(None, None, timestamp=bad)
        t.reset()
        assert len(t.feed(None, [[10, 10, 20, 40, 0.9]], timestamp=0.0)) == 1


def test_primed_on_real_frames_as_ct_track():
    """TUD-Campus from the pixels alone, primed on its first PRIME_SECONDS
    (ct_tracker_prime(), a look-ahead): the binding gives exactly what
    ct-track --prime writes reading the same frames from standard input,
    and both find at least as many of the people of its first second as a
    tracker fed live, which finds two thirds as many or more; fed live, it
    gives what ct-track gives by default."""
    n, fps, w, h = seqinfo("TUD-Campus")
    video = os.path.join(DATA, "TUD-Campus", "video.mp4")
    raw = subprocess.run(["ffmpeg", "-v", "error", "-i", video, "-f", "rawvideo",
                          "-pix_fmt", "yuv420p", "-"], check=True, capture_output=True).stdout
    frames = np.frombuffer(raw, np.uint8).reshape(-1, h * 3 // 2, w)
    start = frames[:math.ceil(ctrack.PRIME_SECONDS * fps)]

    def track(primed):
        lines = []
        with ctrack.Tracker(fps=fps, source=ctrack.SOURCE_PIXELS) as t:
            if primed:
                t.prime(start, format="i420")
            for k, f in enumerate(frames, 1):
                lines += ctrack.mot_lines(k, t.feed(f, format="i420", timestamp=(k - 1) / fps))
        return lines
    primed, live = track(True), track(False)
    y4m = subprocess.run(["ffmpeg", "-v", "error", "-i", video, "-f", "yuv4mpegpipe",
                          "-pix_fmt", "yuv420p", "-"], check=True, capture_output=True).stdout
    out = subprocess.run([os.environ["CTRACK_CT_TRACK"], "-q", "--prime",
                          str(ctrack.PRIME_SECONDS), "-"], input=y4m, check=True,
                         capture_output=True).stdout.decode()
    assert primed == out.splitlines()
    out = subprocess.run([os.environ["CTRACK_CT_TRACK"], "-q", "-"],
                         input=y4m, check=True, capture_output=True).stdout.decode()
    assert live == out.splitlines()

    def first_second(lines):
        return sum(int(line.split(",")[0]) <= fps for line in lines)
    # Live, what changed since the frame before stands in for the background
    # of the first second (docs/tuning.md, "The first second").
    assert first_second(primed) >= first_second(live)
    assert 3 * first_second(live) >= 2 * first_second(primed) > 0


def test_bad_priming_raises_and_changes_nothing():
    frame = np.full((48 * 3 // 2, 64), 128, np.uint8)
    with ctrack.Tracker(source=ctrack.SOURCE_PIXELS) as t:
        with pytest.raises(ValueError, match="at least one"):
            t.prime([])
        with pytest.raises(ValueError, match="None"):
            t.prime([frame, None], format="i420")
        with pytest.raises(ValueError, match="timestamps"):
            t.prime([frame, frame], [0.0], format="i420")
        with pytest.raises(ValueError, match="not finite"):
            t.prime([frame, frame], [0.0, float("nan")], format="i420")
        with pytest.raises(TypeError, match=r"timestamps\[1\]"):
            t.prime([frame, frame], [0.0, True], format="i420")  # not 1 s
        with pytest.raises(ctrack.CtrackError, match=r"frames\[1\].*does not increase"):
            t.prime([frame, frame], [0.0, 0.0], format="i420")
        small = np.full((24 * 3 // 2, 32), 128, np.uint8)
        with pytest.raises(ctrack.CtrackError, match=r"frames\[1\].*32x24.*64x48"):
            t.prime([frame, small], format="i420")
        t.feed(frame, format="i420", timestamp=1.0)
        t.prime([frame, frame], format="i420")
        t.feed(frame, format="i420", timestamp=0.0)  # the time was forgotten


def test_bad_input_raises_and_changes_nothing():
    with ctrack.Tracker() as t:
        before = t.feed(None, [[10, 10, 20, 40, 0.9]])
        with pytest.raises(ctrack.CtrackError, match=r"dets\[1\].width"):
            t.feed(None, [[10, 10, 20, 40, 0.9], [0, 0, float("nan"), 10, 0.5]])
        with pytest.raises(ValueError, match="shape"):
            t.feed(None, [[1, 2, 3]])
        with pytest.raises(ValueError, match="class"):
            t.feed(None, [[1, 2, 3, 4, 0.9, 0.5]])
        with pytest.raises(ValueError, match="uint8"):
            t.feed(np.zeros((4, 4), np.float32))
        with pytest.raises(ValueError, match="HxWx3"):
            t.feed(np.zeros((4, 4, 4), np.uint8))
        with pytest.raises(ValueError, match="format"):
            t.feed(np.zeros((6, 4), np.uint8), format="yuyv")
        with pytest.raises(ValueError, match="H\\*3/2"):
            t.feed(np.zeros((5, 4), np.uint8), format="i420")
        with pytest.raises(ValueError, match="format"):
            t.feed(None, format="i420")
        assert np.array_equal(t.tracks(), before)


def test_close_and_context_manager():
    t = ctrack.Tracker()
    t.close()
    t.close()
    with pytest.raises(ValueError, match="closed"):
        t.feed(None)
    with ctrack.Tracker() as t2:
        t2.feed(None)
    with pytest.raises(ValueError, match="closed"):
        t2.feed(None)


def test_many_tracks_grow_the_buffer():
    dets = [[40.0 * i, 10, 20, 40, 0.9] for i in range(150)]
    with ctrack.Tracker() as t:
        tr = t.feed(None, dets)
    assert len(tr) == 150
    assert list(tr["id"]) == list(range(1, 151))
    assert list(tr["detection_index"]) == list(range(150))


def test_wrong_abi_is_refused(tmp_path):
    with pytest.raises(ImportError):
        ctrack.load(str(tmp_path / "libnothing.so"))


def test_stats():
    with ctrack.Tracker() as t:
        for k in range(4):
            t.feed(None, [[10 + k, 10, 20, 40, 0.9], [100, 10, 20, 40, 0.9]])
        s = t.stats()
    assert s["steps"] == 4
    assert s["live_tracks"] == 2
    assert s["memory_bytes"] > 0
    assert set(s["stages"]) >= {"validate", "predict", "associate", "lifecycle", "report"}
    assert 0 < sum(s["stages"].values()) <= s["feed_seconds"]


def test_pixels_alone_on_real_frames():
    """TUD-Campus's first frames from the pixels alone: blobs are found and
    scored; the host may not add detections."""
    import subprocess as sp
    raw = sp.run(["ffmpeg", "-v", "error", "-i", os.path.join(DATA, "TUD-Campus", "video.mp4"),
                  "-frames:v", "30", "-f", "rawvideo", "-pix_fmt", "yuv420p", "-"],
                 check=True, capture_output=True).stdout
    frames = np.frombuffer(raw, np.uint8).reshape(-1, 480 * 3 // 2, 640)
    seen = 0
    with ctrack.Tracker(fps=25, source=ctrack.SOURCE_PIXELS) as t:
        assert t.person_size()["working_scale"] == 0
        for f in frames:
            t.feed(f, format="i420")
            # Its people (150 to 300 pixels tall) would take the pixels to
            # every fourth only after 200 boxes: 30 frames stay at 2.
            assert t.person_size()["working_scale"] == 2
            c = t.candidates()
            seen += len(c)
            assert set(c.dtype.names) >= {"left", "score", "votes_yes", "voters",
                                          "region_distance", "fill", "top_width"}
            assert np.all((c["score"] >= 0) & (c["score"] <= 1))
            assert np.all((c["fill"] >= 0) & (c["fill"] <= 1))
            assert np.all(c["top_width"] >= 0)
        with pytest.raises(ctrack.CtrackError, match="CT_SOURCE_PIXELS"):
            t.feed(frames[0], [[10, 10, 20, 40, 0.9]], format="i420")
    assert seen > 20


def test_person_size_is_learnt(tud_bgr):
    """TUD-Campus from its public detections: the tracker learns how tall a
    person is where they stand (a street-level camera: about 200 to 300
    pixels at the bottom rows of the image, fewer higher up), from nothing;
    a reset forgets it."""
    frames, fps = tud_bgr
    dets = load_dets("TUD-Campus")
    with ctrack.Tracker(fps=fps) as t:
        assert t.person_size()["known"] is False
        for k, f in enumerate(frames):
            t.feed(f, dets.get(k + 1, np.zeros((0, 5))))
        p = t.person_size()
        assert p["known"] and p["samples"] >= 20
        height = lambda y: p["height_slope"] * y + p["height_intercept"]
        assert 180 <= height(440) <= 320
        assert height(300) < height(440)
        assert 0.25 <= p["width_ratio"] <= 0.6
        t.reset()
        assert 150 <= p["typical_height"] <= 320
        # Detections with frames: the boxes are fitted to the silhouettes
        # (refine_boxes), so a foreground is found.
        assert p["working_scale"] in (1, 2, 4)
        t.reset()
        assert t.person_size() == {"known": False, "height_slope": 0.0,
                                   "height_intercept": 0.0, "width_ratio": 0.0, "samples": 0,
                                   "typical_height": 0.0, "working_scale": 0}


def test_verify_detections_on_real_frames():
    """TUD-Campus's first frames with their public detections, verified by the
    contour template: one vote per detection, in their order, with their
    boxes; none for a frame without pixels; a box outside the image abstains."""
    import subprocess as sp
    raw = sp.run(["ffmpeg", "-v", "error", "-i", os.path.join(DATA, "TUD-Campus", "video.mp4"),
                  "-frames:v", "20", "-f", "rawvideo", "-pix_fmt", "yuv420p", "-"],
                 check=True, capture_output=True).stdout
    frames = np.frombuffer(raw, np.uint8).reshape(-1, 480 * 3 // 2, 640)
    det = np.loadtxt(os.path.join(DATA, "TUD-Campus", "det", "det.txt"), delimiter=",")
    voted = 0
    with ctrack.Tracker(fps=25, verify_detections=1) as t:
        for k, f in enumerate(frames):
            d = det[det[:, 0] == k + 1][:, 2:7]
            d = np.vstack([d, [[-500, -500, 40, 100, 0.9]]])
            t.feed(f, d, format="i420")
            c = t.candidates()
            assert len(c) == len(d)
            assert np.allclose(c["left"], d[:, 0]) and np.allclose(c["height"], d[:, 3])
            assert c["voters"][-1] == 0
            voted += int(np.sum(c["voters"] >= 5))
        t.feed(None, det[det[:, 0] == 21][:, 2:7])
        assert len(t.candidates()) == 0
    assert voted > 20


def test_image_size_for_steps_without_pixels():
    # A person walks right to the edge of a 200-pixel-wide image and is not
    # detected again: once the image is known, the track that leaves it
    # ends at once; with no image size it lives on, lost.
    def live_after(**kw):
        with ctrack.Tracker(fps=10, **kw) as t:
            for k in range(10):
                t.feed(None, np.array([[60.0 + 10 * k, 50, 40, 100, 0.9]]))
            for k in range(5):
                t.feed(None, None)
            return t.stats()["live_tracks"]
    assert live_after(image_size=(200, 300)) == 0
    assert live_after() == 1
    # Whole numbers of any type: OpenCV's CAP_PROP_FRAME_WIDTH is a float.
    assert live_after(image_size=(200.0, np.int32(300))) == 0
    for bad in ((200,), (200, -1), (200.5, 300), (True, 300), (float("nan"), 300), "wide",
                (2**31, 300), 200):
        with pytest.raises(ValueError, match="image_size"):
            ctrack.Tracker(image_size=bad)


def test_refine_boxes_off_reads_no_background(tud_bgr):
    """With detections and frames, refine_boxes=0 keeps no background model
    (no foreground, no working scale) and reports the filter's boxes; on,
    the boxes move to the silhouettes and a foreground is found."""
    frames, fps = tud_bgr
    dets = load_dets("TUD-Campus")
    out = {}
    for refine in (0, 1):
        with ctrack.Tracker(fps=fps, refine_boxes=refine) as t:
            assert t.config["refine_boxes"] == refine
            for k, f in enumerate(frames):
                tracks = t.feed(f, dets.get(k + 1, np.zeros((0, 5))))
            out[refine] = (t.person_size()["working_scale"], tracks)
    assert out[0][0] == 0 and out[1][0] in (1, 2, 4)
    a, b = out[0][1], out[1][1]
    assert len(a) > 0 and list(a["id"]) == list(b["id"])
    assert not np.array_equal(a["left"], b["left"])
