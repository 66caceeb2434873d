#!/bin/bash
# ct-track's command-line behaviour: inputs, outputs and every bad input's
# message and exit status. Uses the real TUD-Campus video and detections.
#   test_cli.sh CT_TRACK DATA_DIR
set -u
data=$2
tud=$data/TUD-Campus
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
. "$(dirname "$0")/../lib/wrap.sh"
ct=$(wrap "$1" "$tmp")
passed=0 failed=0

ok() { passed=$((passed + 1)); echo "ok   $1"; }
bad() { failed=$((failed + 1)); echo "FAIL $1: $2"; }

# expect NAME STATUS STDERR_SUBSTRING -- COMMAND...
expect() {
    local name=$1 want=$2 needle=$3
    shift 4
    "$@" > "$tmp/out" 2> "$tmp/err"
    local got=$?
    if [ "$got" != "$want" ]; then
        bad "$name" "exit $got, want $want; stderr: $(head -c 300 "$tmp/err")"
    elif [ -n "$needle" ] && ! grep -qF -- "$needle" "$tmp/err"; then
        bad "$name" "stderr lacks '$needle': $(head -c 300 "$tmp/err")"
    else
        ok "$name"
    fi
}

same() { # NAME FILE_A FILE_B
    if cmp -s "$2" "$3"; then ok "$1"; else bad "$1" "$2 and $3 differ"; fi
}

# --- inputs that work ------------------------------------------------------
expect "help" 0 "" -- "$ct" --help
grep -q "lost_lifetime" "$tmp/out" && ok "help lists parameters" || bad "help lists parameters" "no lost_lifetime"
expect "version" 0 "" -- "$ct" --version
grep -q "^ct-track [0-9]*\.[0-9]*\.[0-9]*$" "$tmp/out" && ok "version format" || bad "version format" "$(cat "$tmp/out")"

expect "detections only" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -o "$tmp/detonly.txt"
lines=$(wc -l < "$tmp/detonly.txt")
[ "$lines" -gt 200 ] && ok "detections only writes tracks ($lines lines)" || bad "detections only writes tracks" "$lines lines"
if awk -F, 'NF != 10 || $1 < 1 || $1 > 71 || $2 < 1 || $5 <= 0 || $6 <= 0 || $8 != -1 {exit 1}' "$tmp/detonly.txt"; then
    ok "MOTChallenge format"
else
    bad "MOTChallenge format" "$(head -3 "$tmp/detonly.txt")"
fi
expect "standard output" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480
same "standard output equals -o" "$tmp/out" "$tmp/detonly.txt"

# Real frames through ffmpeg: a Y4M file, standard input, raw I420, NV12, grey.
if ! command -v ffmpeg > /dev/null; then
    bad "ffmpeg" "not installed (scripts/install-deps.sh installs it)"
