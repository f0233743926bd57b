"""The workshop leak-down test, marched with the chamber's own step: a constant load on the
plunger, the time over a set travel (compared with :func:`.element.leakdown_time`)."""
from __future__ import annotations

import math

import numpy as np
from numba import njit

from camtrain.dynamics.hla.chamber import (
    chamber_advance,
    chamber_start,
    chamber_step,
    hydraulic_record,
)
from camtrain.dynamics.hla.element import LashAdjuster, leakdown_time


def leakdown_test(adj: LashAdjuster, load: float = 222.0, travel: float = 1.0e-3,
                  start: float = 0.1e-3, per_period: float = 4.0):
    """The workshop leak-down test, marched: the plunger at its full extension, the chamber, the
    reservoir and the check valve's supply at atmospheric pressure, a constant ``load`` [N]
    raised linearly over the first 200 periods of the loaded chamber's oscillation (the tester's
    ram set down gently: a sudden load would ring the plunger on its chamber, nearly undamped)
    and then held (the mass, the spring, the compressible chamber, the leak and the check valve
    of the module docstring). The plunger by the Newmark average acceleration, the chamber by
    :func:`chamber_step` (the train's own step), at 1/20 of that period over the first 400
    periods, then at 1/``per_period`` of it. Returns (time from ``start`` to ``start +
    travel`` of collapse [s], the time at the start mark [s], the chamber pressure at the end
    mark [Pa])."""
    from dataclasses import replace

    adj = replace(adj, supply_pressure=0.0, rest_extension=adj.stroke)
    loaded = replace(adj, rest_extension=adj.stroke - start)
    k = loaded.stiffness((load - adj.spring_preload) / adj.area)
    period = 2.0 * math.pi * math.sqrt(adj.plunger_mass / k)
    estimate = leakdown_time(adj, load, travel, start)
    marks = np.array([start, start + travel])
    out = np.zeros(3)
    plunger = np.array([adj.plunger_mass, adj.spring_rate, adj.spring_preload, load])
    if estimate / (period / per_period) > 5e7:
        raise ValueError(f"the leak-down would take {estimate:.3g} s, more than 5e7 steps of "
                         f"the plunger's period {period:.3g} s")
    record = hydraulic_record(adj, 0, 0, 1.0, 0.0)
    _leakdown_march(record, chamber_start(record, 0.0), plunger,
                    np.array([period / 20.0, 400.0 * period, period / per_period,
                              200.0 * period]), marks, out)
    if not out[1] > out[0] > 0.0:
        raise ValueError("the plunger did not travel the set distance under the load")
    return out[1] - out[0], out[0], out[2]


@njit(cache=True)
def _leakdown_march(hr, hp, plunger, steps, marks, out):
    """The loaded plunger (``plunger`` = mass, spring rate, spring preload at full extension,
    load) over time steps ``steps`` = (fast step, fast span, slow step, load ramp; 0: sudden),
    until its collapse passes both ``marks``; ``out`` = times at the marks, pressure at the
    second; ``hp`` the chamber's state (records.HP_SLOTS), updated."""
    m, k_s, f_s0, load = plunger[0], plunger[1], plunger[2], plunger[3]
    x, xd, acc, t = hr.stroke, 0.0, 0.0, 0.0
    sudden = steps[3] <= 0.0   # no ramp: the full load from t = 0 (the stop takes no pull)
    acc = min(f_s0 - load, 0.0) / m if sudden else 0.0
    found = 0
    for _ in range(100_000_000):
        h = steps[0] if t < steps[1] else steps[2]
        x_pred = x + h * xd + 0.25 * h * h * acc
        share = 1.0 if sudden else min((t + h) / steps[3], 1.0)
        rest = f_s0 + k_s * (hr.stroke - x_pred) - load * share
        eff = m + 0.25 * h * h * k_s
        sigma = 0.25 * h * h / eff
        big_x = x_pred + sigma * rest
        big_xd = xd + 0.5 * h * acc + 0.5 * h * rest / eff
        p1, force, qin, qout = chamber_step(hr, hp, x, big_x, big_xd, sigma, h)
        a1 = (force + rest) / eff
        x1 = x_pred + 0.25 * h * h * a1
        while found < 2 and hr.stroke - x1 >= marks[found]:
            frac = (marks[found] - (hr.stroke - x)) / (x - x1)
            out[found] = t + frac * h
            found += 1
        if found == 2:
            out[2] = p1
            return
        x, xd, acc, t = x1, xd + 0.5 * h * (acc + a1), a1, t + h
        chamber_advance(hr, hp, p1, qin, qout, h, hp)
