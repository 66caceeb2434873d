"""ctrack for Python: multi-target pedestrian tracking through libctrack.

    import ctrack
    with ctrack.Tracker(fps=7) as t:
        for frame, dets in video:          # frame: numpy uint8, dets: (N, 5)
            tracks = t.feed(frame, dets)   # numpy structured array
            for tr in tracks:
                print(tr["id"], tr["left"], tr["top"], tr["width"], tr["height"])

The library is found, in this order: the `library` argument of load(), the
CTRACK_LIBRARY environment variable, a libctrack beside this package, the
build folder of a source checkout (after `make`), then the system's.

Threads: a Tracker may be shared between threads. Each call into the
library (feed, prime, reset, the getters, close) holds the tracker's own
lock, since ctypes lets other threads run while the library works; calls on
one tracker are serialised, and close() waits for the call in flight. One
tracker per thread is fastest: different trackers run at the same time.
"""
import ctypes
import ctypes.util
import functools
import math
import os
import threading

import numpy as np

from . import _abi
from ._abi import (TRACK_CONFIRMED, TRACK_LOST, TRACK_TENTATIVE,  # noqa: F401
                   SOURCE_DETECTIONS, SOURCE_PIXELS, PEDESTRIAN_TEMPLATE, PEDESTRIAN_SIZE,
                   PRIME_SECONDS, PRIME_MAX_FRAMES, PRIME_MAX_BYTES, EVENT_LINE_IN,
                   EVENT_LINE_OUT, EVENT_ZONE_ENTER, EVENT_ZONE_EXIT)

__all__ = ["Tracker", "CtrackError", "load", "version", "version_number", "abi_version",
           "mot_lines", "from_xyxy", "draw", "Trails", "TRACK_DTYPE", "CANDIDATE_DTYPE", "SOURCE_DETECTIONS", "SOURCE_PIXELS",
           "PEDESTRIAN_TEMPLATE", "PEDESTRIAN_SIZE", "PRIME_SECONDS", "PRIME_MAX_FRAMES",
           "PRIME_MAX_BYTES", "TRACK_CONFIRMED", "TRACK_LOST", "TRACK_TENTATIVE",
           "EVENT_DTYPE", "EVENT_LINE_IN", "EVENT_LINE_OUT", "EVENT_ZONE_ENTER",
           "EVENT_ZONE_EXIT"]

#: The version of the header this package mirrors (the library it loads
#: may be newer: version() tells).
__version__ = _abi.VERSION

_lib = None

#: The numpy dtype of a track: the fields of ct_track.
TRACK_DTYPE = np.dtype(_abi.Track)
#: The numpy dtype of a candidate (pixels only): the fields of ct_candidate.
CANDIDATE_DTYPE = np.dtype(_abi.Candidate)
#: The numpy dtype of a counting event (library 0.10.0): the fields of
#: ct_event (kind, index of the line or zone, track_id, timestamp_us, x, y,
#: dwell, ended).
EVENT_DTYPE = np.dtype(_abi.Event)
_DET_DTYPE = np.dtype(_abi.Detection)
_CONFIG_FIELDS = [name for name, _ in _abi.Config._fields_ if name != "size"]


_CONFIG_TYPES = dict(_abi.Config._fields_)
_FLOAT_MAX = float(np.finfo(np.float32).max)


def _number(value):
    """Whether value is a real number of Python's or numpy's, not a bool
    (True is an int to Python, and fps=True is no rate)."""
    return (isinstance(value, (int, float, np.number)) and
            not isinstance(value, (bool, np.bool_, np.complexfloating)))


def _real(value, what):
    """value as a float where it is a real number (see _number); a
    TypeError naming what otherwise: float() would take True as 1.0 and
    "1.5" as 1.5, neither of which the caller meant as seconds or pixels."""
    if not _number(value):
        raise TypeError("%s: %r is not a number" % (what, value))
    return float(value)


