"""Trend tables in the manner of Ball's Tables 5.1-5.3: does a metric rise or fall with a parameter?

Only cases that ran normally (status ok) count: Ball cut his curves at valve bounce and at the
geometry limits, and so do we.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from camtrain.metric_rows import case_metric

RISES, FALLS, CONSTANT, NON_MONOTONE, UNKNOWN = "rises", "falls", "constant", "non-monotone", "n/a"
SYMBOLS = {RISES: "↑", FALLS: "↓", CONSTANT: "–", NON_MONOTONE: "↕", UNKNOWN: "?"}


@dataclass(frozen=True)
class Trend:
    """Direction of one metric against one parameter; ``detail`` spells out a non-monotone shape."""

    metric: str
    parameter: str
    trend: str
    detail: str = ""
    points: int = 0


#: A change counts only above this many standard deviations of a step of pure scatter.
NOISE_SIGMAS = 3.0


def scatter(xs: list[float], ys: list[float]) -> float:
    """The sweep's own scatter of ys about a smooth line: the rms residual of a least-squares
    quadratic in x (n - 3 degrees of freedom); 0 with fewer than five points.

    A metric read off the angle grid (a minimum film, a peak stress at a sampled angle) jitters
    from case to case by up to the grid step's effect; a quadratic follows any physical trend
    over a sweep's range but not that zig-zag, so its residual measures the noise.
    """
    n = len(xs)
    if n < 5:
        return 0.0
    import numpy as np

    x = np.asarray(xs, dtype=float)
    x = (x - x.mean()) / (np.ptp(x) or 1.0)
    y = np.asarray(ys, dtype=float)
    resid = y - np.polyval(np.polyfit(x, y, 2), x)
    return float(math.sqrt(float(resid @ resid) / (n - 3)))


def noise_threshold(xs: list[float], ys: list[float], rtol: float = 1e-6) -> float:
    """Smallest change of ys read as a trend: ``NOISE_SIGMAS`` x sqrt(2) x the scatter (a
    difference of two noisy values), and never below ``rtol`` x the largest |y|."""
    floor = rtol * max((abs(v) for v in ys), default=0.0)
    return max(floor, NOISE_SIGMAS * math.sqrt(2.0) * scatter(xs, ys))


def classify(xs: list[float], ys: list[float], rtol: float = 1e-6) -> tuple[str, str]:
    """(trend, detail) of ys against increasing xs.

    A move counts when ys has changed by more than the noise threshold (``noise_threshold``:
    the sweep's own scatter about a quadratic, or ``rtol`` x the largest |y|) since the last
    move that counted, so neither numerical noise nor grid zig-zag reads as a trend, while a
    slow steady change still does. A metric the parameter does not affect comes out 'constant';
    a non-monotone series gets its sequence of runs as detail, e.g. 'falls then rises'.
    """
    pts = sorted((x, y) for x, y in zip(xs, ys, strict=True) if math.isfinite(y))
    if len(pts) < 2:
        return UNKNOWN, "fewer than two finished cases"
    values = [y for _, y in pts]
    tol = noise_threshold([x for x, _ in pts], values, rtol)
    runs: list[str] = []
    anchor = values[0]
    for b in values[1:]:
        step = RISES if b - anchor > tol else FALLS if anchor - b > tol else None
        if step is None:
            continue
        anchor = b
        if not runs or runs[-1] != step:
            runs.append(step)
    if not runs:
        return CONSTANT, ""
    if len(runs) == 1:
        return runs[0], ""
    return NON_MONOTONE, " then ".join(runs)


def _lines(records: list[dict], param: str, others: list[str]) -> list[list[dict]]:
    """Group ok records into lines along ``param`` with every other parameter held fixed."""
    groups: dict[tuple, list[dict]] = {}
    for r in records:
        key = tuple(r["values"][o] for o in others)
        groups.setdefault(key, []).append(r)
    return list(groups.values())


def trend_table(records: list[dict], params: list[str], metrics: list[str],
                rtol: float = 1e-6, zipped: bool = False) -> list[Trend]:
    """One Trend per (metric, parameter). In a grid, each line along the parameter is classified;
    the trend is theirs if they agree, else non-monotone ('differs along the grid'). Zipped
    parameters move together, so all cases form one line."""
    ok = [r for r in records if r["status"] == "ok"]
    out = []
    for param in params:
        others = [p for p in params if p != param]
        lines = [ok] if zipped else _lines(ok, param, others)
        for metric in metrics:
            found = []
            for line in lines:
                got = [(r["values"][param], case_metric(r["metrics"], metric)) for r in line]
                xs = [x for x, m in got if m is not None]
                ys = [m[0] for _, m in got if m is not None]
                found.append(classify(xs, ys, rtol) + (len(xs),))
            found = [f for f in found if f[0] != UNKNOWN] or found or [(UNKNOWN, "", 0)]
            kinds = {f[:2] for f in found}
            n = sum(f[2] for f in found)
            if len(kinds) == 1:
                trend, detail = kinds.pop()
            else:
                trend, detail = NON_MONOTONE, "differs along the grid"
            out.append(Trend(metric, param, trend, detail, n))
    return out


def trends_markdown(trends: list[Trend], params: list[str], metrics: list[str],
                    units: dict[str, str]) -> str:
    """A metric x parameter table with arrows, like Ball's Tables 5.1-5.3 (↑ rises as the
    parameter increases, ↓ falls, – unaffected, ↕ non-monotone, ? too few cases)."""
    by = {(t.metric, t.parameter): t for t in trends}
    lines = ["| metric | " + " | ".join(f"{p} ↑" for p in params) + " |",
             "|---|" + "---|" * len(params)]
    for m in metrics:
        cells = []
        for p in params:
            t = by[(m, p)]
            cells.append(SYMBOLS[t.trend] + (f" ({t.detail})" if t.detail else ""))
        lines.append(f"| {m} [{units.get(m, '-')}] | " + " | ".join(cells) + " |")
    legend = ("\n↑ rises as the parameter increases, ↓ falls, – unaffected, ↕ non-monotone, "
              "? fewer than two finished cases. Only cases with status ok count. A change counts "
              f"only above the noise threshold: {NOISE_SIGMAS:g} x sqrt(2) x the rms scatter of "
              "the metric about a quadratic fit along the parameter (5 or more cases; this is "
              "the jitter of values read off the angle grid), and at least 1e-6 of its "
              "largest value.\n")
    return "\n".join(lines) + "\n" + legend
