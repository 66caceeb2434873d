"""ctrack's evaluation and research harness: the repository's sequences and
their videos, py-motmetrics scoring, the peers ctrack is compared with.
make eval (eval/eval.py), make bench (bench/bench.py), the sweeps and the
recognition study import it; scripts/venv.sh makes it importable in the
project's venvs."""
