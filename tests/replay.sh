#!/bin/sh
# Golden replay on real data: the MOTChallenge public detections of
# PETS09-S2L1 and TUD-Campus through ct-track, detections only and with the
# frames (mean shift), scored by py-motmetrics against the ground truth. The
# thresholds sit just under the scores in docs/results.md, so a change that
# costs accuracy fails here.
#   replay.sh CT_TRACK DATA_DIR
set -eu
ct_track=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
py=$("$here/../scripts/venv.sh")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { # NAME SEQ MIN_MOTA MIN_IDF1 CT_TRACK_ARGS... (DETS in them: the public detections)
    name=$1 seq=$2 mota=$3 idf1=$4
    shift 4
    # DETS becomes -d and the sequence's detection file (the list is rebuilt
    # in place: the loop walks the original one).
    for a in "$@"; do
        shift
        if [ "$a" = DETS ]; then
            set -- "$@" -d "$data/$seq/det/det.txt"
        else
            set -- "$@" "$a"
        fi
    done
    "$ct_track" -q -o "$tmp/$seq.txt" "$@"
    printf '%s: ' "$name"
    "$py" -m cteval.score "$data/$seq/gt/gt.txt" "$tmp/$seq.txt" \
        --min-mota "$mota" --min-idf1 "$idf1" || fail=1
}
check "PETS09-S2L1, detections" PETS09-S2L1 66.5 64.5 DETS -s 768x576 -r 7
check "TUD-Campus, detections" TUD-Campus 68.5 80.0 DETS -s 640x480 -r 25

# With the frames: TUD-Campus's are in the tree, PETS09-S2L1's are fetched
# (once, cached) from Debian's opencv-doc package.
ffmpeg -v error -i "$data/TUD-Campus/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p "$tmp/tud.y4m"
check "TUD-Campus, detections + pixels" TUD-Campus 68.0 76.5 DETS "$tmp/tud.y4m"
pets=$("$here/../scripts/fetch-pets09.sh")
check "PETS09-S2L1, detections + pixels" PETS09-S2L1 68.5 74.5 DETS "$pets"
check "PETS09-S2L1, detections verified by the contour template" PETS09-S2L1 68.0 73.0 \
    DETS -p verify_detections=1 "$pets"
# From the pixels alone (docs/notes/pixels.md): no detections.
check "PETS09-S2L1, pixels only" PETS09-S2L1 64.5 75.0 -r 7 "$pets"
check "TUD-Campus, pixels only" TUD-Campus 26.5 49.5 -r 25 "$tmp/tud.y4m"
exit $fail
