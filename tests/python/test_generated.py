"""Files the tree holds that a command of the tree generates: generated
again offline, they match the file."""
import importlib.util
import os
import subprocess
import sys

import numpy as np

from conftest import TOP

MAKE_SILHOUETTES = os.path.join(TOP, "scripts", "make-silhouettes.py")
SILHOUETTES = os.path.join(TOP, "lib", "template", "silhouettes.inc")


def check_silhouettes(path):
    return subprocess.run([sys.executable, MAKE_SILHOUETTES, "--check", path],
                          capture_output=True, text=True)


def test_silhouettes_match_their_generator():
    r = check_silhouettes(SILHOUETTES)
    assert r.returncode == 0, r.stderr
    assert "40 silhouettes and 15 shapes a person is not as generated" in r.stdout


def test_a_changed_silhouette_is_noticed(tmp_path):
    with open(SILHOUETTES) as f:
        text = f.read()
    # One coordinate of the first outline moved by a thousandth.
    i = text.index("kOutline[kSilhouettes]")
    j = text.index("f,", i) - 2  # the first number's thousandths
    changed = text[:j] + str((int(text[j]) + 1) % 10) + text[j + 1:]
    path = tmp_path / "silhouettes.inc"
    path.write_text(changed)
    r = check_silhouettes(str(path))
    assert r.returncode == 1 and "differs by" in r.stderr, (r.stdout, r.stderr)
    path.write_text(text.replace("    // front, phase 0/8\n", "", 1))
    r = check_silhouettes(str(path))
    assert r.returncode == 1 and "not what make-silhouettes.py generates" in r.stderr, r.stderr


def generator():
    spec = importlib.util.spec_from_file_location("make_silhouettes", MAKE_SILHOUETTES)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_library_varies():
    """Each view changes with the gait phase; a stride's phases k and 4 - k,
    mirror images of each other for straight legs, differ (the swinging
    knee bends); walking right and left differ; each by a twentieth of the
    box somewhere; a heavy and a slim build differ from the average in the
    torso's width, and a bag changes the outline beside or behind the body
    (by a thirtieth of the box somewhere). Without the knee, with the
    frontal view standing still, or with every build or bag drawn as the
    average, this fails."""
    gen = generator()
    library = gen.library(("bag", "heavy", "slim"))
    sils = {name: p for name, p, _, _ in library}

    def apart(a, b):
        return np.abs(sils[a] - sils[b]).max()

    for view in ("front", "three-quarter, facing right", "side, facing left"):
        phases = ["%s, phase %d/8" % (view, k) for k in range(8)]
        # Seen from the front, phase k + 4 is phase k mirrored: their
        # profiles may be alike, no others.
        alike = [(i, j) for i in range(8) for j in range(i + 1, 8)
                 if apart(phases[i], phases[j]) <= 0.01]
        assert all(view == "front" and j == i + 4 for i, j in alike), (view, alike)
        for k in (0, 1, 3, 4):
            assert apart(phases[k], phases[(4 - k) % 8]) > 0.05, (view, k)
    for view in ("three-quarter", "side"):
        assert apart("%s, facing right, phase 1/8" % view,
                     "%s, facing left, phase 1/8" % view) > 0.05, view
    torso = slice(16, 36)  # the profile's rows from the chest to the hips
    for view in ("front", "three-quarter, facing left", "side, facing right"):
        average = sils["%s, phase 2/8" % view][torso]
        for build in ("heavy", "slim"):
            other = sils["%s, phase 2/8, %s" % (view, build)][torso]
            wider = (other[:, 1] - other[:, 0]).mean() - (average[:, 1] - average[:, 0]).mean()
            assert (wider > 0.02) if build == "heavy" else (wider < -0.005), (view, build, wider)
    for name in ("front, phase 3/8, shoulder bag", "side, facing left, phase 1/8, backpack",
                 "three-quarter, facing right, phase 3/8, in hand",
                 "three-quarter, facing left, phase 1/8, backpack"):
        assert apart(name, name.rsplit(", ", 1)[0]) > 0.03, name
    assert gen.distinct(gen.library()) >= 28


def test_the_shapes_a_person_is_not_are_pairs():
    """Each shape a person is not is two walkers side by side: wider for its
    height than every silhouette of its view and way, and wider the farther
    apart they are. With one walker drawn, or the second on top of the
    first, this fails."""
    gen = generator()
    aspects = {name: aspect for name, _, aspect, _ in gen.library()}
    pairs = gen.not_people()
    assert len(pairs) == 15
    for name, _, aspect, _ in pairs:
        view = name.split("two ")[1].replace(" walkers", "").rsplit(", ", 1)[0]
        alike = [a for n, a in aspects.items() if n.rsplit(", phase", 1)[0] == view]
        assert len(alike) == 8 and aspect < min(alike) - 0.05, (name, aspect, min(alike))
    for k in range(0, 15, 3):
        near, middle, far = (a for _, _, a, _ in pairs[k:k + 3])
        assert near > middle > far, pairs[k][0]


def test_an_unknown_variant_is_refused(tmp_path):
    # A misspelt variant is an error naming those there are, and nothing is
    # written.
    out = tmp_path / "silhouettes.inc"
    r = subprocess.run([sys.executable, MAKE_SILHOUETTES, "--with", "bag,fat", "--out", str(out)],
                       capture_output=True, text=True)
    assert r.returncode == 2 and "no variant fat (there are bag, heavy, slim)" in r.stderr, r.stderr
    assert not out.exists()
