#!/bin/sh
# Creates (once) the project's Python venv with tools/requirements.txt and
# prints its python. The venv lives in $CT_VENV, by default .venv at the top
# of the source tree; it is rebuilt when the requirements change.
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
venv=${CT_VENV:-$top/.venv}
req=$top/tools/requirements.txt
stamp=$venv/.requirements
if [ ! -x "$venv/bin/python" ] || ! cmp -s "$req" "$stamp"; then
    echo "venv: setting up $venv (tools/requirements.txt)" >&2
    rm -rf "$venv"
    python3 -m venv "$venv" >&2 || {
        echo "venv: python3 -m venv failed: install python3-venv (tools/install-deps.sh)" >&2
        exit 1
    }
    "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$req" >&2
    cp "$req" "$stamp"
fi
echo "$venv/bin/python"
