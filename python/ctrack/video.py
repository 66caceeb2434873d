"""Any video ffmpeg reads, as I420 frames for Tracker.feed().

    from ctrack.video import Video
    with Video("clip.mp4") as v:
        for k, frame in enumerate(v, 1):    # (H*3/2) x W uint8, I420
            tracks = tracker.feed(frame, format="i420",
                                  timestamp=v.timestamp(k))

ffmpeg (which must be on the PATH) decodes the video to a Y4M stream on a
pipe, so its size and rate are the ones ct-track reads from that stream.
"""
import itertools
import math
import subprocess
import tempfile

import numpy as np


def frame_time(k, rate):
    """Frame k's (from 1) time in seconds at rate (numerator, denominator)
    frames/s, on ct-track's microsecond grid: llround((k - 1) * 1e6 * den /
    num)."""
    num, den = rate
    return math.floor((k - 1) * 1e6 * den / num + 0.5) / 1e6


def primed(tracker, frames, rate, seconds, note=None, max_bytes=None):
    """As ct-track --prime, a look-ahead for recorded files: primes tracker
    (Tracker.prime()) on the first ceil(seconds * rate) of frames (I420
    arrays at rate (numerator, denominator), timestamps on ct-track's grid)
    and returns an iterator over all the frames again, from the first, to
    feed. seconds <= 0: frames as they are (online). As ct-track, it takes
    at most PRIME_MAX_FRAMES frames, and as many as fit in max_bytes
    (default PRIME_MAX_BYTES): past that it primes on fewer and says so
    through note(message), ct-track's message."""
    from . import PRIME_MAX_BYTES, PRIME_MAX_FRAMES
    if seconds <= 0:
        return iter(frames)
    frames = iter(frames)
    first = next(frames, None)
    if first is None:
        return iter(())
    cap = PRIME_MAX_BYTES if max_bytes is None else max_bytes
    n = min(math.ceil(seconds * rate[0] / rate[1]), PRIME_MAX_FRAMES)
    fit = cap // max(1, first.nbytes)
    if fit < 1:
        return itertools.chain([first], frames)
    if n > fit:
        n = fit
        if note:
            note("--prime: %d frames fit in %d MiB, %.2f s" % (n, cap >> 20, n * rate[1] / rate[0]))
    start = [first] + list(itertools.islice(frames, n - 1))
    tracker.prime(start, [frame_time(k, rate) for k in range(1, len(start) + 1)], format="i420")
    return itertools.chain(start, frames)


class Video:
    """A video being decoded. width, height: the frames' size (an odd one
    loses its last column or row: these I420 arrays are even); rate: the
    frame rate as (numerator, denominator)."""

    def __init__(self, path):
        self.path = path
        self._err = tempfile.TemporaryFile()
        # A session of its own: Ctrl-C at a terminal signals the process
        # group, and an ffmpeg that stopped on it would end the video early
        # as if it were complete; its reader decides when to stop it.
        self._p = subprocess.Popen(["ffmpeg", "-v", "error", "-nostdin", "-i", path, "-f",
                                    "yuv4mpegpipe", "-pix_fmt", "yuv420p", "-"],
                                   stdout=subprocess.PIPE, stderr=self._err,
                                   start_new_session=True)
        header = self._p.stdout.readline().split()
        if not header or header[0] != b"YUV4MPEG2":
            self._p.wait()
            msg = self._ffmpeg_error()
            self.close()
            raise ValueError("ffmpeg could not decode %s%s" % (path, ": " + msg if msg else ""))
        fields = {t[:1]: t[1:] for t in header[1:]}
        try:
            w, h = int(fields[b"W"]), int(fields[b"H"])
            num, den = (int(v) for v in fields.get(b"F", b"25:1").split(b":"))
        except (KeyError, ValueError):
            self.close()
            raise ValueError("%s: ffmpeg's Y4M header is unreadable: %r" % (path, header))
        if w < 2 or h < 2 or num <= 0 or den <= 0:
            self.close()
            raise ValueError("%s: a %dx%d video at %d/%d frames/s" % (path, w, h, num, den))
        self._w, self._h = w, h
        self.width, self.height = w & ~1, h & ~1
        self.rate = (num, den)

    def timestamp(self, k):
        """Frame k's (from 1) time in seconds, as ct-track gives it."""
        return frame_time(k, self.rate)

    def __iter__(self):
        w, h, cw, ch = self._w, self._h, (self._w + 1) // 2, (self._h + 1) // 2
        size = w * h + 2 * cw * ch
        while True:
            tag = self._p.stdout.readline()
            if not tag:
                break
            if not tag.startswith(b"FRAME"):
                raise ValueError("%s: ffmpeg's stream lost its frame markers" % self.path)
            data = self._p.stdout.read(size)
            if len(data) < size:
                raise ValueError("%s: the last frame is cut short (%d of %d bytes)"
                                 % (self.path, len(data), size))
            a = np.frombuffer(data, np.uint8)
            if (w, h) == (self.width, self.height):
                yield a.reshape(h * 3 // 2, w)
                continue
            # Odd sizes: each plane cropped to the even size, packed again.
            W, H = self.width, self.height
            y = a[: w * h].reshape(h, w)[:H, :W]
            u = a[w * h: w * h + cw * ch].reshape(ch, cw)[: H // 2, : W // 2]
            v = a[w * h + cw * ch:].reshape(ch, cw)[: H // 2, : W // 2]
            yield np.concatenate([y.reshape(-1), u.reshape(-1), v.reshape(-1)]).reshape(
                H * 3 // 2, W)
        if self._p.wait() != 0:
            raise ValueError("%s: ffmpeg: %s" % (self.path, self._ffmpeg_error() or "failed"))

    def _ffmpeg_error(self):
        """ffmpeg's last message, without the file name it starts with."""
        self._err.seek(0)
        lines = self._err.read().decode("utf-8", "replace").strip().splitlines()
        last = lines[-1] if lines else ""
        return last[len(self.path) + 2:] if last.startswith(self.path + ": ") else last

    def close(self):
        if self._p.poll() is None:
            self._p.kill()
        self._p.wait()
        self._p.stdout.close()
        self._err.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
