"""Compiled revolution of the monolithic shaft-and-trains march (numba, cached on disk): the
step of :mod:`camtrain.dynamics.monolithic` (Newmark average acceleration, active-set contact
states, Woodbury update of the factorised linear part, explicit friction). Only this module and
the train kernel import numba."""
from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def _gradient_dot(coef, z, ix, iy, iphi, ifol, ival, j):
    return (coef[0] * z[ix[j]] + coef[1] * z[iy[j]] + coef[2] * z[iphi[j]]
            + coef[3] * z[ifol[j]] + coef[4] * z[ival[j]])


@njit(cache=True)
def revolution(q, v, acc, w_prev, x_f0, P, Q, blocks, ainv_basis, b, bd, gx, gy, gphi, fric_mu, arm,
               ratio, cosa, sina, turn, kc, cc, ks, cs, offc, offs, a0, a1, dt, ix, iy, iphi,
               ifol, ival, valve_dof, substeps, out_load, out_acc):
    """March one revolution (steps = b.shape[1]); write the grid samples (every ``substeps``
    steps) into ``out_load``/``out_acc`` (n_lobes x grid). State arrays are updated in place.
    ``P`` = A^-1 M and ``Q`` = A^-1 C are block diagonal (shaft planes, twist, each train):
    ``blocks`` holds the block boundaries, so only the diagonal blocks are multiplied."""
    n = q.size
    lobes = ix.size
    steps = b.shape[1]
    grid = out_load.shape[1]
    rhs_w = np.empty(n)
    rhs_c = np.empty(n)
    base = np.empty(n)
    x0 = np.empty(n)
    x = np.empty(n)
    coef = np.zeros((2 * lobes, 5))
    lobe_of = np.zeros(2 * lobes, dtype=np.int64)
    kk = np.zeros(2 * lobes)
    act_c = np.zeros(lobes, dtype=np.bool_)
    act_s = np.zeros(lobes, dtype=np.bool_)
    w_new = np.zeros(lobes)
    for s in range(steps):
        # the linear part's step from the state (P = A^-1 M, Q = A^-1 C)
        for i in range(n):
            rhs_w[i] = a0 * q[i] + (4.0 / dt) * v[i] + acc[i]
            rhs_c[i] = a1 * q[i] + v[i]
        for k in range(blocks.size - 1):
            lo, hi = blocks[k], blocks[k + 1]
            for i in range(lo, hi):
                total = x_f0[i]
                for e in range(lo, hi):
                    total += P[i, e] * rhs_w[e] + Q[i, e] * rhs_c[e]
                base[i] = total
        # constant contact forces and friction enter through A^-1 of the basis vectors
        for j in range(lobes):
            fr = fric_mu[j, s] * ratio[j, s] * w_prev[j]
            sgn = 1.0 if arm[j, s] >= 0 else -1.0
            tang = -turn * fr * sgn
            for i in range(n):
                base[i] += (-tang * sina[j] * ainv_basis[i, 5 * j]
                            + tang * cosa[j] * ainv_basis[i, 5 * j + 1]
                            - fr * arm[j, s] * ainv_basis[i, 5 * j + 2])
        for j in range(lobes):
            d = (b[j, s] + offc - q[ifol[j]] + gx[j, s] * q[ix[j]] + gy[j, s] * q[iy[j]]
                 + gphi[j, s] * q[iphi[j]])
            act_c[j] = d > 0.0
            act_s[j] = offs - q[ival[j]] > 0.0
        for _it in range(8):
            for i in range(n):
                x0[i] = base[i]
            m = 0
            for j in range(lobes):
                if act_c[j]:
                    coef[m, 0] = gx[j, s]
                    coef[m, 1] = gy[j, s]
                    coef[m, 2] = gphi[j, s]
                    coef[m, 3] = -1.0
                    coef[m, 4] = 0.0
                    hq = (gx[j, s] * q[ix[j]] + gy[j, s] * q[iy[j]] + gphi[j, s] * q[iphi[j]]
                          - q[ifol[j]])
                    hv = (gx[j, s] * v[ix[j]] + gy[j, s] * v[iy[j]] + gphi[j, s] * v[iphi[j]]
                          - v[ifol[j]])
                    f0 = kc * (b[j, s] + offc) + cc * (bd[j, s] - a1 * hq - hv)
                    # f_c = -h (k delta + c delta'): its constant part, through A^-1 h
                    for i in range(n):
                        x0[i] -= f0 * (coef[m, 0] * ainv_basis[i, 5 * j]
                                       + coef[m, 1] * ainv_basis[i, 5 * j + 1]
                                       + coef[m, 2] * ainv_basis[i, 5 * j + 2]
                                       + coef[m, 3] * ainv_basis[i, 5 * j + 3])
                    kk[m] = kc + a1 * cc
                    lobe_of[m] = j
                    m += 1
                if act_s[j]:
                    coef[m, 0] = 0.0
                    coef[m, 1] = 0.0
                    coef[m, 2] = 0.0
                    coef[m, 3] = 0.0
                    coef[m, 4] = -1.0
                    f0 = ks * offs + cs * (a1 * q[ival[j]] + v[ival[j]])
                    for i in range(n):
                        x0[i] += f0 * ainv_basis[i, 5 * j + 4]
                    kk[m] = ks + a1 * cs
                    lobe_of[m] = j
                    m += 1
            if m > 0:
                hinv = np.empty((n, m))
                for c in range(m):
                    j = lobe_of[c]
                    for i in range(n):
                        acc_i = 0.0
                        for e in range(5):
                            acc_i += coef[c, e] * ainv_basis[i, 5 * j + e]
                        hinv[i, c] = acc_i
                small = np.zeros((m, m))
                rhs_small = np.empty(m)
                for r in range(m):
                    small[r, r] = 1.0 / kk[r]
                    jr = lobe_of[r]
                    for c in range(m):
                        small[r, c] += _gradient_dot(coef[r], hinv[:, c], ix, iy, iphi, ifol,
                                                     ival, jr)
                    rhs_small[r] = _gradient_dot(coef[r], x0, ix, iy, iphi, ifol, ival, jr)
                y = np.linalg.solve(small, rhs_small)
                for i in range(n):
                    x[i] = x0[i]
                    for c in range(m):
                        x[i] -= hinv[i, c] * y[c]
            else:
                for i in range(n):
                    x[i] = x0[i]
            same = True
            for j in range(lobes):
                d = (b[j, s] + offc - x[ifol[j]] + gx[j, s] * x[ix[j]] + gy[j, s] * x[iy[j]]
                     + gphi[j, s] * x[iphi[j]])
                new_c = d > 0.0
                new_s = offs - x[ival[j]] > 0.0
                if new_c != act_c[j] or new_s != act_s[j]:
                    same = False
                act_c[j] = new_c
                act_s[j] = new_s
            if same:
                break
        for j in range(lobes):
            w_new[j] = 0.0
            d = (b[j, s] + offc - x[ifol[j]] + gx[j, s] * x[ix[j]] + gy[j, s] * x[iy[j]]
                 + gphi[j, s] * x[iphi[j]])
            if d > 0.0:
                hq = (gx[j, s] * x[ix[j]] + gy[j, s] * x[iy[j]] + gphi[j, s] * x[iphi[j]]
                      - x[ifol[j]])
                hq0 = (gx[j, s] * q[ix[j]] + gy[j, s] * q[iy[j]] + gphi[j, s] * q[iphi[j]]
                       - q[ifol[j]])
                hv0 = (gx[j, s] * v[ix[j]] + gy[j, s] * v[iy[j]] + gphi[j, s] * v[iphi[j]]
                       - v[ifol[j]])
                w = kc * d + cc * (bd[j, s] + a1 * (hq - hq0) - hv0)
                w_new[j] = w if w > 0.0 else 0.0
        for i in range(n):
            vn = a1 * (x[i] - q[i]) - v[i]
            an = a0 * (x[i] - q[i]) - (4.0 / dt) * v[i] - acc[i]
            q[i] = x[i]
            v[i] = vn
            acc[i] = an
        for j in range(lobes):
            w_prev[j] = w_new[j]
        if (s + 1) % substeps == 0:
            g = ((s + 1) // substeps) % grid
            for j in range(lobes):
                out_load[j, g] = w_new[j]
                out_acc[j, g] = acc[valve_dof[j]]
