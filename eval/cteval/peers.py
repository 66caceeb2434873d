"""The trackers people reach for today, run on the same input as ctrack, for
make eval and make bench. Each returns MOTChallenge rows
(frame, id, left, top, width, height) and its tracking time in seconds
(reading the input excluded).

- ByteTrack as supervision 0.30.9 ships it, default thresholds.
- SORT and OC-SORT as Roboflow's trackers 2.6.1 ships them, default
  parameters (frame_rate set to the sequence's).
- norfair 2.3.0 with IoU distance (threshold 0.7, its documented value for
  boxes), otherwise default.
- The pixels-only baseline: OpenCV's MOG2 background subtractor (default
  parameters, shadows dropped), a 3x3 opening and a 7x7 closing, external
  contours as blobs (at least 400 pixels), and an IoU tracker (optimal
  assignment, IoU >= 0.3, confirmed after 3 hits, kept 3 frames without a
  match, reporting matched tracks).
- OpenCV's own trackers (KCF, CSRT from opencv-contrib-python 4.10), one
  per person, on the public detections and the frames: the same IoU
  tracker, where each track's box is where its OpenCV tracker follows the
  person, and a matched detection starts the tracker again on its box.
"""
import time
import warnings

import numpy as np
from scipy.optimize import linear_sum_assignment


def _xyxy(d):
    return np.column_stack([d[:, 0], d[:, 1], d[:, 0] + d[:, 2], d[:, 1] + d[:, 3]])


def _supervision_loop(update, dets_by_frame, n_frames):
    """Feeds each frame's detections to update (supervision Detections in and
    out) and keeps the boxes it gives an id (-1: not yet confirmed)."""
    import supervision as sv
    rows, spent = [], 0.0
    for k in range(1, n_frames + 1):
        d = dets_by_frame.get(k, np.zeros((0, 5)))
        det = sv.Detections(xyxy=_xyxy(d).astype(np.float32),
                            confidence=d[:, 4].astype(np.float32),
                            class_id=np.zeros(len(d), dtype=int))
        t0 = time.perf_counter()
        out = update(det)
        spent += time.perf_counter() - t0
        for (x0, y0, x1, y1), tid in zip(out.xyxy, out.tracker_id):
            if tid >= 0:
                rows.append((k, int(tid), x0, y0, x1 - x0, y1 - y0))
    return rows, spent


def bytetrack(dets_by_frame, n_frames, fps):
    import supervision as sv
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", FutureWarning)  # "removed in 0.31": we pin 0.30.9
        tracker = sv.ByteTrack(frame_rate=fps)
    return _supervision_loop(tracker.update_with_detections, dets_by_frame, n_frames)


def sort(dets_by_frame, n_frames, fps):
    from trackers import SORTTracker
    return _supervision_loop(SORTTracker(frame_rate=fps).update, dets_by_frame, n_frames)


def ocsort(dets_by_frame, n_frames, fps):
    from trackers import OCSORTTracker
    return _supervision_loop(OCSORTTracker(frame_rate=fps).update, dets_by_frame, n_frames)


def norfair_iou(dets_by_frame, n_frames, fps):
    from norfair import Detection, Tracker
    tracker = Tracker(distance_function="iou", distance_threshold=0.7)
    rows, spent = [], 0.0
    for k in range(1, n_frames + 1):
        d = dets_by_frame.get(k, np.zeros((0, 5)))
        t0 = time.perf_counter()
        dets = [Detection(points=np.array([[x, y], [x + w, y + h]]), scores=np.array([s, s]))
                for x, y, w, h, s in d]
        objs = tracker.update(detections=dets)
        spent += time.perf_counter() - t0
        for o in objs:
            (x0, y0), (x1, y1) = o.estimate
            rows.append((k, int(o.id), x0, y0, x1 - x0, y1 - y0))
    return rows, spent


def iou_matrix(a, b):
    """IoU of (N, 4) and (M, 4) boxes in left, top, width, height."""
    if len(a) == 0 or len(b) == 0:
        return np.zeros((len(a), len(b)))
    ax0, ay0, ax1, ay1 = a[:, 0:1], a[:, 1:2], a[:, 0:1] + a[:, 2:3], a[:, 1:2] + a[:, 3:4]
    bx0, by0, bx1, by1 = b[:, 0], b[:, 1], b[:, 0] + b[:, 2], b[:, 1] + b[:, 3]
    iw = np.clip(np.minimum(ax1, bx1) - np.maximum(ax0, bx0), 0, None)
    ih = np.clip(np.minimum(ay1, by1) - np.maximum(ay0, by0), 0, None)
    inter = iw * ih
    return inter / (a[:, 2:3] * a[:, 3:4] + b[:, 2] * b[:, 3] - inter)


