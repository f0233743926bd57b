"""Regenerate the golden files of every shipped deck, and show what changed.

    PYTHONPATH=. python -m tests.golden.regenerate            # review the differences only
    PYTHONPATH=. python -m tests.golden.regenerate --write    # then write the new files

The regeneration compiles every kernel into an empty, temporary cache (a stale cached kernel would
otherwise pin numbers a clean checkout does not compute); ``--reuse-cache`` skips that.

Each deck ``decks/<name>.toml``, and each variant in :data:`VARIANTS` (a shipped deck with a few
fields changed: the conventions the literature tests discuss), has two files in
``tests/golden/data``: ``<name>.json`` (plan, metrics with units and angles, column units and
descriptions, warnings: readable and diffable with git) and ``<name>.npz`` (the per-angle
columns at full precision). These are regression files, not validation: they pin what camtrain
computed when they were written, so a change of any number is seen and must be explained in the
commit that regenerates them.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
DECKS = ROOT / "decks"
DATA = Path(__file__).resolve().parent / "data"

#: relative tolerance of the comparison (issue: same numbers as before the rebuild to 1e-9). The
#: files are written with the newest numpy/scipy; `make test-oldest` compares them on the declared
#: minimum versions, whose different round-off reaches 3e-9 in the iteratively converged transient
#: film's squeeze velocity, and sets CAMTRAIN_GOLDEN_RTOL=1e-8 there (the files stay the same)
RTOL = float(os.environ.get("CAMTRAIN_GOLDEN_RTOL", "1e-9"))
#: values this far below a column's largest magnitude are compared absolutely (round-off near 0)
FLOOR = 1e-12
#: other library versions than the files were written with (`make test-oldest`)
OTHER_VERSIONS = "CAMTRAIN_GOLDEN_RTOL" in os.environ
#: decks whose result is a march stopped at a convergence tolerance, not a fixed sequence of
#: operations: deck -> (that tolerance, residual metrics). Their contact changes and active sets
#: are decided by comparisons, so another library's round-off can move where the march stops
#: within the tolerance (measured on the declared minimum versions: the two-way coupled camshaft,
#: coupling_tolerance 1e-4, lands within 3.6e-5 of each column's largest value and 1.3e-6 of each
#: metric). On other versions they are compared to their tolerance against each column's largest
#: magnitude, without the residual itself; on the versions the files were written with, to RTOL.
CONVERGED: dict[str, tuple[float, tuple[str, ...]]] = {
    "zeta_intake_camshaft_coupled": (1e-4, ("coupling_change",)),
}


#: name -> (shipped deck, changed fields as {section: {field: value}} in deck units)
VARIANTS: dict[str, tuple[str, dict]] = {
    "desmo_rig+mean_entrainment": ("desmo_rig", {"tribology": {"entrainment": "mean"}}),
    "harrison_flat+mean_entrainment": ("harrison_flat", {"tribology": {"entrainment": "mean"}}),
    "pinto_finger+zero_clearance": ("pinto_finger", {"clearance": {"valve_clearance": 0.0}}),
    "pinto_finger_improved+zero_clearance": ("pinto_finger_improved",
                                             {"clearance": {"valve_clearance": 0.0}}),
}


def deck_paths() -> list[Path]:
    """Every shipped deck, then every variant (as ``decks/<variant name>.toml``)."""
    return sorted(DECKS.glob("*.toml")) + [DECKS / f"{v}.toml" for v in VARIANTS]


def variant_model(name: str):
    """The validated model of a variant: its deck with the changed fields."""
    import tomllib

    from camtrain.deck.load import validate

    base, changes = VARIANTS[name]
    raw = tomllib.loads((DECKS / f"{base}.toml").read_text(encoding="utf-8"))
    for section, fields in changes.items():
        raw.setdefault(section, {}).update(fields)
    return validate(raw, name, DECKS)


def snapshot(path: Path, result=None) -> tuple[dict, dict[str, np.ndarray]]:
    """Run one deck (unless its ``result`` is given); its readable part (dict) and its
    per-angle columns (name -> array)."""
    import camtrain.api as ct

    if result is None:
        result = ct.run(variant_model(path.stem) if path.stem in VARIANTS else path)
    flat = flat_columns(result)
    meta = {
        "deck": path.name,
        "plan": list(result.plan.chosen),
        "metrics": {name: {"value": m.value, "unit": m.unit,
                           "angle": m.angle} for name, m in flat_metrics(result).items()},
        "columns": {name: {"unit": unit, "description": desc, "size": int(values.size)}
                    for name, (values, unit, desc) in flat.items()},
        "warnings": list(result.warnings),
    }
    arrays = {name: np.asarray(values, dtype=float) for name, (values, _, _) in flat.items()}
    return meta, arrays


def flat_columns(result) -> dict[str, tuple[np.ndarray, str, str]]:
    """Every per-angle column under its flat output name (as in cycle.csv)."""
    return {name: (c.values, c.unit, c.description) for name, c in result.columns.items()}


def flat_metrics(result) -> dict:
    return dict(result.metrics)


def load(name: str) -> tuple[dict, dict[str, np.ndarray]]:
    meta = json.loads((DATA / f"{name}.json").read_text())
    with np.load(DATA / f"{name}.npz") as z:
        arrays = {k: z[k] for k in z.files}
    return meta, arrays


def close(a, b, rtol: float = RTOL, floor: float = FLOOR) -> np.ndarray:
    """Elementwise: |a - b| <= rtol max(|b|, floor max|b|) (NaN equal to NaN)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    scale = np.nanmax(np.abs(b)) if b.size and np.any(np.isfinite(b)) else 0.0
    tol = rtol * np.maximum(np.abs(b), floor * scale)
    same = (a == b) | (np.abs(a - b) <= tol) | (np.isnan(a) & np.isnan(b))
    return same


