#!/bin/sh
# Prints ctrack's version (or, with --abi, its ABI number) from the one place
# it is written: include/ctrack/ctrack.h.
h="$(dirname "$0")/../include/ctrack/ctrack.h"
get() { sed -n "s/^#define $1 \([0-9][0-9]*\).*/\1/p" "$h"; }
if [ "$1" = "--abi" ]; then
    get CT_ABI_VERSION
else
    echo "$(get CT_VERSION_MAJOR).$(get CT_VERSION_MINOR).$(get CT_VERSION_PATCH)"
fi
