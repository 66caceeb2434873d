#!/bin/sh
# The shared library exports exactly the symbols in docs/symbols-in-versions,
# every one of them ct_*, and each is declared in the public header; and it
# holds no ifunc.
#   symbols.sh LIBCTRACK.so SYMBOLS_FILE HEADER
set -eu
lib=$1 list=$2 header=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
nm -D --defined-only "$lib" | awk '$2 ~ /^[TDBRW]$/ {print $3}' | sort > "$tmp/exported"
grep -v '^#' "$list" | awk 'NF {print $1}' | sort > "$tmp/listed"
status=0
if ! diff -u "$tmp/listed" "$tmp/exported"; then
    echo "symbols: the exports differ from $list (- listed, + exported)"
    status=1
fi
if grep -v '^ct_' "$tmp/exported"; then
    echo "symbols: exports outside the ct_ prefix (above)"
    status=1
fi
while read -r s; do
    grep -q "\\b$s(" "$header" || { echo "symbols: $s is not declared in $header"; status=1; }
done < "$tmp/exported"
# No ifunc resolvers (GCC's target_clones): they run while the library
# loads, before a sanitizer's runtime starts (ThreadSanitizer could not load
# the library). CPU features are dispatched at run time (lib/dsp/dsp.h).
if readelf -sW "$lib" | grep -w IFUNC; then
    echo "symbols: ifunc symbols in the library (above)"
    status=1
fi
[ $status -eq 0 ] && echo "symbols: $(wc -l < "$tmp/exported") exports, all listed and declared"
exit $status