def _whole(value):
    """value as an int where it is a whole number (an int, numpy's, or a
    float such as OpenCV's CAP_PROP_FRAME_WIDTH gives); None for anything
    else, bools included."""
    if not _number(value):
        return None
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)) and math.isfinite(value) and float(value).is_integer():
        return int(value)
    return None


def _config_value(name, value):
    """value as ct_config's field name holds it. ctypes would wrap an integer
    too large for the field (max_tracks=2**32 + 5 stored as 5) and refuse a
    whole float (min_hits=2.0); neither is what the caller meant."""
    ctype = _CONFIG_TYPES[name]
    if isinstance(value, (bool, np.bool_)) and ctype not in (ctypes.c_float, ctypes.c_double):
        return int(value)  # a switch (mean_shift=True)
    if not _number(value):
        raise TypeError("Tracker: %s=%r is not a number" % (name, value))
    if ctype in (ctypes.c_float, ctypes.c_double):
        value = float(value)  # NaN and infinities reach ct_config_check, which names them
        if ctype is ctypes.c_float and math.isfinite(value) and abs(value) > _FLOAT_MAX:
            raise ValueError("Tracker: %s=%r is past the range of a float" % (name, value))
        return value
    whole = _whole(value)
    if whole is None:
        raise ValueError("Tracker: %s=%r is not a whole number" % (name, value))
    bits = 8 * ctypes.sizeof(ctype)
    if not -2**(bits - 1) <= whole < 2**(bits - 1):
        raise ValueError("Tracker: %s=%r is out of the range of a %d-bit integer"
                         % (name, value, bits))
    return whole


class CtrackError(Exception):
    """A call into libctrack failed; `status` is its ct_status code."""

    def __init__(self, status, message):
        super().__init__(message)
        self.status = status


def _candidates(library):
    if library:
        yield library
        return
    env = os.environ.get("CTRACK_LIBRARY")
    if env:
        yield env
        return
    here = os.path.dirname(os.path.abspath(__file__))
    name = "libctrack.so.%d" % _abi.ABI_VERSION
    yield os.path.join(here, name)
    yield os.path.join(here, "..", "..", "build", "lib", name)
    found = ctypes.util.find_library("ctrack")
    yield found or name


def load(library=None):
    """Loads libctrack (once) and returns the ctypes handle. Refuses a
    library whose ABI major differs from this package's."""
    global _lib
    if _lib is not None and library is None:
        return _lib
    errors = []
    for path in _candidates(library):
        if os.path.sep in path and not os.path.exists(path):
            errors.append("%s: no such file" % path)
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError as e:
            errors.append(str(e))
            continue
        try:
            abi = lib.ct_abi_version()
        except AttributeError:
            raise ImportError("%s is not libctrack (no ct_abi_version)" % path)
        if abi != _abi.ABI_VERSION:
            raise ImportError("%s has ABI %d; this ctrack package needs ABI %d"
                              % (path, abi, _abi.ABI_VERSION))
        _abi.declare(lib)
        _lib = lib
        return lib
    raise ImportError("libctrack not found (run `make`, or set CTRACK_LIBRARY): "
                      + "; ".join(errors))


def version():
    """The loaded library's version string, e.g. '0.1.0'."""
    return load().ct_version_string().decode()


def version_number():
    return load().ct_version_number()


def abi_version():
    return load().ct_abi_version()


def mot_lines(frame, tracks):
    """The lines ct-track writes for one frame's tracks, in MOTChallenge's
    format: frame,id,left,top,width,height,confidence,-1,-1,-1 (frame
    numbered from 1; no line ends)."""
    return ["%d,%d,%.2f,%.2f,%.2f,%.2f,%.3f,-1,-1,-1"
            % (frame, t["id"], t["left"], t["top"], t["width"], t["height"], t["confidence"])
            for t in tracks]


