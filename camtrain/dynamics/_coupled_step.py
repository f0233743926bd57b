"""One time step of the shaft-and-trains march (:mod:`._coupled_kernel` marches the revolution).

A step is first taken with the contact states of its start (the linear part's inverse for the
full step is factorised once; the closed contacts enter as a low-rank update,
:mod:`._coupled_lowrank`). When a contact's indicator psi = min(k delta, k delta + c delta')
changes sign over the step, the step is split where it does, as the single-train march does
(:mod:`._kernel`): the crossing is located on the cubic Hermite of delta in time through its
end values and rates (Illinois regula falsi), the part of the step up to it is re-taken, the
contact switched, the acceleration restarted from the equilibrium with the new states and the
rest of the step taken with them. The sub-steps have other lengths than the full step, so they
are solved block by block (both bending planes, the twist and every train are uncoupled but for
the contacts), again with the contacts as a low-rank update. Staggered: the shaft under the
predicted contact loads first, the trains on its motion after (:mod:`._coupled_partition`)."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.dynamics._coupled_lowrank import basis_rows, woodbury
from camtrain.dynamics._coupled_partition import add_shaft_forces, add_shaft_loads, prescribed_inputs
from camtrain.numerics.roots import false_position, illinois_update

#: contact changes located inside one step at most (more: the rest of the step is accepted)
MAX_SWITCHES = 8


@njit(cache=True)
def _hermite(y0, m0, y1, m1, sigma, h):
    """Cubic Hermite at fraction sigma of an interval of length h (m: rates per unit time):
    value and rate."""
    s, s2, s3 = sigma, sigma * sigma, sigma * sigma * sigma
    val = ((2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 * h + (-2 * s3 + 3 * s2) * y1
           + (s3 - s2) * m1 * h)
    der = ((6 * s2 - 6 * s) * y0 + (3 * s2 - 4 * s + 1) * m0 * h + (-6 * s2 + 6 * s) * y1
           + (3 * s2 - 2 * s) * m1 * h) / h
    return val, der


@njit(cache=True)
def _inputs(b, bd, gx, gy, gphi, j, s, frac, dt):
    """Lobe j's cam input, its rate and gradient at fraction ``frac`` of step s (the step runs
    from the time of column s - 1 to that of column s; the columns wrap over the revolution):
    the lift by a cubic Hermite, the rest linear."""
    p = s - 1 if s > 0 else b.shape[1] - 1
    if frac >= 1.0:
        return b[j, s], bd[j, s], gx[j, s], gy[j, s], gphi[j, s]
    if frac <= 0.0:
        return b[j, p], bd[j, p], gx[j, p], gy[j, p], gphi[j, p]
    val, der = _hermite(b[j, p], bd[j, p], b[j, s], bd[j, s], frac, dt)
    w0 = 1.0 - frac
    return (val, der, w0 * gx[j, p] + frac * gx[j, s], w0 * gy[j, p] + frac * gy[j, s],
            w0 * gphi[j, p] + frac * gphi[j, s])


@njit(cache=True)
def cam_gap(z, zd, bj, bdj, gxj, gyj, gphij, offc, ix, iy, iphi, ifol, j):
    """Cam contact j's compression delta and its rate for displacements z, velocities zd."""
    d = bj + offc - z[ifol[j]] + gxj * z[ix[j]] + gyj * z[iy[j]] + gphij * z[iphi[j]]
    dd = bdj - zd[ifol[j]] + gxj * zd[ix[j]] + gyj * zd[iy[j]] + gphij * zd[iphi[j]]
    return d, dd


@njit(cache=True)
def _psi(k, c, d, dd):
    """Contact indicator min(k delta, k delta + c delta') (a separating damper never pulls)."""
    f = k * d + c * dd
    return min(k * d, f)


@njit(cache=True)
def _friction_force(fric, fr_j, tang_j, ix, iy, iphi, cosa, sina, arm_j):
    """Generalised friction force of every lobe (tangential on the shaft, torque mu W r)."""
    fric[:] = 0.0
    for j in range(ix.size):
        fric[ix[j]] += -tang_j[j] * sina[j]
        fric[iy[j]] += tang_j[j] * cosa[j]
        fric[iphi[j]] += -fr_j[j] * arm_j[j]


