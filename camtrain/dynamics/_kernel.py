"""Compiled marches of the lumped valve train (numba, cached on disk).

Two fixed-step schemes over one batch of steps (a camshaft revolution), both with the unilateral
cam contact and valve seat of :mod:`camtrain.dynamics.train`:

* ``newmark_march``: Newmark average acceleration (gamma = 1/2, beta = 1/4: trapezoidal,
  unconditionally stable, second order, no numerical damping). The linear system of a full step
  is inverted once per contact state (4 states); when a contact opens or closes inside a step the
  crossing of its indicator psi is located by regula falsi (Illinois) on sub-steps, the step is
  split there, the acceleration restarted from the equilibrium with the new contact state, and the
  rest of the step marched with it.
* ``central_difference_march``: Teodorescu et al. (2005) eq. 17, explicit, velocity by the
  backward difference (l' = (l_n - l_(n-1)) / dt, as the source); conditionally stable (the
  caller guards the step).

Inputs b, b' of each contact at the step times (seat: zeros); between steps a cubic Hermite in
time. Outputs every ``stride`` steps; events (contact j opening/closing: kind 2 j + closing)
with their time and the contact's approach speed delta'. Only this module imports numba.
"""
from __future__ import annotations

import numpy as np
from numba import njit

MAX_SWITCHES = 8


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
def _psi(u, v, j, node, k, c, off, bj, bdj):
    """Contact indicator min(k delta, k delta + c delta') and the force it would carry."""
    delta = bj - u[node[j]] + off[j]
    rate = bdj - v[node[j]]
    f = k[j] * delta + c[j] * rate
    return min(k[j] * delta, f), f, rate


@njit(cache=True)
def _accel(m, K, C, f0, node, k, c, off, act, u, v, b, bd, n, tau, dt, a):
    """a = M^-1 (f0 + contact forces - C v - K u) for the given contact state."""
    size = m.size
    for i in range(size):
        s = f0[i]
        for q in range(size):
            s -= K[i, q] * u[q] + C[i, q] * v[q]
        a[i] = s
    for j in range(node.size):
        if act[j]:
            bj, bdj = _input(b, bd, j, n, tau, dt)
            a[node[j]] += k[j] * (bj - u[node[j]] + off[j]) + c[j] * (bdj - v[node[j]])
    for i in range(size):
        a[i] /= m[i]


@njit(cache=True)
def _matrix(m, K, C, node, k, c, act, h):
    size = m.size
    A = np.empty((size, size))
    for i in range(size):
        for q in range(size):
            A[i, q] = 0.25 * h * h * K[i, q] + 0.5 * h * C[i, q]
        A[i, i] += m[i]
    for j in range(node.size):
        if act[j]:
            i = node[j]
            A[i, i] += 0.25 * h * h * k[j] + 0.5 * h * c[j]
    return A


