"""What the top floors make of every shipped deck: the accuracy knobs offered, the metrics the
accuracy study reads, the terminal's key results and (with ``--sheets``) the plot sheets written
and the panels each holds.

    PYTHONPATH=. python -m tests.report.declarations                    # show differences only
    PYTHONPATH=. python -m tests.report.declarations --write            # rewrite the fixture
    PYTHONPATH=. python -m tests.report.declarations --sheets [--write] # also run and draw

The fixture ``tests/report/data/declarations.json`` was first written by the code that chose
these by testing column and metric names (before the effects declared them); the declarations
must give the same, or the commit that rewrites it says why. Knobs, study metrics and key
results follow from each deck's plan and metric names, read from its golden file; the sheets
need the deck run and drawn (a few minutes: ``--sheets``), and tests/report/test_every_deck.py
compares them on its own run.
"""
from __future__ import annotations

import json
import sys
import tempfile
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
DECKS = ROOT / "decks"
GOLDEN = ROOT / "tests" / "golden" / "data"
FIXTURE = Path(__file__).resolve().parent / "data" / "declarations.json"
KEYS = ("plan", "sheets", "panels", "knobs", "accuracy_metrics", "key_metrics")


class StoredPlan:
    """A plan as a golden file stores it: the kind and the names of the effects that ran."""

    def __init__(self, kind: str, chosen: list[str]):
        from types import SimpleNamespace

        self.kind, self.chosen = kind, list(chosen)
        self.steps = [SimpleNamespace(effect=n, chosen=True, spec=None) for n in chosen]


def from_golden(name: str) -> dict:
    """Knobs, study metrics and key results of deck ``name`` from its golden file."""
    from camtrain.catalogue import declared_effects
    from camtrain.study.accuracy import relevant_knobs, studied_metrics

    raw = tomllib.loads((DECKS / f"{name}.toml").read_text())
    golden = json.loads((GOLDEN / f"{name}.json").read_text())
    plan = StoredPlan(raw.get("kind", "valve_train"), golden["plan"])
    produced = dict.fromkeys(golden["metrics"])
    declared = dict.fromkeys(m for spec in declared_effects(plan) for m in spec.key_metrics)
    return {"plan": plan.chosen, "knobs": sorted(relevant_knobs(raw, plan)),
            "accuracy_metrics": sorted(studied_metrics([produced], plan)),
            "key_metrics": [m for m in declared if m in produced]}


def axes_drawn(fig) -> list[str]:
    """The visible axes of a saved figure, each as ``title: lines, collections, images``
    (the panels a sheet holds and how many curves, fills or maps each drew)."""
    return [f"{ax.get_title()}: {len(ax.lines)}, {len(ax.collections)}, {len(ax.images)}"
            for ax in fig.axes if ax.get_visible()]


def sheets_written(name: str) -> tuple[list[str], dict[str, list[str]]]:
    """The PNG files a run of deck ``name`` writes with ``--plots sheets`` (by stem), and the
    panels each holds (:func:`axes_drawn`, recorded as every sheet is saved)."""
    from camtrain import api
    from camtrain.report import canvas

    loaded = api.load(DECKS / f"{name}.toml")
    panels: dict[str, list[str]] = {}
    save = canvas.save_sheet

    def recording(fig, stem, formats):
        panels[Path(stem).name] = axes_drawn(fig)
        return save(fig, stem, formats)

    canvas.save_sheet = recording
    try:
        with tempfile.TemporaryDirectory() as tmp:
            written = api.write(api.run(loaded), loaded, Path(tmp), 0.0, plots="sheets")
    finally:
        canvas.save_sheet = save
    return sorted(p.stem for p in written if p.suffix == ".png"), dict(sorted(panels.items()))


def main(argv: list[str]) -> int:
    old = json.loads(FIXTURE.read_text()) if FIXTURE.exists() else {}
    got = {}
    for path in sorted(DECKS.glob("*.toml")):
        got[path.stem] = from_golden(path.stem)
        if "--sheets" in argv:
            got[path.stem]["sheets"], got[path.stem]["panels"] = sheets_written(path.stem)
        else:
            for key in ("sheets", "panels"):
                got[path.stem][key] = old.get(path.stem, {}).get(key)
    changed = 0
    for name in sorted(set(got) | set(old)):
        for key in KEYS:
            a, b = old.get(name, {}).get(key), got.get(name, {}).get(key)
            if a != b:
                changed += 1
                print(f"{name}.{key}:\n  was {a}\n  now {b}")
    print(f"{changed} differences")
    if "--write" in argv:
        FIXTURE.write_text(json.dumps(got, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
