#!/usr/bin/env python3
"""Generates the pedestrian silhouette library of the contour template
(lib/template/silhouettes.inc) from a parametric body model, reproducibly.

    make-silhouettes.py [--out lib/template/silhouettes.inc] [--png docs/img/silhouettes.png]
                        [--with bag,heavy,slim] [--no-not-people]
    make-silhouettes.py --check lib/template/silhouettes.inc

The body (in body heights, x centred): a head (ellipse), a neck, a torso (a
trapezoid from the shoulders to the hips), two arms (capsules) and two legs,
each a thigh and a shin, swinging with the gait phase; the swinging leg's
knee bends, so a stride's phases differ from their mirror images. Three
viewpoints (front, three-quarter, side) change the widths and how far the
limbs spread sideways; the three-quarter and side views walk right and left,
and the front view shows the walk as the swinging foot raised. Eight gait
phases of each make the 40 silhouettes of the shipped library: the average
build with empty hands. To measure, more can be drawn (--with): a heavy
build, a slim one, and 20 carrying a bag at odd phases (over the shoulder
seen from the front, a backpack or a bag in the hand seen from the side or
three-quarters); the shipped library leaves them out (SHIPPED). After
the silhouettes come 15 shapes a person is not (--no-not-people leaves them
out): two walkers side by side, at three distances in each view and way
they face; a blob closer to one of them than to every silhouette is no
pedestrian (lib/template/classifier.cc). Each is
rendered on a fine grid, cut to its bounding box, and kept as its outer
profile: for each of 64 rows, the leftmost and rightmost body point, from
the box's centre in box heights (so a shape keeps its proportions: a box
with a person's aspect is not a person).
No data set is involved.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

ROWS = 64
VIEWS = {  # shoulder half-width, hip half-width, leg spread sideways, limbs forward
    "front": (0.125, 0.095, 0.045, 0.0),
    "three-quarter": (0.10, 0.085, 0.03, 0.6),
    "side": (0.07, 0.075, 0.0, 1.0),
}
PHASES = 8
ARM_SWING = 0.45  # radians at the phase's peak
LEG_SWING = 0.42  # the thigh's, likewise
KNEE_BEND = 0.7  # radians, at mid-swing
THIGH = SHIN = 0.235
BUILDS = {  # the torso's and hips' widths, the limbs' thickness, the head's width
    "average": (1.0, 1.0, 1.0),
    "heavy": (1.3, 1.25, 1.1),
    "slim": (0.85, 0.85, 0.95),
}
# Who can be drawn besides the average build walking with empty hands:
# name: (build, bag or not, the phases drawn in each view and way it faces).
VARIANTS = {
    "bag": ("average", True, (1, 3, 5, 7)),
    "heavy": ("heavy", False, (0, 2, 4, 6)),
    "slim": ("slim", False, (2, 6)),
}
# Those the shipped library holds: none. With the builds, the template takes
# a two-person group for one heavy person and a fragment for a slim one;
# with the bags, as with the builds, tracking from the pixels gains only what
# the same search of the thresholds gains without them, and loses in
# conditions no threshold was chosen on (docs/notes/pixels.md, "Builds and
# bags, chosen by tracking").
SHIPPED = ()


# The views and the ways a walker faces in them: the front view walks
# towards the camera, where facing left or right means nothing.
WALKS = [(view, facing) for view in VIEWS for facing in ((1,) if view == "front" else (1, -1))]


def facing_name(view, facing):
    """The way a walker faces, as the names say it after the view."""
    return "" if view == "front" else ", facing " + ("right" if facing > 0 else "left")


def capsule(xx, yy, x0, y0, x1, y1, r):
    dx, dy = x1 - x0, y1 - y0
    t = np.clip(((xx - x0) * dx + (yy - y0) * dy) / (dx * dx + dy * dy), 0, 1)
    return (xx - (x0 + t * dx)) ** 2 + (yy - (y0 + t * dy)) ** 2 <= r * r


def render(view, phase, facing, build="average", bag=None):
    """The body at gait phase `phase` of PHASES, facing right (1) or left
    (-1) in the views that show the walk, of a build (BUILDS), carrying a
    "shoulder bag", a "backpack", a bag "in hand" or none. Each leg is a
    thigh and a shin; the swinging leg's knee bends (most at mid-swing), so
    that phases k and PHASES/2 - k, mirror images of each other for
    straight legs, differ. In the front view the walk shows as the swinging
    foot raised."""
    sw, hw, spread, forward = VIEWS[view]
    torso, limb, head = BUILDS[build]
    sw, hw = sw * torso, hw * torso
    ys = np.linspace(0, 1, 400)
    xs = np.linspace(-0.5, 0.5, 400)
    xx, yy = np.meshgrid(xs, ys)
    body = ((xx / (0.052 * head)) ** 2 + ((yy - 0.065) / 0.065) ** 2) <= 1  # head
    body |= (np.abs(xx) <= 0.028 * head) & (yy >= 0.11) & (yy <= 0.16)  # neck
    t = np.clip((yy - 0.15) / (0.52 - 0.15), 0, 1)
    body |= (yy >= 0.15) & (yy <= 0.53) & (np.abs(xx) <= sw + (hw - sw) * t)  # torso
    phi = 2 * math.pi * phase / PHASES
    hands = []
    for side in (-1, 1):
        # Arms swing against the legs: forward/back (z) seen through the
        # view's `forward`, slightly out in front.
        a = side * ARM_SWING * math.sin(phi)
        ax0 = side * (sw - 0.02)
        ax1 = ax0 + facing * forward * 0.36 * math.sin(a) + side * 0.03 * (1 - forward)
        ay1 = 0.17 + 0.36 * math.cos(a)
        body |= capsule(xx, yy, ax0, 0.17, ax1, ay1, 0.035 * limb)
        hands.append((ax1, ay1))
        # Legs: this leg's phase; its thigh swings forward and back (z), its
        # knee bends while the leg swings forward (cos > 0).
        p = phi + (0 if side > 0 else math.pi)
        g = LEG_SWING * math.sin(p)
        flex = KNEE_BEND * max(0.0, math.cos(p)) ** 2
        kz, ky = THIGH * math.sin(g), 0.52 + THIGH * math.cos(g)
        fz, fy = kz + SHIN * math.sin(g - flex), ky + SHIN * math.cos(g - flex)
        lx0 = side * max(0.045 - 0.03 * forward, 0.02) * torso
        kx = lx0 + facing * forward * kz + side * spread / 2
        fx = lx0 + facing * forward * fz + side * spread
        body |= capsule(xx, yy, lx0, 0.52, kx, ky, 0.05 * limb)
        body |= capsule(xx, yy, kx, ky, fx, fy, 0.045 * limb)
    if bag == "in hand":
        # A bag hanging from the hand farther out to the side, its far edge
        # a little beyond the hand.
        hx, hy = max(hands, key=lambda h: abs(h[0]))
        out = math.copysign(1, hx)
        body |= ((xx - hx) * out >= -0.03) & ((xx - hx) * out <= 0.07) & (yy >= hy - 0.02) & \
            (yy <= hy + 0.13)
    elif bag == "shoulder bag":
        # On a strap over the shoulder, at the left hip, beside the arm.
        body |= (xx >= -sw - 0.1) & (xx <= -sw) & (yy >= 0.38) & (yy <= 0.52)
    elif bag == "backpack":
        # On the back: behind the torso, seen through the view's `forward`.
        back = -facing * forward
        x0, x1 = sorted((back * sw * 0.5, back * (sw + 0.12)))
        body |= (xx >= x0) & (xx <= x1) & (yy >= 0.17) & (yy <= 0.43)
    return body, xs, ys


# Shapes a person is not, that the vote weighs against the library: two
# people side by side, the second `offset` body heights to the right and at
# another gait phase (a group that a wide silhouette would pass as one
# person). A person torn down the middle was measured too and is not drawn:
# TUD-Campus lost most of its tracks to it (docs/notes/pixels.md, "Shapes a
# person is not").
GROUP_OFFSETS = (0.12, 0.2, 0.28)
NOT_PEOPLE = True


def group(view, facing, phase, offset):
    """Two walkers, the second `offset` body heights to the right and four
    gait phases on."""
    a, xs, ys = render(view, phase, facing)
    b, _, _ = render(view, (phase + PHASES // 2) % PHASES, facing)
    shift = int(round(offset / (xs[1] - xs[0])))
    moved = np.zeros_like(b)
    moved[:, shift:] = b[:, :b.shape[1] - shift]
    return a | moved, xs, ys


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


def bag_of(view, phase):
    """The bag carried in a variant with one: over the shoulder seen from
    the front; on the back or in the hand (by phase) otherwise."""
    if view == "front":
        return "shoulder bag"
    return "backpack" if phase in (1, 5) else "in hand"


def library(variants=SHIPPED):
    """The silhouettes: (name, profile, aspect, outline) for each. First
    the average build with empty hands at every phase, then the VARIANTS
    named."""
    out = []
    for build, bag, phases in [("average", False, range(PHASES))] + [VARIANTS[v] for v in variants]:
        for view, facing in WALKS:
            for phase in phases:
                carried = bag_of(view, phase) if bag else None
                body, xs, ys = render(view, phase, facing, build, carried)
                p, aspect = profile(body, xs, ys)
                name = "%s, phase %d/%d%s%s" % (
                    view + facing_name(view, facing), phase, PHASES,
                    "" if build == "average" else ", " + build,
                    ", " + carried if carried else "")
                out.append((name, p, aspect, contour_points(body, xs, ys)))
    return out


def not_people():
    """The shapes a person is not (GROUP_OFFSETS), as library() gives the
    silhouettes."""
    out = []
    for view, facing in WALKS:
        way = facing_name(view, facing)
        for offset in GROUP_OFFSETS:
            body, xs, ys = group(view, facing, 2, offset)
            p, aspect = profile(body, xs, ys)
            out.append(("not a person: two %s walkers%s, %g apart" % (view, way, offset), p,
                        aspect, contour_points(body, xs, ys)))
    return out


def write(path, sils, negatives=()):
    every = list(sils) + list(negatives)
    with open(path, "w") as f:
        f.write("// Generated by `python3 scripts/make-silhouettes.py` from its parametric body\n"
                "// model (no other input): do not edit.\n")
        f.write("// %d pedestrian silhouettes from a parametric body model, then %d shapes\n"
                % (len(sils), len(negatives)))
        f.write("// a person is not, each the outer profile of its bounding box: for each\n")
        f.write("// of %d rows the left and right edges, from the box's centre in box\n" % ROWS)
        f.write("// heights.\n")
        f.write("constexpr int kSilhouettes = %d;\n" % len(every))
        f.write("constexpr int kPeople = %d; // the first kPeople are pedestrians\n" % len(sils))
        f.write("constexpr float kSilhouette[kSilhouettes][%d][2] = {\n" % ROWS)
        for name, p, _, _ in every:
            f.write("    // %s\n    {" % name)
            f.write(", ".join("{%.4ff, %.4ff}" % (l, r) for l, r in p))
            f.write("},\n")
        f.write("};\n")
        f.write("// The outline of each: %d points, x from the box's centre and y from its\n" % POINTS)
        f.write("// top, in box heights.\n")
        f.write("constexpr int kOutlinePoints = %d;\n" % POINTS)
        f.write("constexpr float kOutline[kSilhouettes][kOutlinePoints][2] = {\n")
        for _, _, _, o in every:
            f.write("    {" + ", ".join("{%.4ff, %.4ff}" % (x, y) for x, y in o) + "},\n")
        f.write("};\n")


def numbers(path):
    with open(path) as f:
        text = f.read()
    names = re.findall(r"^    // (.*)$", text, re.M)
    values = np.array([float(v) for v in re.findall(r"(-?\d+\.\d+)f", text)])
    return names, values


def check(path, sils, negatives=()):
    """Regenerates the library and compares it with `path`: the same
    silhouettes, every coordinate within 2e-4 (the file's four decimals,
    and the last digit's rounding on another machine). Returns the exit
    status."""
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        fresh = os.path.join(tmp, "silhouettes.inc")
        write(fresh, sils, negatives)
        names_a, a = numbers(fresh)
        names_b, b = numbers(path)
    if names_a != names_b or a.shape != b.shape:
        print("%s: not what make-silhouettes.py generates: %d silhouettes named %s..., "
              "expected %d named %s..." % (path, len(names_b), names_b[:1], len(names_a),
                                           names_a[:1]), file=sys.stderr)
        return 1
    worst = float(np.abs(a - b).max())
    if worst > 2e-4:
        print("%s: a coordinate differs by %.4f from what make-silhouettes.py generates"
              % (path, worst), file=sys.stderr)
        return 1
    print("%s: %d silhouettes and %d shapes a person is not as generated (largest difference "
          "%.5f)" % (path, len(sils), len(negatives), worst))
    return 0


def distinct(sils):
    """How many of the profiles differ from every other by more than a
    hundredth of the box's height somewhere."""
    n = 0
    for i, (_, p, _, _) in enumerate(sils):
        n += all(np.abs(p - q).max() > 0.01 for j, (_, q, _, _) in enumerate(sils) if j != i)
    return n


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument("--out", default=os.path.join(here, "..", "lib", "template", "silhouettes.inc"))
    ap.add_argument("--png", help="also draw the silhouettes into this PNG")
    ap.add_argument("--check", metavar="FILE",
                    help="compare FILE with what would be generated, write nothing")
    ap.add_argument("--with", dest="variants", default=",".join(SHIPPED),
                    help="the variants drawn, comma-separated (of %s; the shipped library: "
                    "none): a library to measure" % ", ".join(VARIANTS))
    ap.add_argument("--not-people", dest="not_people", action=argparse.BooleanOptionalAction,
                    default=NOT_PEOPLE, help="draw the shapes a person is not (two people side by "
                    "side) after the silhouettes (default: %s)" % NOT_PEOPLE)
    a = ap.parse_args()
    variants = [v for v in a.variants.split(",") if v]
    unknown = [v for v in variants if v not in VARIANTS]
    if unknown:
        ap.error("no variant %s (there are %s)" % (", ".join(unknown), ", ".join(VARIANTS)))
    sils = library(variants)
    negatives = not_people() if a.not_people else []
    if a.check:
        return check(a.check, sils, negatives)
    write(a.out, sils, negatives)
    aspects = [s[2] for s in sils]
    print("wrote %d silhouettes and %d shapes a person is not to %s, %d distinct "
          "(height/width %.2f to %.2f)" % (len(sils), len(negatives), a.out, distinct(sils),
                                           min(aspects), max(aspects)))
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        drawn = sils + negatives
        rows = (len(drawn) + PHASES - 1) // PHASES
        fig, axes = plt.subplots(rows, PHASES, figsize=(9, 1.2 + 1.3 * rows))
        for ax in axes.flat:
            ax.axis("off")
        for i, (ax, (name, p, _, _)) in enumerate(zip(axes.flat, drawn)):
            ax.fill_betweenx(np.arange(ROWS), p[:, 0], p[:, 1],
                             color="black" if i < len(sils) else "firebrick")
            ax.set_xlim(-0.35, 0.35)
            ax.set_ylim(ROWS, 0)
        fig.suptitle("The contour template's silhouettes (scripts/make-silhouettes.py), as profiles:\n"
                     "the average build at every gait phase (front; three-quarter and side, "
                     "walking right, then left)%s" % "".join(",\nthen " +
                         {"bag": "carrying a bag (over the shoulder, on the back, in the hand)",
                          "heavy": "a heavy build", "slim": "a slim build"}[v] for v in variants) +
                     (";\nin red, shapes a person is not: two walkers side by side"
                      if negatives else ""))
        fig.tight_layout()
        fig.savefig(a.png, dpi=80)
    return 0


if __name__ == "__main__":
    sys.exit(main())
