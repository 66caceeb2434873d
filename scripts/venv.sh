#!/bin/sh
# Creates (once) one of the project's Python venvs and prints its python.
#   venv.sh        tests: tests/requirements.txt, in $CT_VENV (default .venv)
#   venv.sh eval   make eval / make bench: eval/requirements.txt, every
#                  package pinned and installed without dependency resolution,
#                  in $CT_EVAL_VENV (default .venv-eval)
# A venv is rebuilt when its requirements file changes. Both import the
# evaluation harness (eval/cteval) from the tree: a .pth file in the venv
# puts eval/ on its path.
set -eu
top=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = "eval" ]; then
    venv=${CT_EVAL_VENV:-$top/.venv-eval}
    req=$top/eval/requirements.txt
    nodeps=--no-deps
else
    venv=${CT_VENV:-$top/.venv}
    req=$top/tests/requirements.txt
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
        echo "venv: python3 -m venv failed: install python3-venv (scripts/install-deps.sh)" >&2
        exit 1
    }
    "$venv/bin/pip" install --quiet --disable-pip-version-check $nodeps -r "$req" >&2
    cp "$req" "$stamp"
fi
pth=$("$venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')/ctrack-eval.pth
[ "$(cat "$pth" 2>/dev/null)" = "$top/eval" ] || echo "$top/eval" > "$pth"
echo "$venv/bin/python"
