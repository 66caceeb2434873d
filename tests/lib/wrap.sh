# Sourced by the test scripts. In a cross build (make cross-arm64) meson
# runs the test scripts natively and names the emulator in
# MESON_EXE_WRAPPER: `wrap PROGRAM DIR` prints a program that runs PROGRAM
# under it (a small script in DIR), or PROGRAM itself in a native build.
wrap() {
    if [ -z "${MESON_EXE_WRAPPER:-}" ]; then
        echo "$1"
        return
    fi
    _w="$2/$(basename "$1")"
    printf '#!/bin/sh\nexec %s "%s" "$@"\n' "$MESON_EXE_WRAPPER" "$1" > "$_w"
    chmod +x "$_w"
    echo "$_w"
}
