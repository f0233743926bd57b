"""Everything a run writes, staged then moved into place so a failed run leaves no result behind.

All files are first written into a hidden staging directory beside the output directory. Only
when every file (tables, report, plots) exists are they moved in, summary.json last: a directory
with a summary.json always holds a complete result, and a crash part-way leaves the previous
result (if any) untouched.
"""
from __future__ import annotations

import gc
import json
import os
import shutil
import tempfile
from collections.abc import Callable
from contextlib import contextmanager
from pathlib import Path

from camtrain.deck.load import LoadedDeck
from camtrain.report.header import speed_rpm
from camtrain.report.limits import Check, evaluate
from camtrain.report.tables import csv_text, summary_dict
from camtrain.report.text import report_text
from camtrain.result import Result


def check_limits(result: Result, loaded: LoadedDeck) -> list[Check]:
    """The deck's [limits] evaluated against the run (empty when the deck sets none)."""
    deck = loaded.model
    return evaluate(getattr(deck, "limits", None), result, speed_rpm(deck))


def write_run(result: Result, loaded: LoadedDeck, out_dir: Path, wall_time: float, *,
              checks: list[Check] | None = None, plots: str = "sheets",
              progress: Callable[[str, int, int], None] | None = None,
              units: str = "deck") -> list[Path]:
    """Write cycle.csv, report.txt, plots and summary.json. ``plots``: "sheets" (PNG sheets),
    "pdf" (the sheets as PNG and PDF), "all" (also every panel alone, PNG and PDF) or "none".
    ``units``: the tables in the deck's units ("deck") or in SI ("si"); report and plots are for
    people and always in the deck's units."""
    out_dir = Path(out_dir)
    summary = json.dumps(summary_dict(result, loaded, wall_time, checks, units), indent=2,
                         allow_nan=False, ensure_ascii=False) + "\n"
    texts = {
        "report.txt": report_text(result, loaded.model, path=loaded.path, sha=loaded.sha256,
                                  checks=checks, wall_time=wall_time),
    }
    if result.columns:    # a run of single values (a bare engine's correlations) has no cycle
        texts["cycle.csv"] = csv_text(result, units=units)
    for axis in result.axes[1:]:   # columns on another grid (e.g. the piston's ring_angle)
        texts[f"cycle_{axis}.csv"] = csv_text(result, axis, units)
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}.staging-", dir=out_dir.parent))
    try:
        for name, text in texts.items():
            (stage / name).write_text(text, encoding="utf-8", newline="")
        if plots != "none":
            with _cyclic_gc_paused():
                from camtrain.report.sheets import PLOT_CHOICES, write_plots

                formats, single = PLOT_CHOICES[plots]
                write_plots(result, loaded.model, stage, single_panels=single,
                            formats=formats, sha=loaded.sha256, progress=progress)
        (stage / "summary.json").write_text(summary, encoding="utf-8")
        return _move_in(stage, out_dir)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


@contextmanager
def _cyclic_gc_paused():
    """No cyclic garbage collection while matplotlib is imported and the sheets are drawn: they
    allocate about a million short-lived objects, and every collection that triggers walks all
    the objects alive (the whole of matplotlib); a run's sheets then take ~5 % less CPU. What
    they leave in cycles is collected when collection resumes."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def write_staged(out_dir: Path, write: Callable[[Path], object]) -> list[Path]:
    """Call ``write(stage)`` on a staging directory beside ``out_dir``; move what it wrote into
    ``out_dir`` only when it returns (nothing is left behind on an error or Ctrl-C)."""
    out_dir = Path(out_dir)
    out_dir.parent.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=f".{out_dir.name}.staging-", dir=out_dir.parent))
    try:
        write(stage)
        return _move_in(stage, out_dir)
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def _move_in(stage: Path, out_dir: Path) -> list[Path]:
    from camtrain.interrupts import raise_if_interrupted

    raise_if_interrupted()      # a Ctrl-C that something swallowed while the files were drawn
    files = sorted(p for p in stage.rglob("*") if p.is_file())
    files.sort(key=lambda p: p.name == "summary.json")      # the completion mark goes last
    out_dir.mkdir(parents=True, exist_ok=True)
    old = out_dir / "summary.json"
    if old.exists():
        old.unlink()        # while files are replaced the directory must not look complete
    written = []
    for src in files:
        dst = out_dir / src.relative_to(stage)
        dst.parent.mkdir(parents=True, exist_ok=True)
        os.replace(src, dst)
        written.append(dst)
    return written