@njit(cache=True)
def _substep(tau, q, v, acc, act_c, act_s, K, C, M, f0, fric, blocks, bj, bdj, gxj, gyj, gphij,
             kc, cc, ks, cs, offc, offs, ix, iy, iphi, ifol, ival, x, stagger):
    """A Newmark step of length ``tau`` from (q, v, acc) with the contact states fixed, the
    linear part solved block by block (inputs bj ... at the sub-step's end). ``stagger``: the
    shaft carries the predicted contact loads (in ``fric``) and the trains take its motion at
    the sub-step's end as prescribed input (:mod:`._coupled_partition`)."""
    n = q.size
    lobes = ix.size
    a0 = 4.0 / (tau * tau)
    a1 = 2.0 / tau
    x0 = np.empty(n)
    basis = np.zeros((n, 5 * lobes))
    for k in range(blocks.size - 1):
        lo, hi = blocks[k], blocks[k + 1]
        size = hi - lo
        cols = []
        for j in range(lobes):
            for e, dof in enumerate((ix[j], iy[j], iphi[j], ifol[j], ival[j])):
                if lo <= dof < hi:
                    cols.append((5 * j + e, dof))
        A = np.empty((size, size))
        R = np.zeros((size, 1 + len(cols)))
        for i in range(size):
            gi = lo + i
            r = f0[gi] + fric[gi]
            for e in range(size):
                ge = lo + e
                A[i, e] = K[gi, ge] + a1 * C[gi, ge] + a0 * M[gi, ge]
                r += M[gi, ge] * (a0 * q[ge] + (4.0 / tau) * v[ge] + acc[ge]) \
                    + C[gi, ge] * (a1 * q[ge] + v[ge])
            R[i, 0] = r
        for c in range(len(cols)):
            R[cols[c][1] - lo, 1 + c] = 1.0
        S = np.linalg.solve(A, R)
        for i in range(size):
            x0[lo + i] = S[i, 0]
        for c in range(len(cols)):
            col = cols[c][0]
            for i in range(size):
                basis[lo + i, col] = S[i, 1 + c]
    z = np.zeros(5 * lobes)     # friction is in the right-hand side already
    if stagger:     # the shaft's part of x0 is final: no contact column reaches it
        v0 = np.empty(n)
        for i in range(n):
            v0[i] = a1 * (x0[i] - q[i]) - v[i]
        be, bde = np.empty(lobes), np.empty(lobes)
        prescribed_inputs(x0, v0, bj, bdj, gxj, gyj, gphij, ix, iy, iphi, be, bde)
        zero = np.zeros(lobes)
        woodbury(x0, basis, basis_rows(basis, ix, iy, iphi, ifol, ival), z, act_c, act_s, be,
                 bde, zero, zero, zero, q, v, kc, cc, ks, cs, offc, offs, a1, ix, iy, iphi,
                 ifol, ival, x)
        return
    woodbury(x0, basis, basis_rows(basis, ix, iy, iphi, ifol, ival), z, act_c, act_s, bj,
             bdj, gxj, gyj, gphij, q, v, kc, cc, ks, cs, offc, offs, a1, ix, iy, iphi, ifol,
             ival, x)


@njit(cache=True)
def _equilibrium(q, v, act_c, act_s, K, C, Minv, f0, fric, blocks, bj, bdj, gxj, gyj, gphij, kc,
                 cc, ks, cs, offc, offs, ix, iy, iphi, ifol, ival, acc, stagger):
    """acc = M^-1 (f0 + friction + contact forces - K q - C v), block by block (``Minv`` the
    block-diagonal inverse of M)."""
    n = q.size
    r = np.empty(n)
    rb = np.empty(n)
    for i in range(n):
        r[i] = f0[i] + fric[i]
    for j in range(ix.size):
        if act_c[j]:
            d, dd = cam_gap(q, v, bj[j], bdj[j], gxj[j], gyj[j], gphij[j], offc, ix, iy, iphi,
                             ifol, j)
            w = kc * d + cc * dd
            r[ifol[j]] += w
            if not stagger:     # staggered: the shaft carries the predicted load (in fric)
                r[ix[j]] -= w * gxj[j]
                r[iy[j]] -= w * gyj[j]
                r[iphi[j]] -= w * gphij[j]
        if act_s[j]:
            r[ival[j]] += ks * (offs - q[ival[j]]) - cs * v[ival[j]]
    for k in range(blocks.size - 1):
        lo, hi = blocks[k], blocks[k + 1]
        for i in range(lo, hi):
            s = r[i]
            for e in range(lo, hi):
                s -= K[i, e] * q[e] + C[i, e] * v[e]
            rb[i] = s
        for i in range(lo, hi):
            s = 0.0
            for e in range(lo, hi):
                s += Minv[i, e] * rb[e]
            acc[i] = s


@njit(cache=True)
def _indicators(z, zd, j, bj, bdj, gxj, gyj, gphij, kc, cc, ks, cs, offc, offs, ix, iy, iphi,
                ifol, ival):
    """(psi, delta, delta') of lobe j's cam contact and of its seat."""
    d, dd = cam_gap(z, zd, bj, bdj, gxj, gyj, gphij, offc, ix, iy, iphi, ifol, j)
    ds, dds = offs - z[ival[j]], -zd[ival[j]]
    return _psi(kc, cc, d, dd), d, dd, _psi(ks, cs, ds, dds), ds, dds


