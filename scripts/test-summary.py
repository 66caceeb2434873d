#!/usr/bin/env python3
"""Prints the closing line of `make check` from meson's test log:
'check: N passed, N failed' (and the names of the failures)."""
import json
import sys

passed, failed = 0, []
with open(sys.argv[1]) as f:
    for line in f:
        t = json.loads(line)
        if t["result"] in ("OK", "EXPECTEDFAIL"):
            passed += 1
        else:
            failed.append("%s (%s)" % (t["name"], t["result"]))
for name in failed:
    print("failed: " + name)
print("check: %d passed, %d failed" % (passed, len(failed)))
