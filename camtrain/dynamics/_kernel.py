"""Compiled marches of the lumped valve train (numba, cached on disk).

Two fixed-step schemes over one batch of steps (a camshaft revolution), both with the unilateral
cam contact and valve seat of :mod:`camtrain.dynamics.train`:

* ``newmark_march``: Newmark average acceleration (gamma = 1/2, beta = 1/4: trapezoidal,
  unconditionally stable, second order, no numerical damping). The linear system of a full step
  is inverted once per contact state (4 states); when a contact opens or closes inside a step the
  crossing of its indicator psi is located by regula falsi (Illinois) on sub-steps, the step is
  split there, the acceleration restarted from the equilibrium with the new contact state, and the
  rest of the step marched with it.
  A roller's spin (:mod:`camtrain.dynamics.spin`) is advanced over every accepted (sub)step
  at its end state's cam force (backward Euler).
* ``central_difference_march`` (:mod:`._explicit`): Teodorescu et al. (2005) eq. 17, explicit,
  velocity by the backward difference (l' = (l_n - l_(n-1)) / dt, as the source); conditionally
  stable (the caller guards the step).

The data come as the typed records of :mod:`camtrain.dynamics.records` (the train's linear
part, its unilateral contacts, the cam law, the inputs, the state, the samples). Inputs b, b' of
each contact at the step times (seat: zeros); between steps a cubic Hermite in
time. The cam contact's spring is linear (``law`` 0) or a Hertz line contact (``law`` 1, the
relation of :mod:`camtrain.dynamics.contact_law`, constants ``hz``, the cam's radius of
curvature ``rad`` and load ratio ``rat`` at the step times, linear between them): its force
comes from a scalar Newton iteration inside the Newmark step, the linear rest of the step
still solved with the factor of its contact state. Outputs every ``stride`` steps; events
(contact j opening/closing: kind 2 j + closing) with their time and the contact's approach
speed delta'. Only this module imports numba.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np
from numba import njit

from camtrain.dynamics.hla.in_train import (
    add_chamber_force,
    chamber_in_step,
    sample_chamber,
    sealed_restart,
)
from camtrain.dynamics.spin.in_train import sample_spin, spin_step
from camtrain.numerics.compile_notice import announce
from camtrain.numerics.roots import false_position, illinois_update

MAX_SWITCHES = 8

#: work arrays of a Newmark trial step: predictor (pu, pv), right-hand side, A^-1 e_cam,
#: A^-1 (e_plunger - e_body) of a hydraulic lash adjuster
_Work = namedtuple("_Work", "pu pv rhs z zh")


@njit(cache=True)
def _input(b, bd, j, n, tau, dt):
    """Cubic Hermite in time of contact j's input between steps n and n+1 (tau in [0, dt])."""
    if tau <= 0.0:
        return b[j, n], bd[j, n]
    if tau >= dt:
        return b[j, n + 1], bd[j, n + 1]
    s = tau / dt
    s2, s3 = s * s, s * s * s
    y0, y1 = b[j, n], b[j, n + 1]
    m0, m1 = bd[j, n] * dt, bd[j, n + 1] * dt
    val = (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * y1 \
        + (s3 - s2) * m1
    der = ((6 * s2 - 6 * s) * y0 + (3 * s2 - 4 * s + 1) * m0 + (-6 * s2 + 6 * s) * y1
           + (3 * s2 - 2 * s) * m1) / dt
    return val, der


@njit(cache=True)
def _geom(rad, rat, n, tau, dt):
    """Cam radius of curvature and load ratio at time tau into step n (linear)."""
    if rad.size == 0:   # a linear cam contact: no geometry
        return 1.0, 1.0
    s = min(max(tau / dt, 0.0), 1.0)
    m = min(n + 1, rad.size - 1)
    return rad[n] + s * (rad[m] - rad[n]), rat[n] + s * (rat[m] - rat[n])


@njit(cache=True)
def _hz_deflection(f, r1, ratio, hz):
    """Valve-referred deflection of the Hertz line contact (and its series spring) under a
    valve-referred force f > 0, and its derivative (contact_law.HertzLineLaw)."""
    c1, c2, length, r2, ks = hz[0], hz[1], hz[2], hz[3], hz[4]
    w = f * ratio / length
    r = r1 * r2 / (r1 + r2)
    b = np.sqrt(4.0 * w * r * (c1 + c2) / np.pi)
    l1 = np.log(4.0 * r1 / b)
    l2 = np.log(4.0 * r2 / b)
    d = w / np.pi * (c1 * (2.0 * l1 - 1.0) + c2 * (2.0 * l2 - 1.0)) * ratio
    dd = 2.0 / np.pi * (c1 * (l1 - 1.0) + c2 * (l2 - 1.0)) * ratio * ratio / length
    if ks > 0.0:
        d += f / ks
        dd += 1.0 / ks
    return d, dd


@njit(cache=True)
def _hz_solve(target, s, r1, ratio, hz, guess):
    """Force f >= 0 with deflection(f) + s f = target (s >= 0: the step's own compliance;
    Newton from ``guess``, halving when it would leave f > 0)."""
    if target <= 0.0:
        return 0.0
    f = guess if guess > 0.0 else target * 1e8
    for _ in range(60):
        d, dd = _hz_deflection(f, r1, ratio, hz)
        fn = f - (d + s * f - target) / (dd + s)
        if fn <= 0.0:
            fn = 0.5 * f
        if abs(fn - f) <= 1e-13 * fn:
            return fn
        f = fn
    return f


@njit(cache=True)
def _spring(j, delta, k, law, hz, r1, ratio):
    """Spring force of contact j at compression delta: linear, or (cam, law 1) the Hertz line
    contact; a negative delta gives k delta (only its sign matters: the contact indicator)."""
    if j == 0 and law == 1 and delta > 0.0:
        return _hz_solve(delta, 0.0, r1, ratio, hz, k[0] * delta)
    return k[j] * delta


@njit(cache=True)
def _psi(u, v, j, node, k, c, off, bj, bdj, law, hz, r1, ratio):
    """Contact indicator min(F_spring, F_spring + c delta') and the force it would carry."""
    delta = bj - u[node[j]] + off[j]
    rate = bdj - v[node[j]]
    if j == 0 and law == 1 and delta > 0.0:
        g = _hz_solve(delta, 0.0, r1, ratio, hz, k[0] * delta)
    else:
        g = k[j] * delta
    f = g + c[j] * rate
    return min(g, f), f, rate


@njit(cache=True)
def _accel(tr, uni, cl, inp, act, u, v, n, tau, a, p):
    """a = M^-1 (f0 + contact forces - C v - K u) for the given contact state (an adjuster's
    chamber at pressure p)."""
    m, K, C, f0, node = tr.m, tr.K, tr.C, tr.f0, tr.node
    b, bd, dt = inp.b, inp.bd, inp.dt
    size = m.size
    for i in range(size):
        s = f0[i]
        for q in range(size):
            s -= K[i, q] * u[q] + C[i, q] * v[q]
        a[i] = s
    r1, ratio = _geom(cl.rad, cl.rat, n, tau, dt)
    for j in range(node.size):
        if act[j]:
            bj, bdj = _input(b, bd, j, n, tau, dt)
            a[node[j]] += _spring(j, bj - u[node[j]] + uni.off[j], uni.k, cl.law, cl.hz, r1,
                                  ratio) + uni.c[j] * (bdj - v[node[j]])
    add_chamber_force(tr.hla, u, p, a)
    for i in range(size):
        a[i] /= m[i]


@njit(cache=True)
def _matrix(tr, uni, act, h, law):
    """M + h^2/4 K + h/2 C with the active contacts (a Hertz cam contact's spring is not in
    it: its force is solved for separately)."""
    m, K, C, node, k, c = tr.m, tr.K, tr.C, tr.node, uni.k, uni.c
    size = m.size
    A = np.empty((size, size))
    for i in range(size):
        for q in range(size):
            A[i, q] = 0.25 * h * h * K[i, q] + 0.5 * h * C[i, q]
        A[i, i] += m[i]
    for j in range(node.size):
        if act[j]:
            i = node[j]
            kj = 0.0 if (j == 0 and law == 1) else k[j]
            A[i, i] += 0.25 * h * h * kj + 0.5 * h * c[j]
    return A


@njit(cache=True)
def _trial(tr, uni, cl, inp, act, u, v, a, hp, n, tau, h, Ainv, out, work):
    """One Newmark step of length h from time tau of step n, contact state fixed: the end
    state into ``out`` (u1, v1, a1, adjuster's chamber), ``work`` (pu, pv, rhs, z, zh) its work
    arrays. A Hertz cam contact: a1 = A^-1 (rhs + e_i F) with the scalar F solving
    F = F_hertz(delta(a1)), delta = D - h^2/4 z_i F (z = A^-1 e_i); a hydraulic lash adjuster
    (``hp`` its chamber at the start): :func:`camtrain.dynamics.hla.in_train.chamber_in_step`.
    The deck allows not both."""
    u1, v1, a1 = out[0], out[1], out[2]
    pu, pv, rhs, z = work.pu, work.pv, work.rhs, work.z
    m, K, C, f0, node = tr.m, tr.K, tr.C, tr.f0, tr.node
    k, c, off = uni.k, uni.c, uni.off
    size = m.size
    for i in range(size):
        pu[i] = u[i] + h * v[i] + 0.25 * h * h * a[i]
        pv[i] = v[i] + 0.5 * h * a[i]
    for i in range(size):
        s = f0[i]
        for q in range(size):
            s -= K[i, q] * pu[q] + C[i, q] * pv[q]
        rhs[i] = s
    hertz = cl.law == 1 and act[0]
    for j in range(node.size):
        if act[j]:
            bj, bdj = _input(inp.b, inp.bd, j, n, tau + h, inp.dt)
            i = node[j]
            if j == 0 and hertz:
                rhs[i] += c[j] * (bdj - pv[i])
            else:
                rhs[i] += k[j] * (bj - pu[i] + off[j]) + c[j] * (bdj - pv[i])
    A = np.empty((0, 0))
    if Ainv.shape[0] > 0:
        for i in range(size):
            s = 0.0
            for q in range(size):
                s += Ainv[i, q] * rhs[q]
            a1[i] = s
        if hertz:
            for i in range(size):
                z[i] = Ainv[i, node[0]]
    else:
        A = _matrix(tr, uni, act, h, cl.law)
        a1[:] = np.linalg.solve(A, rhs)
        if hertz:
            z[:] = 0.0
            z[node[0]] = 1.0
            z[:] = np.linalg.solve(A, z.copy())
    if hertz:
        i = node[0]
        r1, ratio = _geom(cl.rad, cl.rat, n, tau + h, inp.dt)
        bj, bdj = _input(inp.b, inp.bd, 0, n, tau + h, inp.dt)
        target = bj - pu[i] - 0.25 * h * h * a1[i] + off[0]
        f = _hz_solve(target, 0.25 * h * h * z[i], r1, ratio, cl.hz, k[0] * max(target, 0.0))
        if target <= 0.0:
            # compressed by less than nothing: the linear stand-in (the indicator opens it)
            f = k[0] * target / (1.0 + 0.25 * h * h * z[i] * k[0])
        for q in range(size):
            a1[q] += f * z[q]
    if tr.hla.on:
        chamber_in_step(tr.hla, hp, u, Ainv, A, h, pu, pv, a1, work.zh, out[3])
    for i in range(size):
        u1[i] = pu[i] + 0.25 * h * h * a1[i]
        v1[i] = pv[i] + 0.5 * h * a1[i]


@njit(cache=True)
def _state_index(act):
    idx = 0
    for j in range(act.size):
        if act[j]:
            idx += 1 << j
    return idx


@njit(cache=True)
def _locate(tr, uni, cl, inp, st, end, sub, work, first, alpha, n, tau, h):
    """The crossing of contact ``first``'s indicator in (0, h) by Illinois regula falsi, the
    state at it in ``sub`` (us, vs, as); returns the fraction of the step."""
    u, v, a, act = st.u, st.v, st.a, st.act
    node, k, c, off, law, hz, dt = tr.node, uni.k, uni.c, uni.off, cl.law, cl.hz, inp.dt
    empty = np.empty((0, 0))
    lo, hi = 0.0, 1.0
    level = 0.0 if act[first] else tr.thr[first]
    bj, bdj = _input(inp.b, inp.bd, first, n, tau, dt)
    r1, ratio = _geom(cl.rad, cl.rat, n, tau, dt)
    plo = _psi(u, v, first, node, k, c, off, bj, bdj, law, hz, r1, ratio)[0] - level
    bj, bdj = _input(inp.b, inp.bd, first, n, tau + h, dt)
    r1, ratio = _geom(cl.rad, cl.rat, n, tau + h, dt)
    phi = _psi(end[0], end[1], first, node, k, c, off, bj, bdj, law, hz, r1, ratio)[0] - level
    x = alpha
    side = 0
    for _ in range(30):
        _trial(tr, uni, cl, inp, act, u, v, a, st.hp, n, tau, x * h, empty, sub, work)
        bj, bdj = _input(inp.b, inp.bd, first, n, tau + x * h, dt)
        r1, ratio = _geom(cl.rad, cl.rat, n, tau + x * h, dt)
        px = _psi(sub[0], sub[1], first, node, k, c, off, bj, bdj, law, hz, r1, ratio)[0] \
            - level
        if abs(px) <= 1e-12 * (abs(plo) + abs(phi)) or hi - lo < 1e-10:
            break
        lo, plo, hi, phi, side = illinois_update(lo, plo, hi, phi, x, px, side)
        x = false_position(lo, plo, hi, phi) if plo != phi else 0.5 * (lo + hi)
    return x


@njit(cache=True)
def _switch(tr, uni, cl, inp, st, out, nev, first, n, tau):
    """Contact ``first`` switched at time tau into step n: its event recorded, the
    acceleration restarted from the equilibrium (a sealed incompressible adjuster's chamber
    with it: :mod:`camtrain.dynamics.hla.sealed`). Returns the events so far."""
    closing = not st.act[first]
    st.act[first] = closing
    bj, bdj = _input(inp.b, inp.bd, first, n, tau, inp.dt)
    rate = bdj - st.v[tr.node[first]]
    if nev < out.ev_t.size:
        out.ev_t[nev] = inp.t0 + n * inp.dt + tau
        out.ev_kind[nev] = 2 * first + (1 if closing else 0)
        out.ev_rate[nev] = rate
    _accel(tr, uni, cl, inp, st.act, st.u, st.v, n, tau, st.a, st.hp[0])
    sealed_restart(tr.hla, st.hp, st.a, tr.m)
    return nev + 1


@njit(cache=True)
def _sample(tr, uni, cl, inp, st, out, n, spin):
    """The state and contact forces at the end of step n into the samples (``spin`` the
    roller's record, ``on`` 0 without one)."""
    r = (n + 1) // inp.stride - 1
    out.u[:, r] = st.u
    out.v[:, r] = st.v
    out.a[:, r] = st.a
    r1, ratio = _geom(cl.rad, cl.rat, n + 1, 0.0, inp.dt)
    b, bd, node = inp.b, inp.bd, tr.node
    for j in range(node.size):
        if st.act[j]:
            out.f[j, r] = _spring(j, b[j, n + 1] - st.u[node[j]] + uni.off[j], uni.k, cl.law,
                                  cl.hz, r1, ratio) + uni.c[j] * (bd[j, n + 1] - st.v[node[j]])
        else:
            out.f[j, r] = 0.0
    if tr.hla.on:
        sample_chamber(tr.hla, st.hp, st.u, out.h, r)
    if spin.on:
        sample_spin(st.wr, out.r, r)


@njit(cache=True)
def _inverses(tr, uni, dt, law):
    """The full step's (M + dt^2/4 K + dt/2 C)^-1, once per contact state."""
    size, nu = tr.m.size, tr.node.size
    inverses = np.empty((1 << nu, size, size))
    state = np.zeros(nu, dtype=np.bool_)
    for s_idx in range(1 << nu):
        for j in range(nu):
            state[j] = (s_idx >> j) & 1
        inverses[s_idx] = np.linalg.inv(_matrix(tr, uni, state, dt, law))
    return inverses


@njit(cache=True)
def newmark_march(tr, uni, cl, inp, st, out, spin):
    """March len(b[0]) - 1 steps; state ``st`` (u, v, a, act) updated in place, samples and
    events into ``out``; ``spin`` the roller's record (``on`` 0 without one), marched after
    every accepted (sub)step.

    An open contact closes when psi exceeds ``thr`` (a force far below any load of interest):
    without it a zero-lash contact at rest on the base circle would switch on every round-off
    ripple of the ringing train. (The step's hot path calls the compiled helpers with plain
    arrays: a record passed to a small function called several times a step costs more than
    its arithmetic.)

    Returns (events recorded, cam work [J] = integral of F_cam b' dt, switches cut short).
    """
    node, thr, k, c, off = tr.node, tr.thr, uni.k, uni.c, uni.off
    law, hz, rad, rat = cl.law, cl.hz, cl.rad, cl.rat
    b, bd, dt = inp.b, inp.bd, inp.dt
    u, v, a, act = st.u, st.v, st.a, st.act
    size, nu = tr.m.size, node.size
    inverses = _inverses(tr, uni, dt, law)
    empty = np.empty((0, 0))
    u1, v1, a1 = np.empty(size), np.empty(size), np.empty(size)
    end = (u1, v1, a1, st.hp.copy())
    sub = (np.empty(size), np.empty(size), np.empty(size), st.hp.copy())
    work = _Work(np.empty(size), np.empty(size), np.empty(size), np.empty(size), np.empty(size))
    nev = 0
    energy = 0.0
    cut = 0
    for n in range(b.shape[1] - 1):
        tau = 0.0
        switches = 0
        while True:
            h = dt - tau
            if h <= 0.0:
                break
            Ainv = inverses[_state_index(act)] if tau == 0.0 else empty
            _trial(tr, uni, cl, inp, act, u, v, a, st.hp, n, tau, h, Ainv, end, work)
            # which contact changes state first inside the (sub)step?
            first = -1
            alpha = 2.0
            r0, q0 = 1.0, 1.0
            r1, q1 = 1.0, 1.0
            if law == 1:
                r0, q0 = _geom(rad, rat, n, tau, dt)
                r1, q1 = _geom(rad, rat, n, tau + h, dt)
            for j in range(nu):
                level = 0.0 if act[j] else thr[j]
                bj, bdj = _input(b, bd, j, n, tau, dt)
                p0 = _psi(u, v, j, node, k, c, off, bj, bdj, law, hz, r0, q0)[0] - level
                bj, bdj = _input(b, bd, j, n, tau + h, dt)
                p1 = _psi(u1, v1, j, node, k, c, off, bj, bdj, law, hz, r1, q1)[0] - level
                if (p1 > 0.0) != act[j]:
                    frac = p0 / (p0 - p1) if p0 != p1 else 1.0
                    frac = min(max(frac, 0.0), 1.0)
                    if frac < alpha:
                        alpha, first = frac, j
            stop = first < 0 or switches >= MAX_SWITCHES
            if stop:
                cut += 1 if first >= 0 else 0
                hx, to = h, end       # accept the (sub)step
            else:
                hx, to = _locate(tr, uni, cl, inp, st, end, sub, work, first, alpha, n, tau,
                                 h) * h, sub
            # the cam's work over the (sub)step, trapezoid (the two halves added in turn)
            energy += _cam_power(u, v, act, node, k, c, off, b, bd, n, tau, dt, law, hz, rad,
                                 rat) * 0.5 * hx
            energy += _cam_power(to[0], to[1], act, node, k, c, off, b, bd, n, tau + hx, dt,
                                 law, hz, rad, rat) * 0.5 * hx
            u[:] = to[0]
            v[:] = to[1]
            st.hp[:] = to[3]
            if spin.on and hx > 0.0:   # the roller's spin over the same (sub)step
                spin_step(spin, st.wr, n, tau + hx, dt, hx,
                          _cam_force(u, v, act, node, k, c, off, b, bd, n, tau + hx, dt, law,
                                     hz, rad, rat))
            if stop:
                a[:] = a1
                break
            tau += hx
            nev = _switch(tr, uni, cl, inp, st, out, nev, first, n, tau)
            switches += 1
        if (n + 1) % inp.stride == 0:
            _sample(tr, uni, cl, inp, st, out, n, spin)
    return nev, energy, cut


@njit(cache=True, inline="always")
def _cam_force(u, v, act, node, k, c, off, b, bd, n, tau, dt, law, hz, rad, rat):
    """The valve-referred cam force F_cam [N] at time tau into step n (contact 0 is the cam).
    Inlined where it is called: :func:`_cam_power` calls it twice a step, and as a call of its
    own it cost the Newmark march about a tenth of its time (Zeta intake deck)."""
    if not act[0]:
        return 0.0
    bj, bdj = _input(b, bd, 0, n, tau, dt)
    delta = bj - u[node[0]] + off[0]
    if law == 1:
        r1, ratio = _geom(rad, rat, n, tau, dt)
        g = _spring(0, delta, k, law, hz, r1, ratio)
    else:
        g = k[0] * delta
    return g + c[0] * (bdj - v[node[0]])


@njit(cache=True)
def _cam_power(u, v, act, node, k, c, off, b, bd, n, tau, dt, law, hz, rad, rat):
    """F_cam b' [W] (contact 0 is the cam)."""
    if not act[0]:
        return 0.0
    bdj = _input(b, bd, 0, n, tau, dt)[1]
    return _cam_force(u, v, act, node, k, c, off, b, bd, n, tau, dt, law, hz, rad, rat) * bdj


announce("valve-train dynamics", (newmark_march,))
