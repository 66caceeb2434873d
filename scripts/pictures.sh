#!/bin/sh
# Draws ctrack's tracks on a few PETS09-S2L1 frames for docs/ and the README:
# docs/img/pets09-NNN.jpg (frame numbers 1-based, as in the ground truth) and
# a short GIF with the public detections, and docs/img/pets09-pixels-121.jpg
# and pets09-candidates-121.jpg from the pixels alone; the defaults.
#   pictures.sh BUILD_DIR
set -eu
build=${1:-build}
top=$(cd "$(dirname "$0")/.." && pwd)
pets=$("$top/scripts/fetch-pets09.sh")
out=$top/docs/img
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/tools/ct-track" -q -d "$top/tests/data/mot15/PETS09-S2L1/det/det.txt" \
    -o /dev/null --overlay "$tmp/overlay.y4m" "$pets"
for n in 121 301 651; do
    ffmpeg -v error -y -i "$tmp/overlay.y4m" -vf "select=eq(n\,$((n - 1)))" -frames:v 1 \
        -q:v 4 "$out/pets09-$n.jpg"
done
# From the pixels alone (no detections): one frame, and a part of it twice as
# large with the blobs and their votes (--overlay-candidates).
"$build/tools/ct-track" -q -r 7 -o /dev/null --overlay "$tmp/pixels.y4m" "$pets"
ffmpeg -v error -y -i "$tmp/pixels.y4m" -vf "select=eq(n\,120)" -frames:v 1 -q:v 4 \
    "$out/pets09-pixels-121.jpg"
"$build/tools/ct-track" -q -r 7 -o /dev/null --overlay "$tmp/candidates.y4m" \
    --overlay-candidates "$pets"
ffmpeg -v error -y -i "$tmp/candidates.y4m" \
    -vf "select=eq(n\,120),crop=440:240:328:96,scale=880:-1:flags=neighbor" -frames:v 1 \
    -q:v 3 "$out/pets09-candidates-121.jpg"
# Frames 100-135 at the true 7 fps, 320 pixels wide.
ffmpeg -v error -y -i "$tmp/overlay.y4m" \
    -vf "select=between(n\,99\,134),setpts=N/7/TB,scale=320:-1:flags=lanczos,split[a][b];[a]palettegen=max_colors=32:stats_mode=diff[p];[b][p]paletteuse=dither=none:diff_mode=rectangle" \
    -r 7 "$out/pets09.gif"
ls -la "$out"
