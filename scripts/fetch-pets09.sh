#!/bin/sh
# Fetches the PETS09-S2L1 frames and prints the path of a Y4M file of all 795
# frames at the sequence's true 7 fps, cached in $CT_CACHE (default
# ~/.cache/ctrack). The frames come from Debian's opencv-doc package
# (examples/data/vtest.avi); frame k of the file (0-based) is frame k+1 of
# the MOTChallenge ground truth. Needs apt-get (no root) and ffmpeg.
set -eu
cache=${CT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/ctrack}
y4m=$cache/pets09-s2l1.y4m
if [ -s "$y4m" ]; then
    echo "$y4m"
    exit 0
fi
mkdir -p "$cache"
work=$(mktemp -d "$cache/fetch.XXXXXX")
trap 'rm -rf "$work"' EXIT
avi=./usr/share/doc/opencv-doc/examples/data/vtest.avi
echo "fetch-pets09: downloading Debian's opencv-doc (about 95 MB) for vtest.avi" >&2
(cd "$work" && apt-get download opencv-doc > /dev/null 2>&1) || {
    echo "fetch-pets09: 'apt-get download opencv-doc' failed (run 'apt-get update' first?)" >&2
    exit 1
}
(cd "$work" && dpkg-deb --fsys-tarfile opencv-doc_*.deb | tar -x "$avi")
# The AVI header says 10 fps; the sequence runs at 7. Re-time every frame
# rather than let ffmpeg drop frames to fit.
ffmpeg -v error -i "$work/$avi" -vf setpts=N/7/TB -r 7 -f yuv4mpegpipe \
    -pix_fmt yuv420p "$work/pets.y4m"
# Each frame is "FRAME\n" and 768x576 4:2:0 pixels after the header line.
header=$(head -n 1 "$work/pets.y4m" | wc -c)
size=$(stat -c %s "$work/pets.y4m")
frames=$(( (size - header) / (6 + 768 * 576 * 3 / 2) ))
if [ "$frames" != 795 ]; then
    echo "fetch-pets09: decoded $frames frames, expected 795" >&2
    exit 1
fi
mv "$work/pets.y4m" "$y4m"
echo "$y4m"