@njit(cache=True)
def _trial(m, K, C, f0, node, k, c, off, act, u, v, a, b, bd, n, tau, h, dt, Ainv, u1, v1, a1,
           pu, pv, rhs):
    """One Newmark step of length h from time tau of step n, contact state fixed (pu, pv, rhs:
    work arrays)."""
    size = m.size
    for i in range(size):
        pu[i] = u[i] + h * v[i] + 0.25 * h * h * a[i]
        pv[i] = v[i] + 0.5 * h * a[i]
    for i in range(size):
        s = f0[i]
        for q in range(size):
            s -= K[i, q] * pu[q] + C[i, q] * pv[q]
        rhs[i] = s
    for j in range(node.size):
        if act[j]:
            bj, bdj = _input(b, bd, j, n, tau + h, dt)
            i = node[j]
            rhs[i] += k[j] * (bj - pu[i] + off[j]) + c[j] * (bdj - pv[i])
    if Ainv.shape[0] > 0:
        for i in range(size):
            s = 0.0
            for q in range(size):
                s += Ainv[i, q] * rhs[q]
            a1[i] = s
    else:
        a1[:] = np.linalg.solve(_matrix(m, K, C, node, k, c, act, h), rhs)
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
def newmark_march(m, K, C, f0, node, k, c, off, thr, b, bd, dt, stride, u, v, a, act,
                  out_u, out_v, out_a, out_f, ev_t, ev_kind, ev_rate, t0):
    """March len(b[0]) - 1 steps; state (u, v, a, act) updated in place.

    An open contact closes when psi exceeds ``thr`` (a force far below any load of interest):
    without it a zero-lash contact at rest on the base circle would switch on every round-off
    ripple of the ringing train.

    Returns (events recorded, cam work [J] = integral of F_cam b' dt, switches cut short).
    """
    size = m.size
    nu = node.size
    nsteps = b.shape[1] - 1
    inverses = np.empty((1 << nu, size, size))
    state = np.zeros(nu, dtype=np.bool_)
    for s_idx in range(1 << nu):
        for j in range(nu):
            state[j] = (s_idx >> j) & 1
        inverses[s_idx] = np.linalg.inv(_matrix(m, K, C, node, k, c, state, dt))
    empty = np.empty((0, 0))
    u1 = np.empty(size)
    v1 = np.empty(size)
    a1 = np.empty(size)
    us = np.empty(size)
    vs = np.empty(size)
    as_ = np.empty(size)
    pu = np.empty(size)
    pv = np.empty(size)
    rhs = np.empty(size)
    nev = 0
    work = 0.0
    cut = 0
    for n in range(nsteps):
        tau = 0.0
        switches = 0
        while True:
            h = dt - tau
            if h <= 0.0:
                break
            Ainv = inverses[_state_index(act)] if tau == 0.0 else empty
            _trial(m, K, C, f0, node, k, c, off, act, u, v, a, b, bd, n, tau, h, dt, Ainv,
                   u1, v1, a1, pu, pv, rhs)
            # which contact changes state first inside the (sub)step?
            first = -1
            alpha = 2.0
            for j in range(nu):
                level = 0.0 if act[j] else thr[j]
                bj, bdj = _input(b, bd, j, n, tau, dt)
                p0 = _psi(u, v, j, node, k, c, off, bj, bdj)[0] - level
                bj, bdj = _input(b, bd, j, n, tau + h, dt)
                p1 = _psi(u1, v1, j, node, k, c, off, bj, bdj)[0] - level
                if (p1 > 0.0) != act[j]:
                    frac = p0 / (p0 - p1) if p0 != p1 else 1.0
                    frac = min(max(frac, 0.0), 1.0)
                    if frac < alpha:
                        alpha, first = frac, j
            if first < 0 or switches >= MAX_SWITCHES:
                if first >= 0:
                    cut += 1
                # accept: cam work by the trapezoid rule over the (sub)step
                work += _cam_power(u, v, act, node, k, c, off, b, bd, n, tau, dt) * 0.5 * h
                work += _cam_power(u1, v1, act, node, k, c, off, b, bd, n, tau + h, dt) * 0.5 * h
                u[:] = u1
                v[:] = v1
                a[:] = a1
                break
            # locate the crossing of psi_first in (0, h) by Illinois regula falsi
            lo, hi = 0.0, 1.0
            level = 0.0 if act[first] else thr[first]
            bj, bdj = _input(b, bd, first, n, tau, dt)
            plo = _psi(u, v, first, node, k, c, off, bj, bdj)[0] - level
            bj, bdj = _input(b, bd, first, n, tau + h, dt)
            phi = _psi(u1, v1, first, node, k, c, off, bj, bdj)[0] - level
            x = alpha
            side = 0
            for _ in range(30):
                _trial(m, K, C, f0, node, k, c, off, act, u, v, a, b, bd, n, tau, x * h, dt,
                       empty, us, vs, as_, pu, pv, rhs)
                bj, bdj = _input(b, bd, first, n, tau + x * h, dt)
                px = _psi(us, vs, first, node, k, c, off, bj, bdj)[0] - level
                if abs(px) <= 1e-12 * (abs(plo) + abs(phi)) or hi - lo < 1e-10:
                    break
                if (px > 0.0) == (plo > 0.0):
                    lo, plo = x, px
                    if side == -1:
                        phi *= 0.5
                    side = -1
                else:
                    hi, phi = x, px
                    if side == 1:
                        plo *= 0.5
                    side = 1
                x = lo + (hi - lo) * plo / (plo - phi) if plo != phi else 0.5 * (lo + hi)
            hx = x * h
            work += _cam_power(u, v, act, node, k, c, off, b, bd, n, tau, dt) * 0.5 * hx
            work += _cam_power(us, vs, act, node, k, c, off, b, bd, n, tau + hx, dt) * 0.5 * hx
            u[:] = us
            v[:] = vs
            tau += hx
            closing = not act[first]
            act[first] = closing
            bj, bdj = _input(b, bd, first, n, tau, dt)
            rate = bdj - v[node[first]]
            if nev < ev_t.size:
                ev_t[nev] = t0 + n * dt + tau
                ev_kind[nev] = 2 * first + (1 if closing else 0)
                ev_rate[nev] = rate
            nev += 1
            _accel(m, K, C, f0, node, k, c, off, act, u, v, b, bd, n, tau, dt, a)
            switches += 1
        if (n + 1) % stride == 0:
            r = (n + 1) // stride - 1
            out_u[:, r] = u
            out_v[:, r] = v
            out_a[:, r] = a
            for j in range(nu):
                if act[j]:
                    out_f[j, r] = k[j] * (b[j, n + 1] - u[node[j]] + off[j]) \
                        + c[j] * (bd[j, n + 1] - v[node[j]])
                else:
                    out_f[j, r] = 0.0
    return nev, work, cut


