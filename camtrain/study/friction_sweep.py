"""The FLAME friction map through the sweep machinery: a cartesian sweep of ``speed``,
``load.value`` and ``oil.temperature`` (worker processes or a Dask scheduler), read back as a
:class:`~camtrain.study.friction_map.FrictionMap` (a module of its own: the sweep runner writes
the map files of any such sweep through :mod:`camtrain.study.friction_map`)."""
from __future__ import annotations

from pathlib import Path

from camtrain.study.friction_map import FrictionMap, map_from_records


def sweep_map(deck_path, speeds, loads, temperatures, out_dir, *, measure: str = "imep",
              jobs: int | None = 1, scheduler=None, progress=None) -> FrictionMap:
    """Every grid point through the sweep machinery (FLAME and the correlations per point):
    a cartesian sweep of ``speed``, ``load.value`` (``load.measure`` = ``measure``) and
    ``oil.temperature`` written to ``out_dir``; the map read from its records."""
    from camtrain.deck.load import load_deck, parse_toml, validate
    from camtrain.study.runner import Sweep, run_sweep
    from camtrain.study.sweep import build_parameters, cases, set_path

    loaded = load_deck(str(deck_path))
    raw = parse_toml(loaded.text, loaded.path)
    base_dir = str(Path(deck_path).resolve().parent)
    set_path(raw, "load.measure", measure)
    set_path(raw, "load.value", float(loads[0]))
    validate(raw, loaded.path, Path(base_dir))
    fmt = ",".join
    params = build_parameters(raw, [("speed", "values", fmt(f"{v:g}" for v in speeds)),
                                    ("load.value", "values", fmt(f"{v:g}" for v in loads)),
                                    ("oil.temperature", "values",
                                     fmt(f"{v:g}" for v in temperatures))])
    sweep = Sweep(raw, loaded.path, base_dir, loaded.sha256, params, [], cases(params))
    outcome = run_sweep(sweep, out_dir, jobs=jobs, scheduler=scheduler, plots=False,
                        progress=progress)
    return map_from_records(params, outcome.records, f"{measure.replace('_', ' ')} [bar]")
