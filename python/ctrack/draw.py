"""Tracks drawn on a numpy frame, in the look of ct-track's --overlay: each
track's box in its colour (thick while a detection or the pixels hold it,
thin while predicted), its id in white digits on a label of its colour, and
with a Trails history, the line of its recent barycenters.

    trails = ctrack.Trails()
    for frame in video:                       # HxWx3 uint8 BGR (or RGB)
        tracks = tracker.feed(frame)
        trails.update(tracks)
        ctrack.draw(frame, tracks, trails)    # in place; returns the frame
"""
import numpy as np

from . import _abi

# The overlay's 12 colours (tools/output/overlay.c) as (Y, U, V), BT.601
# limited range, and its 3x5 digits, one row a number of 3 bits.
PALETTE_YUV = [(81, 90, 240), (145, 54, 34), (41, 240, 110), (210, 16, 146), (170, 166, 16),
               (106, 202, 222), (162, 44, 142), (90, 150, 60), (180, 110, 200),
               (60, 200, 170), (130, 80, 80), (200, 128, 128)]
WHITE_YUV = (235, 128, 128)
DIGITS = [(7, 5, 5, 5, 7), (2, 6, 2, 2, 7), (7, 1, 7, 4, 7), (7, 1, 7, 1, 7), (5, 5, 7, 1, 1),
          (7, 4, 7, 1, 7), (7, 4, 7, 5, 7), (7, 1, 1, 1, 1), (7, 5, 7, 5, 7), (7, 5, 7, 1, 7)]
TRAIL = 24       # barycenters kept a track
MAX_TRAILS = 256


def yuv_to_rgb(c):
    """A (Y, U, V) colour, BT.601 limited range, as (R, G, B) bytes."""
    y, u, v = c[0] - 16, c[1] - 128, c[2] - 128
    rgb = (1.164 * y + 1.596 * v, 1.164 * y - 0.392 * u - 0.813 * v, 1.164 * y + 2.017 * u)
    return tuple(int(min(255, max(0, round(x)))) for x in rgb)


class Trails:
    """The recent barycenters of each track (the last 24), for draw(): call
    update() with each step's tracks. Tracks not seen for long are forgotten
    past 256 of them, the least recently seen first."""

    def __init__(self):
        self._points = {}  # id -> list of (x, y), oldest first
        self._seen = {}    # id -> the update it was last seen at
        self._updates = 0

    def update(self, tracks):
        self._updates += 1
        for t in tracks:
            tid = int(t["id"])
            if tid not in self._points and len(self._points) >= MAX_TRAILS:
                oldest = min(self._seen, key=self._seen.get)
                del self._points[oldest], self._seen[oldest]
            pts = self._points.setdefault(tid, [])
            pts.append((float(t["barycenter_x"]), float(t["barycenter_y"])))
            del pts[:-TRAIL]
            self._seen[tid] = self._updates

    def points(self, track_id):
        """The track's barycenters, oldest first (empty if unknown)."""
        return list(self._points.get(int(track_id), []))


class _Canvas:
    """Fills on an image of colour or grey pixels, clipped to it."""

    def __init__(self, image, rgb):
        self.im, self.rgb = image, rgb
        self.h, self.w = image.shape[:2]

    def colour(self, yuv):
        if self.im.ndim == 2:
            return yuv[0]
        r, g, b = yuv_to_rgb(yuv)
        return (r, g, b) if self.rgb else (b, g, r)

    def fill(self, x0, y0, x1, y1, c):
        x0, x1 = max(0, x0), min(self.w, x1)
        y0, y1 = max(0, y0), min(self.h, y1)
        if x0 < x1 and y0 < y1:
            self.im[y0:y1, x0:x1] = c

    def frame_box(self, x0, y0, x1, y1, th, c):
        self.fill(x0, y0, x1, y0 + th, c)
        self.fill(x0, y1 - th, x1, y1, c)
        self.fill(x0, y0, x0 + th, y1, c)
        self.fill(x1 - th, y0, x1, y1, c)

    def line(self, x0, y0, x1, y1, c):
        """Bresenham's line of 2x2 squares, as the overlay draws a trail."""
        dx, dy = abs(x1 - x0), -abs(y1 - y0)
        sx, sy = (1 if x0 < x1 else -1), (1 if y0 < y1 else -1)
        e = dx + dy
        for _ in range(100000):
            self.fill(x0, y0, x0 + 2, y0 + 2, c)
            if x0 == x1 and y0 == y1:
                break
            e2 = 2 * e
            if e2 >= dy:
                e += dy
                x0 += sx
            if e2 <= dx:
                e += dx
                y0 += sy

    def label(self, x, y, number, c, scale):
        s = str(number)
        cw = 4 * scale
        self.fill(x, y, x + len(s) * cw + scale, y + 7 * scale, c)
        white = self.colour(WHITE_YUV)
        for i, ch in enumerate(s):
            for r, bits in enumerate(DIGITS[ord(ch) - 48]):
                for b in range(3):
                    if bits & (4 >> b):
                        x0 = x + scale + i * cw + b * scale
                        y0 = y + scale + r * scale
                        self.fill(x0, y0, x0 + scale, y0 + scale, white)


def _clamp(v, lo, hi):
    return lo if not v > lo else (hi if v > hi else int(v))


def draw(frame, tracks, trails=None, format="bgr"):
    """Draws tracks (Tracker.feed()'s array) on frame, an HxWx3 uint8 image
    in BGR (format='bgr', OpenCV's order) or RGB (format='rgb'), or an HxW
    grey one, in place, as ct-track's --overlay draws them; with trails (a
    Trails updated with these tracks), each track's recent path too.
    Returns the frame."""
    im = np.asarray(frame)
    if im.dtype != np.uint8 or not (im.ndim == 2 or (im.ndim == 3 and im.shape[2] == 3)):
        raise ValueError("frame: an HxWx3 or HxW uint8 image, got %s %s"
                         % (im.dtype, im.shape))
    if format not in ("bgr", "rgb"):
        raise ValueError("format: %r is not 'bgr' or 'rgb'" % (format,))
    if not im.flags.writeable:
        raise ValueError("frame: read-only; draw() draws in place (pass a copy)")
    cv = _Canvas(im, format == "rgb")
    w, h = cv.w, cv.h
    for t in tracks:
        tid = int(t["id"])
        c = cv.colour(PALETTE_YUV[tid % 12])
        if trails is not None:
            pts = trails.points(tid)
            for (xa, ya), (xb, yb) in zip(pts[1:], pts[:-1]):
                cv.line(_clamp(xa, -1, w), _clamp(ya, -1, h), _clamp(xb, -1, w),
                        _clamp(yb, -1, h), c)
        x0, y0 = _clamp(t["left"], -4, w + 4), _clamp(t["top"], -4, h + 4)
        x1 = _clamp(t["left"] + t["width"], -4, w + 4)
        y1 = _clamp(t["top"] + t["height"], -4, h + 4)
        cv.frame_box(x0, y0, x1, y1, 1 if t["state"] == _abi.TRACK_LOST else 2, c)
        cv.label(x0, y0 - 14 if y0 - 14 >= 0 else y0, tid, c, 2)
    return frame
