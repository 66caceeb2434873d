#!/bin/sh
# make demo: tracks the two real sequences from their video and public
# detections (and PETS09-S2L1 from the pixels alone), writes the tracks and
# a video of each run with the tracks drawn (MP4) to $BUILD/demo/, and
# scores the tracks with py-motmetrics.
#   demo.sh BUILD_DIR
set -eu
build=${1:-build}
top=$(cd "$(dirname "$0")/.." && pwd)
data=$top/tests/data/mot15
out=$build/demo
mkdir -p "$out"
py=$("$top/scripts/venv.sh")
ct=$build/tools/ct-track
encoder="-c:v mpeg4 -q:v 5"
if ffmpeg -hide_banner -encoders 2>/dev/null | grep -q libx264; then
    encoder="-c:v libx264 -preset veryfast -crf 28"
fi

# track VIDEO.mp4 CT-TRACK-ARGS...: runs ct-track (its speed as it reports
# it), then again with its overlay encoded into VIDEO.mp4 as it goes
# (through a fifo: a failure of either stops the demo).
track() {
    mp4=$1
    shift
    "$ct" --progress "$@"
    fifo=$out/.overlay.y4m
    rm -f "$fifo"
    mkfifo "$fifo"
    # shellcheck disable=SC2086 # the encoder's options are words
    ffmpeg -v error -y -f yuv4mpegpipe -i "$fifo" $encoder -pix_fmt yuv420p \
        -movflags +faststart "$mp4" &
    encoding=$!
    if ! "$ct" -q --overlay "$fifo" "$@" -o /dev/null; then
        kill "$encoding" 2> /dev/null || true
        rm -f "$fifo"
        exit 1
    fi
    wait "$encoding"
    rm -f "$fifo"
}

pets=$("$top/scripts/fetch-pets09.sh")
echo "PETS09-S2L1: $pets with the public detections"
track "$out/PETS09-S2L1.mp4" -d "$data/PETS09-S2L1/det/det.txt" -o "$out/PETS09-S2L1.txt" "$pets"
"$py" -m cteval.score "$data/PETS09-S2L1/gt/gt.txt" "$out/PETS09-S2L1.txt"

echo "PETS09-S2L1 from the pixels alone (no detections)"
track "$out/PETS09-S2L1-pixels.mp4" -r 7 -o "$out/PETS09-S2L1-pixels.txt" "$pets"
"$py" -m cteval.score "$data/PETS09-S2L1/gt/gt.txt" "$out/PETS09-S2L1-pixels.txt"

echo "TUD-Campus: video.mp4 through ffmpeg with the public detections"
tud=$out/.tud-campus.y4m
ffmpeg -v error -y -i "$data/TUD-Campus/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p "$tud"
track "$out/TUD-Campus.mp4" -d "$data/TUD-Campus/det/det.txt" -o "$out/TUD-Campus.txt" "$tud"
rm -f "$tud"
"$py" -m cteval.score "$data/TUD-Campus/gt/gt.txt" "$out/TUD-Campus.txt"
echo "tracks and videos with the tracks drawn written to $out/"
