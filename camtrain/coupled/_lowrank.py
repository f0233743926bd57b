"""The low-rank (Woodbury) contact update of the shaft-and-trains step (:mod:`._step`): every
cam contact's gradient lies in its lobe's five coordinates (x, y, phi, follower, valve), so the
closed contacts enter the factorised linear part as a small dense system on 5 L numbers."""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def basis_rows(basis, lay):
    """G = the rows of ``basis`` at every lobe's five contact coordinates (5 L x 5 L)."""
    ix, iy, iphi, ifol, ival = lay.ix, lay.iy, lay.iphi, lay.ifol, lay.ival
    lobes = ix.size
    G = np.empty((5 * lobes, 5 * lobes))
    for j in range(lobes):
        dofs = (ix[j], iy[j], iphi[j], ifol[j], ival[j])
        for e in range(5):
            for c in range(5 * lobes):
                G[5 * j + e, c] = basis[dofs[e], c]
    return G


@njit(cache=True)
def woodbury(x0, basis, G, z, lay, uni, st, at, a1, x):
    """x = (A + sum_active kappa h h^T)^-1 (r + E z - sum_active h f0): ``x0`` = A^-1 r,
    ``basis`` = A^-1 E the columns of A^-1 at every lobe's five contact coordinates (x, y, phi,
    follower, valve), ``G`` its rows there (:func:`basis_rows`), ``z`` forces on those
    coordinates (friction; overwritten), the contact states and (q, v) of the state ``st``,
    every lobe's inputs at the step's end ``at``, a1 = 2 / step. Every contact gradient h lies
    in its lobe's five coordinates, so the update works on 5 L numbers and touches the full
    state once."""
    n = x0.size
    lobes = lay.ix.size
    coef = np.zeros((2 * lobes, 5))
    lobe_of = np.zeros(2 * lobes, dtype=np.int64)
    kk = np.zeros(2 * lobes)
    # the closed contacts' gradients, lobes and stiffnesses k + a1 c; their constant forces
    ix, iy, iphi, ifol, ival = lay.ix, lay.iy, lay.iphi, lay.ifol, lay.ival
    kc, cc, offc = uni.k[0], uni.c[0], uni.off[0]
    ks, cs, offs = uni.k[1], uni.c[1], uni.off[1]
    q, v = st.q, st.v
    bj, bdj, gxj, gyj, gphij = at.b, at.bd, at.gx, at.gy, at.gphi
    m = 0
    for j in range(lobes):
        if st.act_c[j]:
            coef[m, 0] = gxj[j]
            coef[m, 1] = gyj[j]
            coef[m, 2] = gphij[j]
            coef[m, 3] = -1.0
            hq = gxj[j] * q[ix[j]] + gyj[j] * q[iy[j]] + gphij[j] * q[iphi[j]] - q[ifol[j]]
            hv = gxj[j] * v[ix[j]] + gyj[j] * v[iy[j]] + gphij[j] * v[iphi[j]] - v[ifol[j]]
            f0 = kc * (bj[j] + offc) + cc * (bdj[j] - a1 * hq - hv)
            # f_c = -h (k delta + c delta'): its constant part
            for e in range(4):
                z[5 * j + e] -= f0 * coef[m, e]
            kk[m] = kc + a1 * cc
            lobe_of[m] = j
            m += 1
        if st.act_s[j]:
            coef[m, 4] = -1.0
            z[5 * j + 4] += ks * offs + cs * (a1 * q[ival[j]] + v[ival[j]])
            kk[m] = ks + a1 * cs
            lobe_of[m] = j
            m += 1
    if m > 0:
        small = np.zeros((m, m))
        rhs_small = np.empty(m)
        for r in range(m):
            jr = lobe_of[r]
            small[r, r] = 1.0 / kk[r]
            dofs = (ix[jr], iy[jr], iphi[jr], ifol[jr], ival[jr])
            total = 0.0
            for e in range(5):
                ce = coef[r, e]
                if ce == 0.0:
                    continue
                row = 5 * jr + e
                acc_e = x0[dofs[e]]
                for b in range(5 * lobes):
                    acc_e += G[row, b] * z[b]
                total += ce * acc_e
                for c in range(m):
                    jc = lobe_of[c]
                    for f in range(5):
                        small[r, c] += ce * G[row, 5 * jc + f] * coef[c, f]
            rhs_small[r] = total
        y = np.linalg.solve(small, rhs_small)
        for c in range(m):
            jc = lobe_of[c]
            for f in range(5):
                z[5 * jc + f] -= coef[c, f] * y[c]
    for i in range(n):
        total = x0[i]
        for b in range(5 * lobes):
            total += basis[i, b] * z[b]
        x[i] = total
