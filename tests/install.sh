#!/bin/sh
# Installs into a scratch folder and builds the example against it through
# the installed ctrack.pc, once linked to the shared and once to the static
# library; both must track. The installed ct-track must run without help,
# and the installed Python package must track as it does.
#   install.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
meson install -C "$build" --destdir "$tmp" --no-rebuild --quiet > /dev/null
prefix=$(meson introspect "$build" --buildoptions | python3 -c \
    'import json,sys; print(next(o["value"] for o in json.load(sys.stdin) if o["name"]=="prefix"))')
root=$tmp$prefix
pc=$(dirname "$(find "$root" -name ctrack.pc | head -n 1)")
[ -n "$pc" ] || { echo "install: no ctrack.pc installed"; exit 1; }
# The .pc file names the real prefix: point pkg-config at the scratch copy.
export PKG_CONFIG_PATH="$pc" PKG_CONFIG_SYSROOT_DIR="$tmp"
test -f "$root/include/ctrack/ctrack.h" || { echo "install: header missing"; exit 1; }
test -x "$root/bin/ct-track" || { echo "install: ct-track missing"; exit 1; }
cc "$src/examples/track_detections.c" $(pkg-config --cflags --libs ctrack) -o "$tmp/shared"
cc "$src/examples/track_detections.c" $(pkg-config --cflags ctrack) \
    $(pkg-config --static --libs ctrack | sed 's/-lctrack/-l:libctrack.a/') -o "$tmp/static"
det=$src/tests/data/mot15/TUD-Campus/det/det.txt
libdir=$(dirname "$(find "$root" -name 'libctrack.so.*' | head -n 1)")
LD_LIBRARY_PATH=$libdir "$tmp/shared" 25 < "$det" > "$tmp/a.txt"
"$tmp/static" 25 < "$det" > "$tmp/b.txt"
cmp "$tmp/a.txt" "$tmp/b.txt"
lines=$(wc -l < "$tmp/a.txt")
[ "$lines" -gt 200 ] || { echo "install: the example tracked $lines lines"; exit 1; }
# ct-track finds the library installed beside it without help (its
# runpath), whatever the prefix.
env -u LD_LIBRARY_PATH "$root/bin/ct-track" --version > /dev/null ||
    { echo "install: the installed ct-track does not find the installed library"; exit 1; }
# The Python package, installed into the site folder of the python3 that
# configured the build: imported from there (not from the source tree), it
# loads the installed library and tracks as the installed ct-track does.
init=$(find "$root" -path '*/ctrack/__init__.py' | head -n 1)
[ -n "$init" ] || { echo "install: no Python package installed"; exit 1; }
site=$(dirname "$(dirname "$init")")
"$root/bin/ct-track" -q -d "$det" -r 25 > "$tmp/ct.txt"
py=$("$src/scripts/venv.sh")
cat > "$tmp/track.py" <<'END'
import sys
import numpy as np
import ctrack
assert ctrack.__file__.startswith(sys.argv[2]), ctrack.__file__
d = np.loadtxt(sys.argv[1], delimiter=",", ndmin=2)
with ctrack.Tracker(fps=25) as t:
    for k in range(1, int(d[:, 0].max()) + 1):
        for line in ctrack.mot_lines(k, t.feed(None, d[d[:, 0] == k][:, 2:7])):
            print(line)
END
(cd "$tmp" && env -u CTRACK_LIBRARY PYTHONPATH="$site" LD_LIBRARY_PATH="$libdir" \
    "$py" track.py "$det" "$site" > py.txt)
cmp "$tmp/ct.txt" "$tmp/py.txt" || { echo "install: the installed Python package and ct-track differ"; exit 1; }
echo "install: header, ct-track, ctrack.pc, the Python package; the shared and static builds and Python agree ($lines lines)"
