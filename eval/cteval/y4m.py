"""Reading Y4M (4:2:0) files as numpy frames, without copying the file."""
import numpy as np


def open_y4m(path):
    """Returns (width, height, (num, den), frames) where frames is an
    (N, bytes) uint8 memmap, one I420 frame a row (after its FRAME line)."""
    with open(path, "rb") as f:
        header = f.readline()
    if not header.startswith(b"YUV4MPEG2 "):
        raise ValueError("%s: not Y4M" % path)
    w = h = None
    rate = (25, 1)
    for tok in header.split()[1:]:
        if tok[:1] == b"W":
            w = int(tok[1:])
        elif tok[:1] == b"H":
            h = int(tok[1:])
        elif tok[:1] == b"F":
            a, b = tok[1:].split(b":")
            rate = (int(a), int(b))
        elif tok[:1] == b"C" and not tok.startswith(b"C420"):
            raise ValueError("%s: colour space %s is not 4:2:0" % (path, tok.decode()))
    frame_bytes = w * h + 2 * ((w + 1) // 2) * ((h + 1) // 2)
    data = np.memmap(path, dtype=np.uint8, mode="r", offset=len(header))
    n = len(data) // (6 + frame_bytes)
    rows = data[: n * (6 + frame_bytes)].reshape(n, 6 + frame_bytes)
    return w, h, rate, rows[:, 6:]


def i420_planes(row, w, h):
    """Y, U, V views of one I420 frame row."""
    cw, ch = (w + 1) // 2, (h + 1) // 2
    y = row[: w * h].reshape(h, w)
    u = row[w * h: w * h + cw * ch].reshape(ch, cw)
    v = row[w * h + cw * ch:].reshape(ch, cw)
    return y, u, v
