#!/bin/sh
# Installs the Debian packages ctrack needs to build, test and run its demo,
# and python3-numpy, which the Python package `make install` puts beside
# Debian's python3 imports.
#   install-deps.sh          install what is missing (uses sudo when not root)
#   install-deps.sh --check  exit 1 if something is missing, installing nothing
#   install-deps.sh --fuzz [--check]
#                            what make fuzz adds: clang, its libFuzzer and
#                            sanitizer runtimes, llvm-profdata and llvm-cov
#   install-deps.sh --arm64 [--check]
#                            what make cross-arm64 adds: the aarch64 cross
#                            compilers, qemu-user, and through multiarch the
#                            arm64 -dev packages (FLANN's headers are the build
#                            machine's: libflann-dev:arm64 would pull in MPI
#                            packages that cannot sit beside the amd64 ones)
set -eu
packages="gcc g++ make pkg-config meson ninja-build check python3 python3-venv python3-numpy ffmpeg
libopencv-core-dev libopencv-imgproc-dev libopencv-video-dev libflann-dev liblz4-dev"
arm64=""
if [ "${1:-}" = "--fuzz" ]; then
    shift
    # libFuzzer's runtime is in the versioned package of Debian's clang.
    v=$(apt-cache depends clang 2>/dev/null | sed -n 's/.*Depends: clang-\([0-9][0-9]*\)$/\1/p' | head -n 1)
    packages="$packages clang libclang-rt-${v:-14}-dev llvm"
elif [ "${1:-}" = "--arm64" ]; then
    shift
    arm64=yes
    packages="$packages gcc-aarch64-linux-gnu g++-aarch64-linux-gnu qemu-user
libopencv-core-dev:arm64 libopencv-imgproc-dev:arm64 libopencv-video-dev:arm64
liblz4-dev:arm64 check:arm64"
fi

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
if [ -n "$arm64" ] && ! dpkg --print-foreign-architectures | grep -qx arm64; then
    $sudo dpkg --add-architecture arm64
fi
$sudo apt-get update -qq
# shellcheck disable=SC2086
$sudo apt-get install -y -qq --no-install-recommends $missing
