"""examples/track_video.py tracks as ct-track does, frame for frame."""
import os
import subprocess
import sys

from conftest import DATA, TOP

EXAMPLE = os.path.join(TOP, "examples", "track_video.py")
TUD = os.path.join(DATA, "TUD-Campus")


def ct_track(args, video_y4m):
    ct = os.environ.get("CTRACK_CT_TRACK")
    assert ct, "CTRACK_CT_TRACK must name ct-track (meson test sets it)"
    return subprocess.run([ct, "-q", *args, video_y4m], check=True, capture_output=True,
                          text=True).stdout


def example(args):
    return subprocess.run([sys.executable, EXAMPLE, os.path.join(TUD, "video.mp4"), *args],
                          check=True, capture_output=True, text=True).stdout


def test_track_video_matches_ct_track(tmp_path):
    """Online by default, as ct-track --prime 0; with --prime, as ct-track
    --prime (a look-ahead, which differs)."""
    y4m = str(tmp_path / "tud.y4m")
    subprocess.run(["ffmpeg", "-v", "error", "-i", os.path.join(TUD, "video.mp4"), "-f",
                    "yuv4mpegpipe", "-pix_fmt", "yuv420p", y4m], check=True)
    det = os.path.join(TUD, "det", "det.txt")
    online = ct_track(["--prime", "0"], y4m)
    for args, want in (([], online), (["--prime", "3"], ct_track(["--prime", "3"], y4m)),
                       (["--detections", det], ct_track(["-d", det], y4m))):
        got = example(args)
        assert got.count("\n") > 100, "too few tracks: %r" % got[:200]
        assert got == want, "the example and ct-track differ (%s)" % (args or "pixels only")
    assert example(["--prime", "3"]) != online


def test_track_video_refuses_what_ffmpeg_cannot_read(tmp_path):
    bad = tmp_path / "not-a-video.mp4"
    bad.write_bytes(b"nothing here")
    r = subprocess.run([sys.executable, EXAMPLE, str(bad)], capture_output=True, text=True)
    assert r.returncode != 0
    assert "could not decode" in r.stderr
