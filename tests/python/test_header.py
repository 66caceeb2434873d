"""What include/ctrack/ctrack.h says of each ct_config field is what the
library does: its stated default is ct_config_default()'s, and its stated
range is the one ct_config_check() enforces (each bound accepted when
closed, refused when open, a value just past it refused)."""
import ctypes
import math
import os
import re

import pytest

import ctrack
from ctrack import _abi
from conftest import TOP

HEADER = os.path.join(TOP, "include", "ctrack", "ctrack.h")
STATED = re.compile(r"Default (-?[0-9.]+)(?: \([A-Z_]+\))?; range ([\[(])([^,]+), ([^\])]+)([\])])\.")


def stated():
    """{field: (default, lo, hi, lo_open, hi_open)} from ct_config's
    comments (bounds as numbers or field names)."""
    with open(HEADER) as f:
        text = f.read()
    body = text[text.index("typedef struct ct_config {"):text.index("} ct_config;")]
    out = {}
    # Each field's comment is the /* ... */ just before its declaration.
    for m in re.finditer(r"/\*((?:(?!\*/).)*)\*/\s*(?:int32_t|float|double) (\w+);", body, re.S):
        comment = " ".join(line.strip(" *") for line in m.group(1).splitlines())
        s = STATED.search(comment)
        assert s, "ct_config.%s: its comment states no 'Default X; range [lo, hi].'" % m.group(2)
        out[m.group(2)] = (float(s.group(1)), s.group(3), s.group(4), s.group(2) == "(",
                           s.group(5) == ")")
    return out


@pytest.fixture(scope="module")
def lib():
    return ctrack.load()


def defaults(lib):
    cfg = _abi.Config()
    assert lib.ct_config_default(ctypes.byref(cfg), ctypes.sizeof(cfg)) == 0
    return cfg


def accepted(lib, field, value):
    """Whether ct_config_check() takes the defaults with field = value (the
    fields bounded by this one moved inside their range first)."""
    cfg = defaults(lib)
    setattr(cfg, field, value)
    if math.isfinite(value):
        for other, (_, lo, hi, _, _) in stated().items():
            if hi == field:
                setattr(cfg, other, min(getattr(cfg, other), value))
            if lo == field:
                setattr(cfg, other, max(getattr(cfg, other), value))
    return lib.ct_config_check(ctypes.byref(cfg), None, 0) == 0


def test_every_field_states_its_default_and_range():
    fields = [f for f, _ in _abi.Config._fields_ if f != "size"]
    assert sorted(stated()) == sorted(fields)


@pytest.mark.parametrize("field", sorted(stated()))
def test_stated_default_is_the_library_s(lib, field):
    want = stated()[field][0]
    got = getattr(defaults(lib), field)
    assert got == pytest.approx(want, rel=1e-6), "%s: the header says %g" % (field, want)


def bound(lib, b):
    """A bound's value: a number, or another field's default."""
    return getattr(defaults(lib), b) if re.match(r"[a-z_]+$", b) else float(b)


@pytest.mark.parametrize("field", sorted(stated()))
def test_stated_range_is_enforced(lib, field):
    _, lo_text, hi_text, lo_open, hi_open = stated()[field]
    lo, hi = bound(lib, lo_text), bound(lib, hi_text)
    integer = dict(_abi.Config._fields_)[field] is ctypes.c_int32
    if integer:
        lo, hi = int(lo), int(hi)
        below, above = lo - 1, hi + 1
    else:
        # Just past each bound, as the field's type holds it.
        single = dict(_abi.Config._fields_)[field] is ctypes.c_float
        ulp = (lambda v: max(abs(v), 1.0) * (2 ** -20 if single else 1e-12))
        below, above = lo - ulp(lo), hi + ulp(hi)
        assert not accepted(lib, field, math.nan)
        assert not accepted(lib, field, math.inf)
    assert accepted(lib, field, lo) != lo_open, "%s = %g" % (field, lo)
    assert accepted(lib, field, hi) != hi_open, "%s = %g" % (field, hi)
    assert not accepted(lib, field, below), "%s = %r" % (field, below)
    assert not accepted(lib, field, above), "%s = %r" % (field, above)
