#!/bin/sh
# examples/track_frames.c, the host without a detector, on TUD-Campus's raw
# I420 frames: it writes what ct-track writes from the pixels alone, fed
# live (--prime 0: the example tracks a stream as it comes), byte for byte,
# and refuses bad arguments and a frame cut short.
#   example_frames.sh TRACK_FRAMES CT_TRACK TUD_Y4M
set -eu
y4m=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/lib/wrap.sh"
ex=$(wrap "$1" "$tmp") ct=$(wrap "$2" "$tmp")
ffmpeg -v error -i "$y4m" -f rawvideo -pix_fmt yuv420p "$tmp/tud.i420"
"$ex" 640 480 25 < "$tmp/tud.i420" > "$tmp/example.txt"
"$ct" -q -r 25 --prime 0 "$y4m" > "$tmp/ct.txt"
lines=$(wc -l < "$tmp/ct.txt")
[ "$lines" -gt 50 ] || { echo "example_frames: ct-track tracked only $lines lines"; exit 1; }
cmp "$tmp/ct.txt" "$tmp/example.txt" ||
    { echo "example_frames: track_frames and ct-track differ"; exit 1; }

# Bad arguments: usage, status 2.
for args in "" "640 480" "0 480 25" "640 480 0" "640 480 nan"; do
    # shellcheck disable=SC2086 # the arguments are words
    if "$ex" $args < /dev/null 2> "$tmp/err"; then
        echo "example_frames: '$args' accepted"; exit 1
    fi
    grep -q usage "$tmp/err" || { echo "example_frames: '$args': no usage"; exit 1; }
done
# Ten frames and a half: the ten are tracked, the half is reported, status 1.
head -c $((640 * 480 * 3 / 2 * 21 / 2)) "$tmp/tud.i420" > "$tmp/cut.i420"
if "$ex" 640 480 25 < "$tmp/cut.i420" > "$tmp/cut.txt" 2> "$tmp/err"; then
    echo "example_frames: a frame cut short was not reported"; exit 1
fi
grep -q "cut short" "$tmp/err" || { echo "example_frames: no message for the cut frame"; exit 1; }
awk -F, '$1 > 10 { bad = 1 } END { exit bad }' "$tmp/cut.txt" ||
    { echo "example_frames: tracks past frame 10"; exit 1; }
echo "example_frames: $lines lines as ct-track writes them; bad arguments and a cut frame refused"
