"""The low-rank (Woodbury) contact update of the shaft-and-trains step (:mod:`._step`): every
cam contact's gradient lies in its lobe's five coordinates (x, y, phi, follower, valve), so the
closed contacts enter the factorised linear part as a small dense system on 5 L numbers.

A hydraulic lash adjuster on every train (``lay.ipl``, the plungers' coordinates) adds a sixth
coordinate per lobe, on which its chamber force acts: :func:`woodbury_hla` calls
:func:`camtrain.coupled.adjuster_step.solve_chambers` once, before the contacts' solve.

Why two entry points taking plain arrays (:func:`woodbury`, :func:`woodbury_hla`): the update
runs once per step and sub-step, and numba hands a record to a compiled call as its fields one
by one; with the layout, contact state and adjuster records (29 fields of the adjuster alone)
the call cost the four-train problem's revolution about a tenth of its time. The entry points
take only the arrays they read and the update's workspace (:data:`.records.Update`: every
lobe's state indices and the scratch arrays, allocated once per revolution); their helpers are
inlined into them (``inline="always"``, with the width a constant of each entry point, 5 or
6), while the entry points stay calls: inlined into the step, the update doubled the
revolution's first compile (docs/performance.md)."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.coupled.adjuster_step import WIDTH as HLA_WIDTH
from camtrain.coupled.adjuster_step import solve_chambers

#: coordinates per lobe in the update without a lash adjuster (x, y, phi, follower, valve)
PLAIN_WIDTH = 5


@njit(cache=True)
def width(lay):
    """Coordinates per lobe in the update: 5, or 6 with a lash adjuster (its plunger)."""
    return HLA_WIDTH if lay.ipl.size > 0 else PLAIN_WIDTH


@njit(cache=True)
def lobe_dofs(lay, j):
    """Lobe j's state indices (x, y, phi, follower, valve, plunger; the follower again
    without an adjuster)."""
    p = lay.ipl[j] if lay.ipl.size > 0 else lay.ifol[j]
    return (lay.ix[j], lay.iy[j], lay.iphi[j], lay.ifol[j], lay.ival[j], p)


def dof_table(lay) -> np.ndarray:
    """Every lobe's state indices in the update (lobes, width): :func:`lobe_dofs`'s first
    ``width`` (for :data:`.records.Update`)."""
    columns = [lay.ix, lay.iy, lay.iphi, lay.ifol, lay.ival]
    if lay.ipl.size > 0:
        columns.append(lay.ipl)
    return np.ascontiguousarray(np.stack(columns, axis=1).astype(np.int64))


@njit(cache=True, inline="always")
def contact_laws(uni):
    """The cam's and the seat's contact laws as six numbers (k, c, off of the cam, then of the
    seat), handed down the step instead of the record of three arrays (every compiled call
    counts an array argument's references in and out, the numbers cost nothing)."""
    return uni.k[0], uni.c[0], uni.off[0], uni.k[1], uni.c[1], uni.off[1]


@njit(cache=True)
def basis_rows(basis, lay):
    """G = the entries of ``basis`` (W L x n, one row per contact coordinate) at every lobe's
    W contact coordinates (W L x W L): G[r, c] = basis[c, dof of r]."""
    lobes, w = lay.ix.size, width(lay)
    G = np.empty((w * lobes, w * lobes))
    for j in range(lobes):
        dofs = lobe_dofs(lay, j)
        for e in range(w):
            for c in range(w * lobes):
                G[w * j + e, c] = basis[c, dofs[e]]
    return G


@njit(cache=True, inline="always")
def _contact_rows(z, q, v, act_c, act_s, at, laws, a1, upd, w):
    """Every closed contact's gradient (``upd.coef``, on its lobe's coordinates), lobe
    (``upd.lobe_of``) and stiffness k + a1 c (``upd.kk``); their constant forces subtracted
    from ``z``. Returns their number m."""
    coef, lobe_of, kk, dof = upd.coef, upd.lobe_of, upd.kk, upd.dof
    kc, cc, offc, ks, cs, offs = laws
    m = 0
    for j in range(act_c.size):
        ix, iy, iphi, ifol, ival = dof[j, 0], dof[j, 1], dof[j, 2], dof[j, 3], dof[j, 4]
        if act_c[j]:
            for e in range(w):
                coef[m, e] = 0.0
            coef[m, 0], coef[m, 1], coef[m, 2], coef[m, 3] = at.gx[j], at.gy[j], at.gphi[j], -1.0
            hq = at.gx[j] * q[ix] + at.gy[j] * q[iy] + at.gphi[j] * q[iphi] - q[ifol]
            hv = at.gx[j] * v[ix] + at.gy[j] * v[iy] + at.gphi[j] * v[iphi] - v[ifol]
            f0 = kc * (at.b[j] + offc) + cc * (at.bd[j] - a1 * hq - hv)
            # f_c = -h (k delta + c delta'): its constant part
            for e in range(4):
                z[w * j + e] -= f0 * coef[m, e]
            kk[m] = kc + a1 * cc
            lobe_of[m] = j
            m += 1
        if act_s[j]:
            for e in range(w):
                coef[m, e] = 0.0
            coef[m, 4] = -1.0
            z[w * j + 4] += ks * offs + cs * (a1 * q[ival] + v[ival])
            kk[m] = ks + a1 * cs
            lobe_of[m] = j
            m += 1
    return m


@njit(cache=True, inline="always")
def _gather(x0, upd, w):
    """``upd.xc`` = x0 at every lobe's W contact coordinates."""
    xc, dof = upd.xc, upd.dof
    for j in range(dof.shape[0]):
        for e in range(w):
            xc[w * j + e] = x0[dof[j, e]]


@njit(cache=True, inline="always")
def _reduced(G, z, m, upd, w, rhs_too):
    """The closed contacts' small system S = diag(1/kk) + C G C^T (m x m, a view of
    ``upd.small``) and, with ``rhs_too``, its right-hand side C (x_c + G z) into ``upd.rhs``,
    in one pass over the contacts' rows."""
    coef, lobe_of, kk, xc, rhs = upd.coef, upd.lobe_of, upd.kk, upd.xc, upd.rhs
    nc = xc.size
    small = upd.small[:m * m].reshape((m, m))
    small[:, :] = 0.0
    for r in range(m):
        jr = lobe_of[r]
        small[r, r] = 1.0 / kk[r]
        total = 0.0
        for e in range(w):
            ce = coef[r, e]
            if ce == 0.0:
                continue
            row = w * jr + e
            if rhs_too:
                acc_e = xc[row]
                for b in range(nc):
                    acc_e += G[row, b] * z[b]
                total += ce * acc_e
            for c in range(m):
                jc = lobe_of[c]
                for f in range(w):
                    small[r, c] += ce * G[row, w * jc + f] * coef[c, f]
        rhs[r] = total
    return small


@njit(cache=True, inline="always")
def _rhs(G, z, m, upd, w):
    """The small system's right-hand side C (x_c + G z) into ``upd.rhs`` (``z`` moved since
    :func:`_reduced` formed the matrix)."""
    coef, lobe_of, xc, rhs = upd.coef, upd.lobe_of, upd.xc, upd.rhs
    for r in range(m):
        row0 = w * lobe_of[r]
        total = 0.0
        for e in range(w):
            ce = coef[r, e]
            if ce == 0.0:
                continue
            acc_e = xc[row0 + e]
            for b in range(xc.size):
                acc_e += G[row0 + e, b] * z[b]
            total += ce * acc_e
        rhs[r] = total


@njit(cache=True, inline="always")
def _finish(x0, basis, z, small, m, upd, w, x):
    """The contacts' forces y = S^-1 rhs taken off ``z``, then x = x0 + basis^T z (row by row
    of ``basis``: every x[i] sums its terms in the same order as a dot product per i would,
    over contiguous memory)."""
    if m > 0:
        coef, lobe_of = upd.coef, upd.lobe_of
        y = np.linalg.solve(small, upd.rhs[:m])
        for c in range(m):
            jc = lobe_of[c]
            for f in range(w):
                z[w * jc + f] -= coef[c, f] * y[c]
    n = x0.size
    for i in range(n):
        x[i] = x0[i]
    for b in range(z.size):
        zb = z[b]
        for i in range(n):
            x[i] += basis[b, i] * zb


@njit(cache=True)
def woodbury(x0, basis, G, z, x, q, v, act_c, act_s, at, laws, a1, upd):
    """x = (A + sum_active kappa h h^T)^-1 (r + E z - sum_active h f0): ``x0`` = A^-1 r,
    ``basis`` = (A^-1 E)^T the columns of A^-1 at every lobe's five contact coordinates (x, y,
    phi, follower, valve; ``upd.dof``) as rows, ``G`` their entries there
    (:func:`basis_rows`), ``z`` forces on those coordinates (friction; overwritten), (q, v)
    and the contact states (act_c, act_s) of the step's start, every lobe's inputs at the
    step's end ``at``, the contact laws ``laws`` (k, c, off of the cam, then of the seat),
    a1 = 2 / step, the workspace ``upd``. Every contact gradient h lies in its lobe's
    coordinates, so the update works on 5 L numbers and touches the full state once. Without
    lash adjusters (:func:`woodbury_hla` with them)."""
    w = PLAIN_WIDTH
    m = _contact_rows(z, q, v, act_c, act_s, at, laws, a1, upd, w)
    _gather(x0, upd, w)
    small = _reduced(G, z, m, upd, w, True)
    _finish(x0, basis, z, small, m, upd, w, x)


@njit(cache=True)
def woodbury_hla(x0, basis, G, z, x, q, v, act_c, act_s, at, laws, a1, upd, hla, hp, hp_end):
    """:func:`woodbury` with a lash adjuster on every train (six coordinates per lobe, the
    plunger the sixth): the chambers' forces (record ``hla``, states ``hp`` at the step's
    start) into ``z`` and their end states into ``hp_end``
    (:func:`camtrain.coupled.adjuster_step.solve_chambers`), then the contacts' solve."""
    w = HLA_WIDTH
    m = _contact_rows(z, q, v, act_c, act_s, at, laws, a1, upd, w)
    _gather(x0, upd, w)
    small = _reduced(G, z, m, upd, w, False)
    solve_chambers(upd.xc, G, z, upd.coef, upd.lobe_of, small, m, q, v, hp, upd.dof, hla, a1,
                   hp_end)
    _rhs(G, z, m, upd, w)
    _finish(x0, basis, z, small, m, upd, w, x)


@njit(cache=True, inline="always")
def update(x0, basis, G, z, x, q, v, act_c, act_s, hp, hp_end, ends, a1, upd, laws, hla):
    """The low-rank contact update of a step or sub-step, the lash adjusters' form with them
    (``hla.on``; the chambers' states ``hp`` into ``hp_end``): (q, v) and the contact states
    of the step's start, ``ends`` the contacts' inputs at the end, ``laws`` the contact laws
    (:func:`contact_laws`). Only arrays and numbers: a record in the scope of the update's call
    has every array of it counted in before the call and out after it, at every step."""
    if hla.on:
        woodbury_hla(x0, basis, G, z, x, q, v, act_c, act_s, ends, laws, a1, upd, hla, hp,
                     hp_end)
    else:
        woodbury(x0, basis, G, z, x, q, v, act_c, act_s, ends, laws, a1, upd)
