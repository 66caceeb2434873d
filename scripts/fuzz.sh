#!/bin/sh
# make fuzz: builds the libFuzzer targets of tests/fuzz with clang (ASan,
# UBSan, source-based coverage) in BUILD, seeds their corpora from
# tests/data, runs each for SECONDS, then reports executions, libFuzzer's
# edge coverage and the line coverage of the code each target reaches
# (llvm-cov over the corpus it grew). A crash, a failed check, a leak or a
# timeout stops the run and fails it, with the input saved beside the corpus.
#   fuzz.sh BUILD SECONDS [TARGET...]     (targets: feed video detfile)
set -eu
build=$1 seconds=$2
shift 2
targets=${*:-feed video detfile}
here=$(cd "$(dirname "$0")/.." && pwd)
data=$here/tests/data/mot15
if [ ! -f "$build/build.ninja" ]; then
    CC=clang CXX=clang++ meson setup "$build" "$here" -Dfuzz=true -Dtests=false \
        -Db_sanitize=address,undefined -Dbuildtype=debugoptimized
fi
for t in $targets; do
    ninja -C "$build" "tests/fuzz/fuzz_$t"
done
work=$build/fuzz
mkdir -p "$work"

# Seeds from the repository's sequences.
seeds=$work/seeds
if [ ! -d "$seeds" ]; then
    mkdir -p "$seeds.tmp/detfile" "$seeds.tmp/video" "$seeds.tmp/feed"
    for seq in "$data"/*/; do
        name=$(basename "$seq")
        head -n 60 "$seq/det/det.txt" > "$seeds.tmp/detfile/$name.txt"
        head -c 512 "$seq/det/det.txt" > "$seeds.tmp/feed/$name"
    done
    # Video: three of TUD-Campus's frames at 32x24, as Y4M and as raw I420,
    # NV12 and grey, each after the four bytes that give the raw size (32
    # and 24 are 34 - 2 and 26 - 2) and format (0 I420, 1 NV12, 2 grey).
    tud=$data/TUD-Campus/video.mp4
    cut() { ffmpeg -v error -i "$tud" -frames:v 3 -vf scale=32:24 "$@"; }
    cut -f yuv4mpegpipe -pix_fmt yuv420p "$seeds.tmp/y4m"
    cut -f yuv4mpegpipe -pix_fmt gray "$seeds.tmp/y4m-gray"
    cut -f rawvideo -pix_fmt yuv420p "$seeds.tmp/i420"
    cut -f rawvideo -pix_fmt nv12 "$seeds.tmp/nv12"
    cut -f rawvideo -pix_fmt gray "$seeds.tmp/gray"
    prefix() { printf "\\042\\032\\$(printf %03o "$1")\\000"; }
    { prefix 0; cat "$seeds.tmp/y4m"; } > "$seeds.tmp/video/y4m"
    { prefix 0; cat "$seeds.tmp/y4m-gray"; } > "$seeds.tmp/video/y4m-gray"
    { prefix 0; cat "$seeds.tmp/i420"; } > "$seeds.tmp/video/i420"
    { prefix 1; cat "$seeds.tmp/nv12"; } > "$seeds.tmp/video/nv12"
    { prefix 2; cat "$seeds.tmp/gray"; } > "$seeds.tmp/video/gray"
    { prefix 0; head -c 1500 "$seeds.tmp/i420"; } > "$seeds.tmp/video/i420-cut"
    # The tracker: a frame's worth of TUD-Campus's pixels too.
    head -c 1024 "$seeds.tmp/i420" > "$seeds.tmp/feed/tud-pixels"
    rm -f "$seeds.tmp/y4m" "$seeds.tmp/y4m-gray" "$seeds.tmp/i420" "$seeds.tmp/nv12" "$seeds.tmp/gray"
    mv "$seeds.tmp" "$seeds"
fi

max_len() { case $1 in feed) echo 4096 ;; video) echo 16384 ;; detfile) echo 8192 ;; esac; }
covered() { # the sources each target is for: their folder or file
    case $1 in
    feed) echo "lib/" ;;
    video) echo "tools/input/video.c" ;;
    detfile) echo "tools/input/detfile.c" ;;
    esac
}
status=0
for t in $targets; do
    corpus=$work/corpus/$t
    mkdir -p "$corpus" "$work/crashes/$t"
    echo "fuzz: fuzz_$t for $seconds s (corpus $corpus)" >&2
    log=$work/$t.log
    # UndefinedBehaviorSanitizer stops at its first report, as in make sanitize.
    if ! UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
        "$build/tests/fuzz/fuzz_$t" -max_total_time="$seconds" -print_final_stats=1 \
        -max_len="$(max_len "$t")" -timeout=30 -rss_limit_mb=4096 \
        -artifact_prefix="$work/crashes/$t/" "$corpus" "$seeds/$t" > "$log" 2>&1; then
        echo "fuzz: fuzz_$t FAILED; the input is in $work/crashes/$t:" >&2
        grep -E "ERROR|check failed|SUMMARY" "$log" | head -5 >&2
        status=1
        continue
    fi
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
    last=$(grep -E '^#[0-9]+' "$log" | tail -1)
    cov=$(echo "$last" | sed -n 's/.* cov: \([0-9]*\) ft: \([0-9]*\) corp: \([0-9]*\).*/\1 edges, \2 features, corpus of \3 inputs/p')
    # Line coverage: the target over its corpus, uninstrumented for speed
    # by nothing but its profile.
    rm -f "$work/$t".*.profraw
    LLVM_PROFILE_FILE="$work/$t.%p.profraw" "$build/tests/fuzz/fuzz_$t" -runs=0 \
        "$corpus" "$seeds/$t" > /dev/null 2>&1
    llvm-profdata merge -sparse "$work/$t".*.profraw -o "$work/$t.profdata"
    # The report's rows: file, regions (3 columns), functions (3), lines
    # (3: count, missed, cover), branches (3); the rows of the target's
    # file, or of the files in its folder and below.
    pat="(^|/)$(covered "$t")"
    case $pat in
    */) pat="$pat.*\$" ;;
    *) pat="$pat\$" ;;
    esac
    lines=$(llvm-cov report "$build/tests/fuzz/fuzz_$t" -instr-profile="$work/$t.profdata" |
        awk -v pat="$pat" '$1 ~ pat { n += $8; miss += $9 }
            END { if (n) printf "%.1f%% of %d lines", 100 * (n - miss) / n, n }')
    printf 'fuzz_%s: %s s, %s executions (%s a second), %s; line coverage of %s: %s\n' \
        "$t" "$seconds" "$execs" "$rate" "$cov" \
        "$(covered "$t")" "$lines" | tee "$work/$t.summary"
    # The parts of lib/ that only scene-like frames reach (docs/robustness.md).
    if [ "$t" = feed ]; then
        cov_of() { python3 "$here/scripts/fuzz-coverage.py" "$build/tests/fuzz/fuzz_feed" \
            "$work/feed.profdata" "$@"; }
        printf 'fuzz_feed: blob merging and group splitting (blobs.cc): %s; the people'"'"'s size (person_size.cc): %s\n' \
            "$(cov_of lib/pixels/blobs.cc merge_fragments split between_heads emptiest rows_of)" \
            "$(cov_of lib/track/person_size.cc '*')" | tee -a "$work/$t.summary"
    fi
done
exit $status
