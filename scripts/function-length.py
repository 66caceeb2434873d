"""No function of the library (or of ct-track) is over 100 lines: measured
by lizard, the ecosystem's function-length analyser, over every C and C++
source under the folders given. A file of which lizard finds no function
fails too (a parse it got wrong would pass everything).
    function-length.py [--max LINES] FOLDER..."""
import argparse
import os
import sys

import lizard


def sources(folders):
    for folder in folders:
        for root, _, files in os.walk(folder):
            for f in sorted(files):
                if f.endswith((".c", ".cc")):
                    yield os.path.join(root, f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--max", type=int, default=100)
    ap.add_argument("folders", nargs="+")
    a = ap.parse_args()
    long, empty, n = [], [], 0
    for path in sources(a.folders):
        info = lizard.analyze_file(path)
        if not info.function_list:
            empty.append(path)
        for fn in info.function_list:
            n += 1
            if fn.length > a.max:
                long.append("%s:%d: %s is %d lines" % (path, fn.start_line, fn.name, fn.length))
    for line in long:
        print(line)
    for path in empty:
        print("%s: lizard found no function" % path)
    print("function_length: %d functions, %d over %d lines" % (n, len(long), a.max))
    return 1 if long or empty or n == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
