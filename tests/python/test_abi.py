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
                                  "PersonSize", "Allocator", "Point", "Line", "Zone", "Event",
                                  "LineCount", "ZoneCount", "Occupant"])
def test_struct_layout(layout, name):
    cls = getattr(_abi, name)
    want = layout[name]
    assert ctypes.sizeof(cls) == want.pop("sizeof")
    got = {f: getattr(cls, f).offset for f, _ in cls._fields_}
    assert got == want


def test_allocator_through_ctypes():
    """A host allocator given through the binding: every block goes back."""
    import ctrack
    lib = ctrack.load()
    live = {}

    @_abi.ALLOC_FN
    def alloc(opaque, size):
        buf = ctypes.create_string_buffer(size + 16)
        addr = (ctypes.addressof(buf) + 15) // 16 * 16
        live[addr] = buf
        return addr

    @_abi.FREE_FN
    def free(opaque, ptr):
        del live[ptr]

    cfg = _abi.Config()
    assert lib.ct_config_default(ctypes.byref(cfg), ctypes.sizeof(cfg)) == 0
    a = _abi.Allocator(ctypes.sizeof(_abi.Allocator), alloc, free, None)
    t = ctypes.c_void_p()
    assert lib.ct_tracker_create_with_allocator(ctypes.byref(cfg), ctypes.byref(a),
                                                ctypes.byref(t)) == 0
    assert live
    frame = _abi.Frame()
    lib.ct_frame_default(ctypes.byref(frame), ctypes.sizeof(frame))
    dets = (_abi.Detection * 2)((10, 10, 20, 50, 0.9, 0), (100, 10, 20, 50, 0.9, 0))
    for k in range(5):
        frame.timestamp_us = k * 40000
        assert lib.ct_tracker_feed(t, ctypes.byref(frame), dets, 2) == 0
    lib.ct_tracker_destroy(t)
    assert not live


def test_constants(layout):
    """The binding's formats, sources and track states are the header's."""
    got = {name: getattr(_abi, name) for name in layout["Constants"]}
    assert got == layout["Constants"]


def test_version_is_the_header_s():
    """_abi.py (and so the pip package) follows the header it mirrors."""
    import ctrack
    assert _abi.VERSION == ctrack.version()
    assert ctrack.__version__ == _abi.VERSION
