"""One time step of the shaft-and-trains march (:mod:`._revolution` marches the revolution).

A step is first taken with the contact states of its start (the linear part's inverse for the
full step is factorised once; the closed contacts enter as a low-rank update,
:mod:`._lowrank`). When a contact's indicator psi = min(k delta, k delta + c delta') changes
sign over the step, the step is split where it does, as the single-train march does
(:mod:`camtrain.dynamics._kernel`): the crossing is located on the cubic Hermite of delta in time
through its end values and rates (Illinois regula falsi), the part of the step up to it is
re-taken, the contact switched, the acceleration restarted from the equilibrium with the new
states and the rest of the step taken with them. The sub-steps have other lengths than the full
step, so they are solved block by block (both bending planes, the twist and every train are
uncoupled but for the contacts), again with the contacts as a low-rank update. Staggered: the
shaft under the predicted contact loads first, the trains on its motion after
(:mod:`._partition`). The data come as the records of :mod:`.records`.
The step's functions that take the whole ``System`` are inlined where they are called
(``inline="always"``), but for the contact change's (:func:`_split`, :func:`_substep`), which
stay calls (why: :mod:`._revolution`)."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.coupled._lowrank import basis_rows, contact_laws, lobe_dofs, update, width
from camtrain.coupled._partition import add_shaft_forces, add_shaft_loads, prescribed_inputs
from camtrain.coupled.adjuster_step import add_chamber_forces, restart_sealed
from camtrain.coupled.records import LobeAt
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
def _inputs(lob, j, s, frac, dt):
    """Lobe j's cam input, its rate and gradient at fraction ``frac`` of step s (the step runs
    from the time of column s - 1 to that of column s; the columns wrap over the revolution):
    the lift by a cubic Hermite, the rest linear."""
    b, bd, gx, gy, gphi = lob.b, lob.bd, lob.gx, lob.gy, lob.gphi
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
def set_inputs(at, lob, s, frac, dt):
    """Every lobe's inputs at fraction ``frac`` of step s into ``at``."""
    for j in range(at.b.size):
        at.b[j], at.bd[j], at.gx[j], at.gy[j], at.gphi[j] = _inputs(lob, j, s, frac, dt)


@njit(cache=True)
def gap_of(base, gx, gy, gphi, zx, zy, zphi, zfol):
    """A cam contact's compression (``base`` = b + offset) or its rate (``base`` = b') from
    its lobe's coordinates: base - z_fol + gx z_x + gy z_y + gphi z_phi (numbers only, so that
    the per-lobe loops of every step pass no array)."""
    return base - zfol + gx * zx + gy * zy + gphi * zphi


@njit(cache=True)
def cam_gap(z, zd, j, ix, iy, iphi, ifol, offc, bj, bdj, gxj, gyj, gphij):
    """Cam contact j's compression delta and its rate for displacements z, velocities zd."""
    d = gap_of(bj + offc, gxj, gyj, gphij, z[ix[j]], z[iy[j]], z[iphi[j]], z[ifol[j]])
    dd = gap_of(bdj, gxj, gyj, gphij, zd[ix[j]], zd[iy[j]], zd[iphi[j]], zd[ifol[j]])
    return d, dd


@njit(cache=True)
def _psi(k, c, d, dd):
    """Contact indicator min(k delta, k delta + c delta') (a separating damper never pulls)."""
    f = k * d + c * dd
    return min(k * d, f)


@njit(cache=True)
def _friction_force(fric, work, lay, lob):
    """Generalised friction force of every lobe (tangential on the shaft, torque mu W r)."""
    fric[:] = 0.0
    for j in range(lay.ix.size):
        fric[lay.ix[j]] += -work.tang[j] * lob.sina[j]
        fric[lay.iy[j]] += work.tang[j] * lob.cosa[j]
        fric[lay.iphi[j]] += -work.fr[j] * work.arm[j]


