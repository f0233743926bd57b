"""Compiled explicit march of the lumped valve train (numba, cached on disk): Teodorescu et al.
(2005) eq. 17, central differences, the contacts evaluated at the step (:mod:`._kernel` holds
the Newmark march and the contact helpers both use; the records of :mod:`.records`)."""
from __future__ import annotations

import numpy as np
from numba import njit

from camtrain.dynamics._kernel import _geom, _psi
from camtrain.numerics.compile_notice import announce


@njit(cache=True)
def central_difference_march(tr, uni, cl, inp, st, out):
    """Teodorescu eq. 17: u_(n+1) = 2 u_n - u_(n-1) + dt^2 a_n, v_n = (u_n - u_(n-1))/dt.

    Contacts are evaluated explicitly at u_n; a change of state is dated by linear interpolation
    of psi between the steps. State ``st`` (u, u_prev, act, psi_prev; v and a are its work
    arrays) updated in place; the batch evaluates steps 0..nsteps (step nsteps is step 0 of the
    next batch, evaluated again there). Returns (events, cam work [J], 0).
    """
    K, C, f0, m = tr.K, tr.C, tr.f0, tr.m
    u, u_prev, v, a = st.u, st.u_prev, st.v, st.a
    dt, bd, stride = inp.dt, inp.bd, inp.stride
    size = m.size
    nsteps = inp.b.shape[1] - 1
    node, thr, psi_prev, act = tr.node, tr.thr, st.psi_prev, st.act
    f = np.empty(node.size)
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
        r1, ratio = _geom(cl.rad, cl.rat, n, 0.0, inp.dt)
        for j in range(node.size):
            p, fj, rate = _psi(st.u, st.v, j, node, uni.k, uni.c, uni.off, inp.b[j, n],
                               inp.bd[j, n], cl.law, cl.hz, r1, ratio)
            on = p > (0.0 if act[j] else thr[j])
            if on != act[j]:
                # date the crossing between the previous step and this one (linear in psi)
                frac = psi_prev[j] / (psi_prev[j] - p) if psi_prev[j] != p else 1.0
                if nev < out.ev_t.size:
                    out.ev_t[nev] = inp.t0 + (n - 1 + min(max(frac, 0.0), 1.0)) * inp.dt
                    out.ev_kind[nev] = 2 * j + (1 if on else 0)
                    out.ev_rate[nev] = rate
                nev += 1
                act[j] = on
            psi_prev[j] = p
            f[j] = fj if on else 0.0
            st.a[node[j]] += f[j]
        for i in range(size):
            a[i] /= m[i]
        if n > 0:
            work += 0.5 * dt * f[0] * bd[0, n]
            if n % stride == 0:
                r = n // stride - 1
                out.u[:, r] = u
                out.v[:, r] = v
                out.a[:, r] = a
                out.f[:, r] = f
        if n < nsteps:
            work += 0.5 * dt * f[0] * bd[0, n]
            for i in range(size):
                nxt = 2.0 * u[i] - u_prev[i] + dt * dt * a[i]
                u_prev[i] = u[i]
                u[i] = nxt
    return nev, work, 0


announce("valve-train dynamics", (central_difference_march,))