@njit(cache=True)
def _cam_power(u, v, act, node, k, c, off, b, bd, n, tau, dt):
    """F_cam b' [W] (contact 0 is the cam)."""
    if not act[0]:
        return 0.0
    bj, bdj = _input(b, bd, 0, n, tau, dt)
    return (k[0] * (bj - u[node[0]] + off[0]) + c[0] * (bdj - v[node[0]])) * bdj


@njit(cache=True)
def central_difference_march(m, K, C, f0, node, k, c, off, thr, b, bd, dt, stride, u, u_prev, act,
                             psi_prev, out_u, out_v, out_a, out_f, ev_t, ev_kind, ev_rate, t0):
    """Teodorescu eq. 17: u_(n+1) = 2 u_n - u_(n-1) + dt^2 a_n, v_n = (u_n - u_(n-1))/dt.

    Contacts are evaluated explicitly at u_n; a change of state is dated by linear interpolation
    of psi between the steps. State (u, u_prev, act, psi_prev) updated in place; the batch
    evaluates steps 0..nsteps (step nsteps is step 0 of the next batch, evaluated again there).
    Returns (events, cam work [J], 0).
    """
    size = m.size
    nu = node.size
    nsteps = b.shape[1] - 1
    v = np.empty(size)
    a = np.empty(size)
    f = np.empty(nu)
    nev = 0
    work = 0.0
    for n in range(nsteps + 1):
        for i in range(size):
            v[i] = (u[i] - u_prev[i]) / dt
        for i in range(size):
            s = f0[i]
            for q in range(size):
                s -= K[i, q] * u[q] + C[i, q] * v[q]
            a[i] = s
        for j in range(nu):
            p, fj, rate = _psi(u, v, j, node, k, c, off, b[j, n], bd[j, n])
            on = p > (0.0 if act[j] else thr[j])
            if on != act[j]:
                # date the crossing between the previous step and this one (linear in psi)
                frac = psi_prev[j] / (psi_prev[j] - p) if psi_prev[j] != p else 1.0
                if nev < ev_t.size:
                    ev_t[nev] = t0 + (n - 1 + min(max(frac, 0.0), 1.0)) * dt
                    ev_kind[nev] = 2 * j + (1 if on else 0)
                    ev_rate[nev] = rate
                nev += 1
                act[j] = on
            psi_prev[j] = p
            f[j] = fj if on else 0.0
            a[node[j]] += f[j]
        for i in range(size):
            a[i] /= m[i]
        if n > 0:
            work += 0.5 * dt * f[0] * bd[0, n]
            if n % stride == 0:
                r = n // stride - 1
                out_u[:, r] = u
                out_v[:, r] = v
                out_a[:, r] = a
                out_f[:, r] = f
        if n < nsteps:
            work += 0.5 * dt * f[0] * bd[0, n]
            for i in range(size):
                nxt = 2.0 * u[i] - u_prev[i] + dt * dt * a[i]
                u_prev[i] = u[i]
                u[i] = nxt
    return nev, work, 0