@njit(cache=True, inline="always")
def _block_matrix(mats, lo, hi, a0, a1):
    """A = K + a1 C + a0 M on the block [lo, hi), in Fortran order: built as A^T row by row
    from the transposes (:data:`.records.Matrices`; unsigned indices, so the compiler
    vectorises the rows), which LAPACK reads as A without a transposing copy."""
    KT, CT, MT = mats.KT, mats.CT, mats.MT
    ulo, size = np.uint64(lo), np.uint64(hi - lo)
    AT = np.empty((size, size))
    for e in range(size):
        ge = ulo + e
        for i in range(size):
            AT[e, i] = KT[ge, ulo + i] + a1 * CT[ge, ulo + i] + a0 * MT[ge, ulo + i]
    return AT.T


@njit(cache=True, inline="always")
def _block_rhs(mats, fric, wv, cv, lo, hi, columns):
    """The block [lo, hi)'s right-hand sides: f0 + friction + M wv + C cv in the first column
    (every row summing its terms in column order), ``columns`` more left zero."""
    CT, MT, f0 = mats.CT, mats.MT, mats.f0
    ulo, size = np.uint64(lo), np.uint64(hi - lo)
    r = np.empty(size)
    for i in range(size):
        r[i] = f0[ulo + i] + fric[ulo + i]
    for e in range(size):
        ge = ulo + e
        we, ce = wv[ge], cv[ge]
        for i in range(size):
            r[i] += MT[ge, ulo + i] * we + CT[ge, ulo + i] * ce
    R = np.zeros((size, 1 + columns))
    for i in range(size):
        R[i, 0] = r[i]
    return R


@njit(cache=True)
def _substep(tau, sys, st, fric, at, x, stagger, upd):
    """A Newmark step of length ``tau`` from the state with the contact states fixed, the
    linear part solved block by block (inputs ``at`` at the sub-step's end). ``stagger``: the
    shaft carries the predicted contact loads (in ``fric``) and the trains take its motion at
    the sub-step's end as prescribed input (:mod:`._partition`)."""
    lay = sys.lay
    n = st.q.size
    lobes, w = lay.ix.size, width(lay)
    a1 = 2.0 / tau
    x0 = np.empty(n)
    basis = np.zeros((w * lobes, n))     # one row per contact coordinate (Stepper.basis)
    blocks = lay.blocks
    q, v, acc = st.q, st.v, st.acc
    a0 = 4.0 / (tau * tau)
    wv, cv = np.empty(n), np.empty(n)       # what M and C multiply in the right-hand side
    for i in range(n):
        wv[i] = a0 * q[i] + (4.0 / tau) * v[i] + acc[i]
        cv[i] = a1 * q[i] + v[i]
    for k in range(blocks.size - 1):
        lo, hi = blocks[k], blocks[k + 1]
        size = hi - lo
        cols = []
        for j in range(lobes):
            dofs = lobe_dofs(lay, j)
            for e in range(w):
                if lo <= dofs[e] < hi:
                    cols.append((w * j + e, dofs[e]))
        R = _block_rhs(sys.mats, fric, wv, cv, lo, hi, len(cols))
        for c in range(len(cols)):
            R[cols[c][1] - lo, 1 + c] = 1.0
        S = np.linalg.solve(_block_matrix(sys.mats, lo, hi, a0, a1), R)
        for i in range(size):
            x0[lo + i] = S[i, 0]
        for c in range(len(cols)):
            col = cols[c][0]
            for i in range(size):
                basis[col, lo + i] = S[i, 1 + c]
    z = np.zeros(w * lobes)     # friction is in the right-hand side already
    ends = at       # the contacts' inputs at the sub-step's end
    if stagger:     # the shaft's part of x0 is final: no contact column reaches it
        v0 = np.empty(n)
        for i in range(n):
            v0[i] = a1 * (x0[i] - st.q[i]) - st.v[i]
        pre = LobeAt(np.empty(lobes), np.empty(lobes), np.zeros(lobes), np.zeros(lobes),
                     np.zeros(lobes))
        prescribed_inputs(x0, v0, at, lay, pre)
        ends = pre
    update(x0, basis, basis_rows(basis, lay), z, x, q, v, st.act_c, st.act_s, st.hp,
           st.hp_end, ends, a1, upd, contact_laws(sys.uni), sys.hla)


