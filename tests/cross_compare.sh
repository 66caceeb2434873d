#!/bin/sh
# The arm64 build gives the tracks the build machine's gives, byte for byte:
# same_tracks.sh --quick over both builds (the public detections of the six
# sequences; TUD-Campus and PETS09-S2L1 from their pixels alone and with
# their detections, live and primed; PETS09-S2L1 at half size and washed
# out from its pixels). The arm64 program runs under qemu-aarch64.
#   cross_compare.sh NATIVE_CT_TRACK ARM64_CT_TRACK DATA_DIR
set -eu
exec "$(dirname "$0")/same_tracks.sh" --quick "$1" "qemu-aarch64 -L / $2" "$3"
