#!/usr/bin/env python3
"""Generates the pedestrian silhouette library of the contour template
(lib/silhouettes.inc) from a parametric body model, reproducibly.

    make-silhouettes.py [--out lib/silhouettes.inc] [--png docs/img/silhouettes.png]

The body (in body heights, x centred): a head (ellipse), a neck, a torso (a
trapezoid from the shoulders to the hips), two arms and two legs (capsules)
swinging with the gait phase. Three viewpoints (front, three-quarter, side)
change the widths and how far the limbs spread sideways; eight gait phases
and two arm swings make 48 silhouettes. Each is rendered on a fine grid, cut
to its bounding box, and kept as its outer profile: for each of 64 rows, the
leftmost and rightmost body point, from the box's centre in box heights (so a
shape keeps its proportions: a box with a person's aspect is not a person).
No data set is involved.
"""
import argparse
import math
import os

import numpy as np

ROWS = 64
VIEWS = {  # shoulder half-width, hip half-width, leg spread sideways, limbs forward
    "front": (0.125, 0.095, 0.045, 0.0),
    "three-quarter": (0.10, 0.085, 0.03, 0.6),
    "side": (0.07, 0.075, 0.0, 1.0),
}
PHASES = 8
ARM_SWINGS = (0.35, 0.6)  # radians at the phase's peak
LEG_SWING = 0.42


def capsule(xx, yy, x0, y0, x1, y1, r):
    dx, dy = x1 - x0, y1 - y0
    t = np.clip(((xx - x0) * dx + (yy - y0) * dy) / (dx * dx + dy * dy), 0, 1)
    return (xx - (x0 + t * dx)) ** 2 + (yy - (y0 + t * dy)) ** 2 <= r * r


def render(view, phase, arm_swing):
    sw, hw, spread, forward = VIEWS[view]
    ys = np.linspace(0, 1, 400)
    xs = np.linspace(-0.5, 0.5, 400)
    xx, yy = np.meshgrid(xs, ys)
    body = ((xx / 0.052) ** 2 + ((yy - 0.065) / 0.065) ** 2) <= 1  # head
    body |= (np.abs(xx) <= 0.028) & (yy >= 0.11) & (yy <= 0.16)  # neck
    t = np.clip((yy - 0.15) / (0.52 - 0.15), 0, 1)
    body |= (yy >= 0.15) & (yy <= 0.53) & (np.abs(xx) <= sw + (hw - sw) * t)  # torso
    s = math.sin(2 * math.pi * phase / PHASES)
    for side in (-1, 1):
        # Arms hang from the shoulders and swing: forward/back in the side
        # view (seen as sideways motion in the image), slightly out in front.
        a = side * arm_swing * s * forward
        ax0 = side * (sw - 0.02)
        ax1 = ax0 + 0.36 * math.sin(a) + side * 0.03 * (1 - forward)
        ay1 = 0.17 + 0.36 * math.cos(a)
        body |= capsule(xx, yy, ax0, 0.17, ax1, ay1, 0.035)
        # Legs swing in opposition.
        g = -side * LEG_SWING * s * forward
        lx0 = side * max(0.045 - 0.03 * forward, 0.02)
        lx1 = lx0 + 0.47 * math.sin(g) + side * spread
        ly1 = 0.52 + 0.47 * math.cos(g)
        body |= capsule(xx, yy, lx0, 0.52, lx1, ly1, 0.05)
    return body, xs, ys


def profile(body, xs, ys):
    rows_any = np.where(body.any(axis=1))[0]
    cols_any = np.where(body.any(axis=0))[0]
    top, bottom = ys[rows_any[0]], ys[rows_any[-1]]
    left, right = xs[cols_any[0]], xs[cols_any[-1]]
    out = np.zeros((ROWS, 2))
    height, centre = bottom - top, (left + right) / 2
    for r in range(ROWS):
        y = top + (r + 0.5) * height / ROWS
        row = body[np.argmin(np.abs(ys - y))]
        idx = np.where(row)[0]
        out[r] = [(xs[idx[0]] - centre) / height, (xs[idx[-1]] - centre) / height]
    return out, height / (right - left)


