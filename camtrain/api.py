"""The public Python API: load a deck, resolve its plan, run it, write its outputs.

    >>> import camtrain.api as ct
    >>> deck = ct.load("decks/harrison_flat.toml")      # doctest: +SKIP
    >>> result = ct.run(deck)                          # doctest: +SKIP
    >>> result["lift"], result.metrics                  # doctest: +SKIP

The command line is a thin layer over these functions.
"""
from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from camtrain.deck.load import LoadedDeck, load_deck, load_deck_text
from camtrain.deck.schema import Deck
from camtrain.result import Result
from camtrain.scene import Plan, resolve


def load(path: str | Path, sets: Sequence[str] = ()) -> LoadedDeck:
    """Read and validate a deck file ('-' for standard input). Raises InputError.

    ``sets``: changes as on the command line (``run --set``), each ``"path=value"`` in the
    deck's units, e.g. ``["solver.angle_points=720", "tribology.entrainment=mean"]``; the
    deck is validated with them, and its recorded text ends with them as comments."""
    if not sets:
        return load_deck(str(path))
    import hashlib

    from camtrain.deck.load import parse_toml, read_text, validate
    from camtrain.study.assign import apply_fixed, assignment_text, parse_assignment

    name, text = read_text(str(path))
    raw = parse_toml(text, name)
    fixed = [parse_assignment(raw, s) for s in sets]
    base = Path(path).resolve().parent if str(path) != "-" else Path.cwd()
    model = validate(apply_fixed(raw, fixed), name, base)
    text += assignment_text(fixed)
    return LoadedDeck(model, name, hashlib.sha256(text.encode()).hexdigest(), text)


def loads(text: str, name: str = "<text>") -> LoadedDeck:
    """Validate deck text (TOML)."""
    return load_deck_text(text, name)


def to_toml(deck: LoadedDeck | Deck) -> str:
    """A deck (validated, any kind) as TOML in its deck units, every field written."""
    from camtrain.deck.writer import to_toml as text

    return text(_model(deck))


def save_deck(deck: LoadedDeck | Deck, path: str | Path) -> Path:
    """Write a deck (e.g. one built or changed in Python with dataclasses.replace, values in
    SI) to ``path`` as TOML that ``load`` reads back to an equal deck."""
    from camtrain.deck.writer import save

    return save(_model(deck), path)


def plan(deck: LoadedDeck | Deck) -> Plan:
    """The effects this deck calls for, with the reason for each."""
    return resolve(_model(deck))


def run(deck: LoadedDeck | Deck | str | Path, progress=None) -> Result:
    """Run a deck (object or path) of any kind and return its Result.

    ``progress(effect name, done, total)``, when given, is called before each effect runs."""
    from camtrain.runner import run_plan

    if isinstance(deck, str | Path):
        deck = load(deck)
    return run_plan(_model(deck), progress=progress)


def lift(deck: LoadedDeck | Deck | str | Path, points: int | None = None) -> Result:
    """Only the lift law of a deck on its angle grid: lift, velocity, acceleration, jerk."""
    from camtrain.tabulate.lift import lift_columns

    if isinstance(deck, str | Path):
        deck = load(deck)
    result = Result()
    lift_columns(_model(deck), result, points)
    return result


#: effects cheap enough for ``check`` to run: the geometry of the train (no loads, no film)
GEOMETRY_EFFECTS = ("kinematics",)


def implausible(deck: LoadedDeck | Deck) -> list[str]:
    """Warnings on part sizes no engine has (0.018 mm: a deck written in metres)."""
    from camtrain.deck.plausible import implausible as sizes

    return sizes(_model(deck))


def check(deck: LoadedDeck | Deck) -> tuple[str, list[str]]:
    """The cheap geometry checks ``camtrain check`` adds to validation: (what was checked,
    warnings of the geometry).

    Runs the plan's geometry effects (``GEOMETRY_EFFECTS``): a flat follower on too small a base
    circle, a mechanism that cannot assemble raise GeometryError here as in ``run``. For a deck
    kind without such an effect the first item says plainly that no geometry was checked."""
    import importlib

    from camtrain.catalogue import kind_of
    from camtrain.runner import Inputs
    from camtrain.scene import effect_module

    model = _model(deck)
    warnings: list[str] = []
    cheap = [s for s in resolve(model).effects if s.name in GEOMETRY_EFFECTS]
    if not cheap:
        hook = kind_of(model).geometry
        if hook:
            module, name = hook.split(":")
            return getattr(importlib.import_module(module), name)(model)
        return "geometry not checked (no kinematic check for this deck kind; run checks it)", \
            warnings
    result = Result()
    for spec in cheap:
        effect_module(spec).run(model, Inputs(spec, {}), result)
    warnings += [w for w in result.warnings if w not in warnings]
    return f"geometry checked ({', '.join(s.name for s in cheap)})", warnings


def write(result: Result, deck: LoadedDeck, out_dir: str | Path, wall_time: float = 0.0, *,
          plots: str = "sheets", units: str = "deck") -> list[Path]:
    """Write a run's outputs into ``out_dir`` atomically: cycle.csv, report.txt, summary.json
    (with the deck's design-limit checks) and, unless ``plots="none"``, the plot sheets
    (``plots``: "sheets" PNG, "pdf" PNG and PDF, "all" also every panel alone). ``units``:
    cycle.csv and summary.json in the deck's units ("deck", each with its unit) or in SI
    ("si")."""
    from camtrain.report.outputs import check_limits, write_run

    return write_run(result, deck, Path(out_dir), wall_time,
                     checks=check_limits(result, deck), plots=plots, units=units)


