"""Every lobe's hydraulic lash adjuster in the shaft-and-trains step (:mod:`._step`,
:mod:`._lowrank`, :mod:`._revolution`): the hook points the compiled march calls, each once and
guarded by ``System.hla.on``.

* :func:`add_chamber_forces`: every chamber's force at its pressure in the equilibrium the
  acceleration restarts from; :func:`restart_sealed`: a sealed incompressible chamber's
  pressure made consistent with it (:func:`camtrain.dynamics.hla.sealed.consistent_restart`);
* :func:`solve_chambers`: in the low-rank contact update, every chamber's force solved against
  its contact-corrected extension. Its force acts along (plunger - follower), a sixth
  coordinate of its lobe (``Layout.ipl``); each chamber is solved with the single train's
  :func:`camtrain.dynamics.hla.chamber_step` against the contact-corrected compliance of its
  extension; the lobes are coupled only through the shaft (the other lobes' chamber forces
  move a lobe's extension through its closed contact), so the chambers are swept lobe by lobe
  until their forces agree (Gauss-Seidel on the lobes' scalar equations);
* :func:`sample_chambers`: every chamber's pressure and plunger extension into the grid samples.

The start of the chambers and their way to the periodic state between revolutions are in
:mod:`.adjusters`."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.dynamics.hla.chamber import chamber_step, extension, plunger_force
from camtrain.dynamics.hla.sealed import consistent_restart

#: adjuster sweeps of a step at most, and their relative agreement of the chamber forces
HLA_SWEEPS = 50
HLA_TOL = 1e-12
#: coordinates per lobe in the low-rank update with an adjuster (x, y, phi, follower, valve,
#: plunger)
WIDTH = 6


@njit(cache=True)
def add_chamber_forces(hla, hp, q, ifol, ipl, r):
    """Every chamber's force at its pressure ``hp[j, 0]`` added to the forces ``r``: body
    (``ifol``) and plunger (``ipl``) pushed apart, ratio times the plunger force."""
    for j in range(ifol.size):
        f, p = ifol[j], ipl[j]
        force = hla.ratio * plunger_force(hp[j, 0], extension(q[f], q[p], hla), hla)
        r[f] -= force
        r[p] += force


@njit(cache=True)
def restart_sealed(hla, hp, acc, Minv, ifol, ipl):
    """Every sealed incompressible chamber restarted consistently with the accelerations
    ``acc`` from the equilibrium (``Minv`` the block-diagonal inverse of M)."""
    for j in range(ifol.size):
        consistent_restart(hla, hp[j], acc, Minv, ifol[j], ipl[j])


@njit(cache=True)
def sample_chambers(hla, hp, q, ifol, ipl, rows, g):
    """Every chamber's pressure and plunger extension into ``rows`` (lobes, 2, grid) at
    grid column g."""
    for j in range(ifol.size):
        rows[j, 0, g] = hp[j, 0]
        rows[j, 1, g] = extension(q[ifol[j]], q[ipl[j]], hla)


@njit(cache=True)
def _contact_forces(c, coef, lobe_of, Sinv, m, w):
    """The closed contacts' forces y = Sinv C c at the coordinates' values ``c``."""
    y = np.zeros(m)
    if m > 0:
        hc = np.zeros(m)
        for r in range(m):
            for e in range(w):
                hc[r] += coef[r, e] * c[w * lobe_of[r] + e]
        y = np.ascontiguousarray(Sinv) @ hc   # a slice of the workspace: BLAS wants it whole
    return y


@njit(cache=True)
def _less_contacts(c, r, G, coef, lobe_of, y, m, w):
    """c[r] less the closed contacts' correction (G C^T y)[r]."""
    total = 0.0
    for s in range(m):
        for f in range(w):
            if coef[s, f] != 0.0:
                total += G[r, w * lobe_of[s] + f] * coef[s, f] * y[s]
    return c[r] - total


