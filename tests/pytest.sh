#!/bin/sh
# Runs the Python tests through the real shared library, in the project venv.
#   pytest.sh LIBCTRACK_SO CT_TRACK ABI_LAYOUT
set -eu
here=$(cd "$(dirname "$0")" && pwd)
py=$("$here/../tools/venv.sh")
export CTRACK_LIBRARY="$(realpath "$1")" CTRACK_CT_TRACK="$(realpath "$2")" CTRACK_ABI_LAYOUT="$(realpath "$3")"
cd "$here/python"
exec "$py" -m pytest -q -p no:cacheprovider .