else
    ffmpeg -v error -i "$tud/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p "$tmp/tud.y4m"
    ffmpeg -v error -i "$tud/video.mp4" -f rawvideo -pix_fmt yuv420p "$tmp/tud.i420"
    ffmpeg -v error -i "$tud/video.mp4" -f rawvideo -pix_fmt nv12 "$tmp/tud.nv12"
    ffmpeg -v error -i "$tud/video.mp4" -f rawvideo -pix_fmt gray "$tmp/tud.gray"
    ffmpeg -v error -i "$tud/video.mp4" -f yuv4mpegpipe -pix_fmt gray "$tmp/tud-mono.y4m"
    head -c 10 "$tmp/tud.y4m" | grep -q "YUV4MPEG2" && ok "ffmpeg wrote Y4M" || bad "ffmpeg wrote Y4M" "no header"

    # The video has 71 frames at 25 fps like the detections. Every form of
    # the same colour frames gives the same tracks; the pixels change them
    # (mean shift) from the detections-only run.
    expect "y4m file" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -o "$tmp/y4m.txt" "$tmp/tud.y4m"
    if cmp -s "$tmp/y4m.txt" "$tmp/detonly.txt"; then bad "pixels are used" "same tracks as detections only"; else ok "pixels are used"; fi
    "$ct" -q -d "$tud/det/det.txt" - < "$tmp/tud.y4m" > "$tmp/stdin.txt" 2> "$tmp/err" \
        && same "y4m on standard input" "$tmp/stdin.txt" "$tmp/y4m.txt" \
        || bad "y4m on standard input" "$(cat "$tmp/err")"
    ffmpeg -v error -i "$tud/video.mp4" -f yuv4mpegpipe -pix_fmt yuv420p - \
        | "$ct" -q -d "$tud/det/det.txt" - > "$tmp/pipe.txt" 2> "$tmp/err" \
        && same "ffmpeg pipe" "$tmp/pipe.txt" "$tmp/y4m.txt" \
        || bad "ffmpeg pipe" "$(cat "$tmp/err")"
    expect "raw i420" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -o "$tmp/i420.txt" "$tmp/tud.i420"
    same "raw i420 tracks" "$tmp/i420.txt" "$tmp/y4m.txt"
    expect "raw nv12" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -f nv12 -o "$tmp/nv12.txt" "$tmp/tud.nv12"
    same "raw nv12 tracks" "$tmp/nv12.txt" "$tmp/y4m.txt"
    expect "raw gray" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -f gray -o "$tmp/gray.txt" "$tmp/tud.gray"
    if cmp -s "$tmp/gray.txt" "$tmp/detonly.txt"; then bad "grey pixels are used" "same tracks as detections only"; else ok "grey pixels are used"; fi
    expect "y4m Cmono" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -o "$tmp/mono.txt" "$tmp/tud-mono.y4m"
    same "y4m Cmono tracks" "$tmp/mono.txt" "$tmp/gray.txt"
    expect "raw on standard input" 0 "" -- sh -c "'$ct' -q -d '$tud/det/det.txt' -s 640x480 - < '$tmp/tud.i420' > '$tmp/rawstdin.txt'"
    same "raw on standard input tracks" "$tmp/rawstdin.txt" "$tmp/y4m.txt"
    expect "--no-pixels" 0 "" -- "$ct" -q --no-pixels -d "$tud/det/det.txt" -o "$tmp/nopix.txt" "$tmp/tud.y4m"
    same "--no-pixels tracks" "$tmp/nopix.txt" "$tmp/detonly.txt"

    # The rate: the Y4M header's 25 fps equals --fps 25; --fps wins over it.
    expect "--fps equal to the header" 0 "" -- "$ct" -q -r 25 -d "$tud/det/det.txt" -o "$tmp/r25.txt" "$tmp/tud.y4m"
    same "--fps equal to the header tracks" "$tmp/r25.txt" "$tmp/y4m.txt"
    expect "--fps over the header" 0 "" -- "$ct" -q -r 5 -d "$tud/det/det.txt" -o "$tmp/r5.txt" "$tmp/tud.y4m"
    if cmp -s "$tmp/r5.txt" "$tmp/y4m.txt"; then bad "--fps changes the timing" "same tracks"; else ok "--fps changes the timing"; fi

    # Bad video inputs.
    head -c $((640 * 480 * 3 / 2 * 3 + 1000)) "$tmp/tud.i420" > "$tmp/cut.i420"
    expect "size does not divide the file" 1 "not a whole number" -- "$ct" -d "$tud/det/det.txt" -s 640x480 "$tmp/cut.i420"
    expect "wrong --size" 1 "not a whole number" -- "$ct" -d "$tud/det/det.txt" -s 640x481 "$tmp/tud.i420"
    expect "truncated last frame on standard input" 1 "truncated frame 4" -- sh -c "'$ct' -d '$tud/det/det.txt' -s 640x480 - < '$tmp/cut.i420'"
    head -c $(( $(stat -c %s "$tmp/tud.y4m") - 5000 )) "$tmp/tud.y4m" > "$tmp/cut.y4m"
    expect "truncated last y4m frame" 1 "truncated frame 71" -- "$ct" -d "$tud/det/det.txt" "$tmp/cut.y4m"
    printf 'YUV4MPEG2 W640 H480 F25:1 C420jpeg\nFRAMX\n' > "$tmp/badframe.y4m"
    expect "bad y4m frame header" 1 "bad Y4M frame header" -- "$ct" -d "$tud/det/det.txt" "$tmp/badframe.y4m"
    expect "raw without --size" 1 "--size" -- "$ct" -d "$tud/det/det.txt" "$tmp/tud.i420"
    # From the pixels alone: tracks, and the candidates with their votes.
    expect "pixels only" 0 "" -- "$ct" -q -o "$tmp/px.txt" --candidates "$tmp/cand.txt" "$tmp/tud.y4m"
    [ -s "$tmp/px.txt" ] && ok "pixels only writes tracks" || bad "pixels only writes tracks" "no tracks"
    if awk -F, '!/^#/ && (NF != 19 || $1 < 1 || $1 > 71 || $4 <= 0 || $5 <= 0 || $6 < 0 || $6 > 1 || $18 < 0 || $18 > 1 || $19 < 0 || ($19 > 0.9 && $6 > 0.5)) {exit 1}' "$tmp/cand.txt" \
        && [ "$(grep -vc '^#' "$tmp/cand.txt")" -gt 50 ]; then
        ok "candidates file"
    else
        bad "candidates file" "$(head -3 "$tmp/cand.txt")"
    fi
    # Detections verified by the contour template: one vote per detection.
    expect "verify_detections" 0 "" -- "$ct" -q -p verify_detections=1 -d "$tud/det/det.txt" \
        -o "$tmp/ver.txt" --candidates "$tmp/vercand.txt" "$tmp/tud.y4m"
    if [ "$(grep -vc '^#' "$tmp/vercand.txt")" = "$(wc -l < "$tud/det/det.txt")" ]; then
        ok "verify_detections: a vote per detection"
    else
        bad "verify_detections: a vote per detection" "$(grep -vc '^#' "$tmp/vercand.txt") votes"
    fi
    expect "verify_detections=2" 2 "config.verify_detections" -- "$ct" -q -p verify_detections=2 \
        -d "$tud/det/det.txt" "$tmp/tud.y4m"
    expect "pixels only from standard input" 0 "" -- sh -c "'$ct' -q - < '$tmp/tud.y4m' > '$tmp/px2.txt'"
    same "pixels only, file and standard input" "$tmp/px.txt" "$tmp/px2.txt"
    # Online by default: without --prime the tracks are --prime 0's. A
    # priming (a look-ahead) differs; it takes the whole clip when asked for
    # more than it holds.
    expect "--prime 0" 0 "" -- "$ct" -q --prime 0 -o "$tmp/px0.txt" "$tmp/tud.y4m"
    same "online by default: no --prime is --prime 0" "$tmp/px.txt" "$tmp/px0.txt"
    expect "--prime 3" 0 "" -- "$ct" -q --prime 3 -o "$tmp/px3.txt" "$tmp/tud.y4m"
    if cmp -s "$tmp/px3.txt" "$tmp/px.txt"; then bad "--prime 3 primes" "the online tracks"; else ok "--prime 3 primes"; fi
    expect "--prime past the end" 0 "" -- "$ct" -q --prime 100 -o "$tmp/px100.txt" "$tmp/tud.y4m"
    same "--prime past the end: the whole clip" "$tmp/px100.txt" "$tmp/px3.txt"
    expect "--prime 3 from standard input" 0 "" -- sh -c "'$ct' -q --prime 3 - < '$tmp/tud.y4m' > '$tmp/px3s.txt'"
    same "--prime 3, file and standard input" "$tmp/px3.txt" "$tmp/px3s.txt"
    expect "--prime with detections alone: nothing to prime" 0 "" -- "$ct" -q --prime 2 \
        -d "$tud/det/det.txt" -o "$tmp/y4m-prime.txt" "$tmp/tud.y4m"
    same "--prime with detections: the same tracks" "$tmp/y4m-prime.txt" "$tmp/y4m.txt"
    # An output that is an input, or another output, is refused before
    # anything is written: the input stays whole.
    cp "$tmp/tud.y4m" "$tmp/self.y4m"
    size_before=$(stat -c %s "$tmp/self.y4m")
    expect "-o INPUT INPUT refused" 1 "would overwrite it" -- "$ct" -q -o "$tmp/self.y4m" \
        "$tmp/self.y4m"
    [ "$(stat -c %s "$tmp/self.y4m")" = "$size_before" ] && ok "-o INPUT INPUT: the input whole" \
        || bad "-o INPUT INPUT: the input whole" "$(stat -c %s "$tmp/self.y4m") bytes"
    ln -sf "$tmp/self.y4m" "$tmp/link.y4m"
    expect "--overlay through a link to the input refused" 1 "--overlay" -- "$ct" -q \
        --overlay "$tmp/link.y4m" "$tmp/self.y4m"
    expect "-o into the input read from standard input refused" 1 "INPUT '-'" -- \
        sh -c "'$ct' -q -o '$tmp/self.y4m' - < '$tmp/self.y4m'"
    [ "$(stat -c %s "$tmp/self.y4m")" = "$size_before" ] && ok "the input whole after all" \
        || bad "the input whole after all" "$(stat -c %s "$tmp/self.y4m") bytes"
    cp "$tud/det/det.txt" "$tmp/det-self.txt"
    expect "-o into the detections refused" 1 "--detections" -- "$ct" -q -d "$tmp/det-self.txt" \
        -s 640x480 -o "$tmp/det-self.txt"
    same "the detections whole" "$tmp/det-self.txt" "$tud/det/det.txt"
    expect "--candidates onto -o refused" 1 "--candidates" -- "$ct" -q -o "$tmp/both.txt" \
        --candidates "$tmp/./both.txt" "$tmp/tud.y4m"
    # A frame cut short inside the primed seconds: the frames before it are
    # tracked and written, and the error comes where it does online.
    expect "truncated y4m, pixels only, primed" 1 "truncated frame 71" -- "$ct" -q --prime 3 \
        -o "$tmp/cutpx.txt" "$tmp/cut.y4m"
    [ "$(grep -c 'truncated frame 71' "$tmp/err")" = 1 ] && ok "truncated y4m, primed: said once" \
        || bad "truncated y4m, primed: said once" "$(cat "$tmp/err")"
    expect "truncated y4m, pixels only, online" 1 "truncated frame 71" -- "$ct" -q \
        -o "$tmp/cutpx0.txt" "$tmp/cut.y4m"
    if [ "$(cut -d, -f1 "$tmp/cutpx.txt" | sort -n | tail -1)" = 70 ]; then
        ok "truncated y4m, primed: frames 1-70 written"
    else
        bad "truncated y4m, primed: frames 1-70 written" "last frame $(cut -d, -f1 "$tmp/cutpx.txt" | sort -n | tail -1)"
    fi

    # Pictures: --overlay writes every frame, as I420 Y4M of the input's size and rate.
    expect "overlay" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -o /dev/null --overlay "$tmp/ov.y4m" "$tmp/tud.y4m"
    [ "$(head -n 1 "$tmp/ov.y4m")" = "YUV4MPEG2 W640 H480 F25:1 Ip A1:1 C420jpeg" ] \
        && ok "overlay header" || bad "overlay header" "$(head -n 1 "$tmp/ov.y4m")"
    [ "$(stat -c %s "$tmp/ov.y4m")" = "$(stat -c %s "$tmp/tud.y4m" | awk -v h="$(head -n 1 "$tmp/tud.y4m" | wc -c)" -v o="$(head -n 1 "$tmp/ov.y4m" | wc -c)" '{print $1 - h + o}')" ] \
        && ok "overlay has every frame" || bad "overlay has every frame" "sizes differ"
    # The candidates drawn too: from the pixels alone there are some, so the
    # frames differ; with detections only there are none to draw.
    expect "overlay with candidates" 0 "" -- "$ct" -q -o /dev/null --overlay "$tmp/ovc.y4m" \
        --overlay-candidates "$tmp/tud.y4m"
    expect "overlay without candidates" 0 "" -- "$ct" -q -o /dev/null --overlay "$tmp/ovp.y4m" \
        "$tmp/tud.y4m"
    if cmp -s "$tmp/ovc.y4m" "$tmp/ovp.y4m"; then
        bad "overlay draws the candidates" "same frames with and without"
    else
        ok "overlay draws the candidates"
    fi
    expect "overlay with candidates, detections only" 0 "" -- "$ct" -q -d "$tud/det/det.txt" \
        -o /dev/null --overlay "$tmp/ovd.y4m" --overlay-candidates "$tmp/tud.y4m"
    same "no candidates to draw with detections" "$tmp/ovd.y4m" "$tmp/ov.y4m"
    # The people's size, once learnt from the tracks, drawn on the edges.
    expect "overlay with the person size" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -o /dev/null \
        --overlay "$tmp/ovs.y4m" --overlay-size "$tmp/tud.y4m"
    if cmp -s "$tmp/ovs.y4m" "$tmp/ov.y4m"; then
        bad "overlay draws the person size" "same frames with and without"
    else
        ok "overlay draws the person size"
    fi
    # From the pixels, the working scale is drawn from the first frame on
    # (the size itself only once learnt).
    expect "overlay with the working scale" 0 "" -- "$ct" -q -o /dev/null \
        --overlay "$tmp/ovw.y4m" --overlay-size "$tmp/tud.y4m"
    expect "overlay of the pixels without it" 0 "" -- "$ct" -q -o /dev/null \
        --overlay "$tmp/ovn.y4m" "$tmp/tud.y4m"
    first=$(( $(head -1 "$tmp/ovw.y4m" | wc -c) + 6 + 640 * 480 * 3 / 2 ))
    if cmp -s <(head -c $first "$tmp/ovw.y4m") <(head -c $first "$tmp/ovn.y4m"); then
        bad "overlay draws the working scale in the first frame" "same first frame"
    else
        ok "overlay draws the working scale in the first frame"
    fi
    expect "overlay of a grey video" 0 """" -- "$ct" -q -d "$tud/det/det.txt" -o /dev/null --overlay "$tmp/ov-gray.y4m" -s 640x480 -f gray "$tmp/tud.gray"
    if cmp -s "$tmp/ov.y4m" "$tmp/tud.y4m"; then bad "overlay draws" "frames unchanged"; else ok "overlay draws"; fi
    expect "overlay from standard input to standard output" 0 "" -- sh -c "'$ct' -q -d '$tud/det/det.txt' -o '$tmp/t.txt' --overlay - - < '$tmp/tud.y4m' > '$tmp/ov2.y4m'"
    same "overlay to standard output" "$tmp/ov2.y4m" "$tmp/ov.y4m"
    expect "progress" 0 "frames/s" -- "$ct" --progress -d "$tud/det/det.txt" -o /dev/null "$tmp/tud.y4m"
    # Into a log (not a terminal): a line per update, no carriage returns.
    # The input pauses for 1.2 s after about ten frames, so that an update
    # comes before the last line.
    expect "progress in a log" 0 "frames in" -- sh -c "(dd if='$tmp/tud.y4m' bs=1M count=5; sleep 1.2; dd if='$tmp/tud.y4m' bs=1M skip=5) 2> /dev/null | '$ct' --progress -d '$tud/det/det.txt' -o /dev/null -"
    if grep -q $'\r' "$tmp/err" || [ "$(grep -c "^ct-track: " "$tmp/err")" -lt 2 ]; then
        bad "progress lines in a log" "$(od -c "$tmp/err" | head -5)"
    else
        ok "progress lines in a log"
    fi
fi

printf 'YUV4MPEG2 H480 F25:1\n' > "$tmp/nowidth.y4m"
expect "y4m without width" 1 "bad Y4M header" -- "$ct" -d "$tud/det/det.txt" "$tmp/nowidth.y4m"
printf 'YUV4MPEG2 W640 H480 F25:1 C422\nFRAME\n' > "$tmp/c422.y4m"
expect "y4m 4:2:2" 1 "unsupported Y4M colour space '422'" -- "$ct" -d "$tud/det/det.txt" "$tmp/c422.y4m"
printf 'YUV4MPEG2 W640 H480 F0:0\n' > "$tmp/rate.y4m"
expect "y4m bad rate" 1 "frame rate" -- "$ct" -d "$tud/det/det.txt" "$tmp/rate.y4m"
printf 'YUV4MPEG2 W99999 H480\n' > "$tmp/huge.y4m"
expect "y4m absurd size" 1 "absurd" -- "$ct" -d "$tud/det/det.txt" "$tmp/huge.y4m"
# Numbers are checked as the types they become: a width that wraps to 1 as
# an int, a rate past INT_MAX, a NUL byte that hides the rest of the line.
printf 'YUV4MPEG2 W4294967297 H2 F25:1\nFRAME\nabcdef' > "$tmp/wrap.y4m"
expect "y4m width past 32 bits" 1 "absurd" -- "$ct" -d "$tud/det/det.txt" "$tmp/wrap.y4m"
printf 'YUV4MPEG2 W2 H2 F99999999999:1\nFRAME\nabcdef' > "$tmp/fast.y4m"
expect "y4m rate past INT_MAX" 1 "frame rate" -- "$ct" -d "$tud/det/det.txt" "$tmp/fast.y4m"
printf 'YUV4MPEG2 W2 H2 F1:999999999\nFRAME\nabcdef' > "$tmp/slow.y4m"
expect "y4m rate too slow" 1 "frame rate" -- "$ct" -d "$tud/det/det.txt" "$tmp/slow.y4m"
printf 'YUV4MPEG2 W2 H2 F25:1\0 W9\nFRAME\nabcdef' > "$tmp/nul.y4m"
expect "y4m header with a NUL byte" 1 "NUL" -- "$ct" -d "$tud/det/det.txt" "$tmp/nul.y4m"
printf 'YUV4MPEG2 W2 H2 F25:1\nFRAME\0junk\nabcdef' > "$tmp/nulframe.y4m"
expect "y4m frame line with a NUL byte" 1 "bad Y4M frame header" -- "$ct" -d "$tud/det/det.txt" "$tmp/nulframe.y4m"
printf 'YUV4MPEG2 W640 H480 Q7\n' > "$tmp/field.y4m"
expect "y4m unknown field" 1 "unknown field" -- "$ct" -d "$tud/det/det.txt" "$tmp/field.y4m"
printf 'YUV4MPEG2 W2 H2 F25:1 Ip A1:1 C420mpeg2 XYSCSS=420MPEG2 XCOLORRANGE=FULL\nFRAME\nabcdef' > "$tmp/tiny.y4m"
expect "y4m X fields and C420mpeg2" 0 "" -- "$ct" -d "$tud/det/det.txt" -o "$tmp/tiny.txt" "$tmp/tiny.y4m"
expect "missing input" 1 "cannot open" -- "$ct" -d "$tud/det/det.txt" "$tmp/nothing.y4m"
expect "directory input" 1 "directory" -- "$ct" -d "$tud/det/det.txt" "$tmp"
expect "empty input" 1 "--size" -- "$ct" -d "$tud/det/det.txt" /dev/null

# --- detections ------------------------------------------------------------
expect "missing detections" 1 "cannot open detections" -- "$ct" -d "$tmp/none.txt" -s 640x480
printf '1,-1,10,10,20,40,0.9,-1,-1,-1\n2,-1,10,10,20\n' > "$tmp/short.txt"
expect "short detection line" 1 "short.txt:2: malformed" -- "$ct" -d "$tmp/short.txt" -s 640x480
printf '1,-1,10,10,20,40,0.9\n1,-1,abc,10,20,40,0.9\n' > "$tmp/word.txt"
expect "non-numeric field" 1 "word.txt:2: malformed" -- "$ct" -d "$tmp/word.txt" -s 640x480
printf '0,-1,10,10,20,40,0.9\n' > "$tmp/zero.txt"
expect "frame 0" 1 "zero.txt:1: frame 0" -- "$ct" -d "$tmp/zero.txt" -s 640x480
printf '1.5,-1,10,10,20,40,0.9\n' > "$tmp/half.txt"
expect "fractional frame" 1 "half.txt:1: frame 1.5" -- "$ct" -d "$tmp/half.txt" -s 640x480
printf '1,-1,10,10,nan,40,0.9\n' > "$tmp/nan.txt"
expect "NaN box" 1 "nan.txt:1: field 5" -- "$ct" -d "$tmp/nan.txt" -s 640x480
printf '1,-1,10,10,-20,40,0.9\n' > "$tmp/neg.txt"
expect "negative width" 1 "neg.txt:1: box size" -- "$ct" -d "$tmp/neg.txt" -s 640x480
printf '1,-1,10,10,20,40,inf\n' > "$tmp/inf.txt"
expect "infinite score" 1 "inf.txt:1: field 7" -- "$ct" -d "$tmp/inf.txt" -s 640x480
printf '1,-1,10,10,1e-50,40,0.9\n' > "$tmp/tinybox.txt"
expect "box size zero as a float" 1 "tinybox.txt:1: box size" -- "$ct" -d "$tmp/tinybox.txt" -s 640x480
printf '1,-1,10,10,20,40,1e300\n' > "$tmp/bigscore.txt"
expect "score past a float" 1 "bigscore.txt:1: field 7" -- "$ct" -d "$tmp/bigscore.txt" -s 640x480
printf '1,-1,10,10,20,40,0.9\0,junk\n' > "$tmp/nuldet.txt"
expect "detection line with a NUL byte" 1 "nuldet.txt:1: a NUL byte" -- "$ct" -d "$tmp/nuldet.txt" -s 640x480
printf '\0,garbage\n' > "$tmp/nulfirst.txt"
expect "detection line starting with a NUL byte" 1 "nulfirst.txt:1: a NUL byte" -- "$ct" -d "$tmp/nulfirst.txt" -s 640x480
# A frame number past the limit is refused at once (detections only, it
# would make ct-track feed that many empty frames first).
printf '99999999,-1,10,10,20,40,0.9\n' > "$tmp/far.txt"
expect "frame past the limit" 1 "far.txt:1: frame 99999999" -- timeout 10 "$ct" -d "$tmp/far.txt" -s 640x480
printf '5000,-1,10,10,20,40,0.9\n' > "$tmp/past.txt"
expect "detections far past the video" 1 "far past" -- "$ct" -d "$tmp/past.txt" "$tmp/tiny.y4m"
printf '# a comment\n\n3,-1,10,10,20,40,0.9\n1,-1,10,10,20,40,0.9\n2,-1,11,10,20,40,0.9\n' > "$tmp/unordered.txt"
expect "unordered lines and comments" 0 "" -- "$ct" -q -d "$tmp/unordered.txt"
[ "$(cut -d, -f1 "$tmp/out" | tr '\n' ' ')" = "1 2 3 " ] && ok "unordered lines sorted by frame" || bad "unordered lines sorted by frame" "$(cat "$tmp/out")"
: > "$tmp/empty.txt"
expect "empty detections" 0 "" -- "$ct" -q -d "$tmp/empty.txt" -s 640x480
[ ! -s "$tmp/out" ] && ok "empty detections give no tracks" || bad "empty detections give no tracks" "output not empty"

# --- options ---------------------------------------------------------------
expect "no arguments" 2 "usage" -- "$ct"
expect "no pixels and no detections" 2 "--no-pixels needs --detections" -- "$ct" --no-pixels "$tmp/tiny.y4m"
expect "an mp4 is answered with the ffmpeg command" 1 "ffmpeg -i '$tud/video.mp4' -f yuv4mpegpipe -pix_fmt yuv420p - | ct-track" -- "$ct" "$tud/video.mp4"
expect "an mp4 on standard input too" 1 "standard input holds an MP4" -- sh -c "'$ct' - < '$tud/video.mp4'"
expect "an mp4 with --size too" 1 "holds an MP4" -- "$ct" -s 640x480 "$tud/video.mp4"
ffmpeg -v error -i "$tud/video.mp4" -frames:v 2 "$tmp/clip.avi" "$tmp/clip.mkv"
expect "an avi" 1 "holds an AVI file" -- "$ct" "$tmp/clip.avi"
expect "a matroska file" 1 "holds a Matroska" -- "$ct" "$tmp/clip.mkv"
cp "$tmp/tud.i420" "$tmp/raw.ts"
expect "a .ts without --size: an encoded video" 1 "ffmpeg -i" -- "$ct" "$tmp/raw.ts"
expect "a .ts with --size: raw" 0 "" -- "$ct" -q -s 640x480 -o /dev/null "$tmp/raw.ts"
expect "two inputs" 2 "one INPUT" -- "$ct" -d "$tud/det/det.txt" a b
expect "size 0x0" 2 "--size" -- "$ct" -d "$tud/det/det.txt" -s 0x0
expect "absurd size" 2 "--size" -- "$ct" -d "$tud/det/det.txt" -s 100000x10
expect "size garbage" 2 "--size" -- "$ct" -d "$tud/det/det.txt" -s 640
expect "bad format" 2 "--format" -- "$ct" -d "$tud/det/det.txt" -f yuyv
expect "bad fps" 2 "--fps" -- "$ct" -d "$tud/det/det.txt" -r 0
expect "nan fps" 2 "--fps" -- "$ct" -d "$tud/det/det.txt" -r nan
expect "fps too slow" 2 "--fps" -- "$ct" -d "$tud/det/det.txt" -r 0.0001
for v in -1 nan x 3601 ""; do
    expect "bad --prime '$v'" 2 "--prime" -- "$ct" --prime "$v" "$tmp/tiny.y4m"
done
expect "unknown parameter" 2 "unknown parameter 'bogus'" -- "$ct" -d "$tud/det/det.txt" -p bogus=1
expect "parameter without value" 2 "NAME=VALUE" -- "$ct" -d "$tud/det/det.txt" -p min_hits
expect "parameter not a number" 2 "not a whole number" -- "$ct" -d "$tud/det/det.txt" -p min_hits=2.5
expect "parameter past 32 bits" 2 "max_tracks: '4294967301' is past the field's 32 bits" -- "$ct" -d "$tud/det/det.txt" -p max_tracks=4294967301
expect "parameter past a float" 2 "high_score: '1e300' is past the field's float" -- "$ct" -d "$tud/det/det.txt" -p high_score=1e300
expect "parameter out of range" 2 "config.lost_lifetime" -- "$ct" -d "$tud/det/det.txt" -p lost_lifetime=-3
expect "parameter NaN" 2 "high_score: 'nan' is not a number" -- "$ct" -d "$tud/det/det.txt" -p high_score=nan
expect "parameter set" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -p min_hits=1 -p report_lost_time=0
if cmp -s "$tmp/out" "$tmp/detonly.txt"; then bad "parameters change the result" "same tracks"; else ok "parameters change the result"; fi
expect "overlay and tracks both on standard output" 2 "--overlay -" -- "$ct" -d "$tud/det/det.txt" --overlay -
expect "candidates drawn on no overlay" 2 "--overlay FILE" -- "$ct" -d "$tud/det/det.txt" -s 640x480 --overlay-candidates
expect "person size drawn on no overlay" 2 "--overlay-size draws" -- "$ct" -d "$tud/det/det.txt" -s 640x480 --overlay-size
expect "overlay without a size" 1 "--size" -- "$ct" -d "$tud/det/det.txt" --overlay "$tmp/x.y4m"
expect "overlay of detections only" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 --overlay "$tmp/grey.y4m"
[ "$(head -n 1 "$tmp/grey.y4m")" = "YUV4MPEG2 W640 H480 F25:1 Ip A1:1 C420jpeg" ] && ok "overlay of detections only header" || bad "overlay of detections only header" "$(head -n 1 "$tmp/grey.y4m")"
expect "unwritable overlay" 1 "cannot write overlay" -- "$ct" -d "$tud/det/det.txt" -s 640x480 --overlay "$tmp/no/such/o.y4m"
expect "unwritable output" 1 "cannot write" -- "$ct" -d "$tud/det/det.txt" -o "$tmp/no/such/dir/out.txt"
if [ -w /dev/full ]; then
    expect "full disk" 1 "error writing" -- "$ct" -q -d "$tud/det/det.txt" -o /dev/full
fi
expect "detections beyond the video" 0 "detections go to frame 71" -- "$ct" -q -d "$tud/det/det.txt" "$tmp/tiny.y4m"

# --- counting ----------------------------------------------------------------
# Lines and a zone on PETS09-S2L1's detections: the events are JSON lines,
# and their crossings, entries and exits add up to the counts printed.
pets=$data/PETS09-S2L1/det/det.txt
expect "pets without counting" 0 "" -- "$ct" -q -d "$pets" -s 768x576 -r 7 -o "$tmp/pets.txt"
expect "counting" 0 "ct-track: line mid:" -- "$ct" -q -d "$pets" -s 768x576 -r 7 \
    -o "$tmp/counted.txt" --line 400,0,400,576,mid --line 0,400,768,400 \
    --zone 100,300,400,300,400,500,100,500,square --events "$tmp/events.jsonl"
if python3 - "$tmp/events.jsonl" "$tmp/err" <<'PY'
import json, re, sys
counts = {}
for line in open(sys.argv[1]):
    e = json.loads(line)
    assert set(e) >= {"frame", "time", "track", "kind", "direction"}, e
    name = e.get("line", e.get("zone"))
    key = {"cross": e["direction"], "enter": "entered", "exit": "exited"}[e["kind"]]
    counts[(name, key)] = counts.get((name, key), 0) + 1
printed = {}
for m in re.finditer(r"line (\S+): (\d+) in, (\d+) out", open(sys.argv[2]).read()):
    printed[(m[1], "in")], printed[(m[1], "out")] = int(m[2]), int(m[3])
for m in re.finditer(r"zone (\S+): (\d+) entered, (\d+) exited", open(sys.argv[2]).read()):
    printed[(m[1], "entered")], printed[(m[1], "exited")] = int(m[2]), int(m[3])
assert len(printed) == 6, printed
assert {k: v for k, v in printed.items() if v} == counts, (printed, counts)
assert sum(counts.values()) >= 20, counts
PY
then ok "counting: events add up to the counts printed"; else bad "counting: events add up to the counts printed" "see above"; fi
cmp -s "$tmp/counted.txt" "$tmp/pets.txt" && ok "counting leaves the tracks as they were" || bad "counting leaves the tracks as they were" "differ"
expect "counting on the overlay" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -o /dev/null \
    --line 320,0,320,480 --zone 100,100,540,100,540,470 --overlay "$tmp/counted.y4m"
expect "events to standard output" 0 "" -- "$ct" -q -d "$tud/det/det.txt" -s 640x480 -o /dev/null \
    --line 320,0,320,480 --events -
grep -q '"kind": "cross"' "$tmp/out" && ok "events to standard output written" || bad "events to standard output written" "$(head -c 200 "$tmp/out")"
expect "events and tracks both on standard output" 2 "--events -" -- "$ct" -d "$tud/det/det.txt" --line 0,0,9,9 --events -
expect "events without lines or zones" 2 "--events writes" -- "$ct" -d "$tud/det/det.txt" --events "$tmp/e.jsonl"
expect "events over the detections" 1 "would overwrite" -- "$ct" -d "$tud/det/det.txt" --line 0,0,9,9 --events "$tud/det/det.txt"
expect "line with 3 numbers" 2 "4 numbers, got 3" -- "$ct" -d "$tud/det/det.txt" --line 1,2,3
expect "line with a word inside" 2 "'x' is not a number" -- "$ct" -d "$tud/det/det.txt" --line 1,x,3,4
expect "line with 5 numbers" 2 "more than 4 numbers" -- "$ct" -d "$tud/det/det.txt" --line 1,2,3,4,5
expect "line with nan" 2 "not a finite number" -- "$ct" -d "$tud/det/det.txt" --line 1,nan,3,4
expect "line of one point" 2 "under a pixel" -- "$ct" -d "$tud/det/det.txt" --line 5,5,5,5
expect "line name too long" 2 "at most 31" -- "$ct" -d "$tud/det/det.txt" --line 0,0,9,9,abcdefghijklmnopqrstuvwxyzabcdefgh
expect "line name twice" 2 "already line 0" -- "$ct" -d "$tud/det/det.txt" --line 0,0,9,9,a --line 0,0,19,9,a
expect "zone of two corners" 2 "3 to 64 corners" -- "$ct" -d "$tud/det/det.txt" --zone 0,0,9,9
expect "zone odd numbers" 2 "got 7 numbers" -- "$ct" -d "$tud/det/det.txt" --zone 0,0,9,9,9,0,4
expect "zone crossing itself" 2 "cross or touch" -- "$ct" -d "$tud/det/det.txt" --zone 0,0,100,100,100,0,0,100
expect "zone without area" 2 "not a simple polygon" -- "$ct" -d "$tud/det/det.txt" --zone 0,0,50,50,100,100
expect "zone past 1e6" 2 "not a point of an image" -- "$ct" -d "$tud/det/det.txt" --zone 0,0,9e9,0,0,9
for v in -0.1 nan 3 x; do
    expect "bad --hysteresis '$v'" 2 "--hysteresis" -- "$ct" -d "$tud/det/det.txt" --line 0,0,9,9 --hysteresis "$v"
done
expect "a wider hysteresis counts no more" 0 "ct-track: line mid:" -- "$ct" -q -d "$pets" -s 768x576 -r 7 \
    -o /dev/null --line 400,0,400,576,mid --hysteresis 0.5
# A refused line opens nothing: the output is not created.
expect "bad line writes nothing" 2 "under a pixel" -- "$ct" -d "$tud/det/det.txt" -s 640x480 -o "$tmp/never.txt" --line 5,5,5,5
[ ! -e "$tmp/never.txt" ] && ok "bad line: no output file" || bad "bad line: no output file" "created"

# Damaged files and parameters, a fixed-seed stream of them.
if python3 "$(dirname "$0")/mutated_inputs.py" "$ct" > "$tmp/mutated.log" 2>&1; then
    ok "damaged inputs: $(tail -n 1 "$tmp/mutated.log")"
else
    bad "damaged inputs" "$(tail -n 20 "$tmp/mutated.log")"
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