def sensitivity(deck: str | Path, inputs, out_dir: str | Path, *, method: str = "sobol",
                samples: int = 1024, metrics=(), seed: int = 1, sets=(), jobs: int | None = 1,
                scheduler=None, resume: bool = False, confidence: float = 0.95,
                plots: bool = True):
    """Sobol' or Morris indices of a deck's metrics to uncertain inputs (docs/sensitivity.md).

    ``inputs``: [(name, distribution, "A:B")], distribution uniform, log-uniform, normal
    (MEAN:SD) or relative (-P%:+P%); a number written with % is relative to the deck's value.
    Returns a report whose ``frame("indices")``, ``frame("convergence")``,
    ``frame("distribution")`` and ``frame("samples")`` are pandas DataFrames (pandas comes
    with SALib)."""
    from camtrain.study.sensitivity import prepare
    from camtrain.study.sensitivity_run import run_study

    study = prepare(deck, [tuple(i) for i in inputs], method=method, samples=samples,
                    seed=seed, metrics=tuple(metrics), sets=list(sets))
    return run_study(study, out_dir, jobs=jobs, scheduler=scheduler, resume=resume,
                     confidence=confidence, plots=plots)


def fit(deck: str | Path, data, constants, out_dir: str | Path, *, sets=(), jobs: int = 1,
        scheduler=None, confidence: float = 0.95, plots: bool = True):
    """Calibrate deck constants to measured CSV data (docs/sensitivity.md#calibration).

    ``data``: CSV paths; ``constants``: [(name, "LOW:HIGH")], started from the deck's
    values. Returns a report whose ``frame("constants")``, ``frame("correlation")``,
    ``frame("singular")`` and ``frame("residuals")`` are pandas DataFrames; the calibrated
    deck is written to ``out_dir``/calibrated.toml."""
    from camtrain.study.fit_run import run_fit

    return run_fit(deck, list(data), [tuple(c) for c in constants], out_dir, sets=list(sets),
                   jobs=jobs, scheduler=scheduler, confidence=confidence, plots=plots)


def design(deck: str | Path, out_dir: str | Path | None = None, *, plots: bool = True):
    """Build a lift law from the valve events and limits of ``deck``'s [design] section
    (docs/design.md): a ``DesignOutcome`` with the law, the deck with a spline [lift]
    (``raw``), every event and limit measured (``items``, ``all_met``). With ``out_dir``,
    also write designed.toml, design.md, design.csv and design.png there."""
    from camtrain.design.command import design_deck, write_design

    outcome = design_deck(deck)
    if out_dir is not None:
        write_design(outcome, Path(out_dir), str(deck), plots=plots)
    return outcome


def optimize(deck: str | Path, variables, objective: str = "power_loss_mean",
             constraints=(), out_dir: str | Path | None = None, *, plots: bool = True,
             **options):
    """Minimise ``objective`` of ``deck`` over ``variables`` (``"base_radius=12:24"`` or
    ``(path, lower, upper)``, deck units) under ``constraints`` (``"no_concave_flank"``,
    ``"no_separation=3000"``, ...; docs/design.md). ``options``: method, step, maxiter, jobs,
    scheduler, sets, popsize, seed, progress. Returns an ``OptimizeOutcome`` (datum, optimum,
    ``gains()``, ``active()``, the path); with ``out_dir`` also writes optimum.toml and the
    report there."""
    from camtrain.study.optimize import optimize as search

    outcome = search(deck, variables, objective, constraints, **options)
    if out_dir is not None:
        from camtrain.study.optimize_output import write_optimize

        write_optimize(outcome, out_dir, plots=plots)
    return outcome


def sweep(deck: str | Path, parameters: dict[str, str | Sequence[float]],
          out_dir: str | Path, *, sets: Sequence[str] = (), zipped: bool = False,
          jobs: int | None = 1, units: str = "deck", plots: bool = False):
    """Run ``deck`` for many values of its design variables, as ``camtrain sweep`` does, and
    return its Outcome (``outcome.to_dataframe()``: one row per case, the swept values, the
    status and every metric in ``units``); sweep.csv and the trend table go to ``out_dir``.

    ``parameters``: name (an alias such as ``base_radius`` or a dotted deck path) -> the values
    in the deck field's unit, or a spec as on the command line: ``"range:14:22:9"`` or
    ``"relative:-25%:+25%:11"``. ``sets``: fixed changes, as :func:`load`'s.

        >>> outcome = sweep("decks/harrison_flat.toml", {"base_radius": [16, 18, 20]},
        ...                 "out/rb")                                   # doctest: +SKIP
        >>> outcome.to_dataframe()["power_loss_mean[W]"]                # doctest: +SKIP
    """
    from camtrain.study.runner import prepare, run_sweep

    specs = []
    for name, values in parameters.items():
        if isinstance(values, str):
            kind, _, text = values.partition(":")
            specs.append((name, kind, text))
        else:
            specs.append((name, "values", ",".join(repr(float(v)) for v in values)))
    prepared = prepare(deck, specs, list(sets), zipped, units)
    return run_sweep(prepared, out_dir, jobs=jobs, plots=plots)


def _model(deck: LoadedDeck | Deck) -> Deck:
    return deck.model if isinstance(deck, LoadedDeck) else deck
