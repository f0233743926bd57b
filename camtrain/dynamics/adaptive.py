"""The adaptive reference integrators (scipy's LSODA and Radau) of the lumped train: one
camshaft revolution per call, with a terminal event on each contact's indicator and a restart
with the other contact state (analytic Jacobian; ``max_step`` bounded so that a step cannot jump
over a short separation). Used by :func:`camtrain.dynamics.integrators.march`."""
from __future__ import annotations

import math

import numpy as np

from camtrain.dynamics.train import CAM, static_state

__all__ = ["Adaptive"]


class Adaptive:
    """scipy solve_ivp (LSODA or Radau) with contact events, one revolution per call."""

    def __init__(self, model, cam, base, theta0, sample_dt, grid, settings):
        self.model, self.cam, self.base, self.theta0 = model, cam, base, theta0
        self.sample_dt, self.grid, self.s = sample_dt, grid, settings
        n = model.size
        if model.series is not None:
            raise ValueError("a series element's state (the hydraulic lash adjuster's chamber) "
                             "is marched by the newmark integrator only")
        u0, act = static_state(model)
        self.y = np.concatenate((u0, np.zeros(n)))
        self.act = [bool(a) for a in act]
        self.minv = 1.0 / model.mass
        self.max_step = settings.max_step / base.omega

    def _inp(self, t):
        base = self.base
        if base.amplitude == 0.0 or base.order == 0:
            lift, d1, _ = self.cam.at(self.theta0 + base.omega * t)
            return (lift, 0.0), (d1 * base.omega, 0.0)
        b, bd, _ = self.cam.in_time(np.array([t]), base, self.theta0)
        return (float(b[0]), 0.0), (float(bd[0]), 0.0)

    def _spring(self, t, j, delta):
        """Spring force of contact j at compression delta (a Hertz cam contact: its law at the
        angle of time t; a negative delta: k delta, which only signs the indicator)."""
        m = self.model
        if j == CAM and m.cam_law is not None and delta > 0.0:
            if self.base.amplitude == 0.0 or self.base.order == 0:
                theta = self.theta0 + self.base.omega * t
            else:
                theta = self.theta0 + float(self.base.angle(np.array([t]))[0][0])
            return m.cam_law.force(delta, *self.cam.geometry_at(theta))
        return m.uni_k[j] * delta

    def _forces(self, t, u, v, act):
        m = self.model
        b, bd = self._inp(t)
        f = np.zeros(2)
        for j in range(2):
            if act[j]:
                i = m.uni_node[j]
                f[j] = (self._spring(t, j, b[j] - u[i] + m.uni_offset[j])
                        + m.uni_c[j] * (bd[j] - v[i]))
        return f, b, bd

    def _rhs(self, t, y, act):
        m = self.model
        n = m.size
        u, v = y[:n], y[n:]
        f, _, _ = self._forces(t, u, v, act)
        out = np.empty(2 * n)
        out[:n] = v
        acc = m.preload - m.stiffness @ u - m.damping @ v
        acc[m.uni_node[0]] += f[0]
        acc[m.uni_node[1]] += f[1]
        out[n:] = acc * self.minv
        return out

    def _jac(self, act):
        m = self.model
        n = m.size
        k, c = m.stiffness.copy(), m.damping.copy()
        for j in range(2):
            if act[j]:
                i = m.uni_node[j]
                k[i, i] += m.uni_k[j]
                c[i, i] += m.uni_c[j]
        jac = np.zeros((2 * n, 2 * n))
        jac[:n, n:] = np.eye(n)
        jac[n:, :n] = -k * self.minv[:, None]
        jac[n:, n:] = -c * self.minv[:, None]
        return jac

    def _psi(self, t, y, j):
        m = self.model
        n = m.size
        b, bd = self._inp(t)
        i = m.uni_node[j]
        delta = b[j] - y[i] + m.uni_offset[j]
        rate = bd[j] - y[n + i]
        g = self._spring(t, j, delta)
        return min(g, g + m.uni_c[j] * rate), rate

    def revolution(self):
        from scipy.integrate import solve_ivp

        m = self.model
        n = m.size
        t_end = self.base.period
        samples = (np.arange(self.grid) + 1) * self.sample_dt
        samples[-1] = t_end
        out_y = np.empty((2 * n, self.grid))
        out_a = np.empty((n, self.grid))
        out_f = np.empty((2, self.grid))
        events = []
        t0 = 0.0
        method = "LSODA" if self.s.integrator == "lsoda" else "Radau"
        while t0 < t_end:
            act = list(self.act)
            evs = []
            for j in range(2):
                def ev(t, y, j=j):
                    return self._psi(t, y, j)[0]
                ev.terminal = True
                ev.direction = -1.0 if act[j] else 1.0
                evs.append(ev)
            take = samples[(samples > t0) & (samples <= t_end)]
            sol = solve_ivp(lambda t, y, act=act: self._rhs(t, y, act), (t0, t_end), self.y, method=method,
                            t_eval=take, events=evs, rtol=self.s.rtol, atol=self.s.atol,
                            max_step=self.max_step, jac=_constant(self._jac(act)))
            for ts, ys in zip(sol.t, np.asarray(sol.y).reshape(2 * n, -1).T, strict=True):
                r = int(round(ts / self.sample_dt)) - 1
                out_y[:, r] = ys
                out_a[:, r] = self._rhs(ts, ys, act)[n:]
                out_f[:, r] = self._forces(ts, ys[:n], ys[n:], act)[0]
            if sol.status != 1:  # reached the end of the revolution (last sample = t_end)
                if sol.status < 0:
                    raise RuntimeError(f"{method} failed: {sol.message}")
                self.y = sol.y[:, -1].copy()
                break
            te, j = min((sol.t_events[q][0], q) for q in range(2) if sol.t_events[q].size)
            ye = sol.y_events[j][0]
            self.act[j] = not self.act[j]
            events.append((te, 2 * j + (1 if self.act[j] else 0), self._psi(te, ye, j)[1]))
            self.y = ye.copy()
            if te <= t0:  # scipy corner case (event root at the bracket start): nudge
                te = t0 + 1e-9 * self.sample_dt
            t0 = te
        return out_y[:n], out_y[n:], out_a, out_f, events, math.nan, 0



def _constant(matrix):
    """A Jacobian callable returning a fixed matrix (LSODA wants a callable)."""
    return lambda t, y: matrix
