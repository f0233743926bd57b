"""Parametric studies: run one deck for many values of its design variables (`camtrain sweep`).

    >>> from camtrain.study import prepare, run_sweep
    >>> sweep = prepare("decks/harrison_flat.toml", [("speed", "range", "1500:3500:5")])  # doctest: +SKIP
    >>> outcome = run_sweep(sweep, "out/speed", jobs=2)                              # doctest: +SKIP

Modules: :mod:`.sweep` (parameters and cases), :mod:`.pivot` (Ball's pivoted-geometry rules),
:mod:`.executors` (serial, processes, Dask), :mod:`.trends` (rises / falls tables),
:mod:`.sweep_output` (sweep.csv, resume, plots) and :mod:`.runner` (the whole sweep).
"""
from __future__ import annotations

from camtrain.study.sweep import ALIASES


def prepare(*args, **kwargs):
    """See :func:`camtrain.study.runner.prepare`."""
    from camtrain.study.runner import prepare as _prepare

    return _prepare(*args, **kwargs)


def run_sweep(*args, **kwargs):
    """See :func:`camtrain.study.runner.run_sweep`."""
    from camtrain.study.runner import run_sweep as _run

    return _run(*args, **kwargs)


__all__ = ["ALIASES", "prepare", "run_sweep"]
