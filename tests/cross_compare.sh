#!/bin/sh
# The arm64 build gives the tracks the build machine's gives, byte for byte:
# ct-track of both builds over the public detections of the six sequences,
# and TUD-Campus and PETS09-S2L1 from their pixels alone and with their
# detections (PETS09-S2L1's frames fetched once, as make eval does), and PETS09-S2L1
# at half size and washed out from its pixels. The arm64 program runs under
# qemu-aarch64.
#   cross_compare.sh NATIVE_CT_TRACK ARM64_CT_TRACK DATA_DIR
set -eu
native=$1 arm=$2 data=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
emu="qemu-aarch64 -L /"
fail=0 n=0
same() { # NAME CT_TRACK_ARGS...
    name=$1
    shift
    "$native" -q -o "$tmp/x86_64.txt" "$@"
    # shellcheck disable=SC2086 # the emulator's command is words
    $emu "$arm" -q -o "$tmp/aarch64.txt" "$@"
    lines=$(wc -l < "$tmp/x86_64.txt")
    n=$((n + 1))
    if [ "$lines" -lt 50 ]; then
        echo "FAIL $name: only $lines lines"; fail=1
    elif cmp -s "$tmp/x86_64.txt" "$tmp/aarch64.txt"; then
        echo "same $name ($lines lines)"
    else
        echo "FAIL $name: the arm64 tracks differ"
        diff "$tmp/x86_64.txt" "$tmp/aarch64.txt" | head -5
        fail=1
    fi
}
same "PETS09-S2L1, detections" -d "$data/PETS09-S2L1/det/det.txt" -s 768x576 -r 7
same "TUD-Campus, detections" -d "$data/TUD-Campus/det/det.txt" -s 640x480 -r 25
same "ADL-Rundle-8, detections" -d "$data/ADL-Rundle-8/det/det.txt" -s 1920x1080 -r 30
same "ETH-Bahnhof, detections" -d "$data/ETH-Bahnhof/det/det.txt" -s 640x480 -r 14
same "KITTI-13, detections" -d "$data/KITTI-13/det/det.txt" -s 1242x375 -r 10
same "Venice-2, detections" -d "$data/Venice-2/det/det.txt" -s 1920x1080 -r 30
ffmpeg -v error -i "$data/TUD-Campus/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p "$tmp/tud.y4m"
same "TUD-Campus, pixels only" -r 25 "$tmp/tud.y4m"
same "TUD-Campus, detections + pixels" -d "$data/TUD-Campus/det/det.txt" "$tmp/tud.y4m"
pets=$("$(dirname "$0")/../scripts/fetch-pets09.sh")
same "PETS09-S2L1, pixels only" -r 7 "$pets"
same "PETS09-S2L1, detections + pixels" -d "$data/PETS09-S2L1/det/det.txt" "$pets"
# At half size: the pixels read at every pixel once the people's size is
# known (the working scale 1, its gathering of one chroma sample for two).
ffmpeg -v error -i "$pets" -vf scale=384:288 -f yuv4mpegpipe -pix_fmt yuv420p "$tmp/half.y4m"
same "PETS09-S2L1 at half size, pixels only" -r 7 "$tmp/half.y4m"
# Washed out: the background's floor and shadow test follow the scene's
# contrast and black level, estimates in floating point.
ffmpeg -v error -i "$pets" -vf eq=contrast=0.55:brightness=0.1 -f yuv4mpegpipe -pix_fmt yuv420p \
    "$tmp/hazy.y4m"
same "PETS09-S2L1 washed out, pixels only" -r 7 "$tmp/hazy.y4m"
[ "$fail" = 0 ] && echo "cross_compare: $n replays, the same tracks on aarch64 as on $(uname -m)"
exit $fail
