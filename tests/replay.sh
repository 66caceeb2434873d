#!/bin/sh
# Golden replay on real data: the MOTChallenge public detections of
# PETS09-S2L1 and TUD-Campus through ct-track, scored by py-motmetrics against
# the ground truth. The thresholds sit just under the scores in
# docs/tuning.md, so a change that costs accuracy fails here.
#   replay.sh CT_TRACK DATA_DIR
set -eu
ct_track=$1
data=$2
here=$(cd "$(dirname "$0")" && pwd)
py=$("$here/../tools/venv.sh")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { # SEQ SIZE FPS MIN_MOTA MIN_IDF1
    "$ct_track" -q -d "$data/$1/det/det.txt" -s "$2" -r "$3" -o "$tmp/$1.txt"
    printf '%s: ' "$1"
    "$py" "$here/../tools/mot_score.py" "$data/$1/gt/gt.txt" "$tmp/$1.txt" \
        --min-mota "$4" --min-idf1 "$5" || fail=1
}
check PETS09-S2L1 768x576 7 66.5 64.5
check TUD-Campus 640x480 25 68.5 80.0
exit $fail
