"""The low-rank (Woodbury) contact update of the shaft-and-trains step (:mod:`._step`): every
cam contact's gradient lies in its lobe's five coordinates (x, y, phi, follower, valve), so the
closed contacts enter the factorised linear part as a small dense system on 5 L numbers.

A hydraulic lash adjuster on every train (``lay.ipl``, the plungers' coordinates) adds a sixth
coordinate per lobe: its chamber force acts along (plunger - follower), so it too is a force
on the lobe's coordinates. The chamber is solved with the single train's
:func:`camtrain.dynamics.hla.chamber_step` against the contact-corrected compliance of its
extension; the lobes are coupled only through the shaft (the other lobes' chamber forces move
a lobe's extension through its closed contact), so the chambers are swept lobe by lobe until
their forces agree (Gauss-Seidel on the lobes' scalar equations)."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.dynamics.hla.chamber import chamber_step, extension, plunger_force

#: adjuster sweeps of a step at most, and their relative agreement of the chamber forces
HLA_SWEEPS = 50
HLA_TOL = 1e-12


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
    nc, w = G.shape[0], 6
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
def _less_contacts(c, r, G, coef, lobe_of, y, m, w):
    """c[r] less the closed contacts' correction (G C^T y)[r]."""
    total = 0.0
    for s in range(m):
        for f in range(w):
            if coef[s, f] != 0.0:
                total += G[r, w * lobe_of[s] + f] * coef[s, f] * y[s]
    return c[r] - total


@njit(cache=True)
def _adjusters(xc, G, z, coef, lobe_of, small, m, st, lay, hla, a1, hp_end):
    """Every lobe's chamber force solved against its contact-corrected extension (the
    module's docstring); the forces R F on (plunger, follower) added to ``z``, every chamber's
    end state into ``hp_end``."""
    lobes, w, R = lay.ix.size, 6, hla.ratio
    h = 2.0 / a1
    Sinv = np.linalg.inv(small) if m > 0 else small
    base, _y = _corrected(xc, G, z, coef, lobe_of, Sinv, m, w)
    E = _extension_responses(G, coef, lobe_of, Sinv, m, lobes, R)
    q, v = st.q, st.v
    X, Xd, x0 = np.empty(lobes), np.empty(lobes), np.empty(lobes)
    for k in range(lobes):
        f, p = lay.ifol[k], lay.ipl[k]
        X[k] = extension(base[w * k + 3], base[w * k + 5], hla)
        vf, vp = a1 * (base[w * k + 3] - q[f]) - v[f], a1 * (base[w * k + 5] - q[p]) - v[p]
        Xd[k] = -R * (vf - vp)
        x0[k] = extension(q[f], q[p], hla)
    F = np.empty(lobes)     # the sweeps start from every chamber's force predicted at the
    for k in range(lobes):  # step's end (its last pressure rate carried over the step), not 0
        F[k] = plunger_force(st.hp[k, 0] + st.hp[k, 3] * h, x0[k], hla)
    for _ in range(HLA_SWEEPS):
        change, top = 0.0, 0.0
        for j in range(lobes):
            xj, xdj = X[j], Xd[j]
            for k in range(lobes):
                if k != j:
                    xj += E[j, k] * F[k]
                    xdj += a1 * E[j, k] * F[k]
            p1, fj, qin, qout = chamber_step(hla, st.hp[j], x0[j], xj, xdj, E[j, j], h)
            change = max(change, abs(fj - F[j]))
            top = max(top, abs(fj))
            F[j] = fj
            hp_end[j, 0], hp_end[j, 1], hp_end[j, 2] = p1, qin, qout
            hp_end[j, 3] = (p1 - st.hp[j, 0]) / h
        if change <= HLA_TOL * max(top, 1.0) or lobes == 1:
            break
    for j in range(lobes):
        z[w * j + 5] += R * F[j]
        z[w * j + 3] -= R * F[j]


@njit(cache=True)
def woodbury(x0, basis, G, z, lay, uni, st, at, a1, x, hla):
    """x = (A + sum_active kappa h h^T)^-1 (r + E z - sum_active h f0): ``x0`` = A^-1 r,
    ``basis`` = A^-1 E the columns of A^-1 at every lobe's W contact coordinates (x, y, phi,
    follower, valve; the plunger with an adjuster), ``G`` its rows there (:func:`basis_rows`),
    ``z`` forces on those coordinates (friction; overwritten), the contact states and (q, v)
    of the state ``st``, every lobe's inputs at the step's end ``at``, a1 = 2 / step. Every
    contact gradient h lies in its lobe's coordinates, so the update works on W L numbers and
    touches the full state once. An adjuster (``hla.on``): :func:`_adjusters`, its chambers'
    end states into ``st.hp_end``."""
    n, lobes, w = x0.size, lay.ix.size, width(lay)
    coef, lobe_of, kk, m = _contact_rows(z, lay, uni, st, at, a1)
    small = _small(G, coef, lobe_of, kk, m, w) if m > 0 else np.zeros((0, 0))
    xc = np.empty(w * lobes)
    for j in range(lobes):
        dofs = lobe_dofs(lay, j)
        for e in range(w):
            xc[w * j + e] = x0[dofs[e]]
    if hla.on:
        _adjusters(xc, G, z, coef, lobe_of, small, m, st, lay, hla, a1, st.hp_end)
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