def _round_off_harmonics(metrics: dict) -> dict[str, float]:
    """Torque harmonics that are round-off (amplitude <= FLOOR x the largest order of the same
    result, e.g. the odd orders of a four-cylinder camshaft): name -> the amplitude bound.

    Their amplitude is checked only to stay below that bound and their phase not at all: both
    change with the numpy/BLAS release (make test-oldest), the physics does not."""
    import re

    out = {}
    families: dict[str, list[str]] = {}
    for k in metrics:
        m = re.fullmatch(r"(.*order_)\d+", k)
        if m:
            families.setdefault(m.group(1), []).append(k)
    for names in families.values():
        values = [abs(metrics[k]["value"] or 0.0) for k in names]
        bound = FLOOR * max(values, default=0.0)
        for k, v in zip(names, values, strict=True):
            if v <= bound:
                out[k] = bound
                out[f"{k}_phase"] = math.inf
    return out


def differences(name: str, meta: dict, arrays: dict[str, np.ndarray]) -> list[str]:
    """Human-readable differences between a fresh snapshot and the golden file of ``name``."""
    if not (DATA / f"{name}.json").exists():
        return [f"{name}: no golden file yet"]
    gold_meta, gold_arrays = load(name)
    out = []
    for key in ("plan", "warnings"):
        if meta[key] != gold_meta[key]:
            out.append(f"{name}: {key} {gold_meta[key]!r} -> {meta[key]!r}")
    for kind, new, old in (("column", meta["columns"], gold_meta["columns"]),
                           ("metric", meta["metrics"], gold_meta["metrics"])):
        for k in sorted(set(old) - set(new)):
            out.append(f"{name}: {kind} {k!r} is gone")
        for k in sorted(set(new) - set(old)):
            out.append(f"{name}: new {kind} {k!r}")
    noise = _round_off_harmonics(gold_meta["metrics"])
    rtol, floor, residuals = RTOL, FLOOR, ()
    if OTHER_VERSIONS and name in CONVERGED:
        rtol, residuals = CONVERGED[name]
        floor = 1.0
    for k in sorted(set(meta["metrics"]) & set(gold_meta["metrics"])):
        new, old = meta["metrics"][k], gold_meta["metrics"][k]
        if k in residuals:
            continue
        if k in noise:
            if abs(new["value"] or 0.0) > noise[k]:
                out.append(f"{name}: metric {k!r} value {old['value']!r} -> {new['value']!r} "
                           f"(was round-off, below {noise[k]:.3g})")
            continue
        if new["unit"] != old["unit"]:
            out.append(f"{name}: metric {k!r} unit {old['unit']} -> {new['unit']}")
        for part in ("value", "angle"):
            a, b = new[part], old[part]
            if (a is None) != (b is None) or (a is not None
                                              and not close(a, b, rtol, floor).all()):
                out.append(f"{name}: metric {k!r} {part} {b!r} -> {a!r}")
    for k in sorted(set(meta["columns"]) & set(gold_meta["columns"])):
        if meta["columns"][k]["unit"] != gold_meta["columns"][k]["unit"]:
            out.append(f"{name}: column {k!r} unit {gold_meta['columns'][k]['unit']} -> "
                       f"{meta['columns'][k]['unit']}")
        a, b = arrays[k], gold_arrays[k]
        if a.shape != b.shape:
            out.append(f"{name}: column {k!r} shape {b.shape} -> {a.shape}")
            continue
        bad = ~close(a, b, rtol, floor)
        if bad.any():
            rel = np.abs(a - b) / np.maximum(np.abs(b), 1e-300)
            out.append(f"{name}: column {k!r} differs at {int(bad.sum())} of {b.size} points "
                       f"(largest relative difference {np.nanmax(np.where(bad, rel, 0)):.3g})")
    return out


