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
# The README's C example, as a user copies it, built against the install.
awk '/^```c$/ { on = 1; next } on && /^```$/ { exit } on' "$src/README.md" > "$tmp/readme.c"
cc -std=c99 -Wall -Wextra -Werror "$tmp/readme.c" $(pkg-config --cflags --libs ctrack) \
    -o "$tmp/readme"
LD_LIBRARY_PATH=$libdir "$tmp/readme" 25 < "$det" > "$tmp/readme.txt"
[ "$(wc -l < "$tmp/readme.txt")" -gt 200 ] ||
    { echo "install: README's example tracked $(wc -l < "$tmp/readme.txt") lines"; exit 1; }
# The Python package, every module of it, installed where the python3 that
# configured the build imports it from (scripts/python-site.py): imported
# from there (not from the source tree), it loads the installed library and
# tracks as the installed ct-track does; python -m ctrack.batch and
# ctrack.video work.
init=$(find "$tmp" -path '*/ctrack/__init__.py' | head -n 1)
[ -n "$init" ] || { echo "install: no Python package installed"; exit 1; }
site=$(dirname "$(dirname "$init")")
for m in "$src"/python/ctrack/*.py; do
    [ -f "$site/ctrack/$(basename "$m")" ] ||
        { echo "install: python/ctrack/$(basename "$m") not installed"; exit 1; }
done
configured=$(meson introspect "$build" --buildoptions | python3 -c \
    'import json,sys; print(next(o["value"] for o in json.load(sys.stdin) if o["name"]=="prefix"))')
want=$(python3 "$src/scripts/python-site.py" "$configured")
[ "$site" = "$tmp$want" ] || { echo "install: the package went to $site, not $tmp$want"; exit 1; }
python3 -c 'import sys; sys.exit(0 if sys.argv[1] in sys.path else 1)' "$want" ||
    python3 -c 'import sys, sysconfig; sys.exit(0 if sys.argv[1] == sysconfig.get_path("purelib") else 1)' "$want" ||
    { echo "install: python3 does not import from $want"; exit 1; }
"$root/bin/ct-track" -q -d "$det" -r 25 > "$tmp/ct.txt"
py=$("$src/scripts/venv.sh")
cat > "$tmp/track.py" <<'END'
import sys
import numpy as np
import ctrack
import ctrack.video  # noqa: F401 (installed too)
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
(cd "$tmp" && env -u CTRACK_LIBRARY PYTHONPATH="$site" LD_LIBRARY_PATH="$libdir" \
    "$py" -m ctrack.batch --help > batch-help.txt) ||
    { echo "install: python -m ctrack.batch --help failed from the install"; exit 1; }
grep -q "OUTDIR" "$tmp/batch-help.txt" || { echo "install: ctrack.batch's help lacks OUTDIR"; exit 1; }
echo "install: header, ct-track, ctrack.pc, the Python package (every module); the shared and static builds, README's example and Python agree ($lines lines)"
