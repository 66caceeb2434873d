#!/bin/sh
# Installs the Debian packages ctrack needs to build, test and run its demo,
# and python3-numpy, which the Python package `make install` puts beside
# Debian's python3 imports.
#   install-deps.sh          install what is missing (uses sudo when not root)
#   install-deps.sh --check  exit 1 if something is missing, installing nothing
set -eu
packages="gcc g++ make pkg-config meson ninja-build check python3 python3-venv python3-numpy ffmpeg
libopencv-core-dev libopencv-imgproc-dev libopencv-video-dev libflann-dev liblz4-dev"

missing=""
for p in $packages; do
    if ! dpkg-query -W -f '${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $p"
    fi
done
if [ -z "$missing" ]; then
    exit 0
fi
if [ "${1:-}" = "--check" ]; then
    echo "missing Debian packages:$missing" >&2
    exit 1
fi
echo "install-deps: installing$missing" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo > /dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
    sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
# shellcheck disable=SC2086
$sudo apt-get install -y -qq --no-install-recommends $missing
