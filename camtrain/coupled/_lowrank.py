"""The low-rank (Woodbury) contact update of the shaft-and-trains step (:mod:`._step`): every
cam contact's gradient lies in its lobe's five coordinates (x, y, phi, follower, valve), so the
closed contacts enter the factorised linear part as a small dense system on 5 L numbers.

A hydraulic lash adjuster on every train (``lay.ipl``, the plungers' coordinates) adds a sixth
coordinate per lobe, on which its chamber force acts: the update calls
:func:`camtrain.coupled.adjuster_step.solve_chambers` once, before the contacts' solve."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.coupled.adjuster_step import solve_chambers


@njit(cache=True)
def width(lay):
    """Coordinates per lobe in the update: 5, or 6 with a lash adjuster (its plunger)."""
    return 6 if lay.ipl.size > 0 else 5


@njit(cache=True)
def lobe_dofs(lay, j):
    """Lobe j's state indices (x, y, phi, follower, valve, plunger; the follower again
    without an adjuster)."""
    p = lay.ipl[j] if lay.ipl.size > 0 else lay.ifol[j]
    return (lay.ix[j], lay.iy[j], lay.iphi[j], lay.ifol[j], lay.ival[j], p)


@njit(cache=True)
def basis_rows(basis, lay):
    """G = the rows of ``basis`` at every lobe's W contact coordinates (W L x W L)."""
    lobes, w = lay.ix.size, width(lay)
    G = np.empty((w * lobes, w * lobes))
    for j in range(lobes):
        dofs = lobe_dofs(lay, j)
        for e in range(w):
            for c in range(w * lobes):
                G[w * j + e, c] = basis[dofs[e], c]
    return G


@njit(cache=True)
def _contact_rows(z, lay, uni, st, at, a1):
    """Every closed contact's gradient (coef, on its lobe's coordinates), lobe and stiffness
    k + a1 c; their constant forces subtracted from ``z``. Returns (coef, lobe_of, kk, m)."""
    lobes, w = lay.ix.size, width(lay)
    coef = np.zeros((2 * lobes, w))
    lobe_of = np.zeros(2 * lobes, dtype=np.int64)
    kk = np.zeros(2 * lobes)
    ix, iy, iphi, ifol, ival = lay.ix, lay.iy, lay.iphi, lay.ifol, lay.ival
    kc, cc, offc = uni.k[0], uni.c[0], uni.off[0]
    ks, cs, offs = uni.k[1], uni.c[1], uni.off[1]
    q, v = st.q, st.v
    m = 0
    for j in range(lobes):
        if st.act_c[j]:
            coef[m, 0], coef[m, 1], coef[m, 2], coef[m, 3] = at.gx[j], at.gy[j], at.gphi[j], -1.0
            hq = at.gx[j] * q[ix[j]] + at.gy[j] * q[iy[j]] + at.gphi[j] * q[iphi[j]] - q[ifol[j]]
            hv = at.gx[j] * v[ix[j]] + at.gy[j] * v[iy[j]] + at.gphi[j] * v[iphi[j]] - v[ifol[j]]
            f0 = kc * (at.b[j] + offc) + cc * (at.bd[j] - a1 * hq - hv)
            # f_c = -h (k delta + c delta'): its constant part
            for e in range(4):
                z[w * j + e] -= f0 * coef[m, e]
            kk[m] = kc + a1 * cc
            lobe_of[m] = j
            m += 1
        if st.act_s[j]:
            coef[m, 4] = -1.0
            z[w * j + 4] += ks * offs + cs * (a1 * q[ival[j]] + v[ival[j]])
            kk[m] = ks + a1 * cs
            lobe_of[m] = j
            m += 1
    return coef, lobe_of, kk, m


@njit(cache=True)
def _small(G, coef, lobe_of, kk, m, w):
    """diag(1/kk) + C G C^T of the closed contacts (m x m)."""
    small = np.zeros((m, m))
    for r in range(m):
        jr = lobe_of[r]
        small[r, r] = 1.0 / kk[r]
        for e in range(w):
            ce = coef[r, e]
            if ce == 0.0:
                continue
            row = w * jr + e
            for c in range(m):
                jc = lobe_of[c]
                for f in range(w):
                    small[r, c] += ce * G[row, w * jc + f] * coef[c, f]
    return small


@njit(cache=True)
def woodbury(x0, basis, G, z, lay, uni, st, at, a1, x, hla):
    """x = (A + sum_active kappa h h^T)^-1 (r + E z - sum_active h f0): ``x0`` = A^-1 r,
    ``basis`` = A^-1 E the columns of A^-1 at every lobe's W contact coordinates (x, y, phi,
    follower, valve; the plunger with an adjuster), ``G`` its rows there (:func:`basis_rows`),
    ``z`` forces on those coordinates (friction; overwritten), the contact states and (q, v)
    of the state ``st``, every lobe's inputs at the step's end ``at``, a1 = 2 / step. Every
    contact gradient h lies in its lobe's coordinates, so the update works on W L numbers and
    touches the full state once. An adjuster (``hla.on``): its chambers' forces into ``z``,
    their end states into ``st.hp_end`` (:func:`camtrain.coupled.adjuster_step.solve_chambers`)."""
    n, lobes, w = x0.size, lay.ix.size, width(lay)
    coef, lobe_of, kk, m = _contact_rows(z, lay, uni, st, at, a1)
    small = _small(G, coef, lobe_of, kk, m, w) if m > 0 else np.zeros((0, 0))
    xc = np.empty(w * lobes)
    for j in range(lobes):
        dofs = lobe_dofs(lay, j)
        for e in range(w):
            xc[w * j + e] = x0[dofs[e]]
    if hla.on:
        solve_chambers(xc, G, z, coef, lobe_of, small, m, st, lay, hla, a1, st.hp_end)
    if m > 0:
        rhs = np.zeros(m)
        for r in range(m):
            row0 = w * lobe_of[r]
            for e in range(w):
                ce = coef[r, e]
                if ce == 0.0:
                    continue
                acc_e = xc[row0 + e]
                for b in range(w * lobes):
                    acc_e += G[row0 + e, b] * z[b]
                rhs[r] += ce * acc_e
        y = np.linalg.solve(small, rhs)
        for c in range(m):
            jc = lobe_of[c]
            for f in range(w):
                z[w * jc + f] -= coef[c, f] * y[c]
    for i in range(n):
        total = x0[i]
        for b in range(w * lobes):
            total += basis[i, b] * z[b]
        x[i] = total
