"""Calibrate deck constants to measured data (`camtrain fit`): least squares, confidence
intervals and what the data cannot tell apart.

The residual of a data point is (camtrain - measured) / the rms of its quantity's data, so
that data sets in different units weigh alike; scipy's trust-region reflective least squares
(``scipy.optimize.least_squares``, within the bounds) minimises their sum of squares over the
constants, each scaled to its bounds. The Jacobian is a central difference whose runs go to the
executor together.

At the solution, with m points, p constants, s^2 = RSS / (m - p) and J the Jacobian in the
constants' units, the covariance is s^2 (J^T J)^-1 (the linearised regression, Bates & Watts
1988, Nonlinear Regression Analysis, eqs 2.7-2.8, 2.11; Seber & Wild 1989 §5.1) and a
constant's interval is value ± t(m - p, (1 + c)/2) sqrt(cov_ii). The singular values of the
Jacobian in relative terms (columns dr/d ln theta_j) tell which combinations of constants
the data fix: a singular value below ``UNIDENTIFIABLE`` times the largest marks a direction in
which the constants change and the prediction does not (Bates & Watts §2.2; two constants that
enter only as a product x^a y^b change the prediction along one such direction), and the
constants with weight in it are reported as not identifiable, with that combination.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from camtrain.study.fit_data import DataSet
from camtrain.study.fit_model import Constant, Predictor

#: relative singular value below which a direction of the constants is not identifiable
UNIDENTIFIABLE = 1e-3
#: a constant with at least this weight in such a direction is reported as not identifiable
WEIGHT = 0.1
#: pairs of constants at least this correlated are reported: the data barely tell them apart
CORRELATED = 0.95
#: central-difference step, as a fraction of each constant's bounds
STEP = 1e-4


@dataclass
class Fit:
    """The outcome of a fit, in the constants' deck units (residuals in SI and deck units)."""

    constants: list[Constant]
    start: np.ndarray
    value: np.ndarray
    half_width: np.ndarray
    confidence: float
    correlation: np.ndarray
    singular: np.ndarray          # relative singular values, largest first
    directions: np.ndarray        # rows: the constants' weights of each singular direction
    unidentifiable: list[str]
    combinations: list[str]
    before: list[np.ndarray]      # predictions at the start (SI), per (data set, quantity)
    after: list[np.ndarray]
    datasets: list[DataSet]
    rss: float
    points: int
    evaluations: int
    status: str
    at_bound: list[str] = field(default_factory=list)

    def poorly_determined(self) -> list[str]:
        """Identifiable constants whose interval is wider than their value."""
        return [c.name for c, v, h in zip(self.constants, self.value, self.half_width,
                                          strict=True)
                if c.name not in self.unidentifiable and h >= abs(v)]

    def correlated(self) -> list[tuple[str, str, float]]:
        """Pairs of identifiable constants whose estimates are correlated by at least
        ``CORRELATED`` (in magnitude): the data barely tell them apart."""
        names = [c.name for c in self.constants]
        return [(names[i], names[j], float(self.correlation[i, j]))
                for i in range(len(names)) for j in range(i + 1, len(names))
                if names[i] not in self.unidentifiable and names[j] not in self.unidentifiable
                and abs(self.correlation[i, j]) >= CORRELATED]

    def rows(self) -> list[dict]:
        """One row per constant: start, value, interval, identifiable."""
        return [{"constant": c.name, "path": c.param.path, "unit": c.param.unit,
                 "start": float(s), "value": float(v), "ci_low": float(v - h),
                 "ci_high": float(v + h), "half_width": float(h),
                 "identifiable": c.name not in self.unidentifiable,
                 "at_bound": c.name in self.at_bound}
                for c, s, v, h in zip(self.constants, self.start, self.value, self.half_width,
                                      strict=True)]


def _scaled(constants: list[Constant]):
    low = np.array([c.low for c in constants])
    span = np.array([c.high - c.low for c in constants])
    return low, span