POINTS = 160


def contour_points(body, xs, ys):
    """POINTS points of the silhouette's outline (body pixels with a
    4-neighbour outside), spread evenly, from the box's centre in box heights
    (x) and from its top in box heights (y)."""
    inner = body.copy()
    inner[1:, :] &= body[:-1, :]
    inner[:-1, :] &= body[1:, :]
    inner[:, 1:] &= body[:, :-1]
    inner[:, :-1] &= body[:, 1:]
    edge = body & ~inner
    r, c = np.where(edge)
    rows_any = np.where(body.any(axis=1))[0]
    cols_any = np.where(body.any(axis=0))[0]
    top, bottom = ys[rows_any[0]], ys[rows_any[-1]]
    centre = (xs[cols_any[0]] + xs[cols_any[-1]]) / 2
    height = bottom - top
    pts = np.column_stack([(xs[c] - centre) / height, (ys[r] - top) / height])
    pick = np.random.default_rng(0).choice(len(pts), POINTS, replace=False)
    return pts[np.sort(pick)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--out", default=os.path.join(here, "silhouettes.inc"))
    ap.add_argument("--png", help="also draw the silhouettes into this PNG")
    a = ap.parse_args()
    sils, names, aspects, outlines = [], [], [], []
    for view in VIEWS:
        for swing in ARM_SWINGS:
            for phase in range(PHASES):
                body, xs, ys = render(view, phase, swing)
                p, aspect = profile(body, xs, ys)
                sils.append(p)
                outlines.append(contour_points(body, xs, ys))
                aspects.append(aspect)
                names.append("%s, arm swing %.2f, phase %d/%d" % (view, swing, phase, PHASES))
    with open(a.out, "w") as f:
        f.write("// Generated by `python3 lib/make-silhouettes.py` from its parametric body\n"
                "// model (no other input): do not edit.\n")
        f.write("// %d pedestrian silhouettes from a parametric body model, each the\n" % len(sils))
        f.write("// outer profile of its bounding box: for each of %d rows the left and\n" % ROWS)
        f.write("// right edges, from the box's centre in box heights.\n")
        f.write("constexpr int kSilhouettes = %d;\n" % len(sils))
        f.write("constexpr float kSilhouette[kSilhouettes][%d][2] = {\n" % ROWS)
        for name, p in zip(names, sils):
            f.write("    // %s\n    {" % name)
            f.write(", ".join("{%.4ff, %.4ff}" % (l, r) for l, r in p))
            f.write("},\n")
        f.write("};\n")
        f.write("// The outline of each: %d points, x from the box's centre and y from its\n" % POINTS)
        f.write("// top, in box heights.\n")
        f.write("constexpr int kOutlinePoints = %d;\n" % POINTS)
        f.write("constexpr float kOutline[kSilhouettes][kOutlinePoints][2] = {\n")
        for o in outlines:
            f.write("    {" + ", ".join("{%.4ff, %.4ff}" % (x, y) for x, y in o) + "},\n")
        f.write("};\n")
    print("wrote %d silhouettes to %s (height/width %.2f to %.2f)"
          % (len(sils), a.out, min(aspects), max(aspects)))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(3, 16, figsize=(16, 4.2))
        for ax, p in zip(axes.flat, sils):
            rows = np.arange(ROWS)
            ax.fill_betweenx(rows, p[:, 0], p[:, 1], color="black")
            ax.set_xlim(-0.35, 0.35)
            ax.set_ylim(ROWS, 0)
            ax.axis("off")
        fig.suptitle("The contour template's silhouettes (lib/make-silhouettes.py): "
                     "front, three-quarter and side views, two arm swings, eight gait phases")
        fig.tight_layout()
        fig.savefig(a.png, dpi=80)


if __name__ == "__main__":
    main()