class IoUTracker:
    """Boxes matched to tracks by IoU (optimal assignment), confirmed after
    min_hits matches, kept max_missed frames without one. The hooks let a
    subclass move the boxes on the pixels between detections."""

    def __init__(self, min_iou=0.3, min_hits=3, max_missed=3):
        self.min_iou, self.min_hits, self.max_missed = min_iou, min_hits, max_missed
        self.tracks = []  # dicts: box, hits, missed, id
        self.next_id = 1

    def update(self, boxes, image=None):
        self._follow(image)
        boxes = np.asarray(boxes, dtype=float).reshape(-1, 4)
        prev = np.array([t["box"] for t in self.tracks]).reshape(-1, 4)
        iou = iou_matrix(prev, boxes)
        matched_t, matched_b = set(), set()
        if iou.size:
            r, c = linear_sum_assignment(-iou)
            for i, j in zip(r, c):
                if iou[i, j] >= self.min_iou:
                    t = self.tracks[i]
                    t["box"], t["hits"], t["missed"] = boxes[j], t["hits"] + 1, 0
                    self._matched(t, image)
                    matched_t.add(i)
                    matched_b.add(j)
        for i, t in enumerate(self.tracks):
            if i not in matched_t:
                t["missed"] += 1
        self.tracks = [t for t in self.tracks if t["missed"] <= self.max_missed]
        for j in range(len(boxes)):
            if j not in matched_b:
                t = {"box": boxes[j], "hits": 1, "missed": 0, "id": 0}
                self._matched(t, image)
                self.tracks.append(t)
        out = []
        for t in self.tracks:
            if self._reported(t) and t["hits"] >= self.min_hits:
                if not t["id"]:
                    t["id"] = self.next_id
                    self.next_id += 1
                out.append((t["id"], t["box"]))
        return out

    def _follow(self, image):
        """Before the association: move the tracks' boxes (here they stay)."""

    def _matched(self, t, image):
        """A box has just been given to track t (matched or new)."""

    def _reported(self, t):
        return t["missed"] == 0


class OpenCVTrackers(IoUTracker):
    """Tracking by detection with one of OpenCV's single-object trackers per
    person, as people build it from OpenCV: each track runs the tracker on
    every frame, the detections are matched to the boxes it gives, and a
    matched detection starts the tracker again on its box (so it does not
    drift). Between detections the tracker follows the person on the
    pixels, and the track is reported while it says it holds them."""

    def __init__(self, kind, width, height, **kw):
        super().__init__(**kw)
        import cv2
        self.make = {"KCF": cv2.TrackerKCF_create, "CSRT": cv2.TrackerCSRT_create}[kind]
        self.width, self.height = width, height

    def _follow(self, image):
        for t in self.tracks:
            t["ok"] = False
            if t["cv"] is not None:
                ok, box = t["cv"].update(image)
                if ok:
                    t["box"], t["ok"] = np.array(box, dtype=float), True

    def _matched(self, t, image):
        # OpenCV's trackers take a box inside the image, in whole pixels.
        x0, y0 = max(0.0, t["box"][0]), max(0.0, t["box"][1])
        x1 = min(float(self.width), t["box"][0] + t["box"][2])
        y1 = min(float(self.height), t["box"][1] + t["box"][3])
        t["cv"], t["ok"] = None, False
        if x1 - x0 >= 4 and y1 - y0 >= 4:
            t["cv"] = self.make()
            t["cv"].init(image, (int(x0), int(y0), int(round(x1 - x0)), int(round(y1 - y0))))
            t["ok"] = True

    def _reported(self, t):
        return t["missed"] == 0 or t["ok"]


class Mog2Blobs:
    """MOG2 foreground, morphology and contours: one box a blob."""

    def __init__(self, min_area=400):
        import cv2
        self.cv2 = cv2
        self.sub = cv2.createBackgroundSubtractorMOG2()
        self.open_k = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (3, 3))
        self.close_k = cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (7, 7))
        self.min_area = min_area

    def boxes(self, bgr):
        cv2 = self.cv2
        mask = self.sub.apply(bgr)
        mask = (mask > 200).astype(np.uint8) * 255  # 127 marks shadows
        mask = cv2.morphologyEx(mask, cv2.MORPH_OPEN, self.open_k)
        mask = cv2.morphologyEx(mask, cv2.MORPH_CLOSE, self.close_k)
        contours, _ = cv2.findContours(mask, cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
        out = []
        for c in contours:
            x, y, w, h = cv2.boundingRect(c)
            if w * h >= self.min_area:
                out.append((x, y, w, h))
        return out


def _on_frames(y4m_path, n_frames, make_step):
    """Runs a tracker over the frames of a Y4M file: make_step(width, height)
    gives step(k, bgr) (frames from 1, BGR as OpenCV converts I420), which
    returns (id, box) pairs. Returns MOTChallenge rows and the time spent
    in step."""
    import cv2
    from .y4m import open_y4m
    w, h, _, frames = open_y4m(y4m_path)
    n = len(frames) if n_frames is None else min(n_frames, len(frames))
    step = make_step(w, h)
    rows, spent = [], 0.0
    for k in range(1, n + 1):
        bgr = cv2.cvtColor(np.asarray(frames[k - 1]).reshape(h * 3 // 2, w),
                           cv2.COLOR_YUV2BGR_I420)
        t0 = time.perf_counter()
        out = step(k, bgr)
        spent += time.perf_counter() - t0
        rows += [(k, tid, x, y, bw, bh) for tid, (x, y, bw, bh) in out]
    return rows, spent


def mog2_iou(y4m_path, n_frames=None):
    """The pixels-only baseline over a Y4M file."""
    def make_step(w, h):
        blobs, tracker = Mog2Blobs(), IoUTracker()
        return lambda k, bgr: tracker.update(blobs.boxes(bgr))
    return _on_frames(y4m_path, n_frames, make_step)


def opencv_trackers(kind, y4m_path, dets_by_frame, n_frames=None):
    """OpenCV's KCF or CSRT tracker per person, on the public detections and
    the frames of a Y4M file (OpenCVTrackers)."""
    def make_step(w, h):
        tracker = OpenCVTrackers(kind, w, h)
        return lambda k, bgr: tracker.update(dets_by_frame.get(k, np.zeros((0, 5)))[:, :4], bgr)
    return _on_frames(y4m_path, n_frames, make_step)