@njit(cache=True, inline="always")
def _equilibrium(sys, st, fric, at, stagger):
    """acc = M^-1 (f0 + friction + contact forces - K q - C v), block by block (``Minv`` the
    block-diagonal inverse of M); a sealed incompressible adjuster's chamber restarted
    consistently with it (:mod:`camtrain.coupled.adjuster_step`)."""
    lay, mats, uni = sys.lay, sys.mats, sys.uni
    KT, CT, MinvT, blocks = mats.KT, mats.CT, mats.MinvT, lay.blocks
    q, v, acc = st.q, st.v, st.acc
    kc, cc, ks, cs, offs = uni.k[0], uni.c[0], uni.k[1], uni.c[1], uni.off[1]
    n = q.size
    r = np.empty(n)
    rb = np.empty(n)
    for i in range(n):
        r[i] = mats.f0[i] + fric[i]
    for j in range(lay.ix.size):
        if st.act_c[j]:
            d, dd = cam_gap(q, v, j, lay.ix, lay.iy, lay.iphi, lay.ifol, uni.off[0], at.b[j],
                            at.bd[j], at.gx[j], at.gy[j], at.gphi[j])
            w = kc * d + cc * dd
            r[lay.ifol[j]] += w
            if not stagger:     # staggered: the shaft carries the predicted load (in fric)
                r[lay.ix[j]] -= w * at.gx[j]
                r[lay.iy[j]] -= w * at.gy[j]
                r[lay.iphi[j]] -= w * at.gphi[j]
        if st.act_s[j]:
            r[lay.ival[j]] += ks * (offs - q[lay.ival[j]]) - cs * v[lay.ival[j]]
    if sys.hla.on:     # the adjusters' chambers at their pressures: body and plunger apart
        add_chamber_forces(sys.hla, st.hp, q, lay.ifol, lay.ipl, r)
    for k in range(blocks.size - 1):     # row by row of the transposes (see _block_matrix)
        lo, hi = np.uint64(blocks[k]), np.uint64(blocks[k + 1])
        for i in range(lo, hi):
            rb[i] = r[i]
        for e in range(lo, hi):
            qe, ve = q[e], v[e]
            for i in range(lo, hi):
                rb[i] -= KT[e, i] * qe + CT[e, i] * ve
        for i in range(lo, hi):
            acc[i] = 0.0
        for e in range(lo, hi):
            rbe = rb[e]
            for i in range(lo, hi):
                acc[i] += MinvT[e, i] * rbe
    if sys.hla.on:      # a sealed incompressible chamber: its pressure is the constraint's
        restart_sealed(sys.hla, st.hp, acc, mats.Minv, lay.ifol, lay.ipl)


@njit(cache=True)
def _indicators(z, zd, j, ix, iy, iphi, ifol, ival, uni, bj, bdj, gxj, gyj, gphij):
    """(psi, delta, delta') of lobe j's cam contact and of its seat."""
    d, dd = cam_gap(z, zd, j, ix, iy, iphi, ifol, uni.off[0], bj, bdj, gxj, gyj, gphij)
    ds, dds = uni.off[1] - z[ival[j]], -zd[ival[j]]
    return _psi(uni.k[0], uni.c[0], d, dd), d, dd, _psi(uni.k[1], uni.c[1], ds, dds), ds, dds


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


@njit(cache=True, inline="always")
def _first_crossing(sys, st, work, at, lob, s, tau, h):
    """The contact that changes state first inside the (sub)step from tau, length h: (lobe,
    whether the seat, fraction of the sub-step), or (-1, False, 2)."""
    lay, uni, dt = sys.lay, sys.uni, sys.step.dt
    x, v1 = work.x, work.v1
    first, seat, alpha = -1, False, 2.0
    ix, iy, iphi, ifol, ival = lay.ix, lay.iy, lay.iphi, lay.ifol, lay.ival
    for j in range(ix.size):
        work.b0[j], work.bd0[j], g0x, g0y, g0p = _inputs(lob, j, s, tau / dt, dt)
        pc0, d0, dd0, ps0, ds0, dds0 = _indicators(st.q, st.v, j, ix, iy, iphi, ifol, ival, uni,
                                                   work.b0[j], work.bd0[j], g0x, g0y, g0p)
        pc1, d1, dd1, ps1, ds1, dds1 = _indicators(x, v1, j, ix, iy, iphi, ifol, ival, uni,
                                                   at.b[j], at.bd[j], at.gx[j], at.gy[j],
                                                   at.gphi[j])
        if (pc1 > 0.0) != st.act_c[j]:
            frac = _crossing(uni.k[0], uni.c[0], d0, dd0, d1, dd1, h)
            if frac < alpha:
                first, seat, alpha = j, False, frac
        if (ps1 > 0.0) != st.act_s[j]:
            frac = _crossing(uni.k[1], uni.c[1], ds0, dds0, ds1, dds1, h)
            if frac < alpha:
                first, seat, alpha = j, True, frac
    return first, seat, alpha


