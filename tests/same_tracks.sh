#!/bin/sh
# Two ct-track programs give the same tracks, byte for byte, over every
# input mode: the public detections of the six sequences; TUD-Campus and
# PETS09-S2L1 from their pixels alone and with their detections (with the
# contour template's check of them too), fed live and primed (a
# look-ahead); and PETS09-S2L1 in make eval's camera conditions and at a
# half and a third of its frame rate. A change that should not change what
# the tracker does (a move of files, a refactoring) is checked with it
# against a build of the commit before; make cross-arm64 checks the arm64
# build against the native one with a shorter list (--quick).
#   same_tracks.sh [--quick] REFERENCE_CT_TRACK OTHER_CT_TRACK DATA_DIR
# OTHER_CT_TRACK may be a command of several words (an emulator and the
# program: "qemu-aarch64 -L / build-arm64/tools/ct-track").
set -eu
quick=
if [ "${1:-}" = --quick ]; then
    quick=yes
    shift
fi
ref=$1 other=$2 data=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0 n=0
same() { # NAME CT_TRACK_ARGS...
    name=$1
    shift
    "$ref" -q -o "$tmp/reference.txt" "$@"
    # shellcheck disable=SC2086 # the other program's command is words
    $other -q -o "$tmp/other.txt" "$@"
    lines=$(wc -l < "$tmp/reference.txt")
    n=$((n + 1))
    if [ "$lines" -lt 50 ]; then
        echo "FAIL $name: only $lines lines"; fail=1
    elif cmp -s "$tmp/reference.txt" "$tmp/other.txt"; then
        echo "same $name ($lines lines)"
    else
        echo "FAIL $name: the tracks differ"
        diff "$tmp/reference.txt" "$tmp/other.txt" | head -5
        fail=1
    fi
}
filtered() { # VIDEO FILTER OUT: the video through an ffmpeg filter, as Y4M
    ffmpeg -v error -y -i "$1" -vf "$2" -f yuv4mpegpipe -pix_fmt yuv420p "$3"
}
for s in PETS09-S2L1:768x576:7 TUD-Campus:640x480:25 ADL-Rundle-8:1920x1080:30 \
         ETH-Bahnhof:640x480:14 KITTI-13:1242x375:10 Venice-2:1920x1080:30; do
    seq=${s%%:*} rest=${s#*:}
    same "$seq, detections" -d "$data/$seq/det/det.txt" -s "${rest%:*}" -r "${rest#*:}"
done
ffmpeg -v error -i "$data/TUD-Campus/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p "$tmp/tud.y4m"
pets=$("$(dirname "$0")/../scripts/fetch-pets09.sh")
tud_det=$data/TUD-Campus/det/det.txt pets_det=$data/PETS09-S2L1/det/det.txt
for prime in 0 3; do
    same "TUD-Campus, pixels only, --prime $prime" --prime $prime -r 25 "$tmp/tud.y4m"
    same "TUD-Campus, detections + pixels, --prime $prime" --prime $prime -d "$tud_det" \
        "$tmp/tud.y4m"
    same "PETS09-S2L1, pixels only, --prime $prime" --prime $prime -r 7 "$pets"
    same "PETS09-S2L1, detections + pixels, --prime $prime" --prime $prime -d "$pets_det" "$pets"
done
# At half size: the pixels read at every pixel once the people's size is
# known (the working scale 1, its gathering of one chroma sample for two).
filtered "$pets" scale=384:288 "$tmp/half.y4m"
same "PETS09-S2L1 at half size, pixels only" --prime 0 -r 7 "$tmp/half.y4m"
# Washed out: the background's floor and shadow test follow the scene's
# contrast and black level, estimates in floating point.
filtered "$pets" eq=contrast=0.55:brightness=0.1 "$tmp/hazy.y4m"
same "PETS09-S2L1 washed out, pixels only" --prime 0 -r 7 "$tmp/hazy.y4m"
if [ -z "$quick" ]; then
    same "TUD-Campus, detections verified by the contour template" --prime 0 \
        -p verify_detections=1 -d "$tud_det" "$tmp/tud.y4m"
    same "PETS09-S2L1, detections verified by the contour template, primed" --prime 3 \
        -p verify_detections=1 -d "$pets_det" "$pets"
    same "PETS09-S2L1, pixels only, size and aspect alone" --prime 0 -p pedestrian_test=1 \
        -r 7 "$pets"
    same "PETS09-S2L1 at half size, pixels only, primed" --prime 3 -r 7 "$tmp/half.y4m"
    for c in "noise:noise=alls=14:allf=t" "darker:eq=brightness=-0.12:contrast=0.55" \
             "mirrored:hflip" \
             "exposure steps:eq=brightness=0.08:contrast=1.2:enable='between(n,30,59)+between(n,300,399)'"; do
        filtered "$pets" "${c#*:}" "$tmp/cond.y4m"
        same "PETS09-S2L1 ${c%%:*}, pixels only" --prime 0 -r 7 "$tmp/cond.y4m"
        same "PETS09-S2L1 ${c%%:*}, detections + pixels" --prime 0 -d "$pets_det" "$tmp/cond.y4m"
        filtered "$tmp/tud.y4m" "${c#*:}" "$tmp/cond.y4m"
        same "TUD-Campus ${c%%:*}, pixels only" --prime 0 -r 25 "$tmp/cond.y4m"
    done
    # A camera that keeps every second or third frame.
    for k in 2 3; do
        filtered "$pets" "framestep=$k" "$tmp/rate.y4m"
        rate=$(awk "BEGIN { print 7 / $k }")
        same "PETS09-S2L1 at 1/$k of its rate, pixels only" --prime 0 -r "$rate" "$tmp/rate.y4m"
    done
fi
[ "$fail" = 0 ] && echo "same_tracks: $n replays, the same tracks from both programs"
exit $fail