def from_xyxy(boxes):
    """Detections given by their corners, [x1, y1, x2, y2, score(, class)]
    a row (as supervision, YOLO and torchvision give them), as feed() takes
    them: [left, top, width, height, score(, class)]."""
    b = np.asarray(boxes, dtype=np.float64)
    if b.size == 0:
        return np.zeros((0, 5))
    if b.ndim != 2 or b.shape[1] not in (5, 6):
        raise ValueError("boxes: shape %s is not (N, 5) or (N, 6) "
                         "[x1, y1, x2, y2, score(, class)]" % (b.shape,))
    out = b.copy()
    out[:, 2] = b[:, 2] - b[:, 0]
    out[:, 3] = b[:, 3] - b[:, 1]
    return out


def _from_supervision(d):
    """A supervision.Detections (xyxy, confidence, class_id) as feed()'s
    rows; a missing confidence is 1."""
    xyxy = np.asarray(d.xyxy, dtype=np.float64).reshape(-1, 4)
    conf = (np.ones(len(xyxy)) if getattr(d, "confidence", None) is None
            else np.asarray(d.confidence, dtype=np.float64).reshape(-1))
    cols = [xyxy, conf[:, None]]
    if getattr(d, "class_id", None) is not None:
        cols.append(np.asarray(d.class_id, dtype=np.float64).reshape(-1, 1))
    return from_xyxy(np.hstack(cols))


def _status_error(lib, status, message):
    return CtrackError(status, "%s: %s" % (lib.ct_status_str(status).decode(), message))


