"""Design limits of a deck ([limits]) checked against a run: metric, value, limit, angle.

Per-angle columns are preferred to scalar metrics, so a violation names the cam angle where it is
worst; film and λ limits look only where the cam and follower are in contact. A limit whose
quantity the run did not compute is reported as ``unavailable`` and fails the check: a CI gate
must never pass because a number was missing.
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from camtrain.catalogue import planned_products
from camtrain.report.findings import in_contact
from camtrain.result import Result

PASS, FAIL, UNAVAILABLE = "pass", "fail", "unavailable"


@dataclass(frozen=True)
class Check:
    limit: str            # deck key, e.g. "max_hertz"
    quantity: str         # what was measured
    kind: str             # "max" or "min"
    value: float | None   # in ``unit``
    bound: float          # the limit, in ``unit``
    unit: str
    angle_deg: float | None
    status: str
    note: str = ""

    @property
    def ok(self) -> bool:
        return self.status == PASS

    def text(self) -> str:
        where = "" if self.angle_deg is None else f" at {self.angle_deg:+.1f}° cam"
        rel = "≤" if self.kind == "max" else "≥"
        unit = "" if self.unit == "-" else f" {self.unit}"
        if self.status == UNAVAILABLE:
            return f"{self.limit}: {self.quantity} not computed ({self.note}); limit {rel} " \
                   f"{self.bound:g}{unit}"
        verdict = "ok" if self.ok else "VIOLATED"
        return (f"{self.limit}: {self.quantity} = {self.value:.4g}{unit}{where}; "
                f"limit {rel} {self.bound:g}{unit}: {verdict}")

    def as_dict(self) -> dict:
        return asdict(self)


def in_si(check: Check) -> Check:
    """The same check with its value and bound in SI (for ``--units si`` outputs)."""
    from dataclasses import replace

    from camtrain.units import UNITS

    factor, unit = UNITS[check.unit]
    value = None if check.value is None else check.value * factor
    return replace(check, value=value, bound=_clean(check.bound * factor), unit=unit)


def _clean(x: float) -> float:
    """A deck value brought back from SI without the float noise of the round trip
    (0.049999999999999996 -> 0.05): 12 significant digits are far beyond any deck's."""
    return float(f"{x:.12g}")


# deck key -> (quantity, kind, display unit, factor SI -> display, product, column, metric): the
# check reads the column or metric of the effect that makes ``product``, when the plan made it
SPECS = {
    "max_hertz": ("maximum Hertz stress", "max", "MPa", 1e-6, "ContactHertz", "hertz_pmax",
                  "hertz_max"),
    "min_film": ("minimum film thickness in contact", "min", "µm", 1e6, "ContactFilm",
                 "film_min", "film_min"),
    "min_film_at_max_lift": ("minimum film at maximum lift", "min", "µm", 1e6, "ContactFilm",
                             None, "film_min_at_max_lift"),
    "min_lambda": ("minimum λ in contact", "min", "-", 1.0, "ContactFilm", "lambda", None),
    "min_bounce_margin": ("margin below the valve-bounce speed", "min", "%", 100.0, None, None,
                          None),
    "max_power_loss": ("mean frictional power loss", "max", "W", 1.0, "CamTorque", None,
                       "power_loss_mean"),
    "max_load": ("maximum contact load", "max", "N", 1.0, "ContactLoad", "load", "load_max"),
    "max_friction_torque": ("peak friction torque", "max", "N·m", 1.0, "CamTorque",
                            "friction_torque", "friction_torque_peak"),
}


def evaluate(limits, result: Result, speed_rpm: float | None = None) -> list[Check]:
    """Check every limit the deck sets; ``limits`` is the deck's Limits section (SI) or None."""
    if limits is None:
        return []
    checks = []
    made = planned_products(result.plan)
    for key, (quantity, kind, unit, factor, product, column, metric) in SPECS.items():
        bound_si = getattr(limits, key, None)
        if bound_si is None:
            continue
        bound = _clean(bound_si * factor)
        if key == "min_bounce_margin":
            value, angle, note = _bounce_margin(result, speed_rpm)
        else:
            value, angle, note = _measure(result, kind, column if product in made else None,
                                          metric if product in made else None)
        if value is None:
            note = note or f"the run has no {_either(column, metric)}"
            checks.append(Check(key, quantity, kind, None, bound, unit, None, UNAVAILABLE, note))
            continue
        value = value * (1.0 if key == "min_bounce_margin" else factor)
        ok = value <= bound if kind == "max" else value >= bound
        checks.append(Check(key, quantity, kind, value, bound, unit,
                            None if angle is None else round(math.degrees(angle), 3),
                            PASS if ok else FAIL, note))
    return checks


def _measure(result: Result, kind: str, column: str | None, metric: str | None):
    """The worst value of ``column`` over the cycle (where the pair is in contact, for a
    lower bound), else the value of ``metric``; None for either the plan did not make."""
    if column:
        y = np.asarray(result[column], dtype=float)
        if kind == "max" and column == "friction_torque":
            y = np.abs(y)
        mask = ~np.isnan(y)  # an infinite value is the worst one, never skipped
        contact = in_contact(result)
        if kind == "min" and contact is not None:
            mask &= contact
        if mask.any():
            idx = np.flatnonzero(mask)
            i = idx[np.argmax(y[idx])] if kind == "max" else idx[np.argmin(y[idx])]
            return float(y[i]), float(result["cam_angle"][i]), ""
    m = result.metrics.get(metric) if metric else None   # NaN or unstated: not computed
    if m is not None and not math.isnan(m.value):
        return m.value, m.angle, ""
    return None, None, ""


def _either(column: str | None, metric: str | None) -> str:
    return " or ".join(f"'{n}'" for n in (column, metric) if n)


def _bounce_margin(result: Result, speed_rpm: float | None):
    m = result.metrics.get("bounce_speed")
    if m is None or speed_rpm is None or not math.isfinite(m.value) or m.value <= 0:
        return None, None, "the run has no 'bounce_speed' (needs the loads effect)"
    bounce = m.value if m.unit == "rpm" else m.value * 60.0 / (2.0 * math.pi)
    low = result.metrics.get("load_min")
    angle = low.angle if low is not None else m.angle
    return 100.0 * (1.0 - speed_rpm / bounce), angle, f"bounce at {bounce:.0f} rpm"


def violated(checks: list[Check]) -> list[Check]:
    return [c for c in checks if not c.ok]
