"""The ctypes mirrors match the C compiler's layout of the public structs."""
import ctypes
import json
import os
import subprocess

import pytest

from ctrack import _abi


@pytest.fixture(scope="module")
def layout():
    exe = os.environ.get("CTRACK_ABI_LAYOUT")
    assert exe, "CTRACK_ABI_LAYOUT must name the abi_layout helper (meson test sets it)"
    return json.loads(subprocess.run([exe], check=True, capture_output=True).stdout)


@pytest.mark.parametrize("name", ["Config", "Frame", "Detection", "Track", "Stats", "Candidate",
                                  "PersonSize"])
def test_struct_layout(layout, name):
    cls = getattr(_abi, name)
    want = layout[name]
    assert ctypes.sizeof(cls) == want.pop("sizeof")
    got = {f: getattr(cls, f).offset for f, _ in cls._fields_}
    assert got == want


def test_constants(layout):
    """The binding's formats, sources and track states are the header's."""
    got = {name: getattr(_abi, name) for name in layout["Constants"]}
    assert got == layout["Constants"]


def test_version_is_the_header_s():
    """_abi.py (and so the pip package) follows the header it mirrors."""
    import ctrack
    assert _abi.VERSION == ctrack.version()
    assert ctrack.__version__ == _abi.VERSION
