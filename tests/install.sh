#!/bin/sh
# Installs into a scratch folder and builds the example against it through
# the installed ctrack.pc, once linked to the shared and once to the static
# library; both must track.
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
echo "install: header, ct-track, ctrack.pc; shared and static builds agree ($lines lines)"
