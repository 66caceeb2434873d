# The short verbs. meson.build is the one build description: this file keeps
# no list of sources.
BUILD ?= build
MESON_OPTS ?=
PREFIX ?= /usr/local

.PHONY: all deps check demo install clean eval bench sanitize tsan soak cross-arm64 fuzz

# Every verb first installs the Debian packages that are missing (a quick
# dpkg query when nothing is).
all: deps $(BUILD)/build.ninja
	meson compile -C $(BUILD)

deps:
	@scripts/install-deps.sh --check 2>/dev/null || scripts/install-deps.sh

$(BUILD)/build.ninja: | deps
	meson setup $(BUILD) --prefix=$(PREFIX) $(MESON_OPTS)

check: all
	@status=0; meson test -C $(BUILD) --print-errorlogs || status=$$?; \
	python3 scripts/test-summary.py $(BUILD)/meson-logs/testlog.json; exit $$status

demo: all
	scripts/demo.sh $(BUILD)

# The C suites, the CLI, the Python tests and the real-data replay again,
# built with AddressSanitizer and UndefinedBehaviorSanitizer, which stop at
# their first report (Python runs with their runtimes preloaded; the install
# test links without them, so it runs in `make check` only). GCC's
# "undefined" leaves out a float converted to an int it does not fit, which
# the fuzzer's Clang build checks: it is asked for here too.
SANITIZE_BUILD ?= build-sanitize
FLOAT_CAST = -fsanitize=float-cast-overflow
sanitize: deps
	@[ -f $(SANITIZE_BUILD)/build.ninja ] || meson setup $(SANITIZE_BUILD) \
	    -Db_sanitize=address,undefined -Dbuildtype=debugoptimized \
	    -Dc_args=$(FLOAT_CAST) -Dcpp_args=$(FLOAT_CAST) \
	    -Dc_link_args=$(FLOAT_CAST) -Dcpp_link_args=$(FLOAT_CAST) $(MESON_OPTS)
	ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 \
	UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 \
	CTRACK_PRELOAD="$$($(CC) -print-file-name=libasan.so) $$($(CC) -print-file-name=libubsan.so)" \
	    meson test -C $(SANITIZE_BUILD) --suite lib --suite cli --suite python --suite replay \
	    --print-errorlogs

# The thread tests under ThreadSanitizer (GCC's): trackers in several
# threads at once, on the public detections and on TUD-Campus's frames in
# the three modes, each giving what it gives alone, with no data race
# reported (TSan stops at its first report). TSan runs code 5-15 times
# slower, so the tests' timeouts are stretched as for the emulated build.
TSAN_BUILD ?= build-tsan
tsan: deps
	@[ -f $(TSAN_BUILD)/build.ninja ] || meson setup $(TSAN_BUILD) \
	    -Db_sanitize=thread -Dbuildtype=debugoptimized $(MESON_OPTS)
	TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
	    meson test -C $(TSAN_BUILD) threads pixels --timeout-multiplier 4 \
	    --print-errorlogs

# meson does not refresh the loader's cache: without ldconfig, programs
# linked to the new library (and `import ctrack`) would not find it.
install: all
	meson install -C $(BUILD)
	@if [ -z "$(DESTDIR)" ] && [ "$$(id -u)" = 0 ] && command -v ldconfig > /dev/null; then \
	    ldconfig; fi

# The libFuzzer targets of tests/fuzz (the tracker's C interface, the video
# readers, the detection-file parser), built with clang, ASan and UBSan in
# build-fuzz, each run FUZZ_SECONDS from corpora seeded by tests/data; prints
# executions and coverage (scripts/fuzz.sh). CI runs a short pass.
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
fuzz: deps
	@scripts/install-deps.sh --fuzz --check 2>/dev/null || scripts/install-deps.sh --fuzz
	scripts/fuzz.sh $(FUZZ_BUILD) $(FUZZ_SECONDS)

# The library, ct-track, the examples and the C suites built for 64-bit ARM
# (cross/aarch64-linux-gnu.txt), with the Debian packages that takes; the C
# suites, the CLI tests and the soak run under qemu-aarch64 (four times the
# timeouts: emulation is some ten times slower), then ten
# replays must give the tracks of the native build byte for byte
# (tests/cross_compare.sh). The Python suite is left out: ctypes in the
# build machine's Python cannot load an arm64 library.
ARM64_BUILD ?= build-arm64
cross-arm64: all
	@scripts/install-deps.sh --arm64 --check 2>/dev/null || scripts/install-deps.sh --arm64
	@[ -f $(ARM64_BUILD)/build.ninja ] || meson setup $(ARM64_BUILD) \
	    --cross-file cross/aarch64-linux-gnu.txt $(MESON_OPTS)
	meson compile -C $(ARM64_BUILD)
	CK_TIMEOUT_MULTIPLIER=4 meson test -C $(ARM64_BUILD) --suite lib --suite cli --suite soak \
	    --timeout-multiplier 4 --print-errorlogs
	meson test -C $(ARM64_BUILD) header-c header-cxx symbols --print-errorlogs
	tests/cross_compare.sh $(BUILD)/tools/ct-track $(ARM64_BUILD)/tools/ct-track tests/data/mot15

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(TSAN_BUILD) $(ARM64_BUILD) $(FUZZ_BUILD)

# Both run in their own venv (scripts/venv.sh eval), created on first use.
eval: all
	"$$(scripts/venv.sh eval)" eval/eval.py $(BUILD)

bench: all
	PYTHONPATH=python "$$(scripts/venv.sh eval)" bench/bench.py $(BUILD)

# One tracker for a million frames of detections and 100,000 frames of
# pixels: memory and time per frame at the start, middle and end; fails if
# the memory grows past 2 MiB from the middle to the end (make check runs a
# short one, the test `soak`).
soak: all
	$(BUILD)/bench/ct-soak 1000000 100000 2048
