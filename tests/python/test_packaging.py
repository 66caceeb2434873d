"""python/ is a package pip installs: from a copy of it, without the network
(pip --no-index, the venv's setuptools), into a scratch folder, from where
it imports, reports its version and tracks through the library."""
import os
import shutil
import subprocess
import sys

import ctrack
from conftest import TOP

CHECK = """
import importlib.metadata, sys
import numpy as np
import ctrack
assert ctrack.__file__.startswith(sys.argv[1]), ctrack.__file__
assert importlib.metadata.version("ctrack") == ctrack.__version__, importlib.metadata.version("ctrack")
assert any(r.startswith("numpy") for r in importlib.metadata.requires("ctrack"))
with ctrack.Tracker(fps=10) as t:
    for k in range(5):
        tracks = t.feed(None, np.array([[10.0 + k, 20, 30, 80, 0.9]]))
assert len(tracks) == 1 and tracks["id"][0] == 1, tracks
print(ctrack.__version__)
"""


def test_pip_installs_the_package(tmp_path):
    # A copy: pip builds in the source folder and would leave build/ and
    # *.egg-info in the tree.
    src = tmp_path / "src"
    shutil.copytree(os.path.join(TOP, "python"), src)
    site = tmp_path / "site"
    subprocess.run([sys.executable, "-m", "pip", "install", "--quiet", "--no-index",
                    "--no-build-isolation", "--no-deps", "--disable-pip-version-check",
                    "--target", str(site), str(src)], check=True)
    assert (site / "ctrack" / "__init__.py").exists()
    env = dict(os.environ, PYTHONPATH=str(site))
    out = subprocess.run([sys.executable, "-c", CHECK, str(site)], cwd=str(tmp_path), env=env,
                         check=True, capture_output=True, text=True).stdout
    assert out.strip() == ctrack.__version__


def test_make_install_lists_every_module():
    """meson.build installs the package's modules by name: every module of
    python/ctrack is in the list (tests/install.sh checks they arrive)."""
    import re
    with open(os.path.join(TOP, "meson.build")) as f:
        listed = set(re.findall(r"'python/ctrack/([a-z_]+\.py)'", f.read()))
    here = {m for m in os.listdir(os.path.join(TOP, "python", "ctrack")) if m.endswith(".py")}
    assert listed == here
