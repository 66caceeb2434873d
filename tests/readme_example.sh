#!/bin/sh
# README.md's C example, as a user copies it: the first ```c block of
# README.md, built as a whole program against the build tree (meson's
# uninstalled pkg-config file, as README says) and run over TUD-Campus's
# detections. Its tracks must be ct-track's (the same boxes, to the
# hundredth). tests/install.sh builds the same block against an install.
#   readme_example.sh BUILD_DIR SOURCE_DIR CT_TRACK
set -eu
build=$1 src=$2 ct=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
awk '/^```c$/ { on = 1; next } on && /^```$/ { exit } on' "$src/README.md" > "$tmp/track.c"
[ -s "$tmp/track.c" ] || { echo "readme_example: no \`\`\`c block in README.md"; exit 1; }
grep -q 'int main' "$tmp/track.c" || { echo "readme_example: the block has no main()"; exit 1; }
export PKG_CONFIG_PATH="$build/meson-uninstalled"
# shellcheck disable=SC2046 # pkg-config's flags are words
cc -std=c99 -Wall -Wextra -Werror "$tmp/track.c" $(pkg-config --cflags --libs ctrack) \
    -o "$tmp/track"
det=$src/tests/data/mot15/TUD-Campus/det/det.txt
LD_LIBRARY_PATH="$build/lib" "$tmp/track" 25 < "$det" > "$tmp/readme.txt"
"$ct" -q -d "$det" -r 25 | cut -d, -f1-6 > "$tmp/ct.txt" # no image size, as the program
lines=$(wc -l < "$tmp/readme.txt")
[ "$lines" -gt 200 ] || { echo "readme_example: $lines lines of tracks"; exit 1; }
cmp "$tmp/readme.txt" "$tmp/ct.txt" ||
    { echo "readme_example: README's program and ct-track differ"; exit 1; }
echo "readme_example: README's C example builds (-Wall -Wextra -Werror) and tracks as ct-track ($lines lines)"