@njit(cache=True)
def _crossing(k, c, d0, dd0, d1, dd1, h):
    """Fraction of an interval of length h where psi = min(k delta, k delta + c delta') of the
    cubic Hermite delta(t) through (d0, dd0) and (d1, dd1) changes sign (Illinois)."""
    lo, hi = 0.0, 1.0
    plo = _psi(k, c, d0, dd0)
    phi = _psi(k, c, d1, dd1)
    if plo == phi or (plo > 0.0) == (phi > 0.0):
        return 0.0
    x = plo / (plo - phi)
    side = 0
    for _ in range(40):
        val, der = _hermite(d0, dd0, d1, dd1, x, h)
        px = _psi(k, c, val, der)
        if abs(px) <= 1e-13 * (abs(plo) + abs(phi)) or hi - lo < 1e-12:
            break
        lo, plo, hi, phi, side = illinois_update(lo, plo, hi, phi, x, px, side)
        x = false_position(lo, plo, hi, phi)
    return x


@njit(cache=True)
def advance(s, q, v, acc, act_c, act_s, x_f0, P, Q, blocks, ainv_basis, G, K, C, M, Minv, f0, b,
             bd, gx, gy, gphi, kc, cc, ks, cs, offc, offs, a0, a1, dt, ix, iy, iphi, ifol, ival,
             fr_j, tang_j, arm_j, cosa, sina, bj, bdj, gxj, gyj, gphij, b0, bd0, zf, fric, hub,
             torque, hub_basis, hub_x, hub_y, hub_cos, hub_sin, hub_radius, stagger, w_pred,
             rhs_w, rhs_c, base, x, v1, a1v, be, bde, zero, fresh, drive_u, drive_j,
             drive_acc):
    """Step s of the revolution (:func:`revolution`): the state (q, v, acc, contact states)
    advanced in place, the inputs bj ... at the step's end. ``stagger``: the shaft under the
    predicted loads ``w_pred`` first, then the trains with its motion prescribed
    (:mod:`._coupled_partition`). Returns the contact changes located and whether the step
    had more than MAX_SWITCHES. ``fresh`` False: ``base`` (the step's solution without contact
    and friction forces) is still that of the same start, from the step's previous pass.
    ``drive_acc``: the drive's angular acceleration at the step's end, whose inertia load
    -J theta'' (``drive_j`` = J 1 on the twist coordinates, ``drive_u`` = A^-1 of it) the
    twist, measured from the drive, carries."""
    n = q.size
    lobes = ix.size
    located = 0
    cut = 0
    if fresh:   # the full step with the states of its start (P = A^-1 M, Q = A^-1 C)
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
        if hub_x >= 0:      # the belt's torque-dependent pull at the drive station
            pull = abs(torque) / hub_radius
            hub[0], hub[1] = pull * hub_cos, pull * hub_sin
            for i in range(n):
                base[i] += hub_basis[i, 0] * hub[0] + hub_basis[i, 1] * hub[1]
        if drive_acc != 0.0:    # the drive's speed oscillation: -J theta'' on the twist
            for i in range(n):
                base[i] -= drive_u[i] * drive_acc
    for j in range(lobes):      # friction on the lobe's coordinates
        zf[5 * j] = -tang_j[j] * sina[j]
        zf[5 * j + 1] = tang_j[j] * cosa[j]
        zf[5 * j + 2] = -fr_j[j] * arm_j[j]
        zf[5 * j + 3] = 0.0
        zf[5 * j + 4] = 0.0
    if stagger:     # the shaft first, under the predicted loads; the trains on its motion
        add_shaft_loads(zf, w_pred, gxj, gyj, gphij)
        for i in range(n):
            total_x = base[i]
            for c in range(5 * lobes):
                total_x += ainv_basis[i, c] * zf[c]
            x[i] = total_x
            v1[i] = a1 * (x[i] - q[i]) - v[i]
        prescribed_inputs(x, v1, bj, bdj, gxj, gyj, gphij, ix, iy, iphi, be, bde)
        woodbury(base, ainv_basis, G, zf, act_c, act_s, be, bde, zero, zero, zero, q, v, kc,
                 cc, ks, cs, offc, offs, a1, ix, iy, iphi, ifol, ival, x)
    else:
        woodbury(base, ainv_basis, G, zf, act_c, act_s, bj, bdj, gxj, gyj, gphij, q, v, kc,
                 cc, ks, cs, offc, offs, a1, ix, iy, iphi, ifol, ival, x)
    for i in range(n):
        v1[i] = a1 * (x[i] - q[i]) - v[i]
    changed = False
    for j in range(lobes):
        pc, _d, _dd, ps, _ds, _dds = _indicators(x, v1, j, bj[j], bdj[j], gxj[j], gyj[j],
                                                 gphij[j], kc, cc, ks, cs, offc, offs, ix,
                                                 iy, iphi, ifol, ival)
        if (pc > 0.0) != act_c[j] or (ps > 0.0) != act_s[j]:
            changed = True
    if not changed:
        for i in range(n):
            acc[i] = a0 * (x[i] - q[i]) - (4.0 / dt) * v[i] - acc[i]
            q[i] = x[i]
            v[i] = v1[i]
    else:
        _friction_force(fric, fr_j, tang_j, ix, iy, iphi, cosa, sina, arm_j)
        if hub_x >= 0:
            fric[hub_x] += hub[0]
            fric[hub_y] += hub[1]
        if stagger:
            add_shaft_forces(fric, w_pred, gxj, gyj, gphij, ix, iy, iphi)
        if drive_acc != 0.0:
            for i in range(n):
                fric[i] -= drive_j[i] * drive_acc
        tau = 0.0
        switches = 0
        while True:
            h = dt - tau
            if h <= 1e-12 * dt:
                break
            if switches > 0:   # the full step with the start's states is x, v1 already
                _substep(h, q, v, acc, act_c, act_s, K, C, M, f0, fric, blocks, bj, bdj,
                         gxj, gyj, gphij, kc, cc, ks, cs, offc, offs, ix, iy, iphi, ifol,
                         ival, x, stagger)
                for i in range(n):
                    v1[i] = (2.0 / h) * (x[i] - q[i]) - v[i]
            # which contact changes state first inside the (sub)step?
            first, seat, alpha = -1, False, 2.0
            for j in range(lobes):
                b0[j], bd0[j], g0x, g0y, g0p = _inputs(b, bd, gx, gy, gphi, j, s,
                                                       tau / dt, dt)
                pc0, d0, dd0, ps0, ds0, dds0 = _indicators(
                    q, v, j, b0[j], bd0[j], g0x, g0y, g0p, kc, cc, ks, cs, offc, offs, ix,
                    iy, iphi, ifol, ival)
                pc1, d1, dd1, ps1, ds1, dds1 = _indicators(
                    x, v1, j, bj[j], bdj[j], gxj[j], gyj[j], gphij[j], kc, cc, ks, cs, offc,
                    offs, ix, iy, iphi, ifol, ival)
                if (pc1 > 0.0) != act_c[j]:
                    frac = _crossing(kc, cc, d0, dd0, d1, dd1, h)
                    if frac < alpha:
                        first, seat, alpha = j, False, frac
                if (ps1 > 0.0) != act_s[j]:
                    frac = _crossing(ks, cs, ds0, dds0, ds1, dds1, h)
                    if frac < alpha:
                        first, seat, alpha = j, True, frac
            if first < 0 or switches >= MAX_SWITCHES:
                if first >= 0:
                    cut += 1
                for i in range(n):
                    a1v[i] = (4.0 / (h * h)) * (x[i] - q[i]) - (4.0 / h) * v[i] - acc[i]
                    q[i] = x[i]
                    v[i] = v1[i]
                    acc[i] = a1v[i]
                break
            # take the step up to the change, switch the contact, restart the acceleration
            hs = alpha * h
            frac_end = (tau + hs) / dt
            for j in range(lobes):
                bj[j], bdj[j], gxj[j], gyj[j], gphij[j] = _inputs(b, bd, gx, gy, gphi, j, s,
                                                                  frac_end, dt)
            if hs > 1e-12 * dt:
                _substep(hs, q, v, acc, act_c, act_s, K, C, M, f0, fric, blocks, bj, bdj,
                         gxj, gyj, gphij, kc, cc, ks, cs, offc, offs, ix, iy, iphi, ifol,
                         ival, x, stagger)
                for i in range(n):
                    v[i] = (2.0 / hs) * (x[i] - q[i]) - v[i]
                    q[i] = x[i]
            tau += hs
            if seat:
                act_s[first] = not act_s[first]
            else:
                act_c[first] = not act_c[first]
            _equilibrium(q, v, act_c, act_s, K, C, Minv, f0, fric, blocks, bj, bdj, gxj, gyj,
                         gphij, kc, cc, ks, cs, offc, offs, ix, iy, iphi, ifol, ival, acc,
                         stagger)
            switches += 1
            located += 1
            for j in range(lobes):
                bj[j], bdj[j], gxj[j], gyj[j], gphij[j] = b[j, s], bd[j, s], gx[j, s], \
                    gy[j, s], gphi[j, s]
    return located, cut
