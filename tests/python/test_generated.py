"""Files the tree holds that a command of the tree generates: generated
again offline, they match the file."""
import os
import subprocess
import sys

from conftest import TOP

MAKE_SILHOUETTES = os.path.join(TOP, "lib", "make-silhouettes.py")
SILHOUETTES = os.path.join(TOP, "lib", "silhouettes.inc")


def check_silhouettes(path):
    return subprocess.run([sys.executable, MAKE_SILHOUETTES, "--check", path],
                          capture_output=True, text=True)


def test_silhouettes_match_their_generator():
    r = check_silhouettes(SILHOUETTES)
    assert r.returncode == 0, r.stderr
    assert "48 silhouettes as generated" in r.stdout


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
    path.write_text(text.replace("    // front, arm swing 0.35, phase 0/8\n", "", 1))
    r = check_silhouettes(str(path))
    assert r.returncode == 1 and "not what make-silhouettes.py generates" in r.stderr, r.stderr