@njit(cache=True)
def _split(sys, st, work, at, lob, s, stagger):
    """The step split at every contact change inside it (at most MAX_SWITCHES): returns the
    changes located and whether there were more. The sub-steps carry friction, the belt's
    pull, the staggered step's predicted loads and the drive's inertia load in their
    right-hand side (``work.fric``)."""
    fric, drive, dt = work.fric, sys.drive, sys.step.dt
    _friction_force(fric, work, sys.lay, lob)
    if drive.x >= 0:
        fric[drive.x] += work.hub[0]
        fric[drive.y] += work.hub[1]
    if stagger:
        add_shaft_forces(fric, work.w_pred, at, sys.lay)
    drive_acc = lob.drive_acc[s]
    if drive_acc != 0.0:
        for i in range(fric.size):
            fric[i] -= drive.j[i] * drive_acc
    q, v, acc, x = st.q, st.v, st.acc, work.x
    n = q.size
    tau = 0.0
    switches = 0
    while True:
        h = dt - tau
        if h <= 1e-12 * dt:
            break
        if switches > 0:   # the full step with the start's states is x, v1 already
            _substep(h, sys, st, fric, at, x, stagger, work.upd)
            for i in range(n):
                work.v1[i] = (2.0 / h) * (x[i] - q[i]) - v[i]
        first, seat, alpha = _first_crossing(sys, st, work, at, lob, s, tau, h)
        if first < 0 or switches >= MAX_SWITCHES:
            for i in range(n):      # the (sub)step taken
                work.a1v[i] = (4.0 / (h * h)) * (x[i] - q[i]) - (4.0 / h) * v[i] - acc[i]
                q[i] = x[i]
                v[i] = work.v1[i]
                acc[i] = work.a1v[i]
            st.hp[:] = st.hp_end
            return switches, 1 if first >= 0 else 0
        # take the step up to the change, switch the contact, restart the acceleration
        hs = alpha * h
        set_inputs(at, lob, s, (tau + hs) / dt, dt)
        if hs > 1e-12 * dt:
            _substep(hs, sys, st, fric, at, x, stagger, work.upd)
            for i in range(n):
                v[i] = (2.0 / hs) * (x[i] - q[i]) - v[i]
                q[i] = x[i]
            st.hp[:] = st.hp_end
        tau += hs
        if seat:
            st.act_s[first] = not st.act_s[first]
        else:
            st.act_c[first] = not st.act_c[first]
        _equilibrium(sys, st, fric, at, stagger)
        switches += 1
        set_inputs(at, lob, s, 1.0, dt)
    return switches, 0