@njit(cache=True)
def _corrected(xc, G, z, coef, lobe_of, Sinv, m, w):
    """The coordinates' values x_c + G z less the closed contacts' correction, and y (the
    contacts' forces) with it: c = (xc + G z) - G C^T y, y = Sinv C (xc + G z)."""
    nc = xc.size
    c = xc.copy()
    for r in range(nc):
        for b in range(nc):
            c[r] += G[r, b] * z[b]
    y = _contact_forces(c, coef, lobe_of, Sinv, m, w)
    if m > 0:
        for r in range(nc):
            c[r] = _less_contacts(c, r, G, coef, lobe_of, y, m, w)
    return c, y


@njit(cache=True)
def _extension_responses(G, coef, lobe_of, Sinv, m, lobes, R):
    """E[k, j]: lobe k's extension per unit plunger force of lobe j with the closed contacts'
    correction (:func:`_corrected` of the force pair R on (plunger, follower) alone, worked
    out only where E reads it: the force touches two columns of G, the extensions two rows
    per lobe; the same sums in the same order)."""
    nc, w = G.shape[0], WIDTH
    E = np.empty((lobes, lobes))
    c = np.empty(nc)
    for j in range(lobes):
        for r in range(nc):
            c[r] = G[r, w * j + 3] * -R + G[r, w * j + 5] * R
        y = _contact_forces(c, coef, lobe_of, Sinv, m, w)
        for k in range(lobes):
            plunger = _less_contacts(c, w * k + 5, G, coef, lobe_of, y, m, w)
            follower = _less_contacts(c, w * k + 3, G, coef, lobe_of, y, m, w)
            E[k, j] = R * (plunger - follower)
    return E


@njit(cache=True)
def solve_chambers(xc, G, z, coef, lobe_of, small, m, q, v, hp, dof, hla, a1, hp_end):
    """Every lobe's chamber force solved against its contact-corrected extension (the
    module's docstring): ``xc`` the coordinates' values A^-1 r, ``G`` the rows of A^-1 there,
    the closed contacts' rows (``coef``, ``lobe_of``, their small system ``small``, ``m`` of
    them), (q, v) and the chambers' states ``hp`` at the step's start, every lobe's state
    indices ``dof`` (lobes, WIDTH: the follower fourth, the plunger sixth), a1 = 2 / step; the
    forces R F on (plunger, follower) added to ``z``, every chamber's end state into
    ``hp_end``."""
    lobes, w, R = dof.shape[0], WIDTH, hla.ratio
    h = 2.0 / a1
    Sinv = np.linalg.inv(small) if m > 0 else small
    base, _y = _corrected(xc, G, z, coef, lobe_of, Sinv, m, w)
    E = _extension_responses(G, coef, lobe_of, Sinv, m, lobes, R)
    X, Xd, x0 = np.empty(lobes), np.empty(lobes), np.empty(lobes)
    for k in range(lobes):
        f, p = dof[k, 3], dof[k, 5]
        X[k] = extension(base[w * k + 3], base[w * k + 5], hla)
        vf, vp = a1 * (base[w * k + 3] - q[f]) - v[f], a1 * (base[w * k + 5] - q[p]) - v[p]
        Xd[k] = -R * (vf - vp)
        x0[k] = extension(q[f], q[p], hla)
    F = np.empty(lobes)     # the sweeps start from every chamber's force predicted at the
    for k in range(lobes):  # step's end (its last pressure rate carried over the step), not 0
        F[k] = plunger_force(hp[k, 0] + hp[k, 3] * h, x0[k], hla)
    for _ in range(HLA_SWEEPS):
        change, top = 0.0, 0.0
        for j in range(lobes):
            xj, xdj = X[j], Xd[j]
            for k in range(lobes):
                if k != j:
                    xj += E[j, k] * F[k]
                    xdj += a1 * E[j, k] * F[k]
            p1, fj, qin, qout = chamber_step(hla, hp[j], x0[j], xj, xdj, E[j, j], h)
            change = max(change, abs(fj - F[j]))
            top = max(top, abs(fj))
            F[j] = fj
            hp_end[j, 0], hp_end[j, 1], hp_end[j, 2] = p1, qin, qout
            hp_end[j, 3] = (p1 - hp[j, 0]) / h
        if change <= HLA_TOL * max(top, 1.0) or lobes == 1:
            break
    for j in range(lobes):
        z[w * j + 5] += R * F[j]
        z[w * j + 3] -= R * F[j]
