"""The sources' own rules: no function of the library or of ct-track over
100 lines (scripts/function-length.py, lizard's measure)."""
import os
import subprocess
import sys

from conftest import TOP

SCRIPT = os.path.join(TOP, "scripts", "function-length.py")


def function_length(*args):
    return subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True,
                          cwd=TOP)


def test_no_function_is_over_100_lines():
    r = function_length("lib", "tools")
    assert r.returncode == 0, r.stdout + r.stderr
    # Every source was read: a few hundred functions.
    assert int(r.stdout.split()[1]) > 300, r.stdout


def test_a_longer_function_is_named():
    r = function_length("--max", "60", "lib")
    assert r.returncode == 1
    assert "lib/template/classifier.cc" in r.stdout and "classify is" in r.stdout, r.stdout