def write(name: str, meta: dict, arrays: dict[str, np.ndarray]) -> None:
    DATA.mkdir(parents=True, exist_ok=True)
    (DATA / f"{name}.json").write_text(json.dumps(meta, indent=1, sort_keys=False) + "\n")
    np.savez_compressed(DATA / f"{name}.npz", **arrays)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="write the new golden files")
    parser.add_argument("--reuse-cache", action="store_true",
                        help="use the compiled kernels already on disk (may be stale after an edit)")
    parser.add_argument("decks", nargs="*", help="deck names (default: every shipped deck)")
    args = parser.parse_args(argv)
    paths = [p for p in deck_paths() if not args.decks or p.stem in args.decks]
    changed = 0
    for path in paths:
        meta, arrays = snapshot(path)
        diff = differences(path.stem, meta, arrays)
        for line in diff:
            print(line)
        changed += bool(diff)
        if args.write and diff:
            write(path.stem, meta, arrays)
            print(f"wrote {path.stem}")
    print(f"{changed} of {len(paths)} decks differ from their golden files"
          + ("" if args.write or not changed else "; --write to accept after review"))
    return 0


def fresh_kernel_cache() -> None:
    """Run again in a new process whose compiled kernels start from an empty disk cache.

    numba keys a cached kernel by its own source file only: after an edit to a kernel it calls
    from another module, a cached caller still runs the old code. Golden files written from such a
    stale cache would pin numbers no clean checkout computes, so the regeneration always compiles
    afresh (``--reuse-cache`` skips this, for a quick look).
    """
    import subprocess
    import tempfile

    with tempfile.TemporaryDirectory(prefix="golden-kernels-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        argv = [a for a in sys.argv[1:] if a != "--reuse-cache"]
        command = [sys.executable, "-m", "tests.golden.regenerate", "--reuse-cache", *argv]
        sys.exit(subprocess.call(command, env=env, cwd=ROOT))


if __name__ == "__main__":
    if "--reuse-cache" not in sys.argv[1:]:
        fresh_kernel_cache()
    sys.exit(main())
