#!/bin/sh
# Runs the Python tests through the real shared library, in the project venv.
#   pytest.sh LIBCTRACK_SO CT_TRACK ABI_LAYOUT
set -eu
here=$(cd "$(dirname "$0")" && pwd)
py=$("$here/../scripts/venv.sh")
export CTRACK_LIBRARY="$(realpath "$1")" CTRACK_CT_TRACK="$(realpath "$2")" CTRACK_ABI_LAYOUT="$(realpath "$3")"
cd "$here/python"
# make sanitize: the sanitizers' runtimes, loaded ahead of Python, which was
# not built with them (Python's own allocations are not leak-checked).
if [ -n "${CTRACK_PRELOAD:-}" ]; then
    export LD_PRELOAD="$CTRACK_PRELOAD" ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi
exec "$py" -m pytest -q -p no:cacheprovider .
