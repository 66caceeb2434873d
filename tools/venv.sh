#!/bin/sh
# Creates (once) one of the project's Python venvs and prints its python.
#   venv.sh        tests: tools/requirements.txt, in $CT_VENV (default .venv)
#   venv.sh eval   make eval / make bench: tools/requirements-eval.txt, every
#                  package pinned and installed without dependency resolution,
#                  in $CT_EVAL_VENV (default .venv-eval)
# A venv is rebuilt when its requirements file changes.
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "eval" ]; then
    venv=${CT_EVAL_VENV:-$top/.venv-eval}
    req=$top/tools/requirements-eval.txt
    nodeps=--no-deps
else
    venv=${CT_VENV:-$top/.venv}
    req=$top/tools/requirements.txt
    nodeps=
fi
stamp=$venv/.requirements
# Tests run in parallel, and two of them may ask for the venv at once: the
# second waits for the first to finish it (flock, util-linux).
exec 9> "$venv.lock"
flock 9
if [ ! -x "$venv/bin/python" ] || ! cmp -s "$req" "$stamp"; then
    echo "venv: setting up $venv ($(basename "$req"))" >&2
    rm -rf "$venv"
    python3 -m venv "$venv" >&2 || {
        echo "venv: python3 -m venv failed: install python3-venv (tools/install-deps.sh)" >&2
        exit 1
    }
    "$venv/bin/pip" install --quiet --disable-pip-version-check $nodeps -r "$req" >&2
    cp "$req" "$stamp"
fi
echo "$venv/bin/python"