def bgr_to_i420(image):
    """Converts an HxWx3 uint8 BGR image to an (H*3/2, W) I420 array (BT.601,
    limited range, chroma averaged over 2x2 blocks: OpenCV's
    COLOR_BGR2YUV_I420 up to rounding). Odd sizes are padded to even."""
    img = np.asarray(image)
    h, w = img.shape[:2]
    if h % 2 or w % 2:
        img = np.pad(img, ((0, h % 2), (0, w % 2), (0, 0)), mode="edge")
    b, g, r = (img[..., i].astype(np.int32) for i in range(3))
    y = ((66 * r + 129 * g + 25 * b + 128) >> 8) + 16
    u = ((-38 * r - 74 * g + 112 * b + 128) >> 8) + 128
    v = ((112 * r - 94 * g - 18 * b + 128) >> 8) + 128
    H, W = y.shape

    def sub(c):
        return ((c[0::2, 0::2] + c[1::2, 0::2] + c[0::2, 1::2] + c[1::2, 1::2] + 2) >> 2)
    out = np.empty((H * 3 // 2, W), np.uint8)
    out[:H] = np.clip(y, 0, 255)
    out[H:].reshape(-1)[: (H // 2) * (W // 2)] = np.clip(sub(u), 0, 255).reshape(-1)
    out[H:].reshape(-1)[(H // 2) * (W // 2):] = np.clip(sub(v), 0, 255).reshape(-1)
    return out


def _microseconds(ts, what):
    """Seconds as the int64 microseconds of ct_frame.timestamp_us."""
    ts = _real(ts, what)
    if not math.isfinite(ts):
        raise ValueError("%s: %r is not finite" % (what, ts))
    us = int(round(ts * 1e6))
    if not -2**63 <= us < 2**63:
        # ctypes would wrap it round silently
        raise ValueError("%s: %r s is outside int64 microseconds "
                         "(about +-292,000 years)" % (what, ts))
    return us


def _locked(method):
    """The method runs holding the tracker's lock: a tracker shared between
    threads serves one call at a time (the library's contract)."""
    @functools.wraps(method)
    def locked(self, *args, **kwargs):
        with self._lock:
            return method(self, *args, **kwargs)
    return locked


class Tracker:
    """One tracker. Keyword parameters are the fields of ct_config
    (high_score, min_hits, lost_lifetime, ...; see docs/API.md), plus `fps`
    (default 25), the rate assumed when feed() gets no timestamp, and
    `image_size` (width, height), the image the boxes lie in for steps
    without pixels until a frame tells it (default unknown: (0, 0)). An
    integer field takes a whole number that fits its 32 bits (2, 2.0,
    numpy's integers, True for a switch); anything else raises.

    Safe to share between threads: every call holds the tracker's lock (one
    call at a time; see the module's help)."""

    def __init__(self, fps=25.0, library=None, image_size=None, **params):
        self._lock = threading.RLock()
        self._t = None
        self._lib = load(library)
        if not (_number(fps) and math.isfinite(fps) and fps > 0):
            raise ValueError("fps: %r is not a positive rate" % (fps,))
        if image_size is not None:
            try:
                size = [_whole(v) for v in image_size] if not isinstance(image_size, str) else []
            except TypeError:  # not a sequence
                size = []
            if len(size) != 2 or not all(v is not None and 0 <= v < 2**31 for v in size):
                raise ValueError("image_size: %r is not (width, height) in whole pixels"
                                 % (image_size,))
            image_size = tuple(size)
        self.fps = float(fps)
        cfg = _abi.Config()
        self._lib.ct_config_default(ctypes.byref(cfg), ctypes.sizeof(cfg))
        for name, value in params.items():
            if name not in _CONFIG_FIELDS:
                raise TypeError("Tracker: unknown parameter %r (known: %s)"
                                % (name, ", ".join(_CONFIG_FIELDS + ["fps"])))
            setattr(cfg, name, _config_value(name, value))
        self.config = {name: getattr(cfg, name) for name in _CONFIG_FIELDS}
        msg = ctypes.create_string_buffer(512)
        st = self._lib.ct_config_check(ctypes.byref(cfg), msg, len(msg))
        if st != _abi.OK:
            raise _status_error(self._lib, st, msg.value.decode())
        handle = ctypes.c_void_p()
        st = self._lib.ct_tracker_create(ctypes.byref(cfg), ctypes.byref(handle))
        if st != _abi.OK:
            raise _status_error(self._lib, st, "ct_tracker_create failed")
        self._t = handle
        # Libraries from 0.8.0 take packed BGR and RGB frames themselves.
        self._packed = self._lib.ct_version_number() >= 0x000800
        self._last_ts = None
        self._size = tuple(image_size) if image_size is not None else (0, 0)
        self._out = (_abi.Track * 64)()

    # -- lifetime ----------------------------------------------------------
    def close(self):
        """Frees the tracker, once the call in flight on another thread (if
        any) has returned; every later call raises ValueError. Idempotent."""
        lock = getattr(self, "_lock", None)
        if lock is None:  # __init__ failed before the tracker existed
            return
        with lock:
            if self._t:
                self._lib.ct_tracker_destroy(self._t)
                self._t = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def __del__(self):
        self.close()

    def _handle(self):
        if not self._t:
            raise ValueError("the tracker is closed (Tracker.close() was called)")
        return self._t

    def _check(self, st):
        if st != _abi.OK:
            raise _status_error(self._lib, st, self._lib.ct_tracker_last_error(self._t).decode())

    # -- tracking ----------------------------------------------------------
    @_locked
    def reset(self):
        """Forgets every track and the time; ids keep increasing."""
        self._check(self._lib.ct_tracker_reset(self._handle()))
        self._last_ts = None

    @_locked
    def prime(self, frames, timestamps=None, format=None):
        """A look-ahead for recorded files: learns the scene's background
        from a recording's first seconds (ct_tracker_prime(); PRIME_SECONDS
        is a usual length), then forgets the tracks and the time: feed the
        recording from its first frame next, and the people there when it
        starts are found from it, so that frame 1's tracks depend on later
        frames. Nothing else the tracker learnt changes; a failed call
        changes nothing. A camera's live stream cannot be primed; no
        tracker primes unless asked. frames: a sequence of images as feed()
        takes them, all of one size and format, with pixels. timestamps:
        seconds, increasing; None means k / fps for frame k from 0."""
        t = self._handle()
        if not hasattr(self._lib, "ct_tracker_prime"):
            raise CtrackError(_abi.ERROR_UNSUPPORTED,
                              "this libctrack has no ct_tracker_prime (before 0.9.0)")
        frames = list(frames)
        if not frames:
            raise ValueError("frames: priming takes at least one frame")
        if timestamps is None:
            timestamps = [k / self.fps for k in range(len(frames))]
        timestamps = list(timestamps)
        if len(timestamps) != len(frames):
            raise ValueError("timestamps: %d for %d frames" % (len(timestamps), len(frames)))
        arr = (_abi.Frame * len(frames))()
        keep = []
        for k, (frame, ts) in enumerate(zip(frames, timestamps)):
            if frame is None:
                raise ValueError("frames[%d]: None; priming learns from the pixels" % k)
            f = arr[k]
            self._lib.ct_frame_default(ctypes.byref(f), ctypes.sizeof(f))
            keep.append(self._fill_frame(f, frame, format))
            f.timestamp_us = _microseconds(ts, "timestamps[%d]" % k)
        ptrs = (ctypes.POINTER(_abi.Frame) * len(frames))(*[ctypes.pointer(f) for f in arr])
        self._check(self._lib.ct_tracker_prime(t, ptrs, len(frames)))
        del keep
        self._last_ts = None
        self._size = (arr[0].width, arr[0].height)

    @_locked
    def feed(self, frame=None, detections=None, timestamp=None, format=None):
        """Runs one step and returns the reported tracks (TRACK_DTYPE).

        frame: None (no pixels), an HxW uint8 grey image, an (H*3/2)xW uint8
            array with format='i420' or 'nv12', or an HxWx3 uint8 colour
            image: BGR (OpenCV's order; format None or 'bgr') or RGB
            (format='rgb'). The library converts a colour image to I420 as
            bgr_to_i420 does (in C, from ctrack 0.8.0; with an older library
            this package converts it with numpy, and a step at 768x576 takes
            some 20 times longer).
        detections: None, an (N, 5) / (N, 6) array of
            [left, top, width, height, score(, class)] in pixels, or a
            supervision.Detections (its xyxy, confidence and class_id);
            from_xyxy() converts [x1, y1, x2, y2, score(, class)] rows.
        timestamp: seconds; None means one frame period (1 / fps) after the
            last.
        """
        t = self._handle()
        f = _abi.Frame()
        self._lib.ct_frame_default(ctypes.byref(f), ctypes.sizeof(f))
        keep = self._fill_frame(f, frame, format)
        dets = self._detections(detections)
        if timestamp is None:
            ts = 0.0 if self._last_ts is None else self._last_ts + 1.0 / self.fps
        else:
            ts = _real(timestamp, "timestamp")
        f.timestamp_us = _microseconds(ts, "timestamp")
        ptr = dets.ctypes.data if len(dets) else None
        self._check(self._lib.ct_tracker_feed(t, ctypes.byref(f), ptr, len(dets)))
        del keep
        self._last_ts = ts
        if f.format != _abi.FORMAT_NONE:
            self._size = (f.width, f.height)
        return self.tracks()

    @_locked
    def tracks(self):
        """The tracks reported for the last step (a copy)."""
        t = self._handle()
        count = ctypes.c_size_t()
        size = ctypes.sizeof(_abi.Track)
        st = self._lib.ct_tracker_get_tracks(t, self._out, len(self._out), size,
                                             ctypes.byref(count))
        if st == _abi.ERROR_BUFFER_TOO_SMALL:
            self._out = (_abi.Track * (2 * count.value))()
            st = self._lib.ct_tracker_get_tracks(t, self._out, len(self._out), size,
                                                 ctypes.byref(count))
        self._check(st)
        return np.frombuffer(self._out, dtype=TRACK_DTYPE, count=count.value).copy()

    def _copy_all(self, getter, cls):
        """Everything a ct_tracker_get_* array getter has, as a ctypes
        array of cls and its count."""
        t = self._handle()
        fn = getattr(self._lib, getter)
        count = ctypes.c_size_t()
        size = ctypes.sizeof(cls)
        st = fn(t, None, 0, size, ctypes.byref(count))
        if st not in (_abi.OK, _abi.ERROR_BUFFER_TOO_SMALL):
            self._check(st)
        buf = (cls * max(1, count.value))()
        self._check(fn(t, buf, len(buf), size, ctypes.byref(count)))
        return buf, count.value

    # -- counting ----------------------------------------------------------
    def _need_counting(self):
        if not hasattr(self._lib, "ct_tracker_add_line"):
            raise CtrackError(_abi.ERROR_UNSUPPORTED,
                              "counting needs libctrack 0.10.0 or newer (this one is %s)"
                              % self._lib.ct_version_string().decode())

    @staticmethod
    def _name(name):
        if name is None:
            return None
        if not isinstance(name, str):
            raise TypeError("name: %r is not a str" % (name,))
        return name.encode()

    @staticmethod
    def _point(p, what):
        try:
            x, y = p
        except (TypeError, ValueError):
            x = y = None  # not a pair
        if not (_number(x) and _number(y)):
            raise ValueError("%s: %r is not a point (x, y)" % (what, p))
        return _abi.Point(float(x), float(y))

    @_locked
    def add_line(self, a, b, name=None, hysteresis=None):
        """Counts crossings of the segment from a to b ((x, y) in pixels):
        "in" to the right-hand side of a -> b as the image shows it (for a
        line drawn left to right, downward), "out" the other way. `name`
        (default "line<index>") names it in counts(); `hysteresis` (default
        0.1) is how far past the line, in heights of the track's box, the
        feet must go for a crossing to count. Returns its index, the
        `index` of its events. ValueError for a bad line (nothing
        added)."""
        self._need_counting()
        line = _abi.Line()
        self._lib.ct_line_default(ctypes.byref(line), ctypes.sizeof(line))
        line.a = self._point(a, "a")
        line.b = self._point(b, "b")
        return self._add(self._lib.ct_tracker_add_line, line, name, hysteresis)

    @_locked
    def add_zone(self, points, name=None, hysteresis=None):
        """Counts the people who enter and leave the polygon `points` (3 to
        64 (x, y) corners in order, its edges not crossing) and those in it
        now, with their dwell time. `name` defaults to "zone<index>";
        `hysteresis` (default 0.1 box heights) is how far inside or outside
        it, from its nearest edge, the feet must go. Returns its index.
        ValueError for a bad zone (nothing added)."""
        self._need_counting()
        pts = [self._point(p, "points[%d]" % i) for i, p in enumerate(points)]
        arr = (_abi.Point * max(1, len(pts)))(*pts)
        zone = _abi.Zone()
        self._lib.ct_zone_default(ctypes.byref(zone), ctypes.sizeof(zone))
        zone.points = arr
        zone.n_points = len(pts)
        return self._add(self._lib.ct_tracker_add_zone, zone, name, hysteresis)

    def _add(self, add, shape, name, hysteresis):
        """A ct_line or ct_zone named and with its hysteresis, added by
        add; its index. An argument the library refused is the caller's
        ValueError."""
        shape.name = self._name(name)
        if hysteresis is not None:
            shape.hysteresis = _real(hysteresis, "hysteresis")
        index = ctypes.c_int32()
        st = add(self._handle(), ctypes.byref(shape), ctypes.byref(index))
        if st == _abi.ERROR_INVALID_ARGUMENT:
            raise ValueError(self._lib.ct_tracker_last_error(self._t).decode())
        self._check(st)
        return index.value

    @_locked
    def events(self):
        """The counting events of the last step, a numpy structured array
        (EVENT_DTYPE): kind (EVENT_LINE_IN, EVENT_LINE_OUT, EVENT_ZONE_ENTER,
        EVENT_ZONE_EXIT), the line's or zone's index, track_id,
        timestamp_us, the feet's x and y, and for an exit the dwell in
        seconds and ended (1 when the track ended in the zone)."""
        if not hasattr(self._lib, "ct_tracker_get_events"):
            return np.zeros(0, dtype=EVENT_DTYPE)
        buf, n = self._copy_all("ct_tracker_get_events", _abi.Event)
        return np.frombuffer(buf, dtype=EVENT_DTYPE, count=n).copy()

    @_locked
    def counts(self):
        """The counts as of the last step: {"lines": {name: {"in": n,
        "out": n}}, "zones": {name: {"entered": n, "exited": n, "inside": n,
        "occupants": {track_id: dwell seconds}}}}, in the order added."""
        if not hasattr(self._lib, "ct_tracker_get_line_counts"):
            return {"lines": {}, "zones": {}}
        lines, nl = self._copy_all("ct_tracker_get_line_counts", _abi.LineCount)
        zones, nz = self._copy_all("ct_tracker_get_zone_counts", _abi.ZoneCount)
        occ, no = self._copy_all("ct_tracker_get_occupants", _abi.Occupant)
        out = {"lines": {}, "zones": {}}
        for c in lines[:nl]:
            out["lines"][c.name.decode()] = {"in": c.in_, "out": c.out}
        names = []
        for c in zones[:nz]:
            names.append(c.name.decode())
            out["zones"][names[-1]] = {"entered": c.entered, "exited": c.exited,
                                       "inside": c.inside, "occupants": {}}
        for o in occ[:no]:
            out["zones"][names[o.zone]]["occupants"][o.track_id] = o.dwell
        return out

    @_locked
    def candidates(self):
        """From the pixels alone (source=SOURCE_PIXELS): the blobs of the
        last step, a numpy structured array (CANDIDATE_DTYPE: the box, the
        contour template's score and votes, region_distance per region, and
        fill: how much of its convex hull the blob fills, and top_width: how
        wide its top is against its body).
        With detections and verify_detections=1: one vote per detection of
        the last step, in their order."""
        buf, n = self._copy_all("ct_tracker_get_candidates", _abi.Candidate)
        return np.frombuffer(buf, dtype=CANDIDATE_DTYPE, count=n).copy()

    @_locked
    def person_size(self):
        """What the tracker has learnt of its people's size (library 0.9.0
        or newer): a dict with `known`, and the height in pixels of a
        standing person whose feet are at row y, `height_slope * y +
        height_intercept`, the `width_ratio` three people in four stay under,
        the `samples` seen, a `typical_height`, and from the pixels the
        `working_scale` (frame pixels a working pixel of the foreground: 1,
        2 or 4; 0 until a foreground was found). None with an older
        library."""
        if not hasattr(self._lib, "ct_tracker_get_person_size"):
            return None
        s = _abi.PersonSize()
        s.size = ctypes.sizeof(s)
        self._check(self._lib.ct_tracker_get_person_size(self._handle(), ctypes.byref(s)))
        return {"known": bool(s.known), "height_slope": s.height_slope,
                "height_intercept": s.height_intercept, "width_ratio": s.width_ratio,
                "samples": s.samples, "typical_height": s.typical_height,
                "working_scale": s.working_scale}

    @_locked
    def stats(self):
        """The library's counters: steps, feed time and time per stage (in
        seconds), live tracks and the heap bytes the tracker holds."""
        t = self._handle()
        s = _abi.Stats()
        s.size = ctypes.sizeof(s)
        self._check(self._lib.ct_tracker_get_stats(t, ctypes.byref(s)))
        stages = {}
        for i in range(_abi.STATS_MAX_STAGES):
            name = self._lib.ct_stage_name(i)
            if name:
                stages[name.decode()] = s.stage_ns[i] * 1e-9
        return {"steps": s.steps, "feed_seconds": s.feed_ns * 1e-9, "stages": stages,
                "live_tracks": s.live_tracks, "memory_bytes": s.memory_bytes,
                "mean_shift_runs": s.mean_shift_runs, "ddis_runs": s.ddis_runs,
                "template_builds": s.template_builds, "blobs_dropped": s.blobs_dropped,
                "masks_flooded": s.masks_flooded}

    # -- conversions -------------------------------------------------------
    def _fill_frame(self, f, frame, format):
        """Fills f's planes from a numpy frame; returns the arrays that must
        stay alive until the call returns."""
        if frame is None:
            if format is not None:
                raise ValueError("format=%r given without a frame" % (format,))
            f.format = _abi.FORMAT_NONE
            f.width, f.height = self._size
            return None
        a = np.asarray(frame)
        if a.dtype != np.uint8:
            raise ValueError("frame: dtype %s; ctrack reads uint8 pixels" % a.dtype)
        if a.ndim == 3:
            if a.shape[2] != 3:
                raise ValueError("frame: a 3-D frame must be HxWx3 BGR or RGB; got shape %s"
                                 % (a.shape,))
            if format not in (None, "bgr", "rgb"):
                raise ValueError("format: %r is not 'bgr' or 'rgb' for an HxWx3 frame"
                                 % (format,))
            h, w = a.shape[:2]
            if self._packed:
                if a.strides[2] != 1 or a.strides[1] != 3 or a.strides[0] < 3 * w:
                    a = np.ascontiguousarray(a)
                f.format = _abi.FORMAT_RGB24 if format == "rgb" else _abi.FORMAT_BGR24
                f.width, f.height = w, h
                f.planes[0] = a.ctypes.data
                f.strides[0] = a.strides[0]
                return a
            a = bgr_to_i420(a[..., ::-1] if format == "rgb" else a)
            fmt = "i420"
            h2 = (h + 1) // 2 * 2
            w2 = (w + 1) // 2 * 2
            return self._planes(f, a, fmt, w2, h2, crop=(w, h))
        if a.ndim != 2:
            raise ValueError("frame: shape %s is not HxW, (H*3/2)xW or HxWx3" % (a.shape,))
        if format is None or format == "gray":
            return self._planes(f, a, "gray", a.shape[1], a.shape[0])
        if format not in ("i420", "nv12"):
            raise ValueError("format: %r is not 'i420', 'nv12' or 'gray'" % (format,))
        if a.shape[0] % 3 != 0:
            raise ValueError("frame: %d rows is not H*3/2 for an %s frame" % (a.shape[0], format))
        h = a.shape[0] * 2 // 3
        if h % 2 or a.shape[1] % 2:
            raise ValueError("frame: a packed %s array needs an even size, got %dx%d"
                             % (format, a.shape[1], h))
        return self._planes(f, a, format, a.shape[1], h)

    @staticmethod
    def _planes(f, a, fmt, w, h, crop=None):
        if a.strides[1] != 1 or a.strides[0] < a.shape[1]:
            a = np.ascontiguousarray(a)
        stride = a.strides[0]
        base = a.ctypes.data
        f.width, f.height = crop if crop else (w, h)
        f.planes[0] = base
        f.strides[0] = stride
        if fmt == "gray":
            f.format = _abi.FORMAT_GRAY8
            return a
        if stride != w:
            a = np.ascontiguousarray(a)
            base, stride = a.ctypes.data, w
            f.planes[0], f.strides[0] = base, stride
        luma = w * h
        if fmt == "i420":
            f.format = _abi.FORMAT_I420
            f.planes[1] = base + luma
            f.planes[2] = base + luma + (w // 2) * (h // 2)
            f.strides[1] = f.strides[2] = w // 2
        else:
            f.format = _abi.FORMAT_NV12
            f.planes[1] = base + luma
            f.strides[1] = w
        return a

    @staticmethod
    def _detections(detections):
        if detections is None:
            return np.zeros(0, _DET_DTYPE)
        if hasattr(detections, "xyxy"):  # a supervision.Detections
            detections = _from_supervision(detections)
        d = np.asarray(detections, dtype=np.float64)
        if d.size == 0:
            return np.zeros(0, _DET_DTYPE)
        if d.ndim != 2 or d.shape[1] not in (5, 6):
            raise ValueError("detections: shape %s is not (N, 5) or (N, 6) "
                             "[left, top, width, height, score(, class)]" % (d.shape,))
        out = np.zeros(len(d), _DET_DTYPE)
        for i, name in enumerate(("left", "top", "width", "height", "score")):
            out[name] = d[:, i]
        if d.shape[1] == 6:
            cls = d[:, 5]
            if not np.all(np.isfinite(cls)) or np.any(cls != np.round(cls)):
                raise ValueError("detections: the class column must hold whole numbers")
            out["class_id"] = cls.astype(np.int32)
        return out


from .draw import Trails, draw  # noqa: E402 (draw imports _abi only)