@njit(cache=True, inline="always")
def advance(s, sys, st, work, at, pre, lob, torque, stagger, fresh, laws):
    """Step s of the revolution (:func:`camtrain.coupled._revolution.revolution`): the state
    ``st`` advanced in place, ``at`` every lobe's inputs at the step's end, ``torque`` the
    summed lobe torque of the last step (the belt's pull). ``stagger``: the shaft under the
    predicted loads ``work.w_pred`` first, then the trains with its motion prescribed in
    ``pre`` (:mod:`._partition`). ``fresh`` False: ``work.base`` (the step's solution without
    contact and friction forces, P = A^-1 M, Q = A^-1 C) is still that of the same start, from
    the step's previous pass. The drive's angular acceleration at the step's end
    (``lob.drive_acc``) loads the twist, measured from the drive, with -J theta''. Returns the
    contact changes located and whether the step had more than MAX_SWITCHES. ``laws``: the
    contact laws as numbers (:func:`contact_laws`)."""
    step, drive, lay = sys.step, sys.drive, sys.lay
    q, v, acc = st.q, st.v, st.acc
    base, hub, zf, x, v1 = work.base, work.hub, work.zf, work.x, work.v1
    a0, a1, dt = step.a0, step.a1, step.dt
    n, lobes, w = q.size, lay.ix.size, width(lay)
    if fresh:   # the full step with the states of its start
        rhs_w, rhs_c, blocks = work.rhs_w, work.rhs_c, lay.blocks
        for i in range(n):
            rhs_w[i] = a0 * q[i] + (4.0 / dt) * v[i] + acc[i]
            rhs_c[i] = a1 * q[i] + v[i]
        PT, QT, x_f0 = step.PT, step.QT, step.x_f0
        for k in range(blocks.size - 1):
            lo, hi = np.uint64(blocks[k]), np.uint64(blocks[k + 1])
            for i in range(lo, hi):
                base[i] = x_f0[i]
            for e in range(lo, hi):
                rw, rc = rhs_w[e], rhs_c[e]
                for i in range(lo, hi):
                    base[i] += PT[e, i] * rw + QT[e, i] * rc
        if drive.x >= 0:      # the belt's torque-dependent pull at the drive station
            pull = abs(torque) / drive.radius
            hub[0], hub[1] = pull * drive.cos, pull * drive.sin
            for i in range(n):
                base[i] += drive.basis[i, 0] * hub[0] + drive.basis[i, 1] * hub[1]
        if lob.drive_acc[s] != 0.0:    # the drive's speed oscillation: -J theta'' on the twist
            for i in range(n):
                base[i] -= drive.u[i] * lob.drive_acc[s]
    zf[:] = 0.0
    for j in range(lobes):      # friction on the lobe's coordinates
        zf[w * j] = -work.tang[j] * lob.sina[j]
        zf[w * j + 1] = work.tang[j] * lob.cosa[j]
        zf[w * j + 2] = -work.fr[j] * work.arm[j]
    ends = at       # the contacts' inputs at the step's end
    if stagger:     # the shaft first, under the predicted loads; the trains on its motion
        add_shaft_loads(zf, work.w_pred, at)
        for i in range(n):
            x[i] = base[i]
        for c in range(w * lobes):
            zc = zf[c]
            for i in range(n):
                x[i] += step.basis[c, i] * zc
        for i in range(n):
            v1[i] = a1 * (x[i] - q[i]) - v[i]
        prescribed_inputs(x, v1, at, lay, pre)
        ends = pre
    update(base, step.basis, step.G, zf, x, q, v, st.act_c, st.act_s, st.hp, st.hp_end, ends,
           a1, work.upd, laws, sys.hla)
    for i in range(n):
        v1[i] = a1 * (x[i] - q[i]) - v[i]
    if _changes(x, v1, st.act_c, st.act_s, work.upd.dof, at, laws):
        return _split(sys, st, work, at, lob, s, stagger)
    for i in range(n):
        acc[i] = a0 * (x[i] - q[i]) - (4.0 / dt) * v[i] - acc[i]
        q[i] = x[i]
        v[i] = v1[i]
    st.hp[:] = st.hp_end
    return 0, 0


@njit(cache=True)
def _changes(x, v1, act_c, act_s, dof, at, laws):
    """Whether any contact's state (``act_c``, ``act_s``) differs at the trial step's end
    (x, v1) from its start: every lobe's indicators as :func:`_indicators` forms them, from
    its state indices ``dof`` and the contact laws ``laws`` (:func:`contact_laws`)."""
    kc, cc, offc, ks, cs, offs = laws
    for j in range(act_c.size):
        ix, iy, iphi, ifol, ival = dof[j, 0], dof[j, 1], dof[j, 2], dof[j, 3], dof[j, 4]
        gx, gy, gphi = at.gx[j], at.gy[j], at.gphi[j]
        d = gap_of(at.b[j] + offc, gx, gy, gphi, x[ix], x[iy], x[iphi], x[ifol])
        dd = gap_of(at.bd[j], gx, gy, gphi, v1[ix], v1[iy], v1[iphi], v1[ifol])
        if (_psi(kc, cc, d, dd) > 0.0) != act_c[j]:
            return True
        if (_psi(ks, cs, offs - x[ival], -v1[ival]) > 0.0) != act_s[j]:
            return True
    return False
