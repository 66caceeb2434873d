# The short verbs. meson.build is the one build description: this file keeps
# no list of sources.
BUILD ?= build
MESON_OPTS ?=
PREFIX ?= /usr/local

.PHONY: all deps check demo install clean eval bench

# Every verb first installs the Debian packages that are missing (a quick
# dpkg query when nothing is).
all: deps $(BUILD)/build.ninja
	meson compile -C $(BUILD)

deps:
	@tools/install-deps.sh --check 2>/dev/null || tools/install-deps.sh

$(BUILD)/build.ninja: | deps
	meson setup $(BUILD) --prefix=$(PREFIX) $(MESON_OPTS)

check: all
	@status=0; meson test -C $(BUILD) --print-errorlogs || status=$$?; \
	python3 tools/test-summary.py $(BUILD)/meson-logs/testlog.json; exit $$status

demo: all
	tools/demo.sh $(BUILD)

install: all
	meson install -C $(BUILD)

clean:
	rm -rf $(BUILD)

# Both run in their own venv (tools/venv.sh eval), created on first use.
eval: all
	"$$(tools/venv.sh eval)" tools/eval.py $(BUILD)

bench: all
	"$$(tools/venv.sh eval)" bench/bench.py $(BUILD)
