"""Indices, their convergence and the metrics' distributions from a sensitivity study's cases.

The estimators are SALib's: Sobol' first-order and total indices by Saltelli's design
(Saltelli et al. 2010, Comput. Phys. Commun. 181:259, first order; Jansen's estimator of the
total index, their Table 2), with bootstrap confidence intervals; Morris' elementary effects
(Morris 1991, Technometrics 33:161) with Campolongo et al.'s (2007) mu* and its bootstrap
interval. Elementary effects are taken in probability (the unit hypercube), so that mu* of
inputs with different units and distributions compare.

Every function here takes plain arrays (cases in sample order) and returns rows of plain
values; :mod:`camtrain.study.sensitivity_output` writes them.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.metric_rows import case_metric

#: probabilities of the distribution table
QUANTILES = (0.05, 0.25, 0.5, 0.75, 0.95)
#: the smallest base sample (Sobol) or number of trajectories (Morris) of the convergence ladder
LADDER_START = 8


def metric_values(records: list[dict], metrics: list[str]) -> dict[str, tuple[str, np.ndarray]]:
    """Each metric over the cases in case order (its unit; NaN where a case is not ok)."""
    ordered = sorted(records, key=lambda r: r["index"])
    out = {}
    for name in metrics:
        cells = [case_metric(r["metrics"], name) for r in ordered]
        unit = next((cell[1] for cell in cells if cell is not None), "")
        values = [cell[0] if r["status"] == "ok" and cell is not None else math.nan
                  for r, cell in zip(ordered, cells, strict=True)]
        out[name] = (unit, np.asarray(values, dtype=float))
    return out


def varying_metrics(records: list[dict]) -> list[str]:
    """The metrics that change over the ok cases (the default of a study), in sweep order."""
    from camtrain.study.sweep_output import metric_order

    names = metric_order(records)
    out = []
    for name, (_, y) in metric_values(records, names).items():
        y = y[np.isfinite(y)]
        if y.size > 1 and np.ptp(y) > 1e-12 * np.max(np.abs(y)):
            out.append(name)
    return out


def why_not(y: np.ndarray) -> str:
    """Why a metric's indices cannot be estimated ('' when they can)."""
    bad = int(np.count_nonzero(~np.isfinite(y)))
    if bad:
        return (f"{bad} of {y.size} cases give no value (not ok, or undefined): the estimators "
                "need every case; narrow the ranges")
    if not np.ptp(y) > 1e-12 * np.max(np.abs(y)):
        return "constant over the sample"
    return ""


def sobol_rows(prob: dict, y: np.ndarray, conf: float, seed: int) -> list[dict]:
    """First-order and total Sobol' indices of one metric with their confidence half-widths."""
    from SALib.analyze import sobol

    si = sobol.analyze(prob, y, calc_second_order=False, conf_level=conf, seed=seed)
    return [{"input": name, "S1": float(si["S1"][j]), "S1_conf": float(si["S1_conf"][j]),
             "ST": float(si["ST"][j]), "ST_conf": float(si["ST_conf"][j])}
            for j, name in enumerate(prob["names"])]


def morris_rows(prob: dict, unit: np.ndarray, y: np.ndarray, conf: float, seed: int,
                levels: int) -> list[dict]:
    """Morris mu, mu* (with its confidence half-width) and sigma of one metric, per unit of
    probability of each input."""
    from SALib.analyze import morris

    si = morris.analyze(prob, unit, y, conf_level=conf, num_levels=levels, seed=seed)
    return [{"input": name, "mu": float(si["mu"][j]), "mu_star": float(si["mu_star"][j]),
             "mu_star_conf": float(si["mu_star_conf"][j]), "sigma": float(si["sigma"][j])}
            for j, name in enumerate(prob["names"])]


def ladder(samples: int) -> list[int]:
    """Base samples (or trajectories) of the convergence study: powers of two up to the full
    sample, which is always the last rung."""
    rungs, n = [], LADDER_START
    while n < samples:
        rungs.append(n)
        n *= 2
    return rungs + [samples]


def indices(method: str, prob: dict, unit: np.ndarray, y: np.ndarray, samples: int,
            conf: float, seed: int, levels: int) -> list[dict]:
    """The indices of one metric from the first ``samples`` base samples (or trajectories)."""
    d = prob["num_vars"]
    if method == "sobol":
        rows = samples * (d + 2)
        return sobol_rows(prob, y[:rows], conf, seed)
    rows = samples * (d + 1)
    return morris_rows(prob, unit[:rows], y[:rows], conf, seed, levels)


def convergence(method: str, prob: dict, unit: np.ndarray, y: np.ndarray, samples: int,
                conf: float, seed: int, levels: int) -> list[dict]:
    """The indices against the number of samples (each rung the leading part of the sample),
    with the model evaluations each rung costs."""
    per = prob["num_vars"] + (2 if method == "sobol" else 1)
    out = []
    for n in ladder(samples):
        for row in indices(method, prob, unit, y, n, conf, seed, levels):
            out.append({"samples": n, "evaluations": n * per, **row})
    return out


def independent_rows(method: str, d: int, cases: int) -> np.ndarray:
    """Rows of the sample that are independent draws of the inputs' distribution: Saltelli's
    matrices A and B (the mixed rows repeat their coordinates); every point of the Morris
    trajectories (on its grid of levels)."""
    if method == "sobol":
        step = d + 2
        rows = np.arange(cases)
        return rows[(rows % step == 0) | (rows % step == step - 1)]
    return np.arange(cases)


def distribution_row(y: np.ndarray) -> dict:
    """Mean, standard deviation, quantiles and extremes of one metric's values."""
    y = y[np.isfinite(y)]
    if y.size == 0:
        return {"cases": 0}
    q = np.quantile(y, QUANTILES)
    return {"cases": int(y.size), "mean": float(y.mean()),
            "std": float(y.std(ddof=1)) if y.size > 1 else 0.0,
            **{f"p{round(100 * p):02d}": float(v) for p, v in zip(QUANTILES, q, strict=True)},
            "min": float(y.min()), "max": float(y.max())}
