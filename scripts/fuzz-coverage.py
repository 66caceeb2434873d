#!/usr/bin/env python3
"""Line coverage of named functions of one source file, from llvm-cov
(make fuzz): the lines llvm-cov counts in each function whose mangled name
holds one of the names, covered or not.

    fuzz-coverage.py BINARY PROFDATA FILE NAME [NAME...]   (NAME "*": all)

Prints "C% of N lines"."""
import json
import re
import subprocess
import sys


def main():
    binary, profdata, source = sys.argv[1:4]
    names = sys.argv[4:]
    exported = json.loads(subprocess.run(
        ["llvm-cov", "export", binary, "-instr-profile=" + profdata, "-skip-expansions"],
        check=True, capture_output=True, text=True).stdout)
    spans = []
    for f in exported["data"][0]["functions"]:
        if not any(fn.endswith(source) for fn in f["filenames"][:1]):
            continue
        if "*" in names or any(n in f["name"] for n in names):
            r = f["regions"][0]
            spans.append((r[0], r[2]))
    shown = subprocess.run(
        ["llvm-cov", "show", binary, "-instr-profile=" + profdata, "-show-line-counts",
         "-use-color=false", "-show-instantiations=false", "-show-expansions=false"],
        check=True, capture_output=True, text=True).stdout
    # The file's part of the listing, then its lines "  NUM|  COUNT|code".
    counted = covered = 0
    inside = False
    for line in shown.splitlines():
        if line.startswith("/") and line.endswith(":"):
            inside = line[:-1].endswith(source)
            continue
        m = re.match(r"\s*(\d+)\|\s*([0-9.]+[kMG]?)?\|", line)
        if not inside or not m or m.group(2) is None:
            continue
        n = int(m.group(1))
        if any(a <= n <= b for a, b in spans):
            counted += 1
            covered += m.group(2) != "0"
    if not counted:
        sys.exit("fuzz-coverage: no function of %s named %s" % (source, " ".join(names)))
    print("%.1f%% of %d lines" % (100.0 * covered / counted, counted))


if __name__ == "__main__":
    main()