def fit(predictor: Predictor, confidence: float = 0.95, progress=None) -> Fit:
    """Least squares of the predictor's constants against its data sets."""
    from scipy.optimize import least_squares

    constants = predictor.constants
    data = [q.si() for s in predictor.sources for q in s.data.series]
    scale = [float(np.sqrt(np.mean(d ** 2))) or 1.0 for d in data]
    low, span = _scaled(constants)
    theta = lambda x: low + span * np.asarray(x)  # noqa: E731 - the map from scaled to deck
    cache: dict[bytes, list[np.ndarray]] = {}
    count = [0]

    def residual_of(prediction: list[np.ndarray]) -> np.ndarray:
        return np.concatenate([(p - d) / s for p, d, s in zip(prediction, data, scale,
                                                              strict=True)])

    def predict(xs: list[np.ndarray]) -> list[list[np.ndarray]]:
        missing = [x for x in xs if x.tobytes() not in cache]
        if missing:
            for x, p in zip(missing, predictor.predict([theta(x) for x in missing]), strict=True):
                cache[x.tobytes()] = p
            count[0] += len(missing)
            if progress:
                progress(count[0])
        return [cache[x.tobytes()] for x in xs]

    def fun(x):
        return residual_of(predict([np.asarray(x, dtype=float)])[0])

    def jac(x):
        # central differences (one-sided at a bound): second-order accurate, and a step large
        # enough to stand above the tolerance of iterated loads
        x = np.asarray(x, dtype=float)
        lows, highs = [], []
        for j in range(x.size):
            lo, hi = x.copy(), x.copy()
            lo[j], hi[j] = max(x[j] - STEP, 0.0), min(x[j] + STEP, 1.0)
            lows.append(lo)
            highs.append(hi)
        runs = predict([*lows, *highs])
        return np.column_stack([(residual_of(runs[x.size + j]) - residual_of(runs[j]))
                                / (highs[j][j] - lows[j][j]) for j in range(x.size)])

    x0 = np.clip((np.array([c.param.datum for c in constants]) - low) / span, 0.0, 1.0)
    before = predict([x0])[0]
    sol = least_squares(fun, x0, jac=jac, bounds=(0.0, 1.0), method="trf", x_scale="jac")
    J = jac(sol.x) / span                      # d residual / d constant (deck units)
    out = _statistics(J, sol.fun, theta(sol.x), confidence, constants)
    at_bound = [c.name for c, b in zip(constants, sol.active_mask, strict=True) if b != 0]
    return Fit(constants, theta(x0), theta(sol.x), confidence=confidence,
               before=before, after=predict([sol.x])[0], datasets=[s.data for s in
                                                                   predictor.sources],
               rss=float(sol.fun @ sol.fun), points=sol.fun.size, evaluations=count[0],
               status=sol.message, at_bound=at_bound, **out)


def _statistics(J: np.ndarray, r: np.ndarray, value: np.ndarray, confidence: float,
                constants: list[Constant]) -> dict:
    """Intervals, correlations and identifiability from the Jacobian at the solution."""
    from scipy import stats

    m, p = J.shape
    dof = max(m - p, 1)
    s2 = float(r @ r) / dof
    _, sv, vt = np.linalg.svd(J, full_matrices=False)
    tiny = sv <= sv[0] * 1e-12
    inv = np.where(tiny, 0.0, 1.0 / np.where(tiny, 1.0, sv) ** 2)
    cov = (vt.T * inv) @ vt * s2
    half = stats.t.ppf(0.5 + confidence / 2.0, dof) * np.sqrt(np.diag(cov))
    # the relative Jacobian: columns d r / d ln theta, so that constants of any unit compare
    _, rel, directions = np.linalg.svd(J * np.abs(value), full_matrices=False)
    rel = rel / rel[0] if rel[0] > 0 else rel
    names = [c.name for c in constants]
    bad: list[str] = []
    combos: list[str] = []
    for k in np.nonzero(rel < UNIDENTIFIABLE)[0]:
        weights = directions[k]
        involved = [j for j in range(p) if abs(weights[j]) >= WEIGHT]
        bad += [names[j] for j in involved if names[j] not in bad]
        combos.append(_combination(names, weights, involved))
    for j, name in enumerate(names):
        if name in bad or tiny.any() and abs(vt[tiny][:, j]).max() >= WEIGHT:
            half[j] = np.inf
            if name not in bad:
                bad.append(name)
    sd = np.sqrt(np.diag(cov))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(sd, sd)
    return {"half_width": half, "correlation": corr, "singular": rel,
            "directions": directions, "unidentifiable": bad, "combinations": combos}


def _combination(names: list[str], weights: np.ndarray, involved: list[int]) -> str:
    """What the data do fix when the constants may move along ``weights`` (in ln theta)
    unseen: for two constants, the product x^a y^b with (a, b) orthogonal to the direction."""
    if len(involved) == 2:
        i, j = involved
        a, b = weights[j], -weights[i]      # a w_i + b w_j = 0: ln(x^a y^b) is unchanged
        if a < 0:
            a, b = -a, -b
        return f"{names[i]}^{a / max(abs(a), abs(b)):.3g} · {names[j]}^{b / max(abs(a), abs(b)):.3g}"
    return " + ".join(f"{weights[j]:+.3g} ln {names[j]}" for j in involved) + \
        " (this combination is not fixed by the data)"
