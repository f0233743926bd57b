"""The adjuster in the single train's Newmark march (:mod:`camtrain.dynamics._kernel`): the
four hook points the march calls, each once and guarded by ``Train.hla.on`` (the two of a
contact change, :func:`add_chamber_force` and :func:`sealed_restart`, guard themselves and
return at once without an adjuster: so the march's code without one ran as fast as before the
hooks moved here; with the guard in the march it measured 2-6 % slower, in-process A/B).

* :func:`add_chamber_force`: the chamber's force at a known pressure in the train's
  equilibrium (the acceleration a contact change restarts from);
* :func:`chamber_in_step`: the chamber's pressure and force solved together with the
  Newmark step, its end state written;
* :func:`sealed_restart`: a sealed incompressible chamber's pressure made consistent with the
  restarted acceleration (:mod:`.sealed`);
* :func:`sample_chamber`: the chamber's rows of the march's samples (``records.H_ROWS``).

All take the train's adjuster record (``records.Hydraulic``) and the plain arrays they read
(a record passed whole to a helper called every step costs more than its arithmetic:
docs/architecture.md, "Compiled kernels take typed records")."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.dynamics.hla.chamber import chamber_advance, chamber_step, extension, plunger_force
from camtrain.dynamics.hla.sealed import restart_force


@njit(cache=True)
def add_chamber_force(hla, u, p, a):
    """Add the adjuster's force at chamber pressure p to the node forces ``a`` (valve-referred:
    the plunger force times its motion ratio, body and plunger pushed apart); nothing without
    an adjuster."""
    if hla.on == 0:
        return
    f = hla.ratio * plunger_force(p, extension(u[hla.f], u[hla.q], hla), hla)
    a[hla.f] -= f
    a[hla.q] += f


@njit(cache=True)
def chamber_in_step(hla, hp, u, Ainv, A, h, pu, pv, a1, z, hp_end):
    """The adjuster's force in the Newmark step of length h: a1 += R F z (z = A^-1 (e_q - e_f),
    from the step's inverse ``Ainv`` or, for a sub-step (``Ainv`` empty), by solving with its
    matrix ``A``), the chamber's pressure and F solved together (:func:`.chamber.chamber_step`)
    with the plunger's end extension x1 = X + sigma F (``pu``, ``pv`` the predictor, ``a1`` the
    end acceleration without the chamber, ``z`` a work array); the chamber's end state
    (:func:`.chamber.chamber_advance`) into ``hp_end`` (``hp`` the state at the step's start)."""
    f, q = hla.f, hla.q
    if Ainv.shape[0] > 0:
        for i in range(z.size):
            z[i] = Ainv[i, q] - Ainv[i, f]
    else:
        z[:] = 0.0
        z[q], z[f] = 1.0, -1.0
        z[:] = np.linalg.solve(A, z.copy())
    s = z[q] - z[f]
    w_end = pu[f] - pu[q] + 0.25 * h * h * (a1[f] - a1[q])
    wd_end = pv[f] - pv[q] + 0.5 * h * (a1[f] - a1[q])
    big_x = hla.x_rest - hla.ratio * (w_end - hla.w0)
    sigma = hla.ratio * hla.ratio * 0.25 * h * h * s
    p1, force, qin, qout = chamber_step(hla, hp, extension(u[f], u[q], hla), big_x,
                                        -hla.ratio * wd_end, sigma, h)
    for i in range(z.size):
        a1[i] += hla.ratio * force * z[i]
    chamber_advance(hla, hp, p1, qin, qout, h, hp_end)


@njit(cache=True)
def sealed_restart(hla, hp, a, m):
    """At a contact change, a sealed incompressible chamber's pressure is the constraint's
    (:func:`.sealed.restart_force`): the accelerations ``a`` restarted from the equilibrium
    (lumped masses ``m``) take its force's change; any other chamber (or none) is left as it
    is."""
    if hla.on == 0:
        return
    f, q, r = hla.f, hla.q, hla.ratio
    force = restart_force(hla, hp, -r * (a[f] - a[q]), r * r * (1.0 / m[f] + 1.0 / m[q]))
    a[f] -= r * force / m[f]
    a[q] += r * force / m[q]


@njit(cache=True)
def sample_chamber(hla, hp, u, rows, r):
    """The chamber's sample ``r`` into ``rows`` (records.H_ROWS): pressure, flows, the plunger's
    extension and, where the rows and the state hold them, the volumes over the sample's
    interval (their accumulators restart) and the ball's lift."""
    rows[0, r], rows[1, r], rows[2, r] = hp[0], hp[1], hp[2]
    rows[3, r] = extension(u[hla.f], u[hla.q], hla)
    if rows.shape[0] > 6 and hp.size > 7:
        rows[4, r], rows[5, r], rows[6, r] = hp[4], hp[5], hp[6]
        hp[4] = 0.0
        hp[5] = 0.0
