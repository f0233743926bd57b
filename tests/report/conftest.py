"""Synthetic results for the report tests: a flat follower with a smooth lift, built here in SI.

The numbers are plausible, not physics: the report layer must draw and tabulate whatever columns
it is given, so the tests control exactly which columns exist.
"""
from __future__ import annotations

import numpy as np
import pytest

from camtrain.result import Result

OMEGA = 2500 * 2 * np.pi / 60
R_B = 0.018


def chain_plan(*effects: str, models: dict[str, str] | None = None):
    """The plan of a valve-train run of these effects (what the report reads the findings and
    sheets from); ``models``: effect -> the model its step records (Step.model), e.g.
    ``{"film": "squeeze"}``."""
    from camtrain.catalogue import KINDS
    from camtrain.plan import Plan, Step

    specs = {spec.name: spec for spec in KINDS["valve_train"].effects}
    models = models or {}
    return Plan("auto", tuple(Step(e, True, "synthetic", specs[e], models.get(e, ""))
                              for e in effects), "valve_train")


def synthetic(points: int = 360, *, level: str = "full", bounce: bool = False,
              concave: bool = False) -> Result:
    """level: 'lift' (lift law only), 'kinematics' (+ contact, no loads), 'full' (+ tribology).

    concave: a sharper lift whose nose radius goes negative (a cam that cannot be ground).
    """
    r = Result()
    th = np.linspace(-np.pi, np.pi, points, endpoint=False)
    half = np.radians(70.0 if concave else 80.0)
    s = np.clip(th / half, -1, 1)
    inside = np.abs(th) < half
    lift = np.where(inside, 0.0094 * np.cos(0.5 * np.pi * s) ** (4 if concave else 2), 0.0)
    d1 = np.gradient(lift, th)
    d2 = np.gradient(d1, th)
    d3 = np.gradient(d2, th)
    r.add_column("cam_angle", th, "rad", "cam angle from the maximum-lift position")
    r.add_column("lift", lift, "m", "lift at the valve")
    r.add_column("velocity", d1, "m/rad", "dl/dtheta")
    r.add_column("acceleration", d2, "m/rad^2", "d2l/dtheta2")
    r.add_column("jerk", d3, "m/rad^3", "d3l/dtheta3")
    r.add_metric("max_lift", lift.max(), "m", "maximum lift", 0.0)
    if level == "lift":
        return r
    rc = R_B + lift + d2
    ang = np.pi / 2 + th
    ux, uy, tx, ty = np.cos(ang), np.sin(ang), -np.sin(ang), np.cos(ang)
    r.add_column("contact_x", (R_B + lift) * ux + d1 * tx, "m", "contact point x, cam frame")
    r.add_column("contact_y", (R_B + lift) * uy + d1 * ty, "m", "contact point y, cam frame")
    r.add_column("eccentricity", d1, "m", "contact position on the follower face")
    r.add_column("cam_radius", rc, "m", "cam radius of curvature")
    r.add_column("equivalent_radius", rc, "m", "equivalent radius")
    vc, vf = OMEGA * rc, OMEGA * d2
    r.add_column("v_cam", vc, "m/s", "V_c")
    r.add_column("v_follower", vf, "m/s", "V_f")
    r.add_column("entrainment", 0.5 * (vc + vf), "m/s", "(V_c + V_f)/2")
    r.add_column("sliding", vc - vf, "m/s", "V_c - V_f")
    r.plan = chain_plan("kinematics")
    if level == "kinematics":
        return r
    r.plan = chain_plan("kinematics", "loads", "hertz", "film", "friction", "power")
    mass = 0.172 * (6.0 if bounce else 1.0)
    load = 38254 * (0.0064 + lift) + mass * OMEGA ** 2 * d2
    r.add_column("load", load, "N", "contact load")
    ue = np.abs(0.5 * (vc + vf))
    h = 2.0e-6 * (ue / 5.0) ** 0.7 * (np.abs(rc) / 0.02) ** 0.43
    h = np.where(load > 0, h, np.nan)
    r.add_column("film_min", h, "m", "minimum film")
    r.add_column("film_central", 1.3 * h, "m", "central film")
    r.add_column("lambda", h / 0.2e-6, "-", "h_min/sigma")
    p = 1e8 * np.sqrt(np.clip(load, 0, None) / np.abs(rc) / 1e5)
    r.add_column("hertz_pmax", p, "Pa", "max Hertz pressure")
    mu = np.where(h / 0.2e-6 < 1, 0.08, 0.02)
    f = mu * np.clip(load, 0, None)
    r.add_column("friction_coefficient", mu, "-", "mu")
    r.add_column("friction_force", f, "N", "friction force")
    torque = f * (R_B + lift)
    r.add_column("friction_torque", torque, "N*m", "friction torque")
    r.add_column("power_loss", torque * OMEGA, "W", "friction power")
    i = int(np.argmax(p))
    r.add_metric("hertz_max", p[i], "Pa", "largest Hertz pressure", th[i])
    r.add_metric("film_min", float(np.nanmin(h)), "m", "smallest film",
                 th[int(np.nanargmin(h))])
    r.add_metric("load_max", load.max(), "N", "largest load", th[int(np.argmax(load))])
    r.add_metric("load_min", load.min(), "N", "smallest load", th[int(np.argmin(load))])
    r.add_metric("power_loss_mean", float(np.mean(torque * OMEGA)), "W", "mean power")
    r.add_metric("bounce_speed", 3600.0 / np.sqrt(mass / 0.172), "rpm", "bounce speed")
    r.timings.update({"kinematics": 0.01, "loads": 0.002})
    r.warn("synthetic result for tests")
    return r


@pytest.fixture
def full_result() -> Result:
    return synthetic()
