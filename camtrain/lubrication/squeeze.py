r"""Level 1 transient film: Teodorescu's film formula with the squeeze term, marched in time.

Teodorescu, Kushwaha, Rahnejat & Taraza (2005) eq. 5 (after Rahnejat 1984) gives the central
film of a finite line contact with entraining and squeeze action,

.. math:: h = F\,\exp(-96.775\,w_s), \qquad w_s = \dot h/u \quad\text{(eq. 6)},

where F is the steady film (w_s = 0) of :func:`camtrain.formulas.rahnejat_1984`. Solving eq. 5 for
the squeeze rate gives a first-order relaxation law (derived; the paper does not say how its
implicit formula is resolved):

.. math:: \dot h = -\frac{|u|}{96.775}\,\ln\frac{h}{F}

Where |u| is large the film follows F within a relaxation time 96.775 h/|u|; where the
entrainment passes through zero the rate vanishes and the film stays *trapped* at the value the
approach left, instead of falling to zero with F. Design choices (flagged in the docs):

* |u| is used through the reversal (the paper is silent);
* h0* = h0/R (the paper does not define h0*);
* the load exponent: printed +0.059, physically consistent -0.059 (the default; every EHL
  regression has a negative load exponent). :data:`LOAD_EXPONENTS` names both.

The march is implicit Euler (the law is stiff: relaxation lengths ~1e-3 rad on the flanks). Each
step solves h + k ln h = h_n + k ln F_{n+1}, k = |u| dt / 96.775, exactly through the Wright omega
function (h = k omega(C/k - ln k)), so the march costs one special-function call per angle and
the marched film satisfies eq. 5 with the backward-difference w_s to round-off.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from scipy.special import wrightomega

from camtrain.formulas import rahnejat_1984

__all__ = ["SQUEEZE_COEFFICIENT", "LOAD_EXPONENTS", "teodorescu_steady_film",
           "squeeze_ratio", "relaxation_step", "squeeze_film_march", "SqueezeFilm"]

#: Teodorescu et al. (2005) eq. 5: h ~ exp(-96.775 w_s).
SQUEEZE_COEFFICIENT = 96.775

#: The W* exponent of eq. 5: ``consistent`` (default, -0.059) or ``printed`` (+0.059 as printed).
LOAD_EXPONENTS = {"consistent": -0.059, "printed": +0.059}


def load_exponent(sign: str) -> float:
    """The W* exponent for the named option (``consistent`` or ``printed``)."""
    try:
        return LOAD_EXPONENTS[sign]
    except KeyError:
        raise ValueError(f"load exponent option {sign!r}: expected one of "
                         f"{', '.join(LOAD_EXPONENTS)}") from None


def teodorescu_steady_film(w, R, u, eta0, alpha, E_r, exponent: str = "consistent"):
    """Steady film F of eq. 5 (w_s = 0) [m]: 1.67 R G^0.421 U^0.541 W^(-/+0.059)."""
    return rahnejat_1984(w, R, u, eta0, alpha, E_r, squeeze_ratio=0.0,
                         load_exponent=load_exponent(exponent))


def squeeze_ratio(h_new, h_old, dt, u):
    """Squeeze-roll ratio w_s = (dh/dt)/|u| of eq. 6 from a backward difference (0 where u = 0)."""
    u = np.abs(np.asarray(u, dtype=float))
    rate = (np.asarray(h_new, dtype=float) - h_old) / dt
    return np.where(u > 0.0, rate / np.where(u > 0.0, u, 1.0), 0.0)


def relaxation_step(h_old: float, F_new: float, speed: float, dt: float) -> float:
    r"""One implicit-Euler step of dh/dt = -(|u|/96.775) ln(h/F) [m].

    Solves h + k ln h = h_old + k ln F_new with k = |u| dt / 96.775: h = k omega(C/k - ln k)
    (Wright omega, omega + ln omega = z, finite for any z). k = 0 (no entrainment) or
    F_new = 0 traps the film: h = h_old. An unbounded F_new (unloaded contact) also keeps h.
    """
    k = abs(speed) * dt / SQUEEZE_COEFFICIENT
    if k <= 1e-300 * h_old or not (0.0 < F_new < math.inf):
        return h_old
    z = h_old / k + math.log(F_new / k)
    return k * float(wrightomega(z).real)


class SqueezeFilm(NamedTuple):
    film: np.ndarray          #: marched film h [m] at each angle
    steady: np.ndarray        #: steady film F [m] (w_s = 0)
    squeeze_ratio: np.ndarray  #: w_s = (dh/dt)/|u| [-] (backward difference)
    cycles: int               #: cycles marched until the film repeated
    period_error: float       #: |h(start) - h(end)| / h(start) of the last cycle


def squeeze_film_march(theta, steady, u, omega, cycles_max: int = 5, period_tol: float = 1e-9,
                       squeeze: bool = True) -> SqueezeFilm:
    r"""March the level-1 film around a periodic cycle of cam angles (implicit Euler).

    Args:
        theta: ascending cam angles over one period [rad] (uniform or not; the end point
            theta[0] + 2 pi is implied and must not be repeated).
        steady: steady film F(theta) [m] (e.g. :func:`teodorescu_steady_film`); 0 where u = 0;
            non-finite (unloaded) angles keep the film.
        u: entrainment speed [m/s] (mean); only |u| enters.
        omega: cam speed [rad/s] (> 0); time step dt = dtheta / omega.
        cycles_max, period_tol: repeat whole cycles until the film at the first angle changes
            by less than ``period_tol`` (relative), at most ``cycles_max`` cycles.
        squeeze: False returns the steady film (the quasi-steady limit w_s = 0).

    Returns:
        :class:`SqueezeFilm`. The periodic cycle starts from F at theta[0].
    """
    theta = np.asarray(theta, dtype=float)
    F = np.asarray(steady, dtype=float)
    speed = np.abs(np.asarray(u, dtype=float))
    n = theta.size
    if not (F.shape == speed.shape == theta.shape and n >= 2):
        raise ValueError("theta, steady and u must be equal-length arrays (>= 2 angles)")
    if not omega > 0.0:
        raise ValueError(f"omega must be > 0 rad/s, got {omega}")
    dtheta = np.diff(theta, append=theta[0] + 2.0 * np.pi)
    if np.any(dtheta <= 0.0):
        raise ValueError("theta must ascend within one period")
    if not squeeze:
        return SqueezeFilm(F.copy(), F, np.zeros(n), 0, 0.0)
    dt = np.roll(dtheta, 1) / omega              # step that arrives at angle i
    good = np.isfinite(F) & (F > 0.0)
    start = F[0] if good[0] else float(np.nanmax(np.where(good, F, np.nan)))
    h = np.empty(n)
    F_l, s_l, dt_l = F.tolist(), speed.tolist(), dt.tolist()
    error, cycles = math.inf, 0
    while cycles < cycles_max and error > period_tol:
        h_prev = start
        for i in range(n):
            h_prev = relaxation_step(h_prev, F_l[i], s_l[i], dt_l[i])
            h[i] = h_prev
        cycles += 1
        # h[n-1] stepped once more to theta[0] + 2 pi closes the cycle
        end = relaxation_step(h[-1], F_l[0], s_l[0], dt_l[0])
        error = abs(end - h[0]) / h[0]
        start = h[-1]
    ws = squeeze_ratio(h, np.roll(h, 1), dt, speed)
    return SqueezeFilm(h, F, ws, cycles, float(error))
