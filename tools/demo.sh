#!/bin/sh
# make demo: tracks the two real sequences from their video and public
# detections (and PETS09-S2L1 from the pixels alone), writes the tracks to
# $BUILD/demo/, and scores them with py-motmetrics.
#   demo.sh BUILD_DIR
set -eu
build=${1:-build}
top=$(cd "$(dirname "$0")/.." && pwd)
data=$top/tests/data/mot15
out=$build/demo
mkdir -p "$out"
py=$("$top/tools/venv.sh")
ct=$build/tools/ct-track

pets=$("$top/tools/fetch-pets09.sh")
echo "PETS09-S2L1: $pets with the public detections"
"$ct" --progress -d "$data/PETS09-S2L1/det/det.txt" -o "$out/PETS09-S2L1.txt" "$pets"
"$py" "$top/tools/mot_score.py" "$data/PETS09-S2L1/gt/gt.txt" "$out/PETS09-S2L1.txt"

echo "PETS09-S2L1 from the pixels alone (no detections)"
"$ct" --progress -r 7 -o "$out/PETS09-S2L1-pixels.txt" "$pets"
"$py" "$top/tools/mot_score.py" "$data/PETS09-S2L1/gt/gt.txt" "$out/PETS09-S2L1-pixels.txt"

echo "TUD-Campus: video.mp4 through ffmpeg with the public detections"
ffmpeg -v error -i "$data/TUD-Campus/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p - \
    | "$ct" --progress -d "$data/TUD-Campus/det/det.txt" -o "$out/TUD-Campus.txt" -
"$py" "$top/tools/mot_score.py" "$data/TUD-Campus/gt/gt.txt" "$out/TUD-Campus.txt"
echo "tracks written to $out/"
