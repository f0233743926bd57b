r"""Transient elastohydrodynamic line contact marched through a cam cycle (implicit in time).

The contact of each time step is the steady problem of :mod:`.ehl_line` with the squeeze term,
the signed entrainment and mass-conserving cavitation (:mod:`.ehl_transient_system`), solved
by semismooth Newton in (s, H0) on a grid of its own:

* **grid**: ``nodes`` points, uniform and symmetric, on |x| <= L with L = ``inlet`` Hertz
  half-widths of the step, widened to 20 rigid lengths sqrt(2 R h) where the contact is light
  (the steady solver's rule, h the larger of Moes' film of the step's inputs and the
  previous step's central film); symmetric because the inlet changes side at each entrainment
  reversal. L is rounded up to a power of 1.25 (in metres): neighbouring steps share their
  nodes, and equal inputs give equal grids whatever came before; where L changes, the film
  content rho theta h of the previous steps is interpolated onto the new grid (linear; outside
  the old domain the flooded rigid gap continues it).
* **deflection**: the FFT convolution of :mod:`.ehl_elastic` on every step's spacing (the
  kernel of a spacing dx is dx times the unit kernel plus a constant, which H0 absorbs).
* **time**: backward Euler or BDF2 (``march``) in time t = theta/omega, from the steady solution
  at the start angle (:func:`.ehl_line.solve_ehl_line`, then the same step with c_t = 0); one
  revolution, then the start angle once more (its change is the period error). A step whose
  Newton iteration fails is split into two (up to three times); if it still fails (a jump in
  the inputs, e.g. a lift law whose acceleration jumps, so that the radius and the load jump
  within one step) the march restarts there from the steady solution and lists the step in
  ``restarts`` (the film law warns).
* **Newton**: backtracking on the residual norm; the direction (``linear_solver``) matrix-free
  by GMRES with a two-level preconditioner (:mod:`.ehl_step_krylov`, from 384 nodes under
  ``auto``), or from the dense Jacobian (elastic block from the Toeplitz influence matrix),
  its LU kept across iterations and steps while each step at least halves the residual.

Friction (per unit width, times the width): the Couette shear of the liquid film,
tau = tau_0 asinh(eta |u_s| / (h tau_0)) (Eyring; Johnson & Tevaarwerk 1977) on the liquid
fraction theta outside the real contact area, plus the asperity shear tau_0 a_a + m p_a of
Greenwood-Tripp (as the averaged Reynolds film, Teodorescu et al. 2005 eq. 8).
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.numerics.blas_threads import one_blas_thread

from .asperity import asperity_area_fraction, asperity_pressure
from .ehl_cycle_records import MARCHES, CycleContact, CycleResolution, EHLCycle, _State
from .ehl_line import NotConverged
from .ehl_step import _Marcher

__all__ = ["CycleContact", "CycleResolution", "EHLCycle", "march_ehl_cycle", "MARCHES"]


def _friction(c: CycleContact, k, f, sysm, b, p_h, R, coef):
    """(fluid, asperity) friction [N] of a solved step (module docstring)."""
    h = np.maximum(f.H, 1e-300) * b**2 / R
    x = sysm.X * b
    log_eta, _ = sysm.oil.log_viscosity(f.P)
    eta = c.oil.eta0 * np.exp(log_eta)
    rate = abs(float(c.u_s[k])) / h
    tau = eta * rate
    if c.eyring_stress > 0.0:
        tau = c.eyring_stress * np.arcsinh(tau / c.eyring_stress)
    if c.sigma > 0.0:
        aa = asperity_area_fraction(h, c.sigma, c.zeta_beta_sigma)
        pa = asperity_pressure(h, c.sigma, coef)
    else:
        aa = pa = np.zeros_like(h)
    film = f.theta * (f.P >= 0.0) if sysm.cavitation == "half_sommerfeld" else f.theta
    fluid = np.trapezoid(tau * film * (1.0 - aa), x)
    boundary = np.trapezoid(c.eyring_stress * aa + c.boundary_shear * pa, x)
    return c.width * float(fluid), c.width * float(boundary)


@one_blas_thread()   # small dense factorisations in a loop: see numerics.blas_threads
def march_ehl_cycle(contact: CycleContact, resolution: CycleResolution | None = None,
                    h_start: float | None = None) -> EHLCycle:
    """March the transient EHL contact over one period of steps (module docstring).

    Steps with w <= 0 are unloaded (NaN outputs; the next loaded step starts again from its
    steady solution). The march starts at the loaded step of largest |u| among the first
    loaded run of steps, so that its steady solution exists. ``h_start`` [m]: instead, march
    once from t[0] (not periodic) from a rigid gap h_start + x^2/(2R) without pressure
    (e.g. a pure squeeze, where no steady solution exists)."""
    c = contact
    resolution = resolution or CycleResolution()
    n = c.t.size
    period = c.t[-1] - c.t[0] + (c.t[-1] - c.t[-2])
    out = _empty(n, resolution.map_nodes)
    m = _Marcher(c, resolution)
    loaded = c.w > 0.0
    if not np.any(loaded):
        return out
    start = 0 if h_start is not None else _start_index(c, loaded)
    order = [(start + j) % n for j in range(n if h_start is not None else n + 1)]
    state, first = (None if h_start is None else m.rigid_start(h_start)), math.nan
    if state is not None:
        out.h_central[0] = out.h_min[0] = h_start
    for j, k in enumerate(order):
        if not loaded[k] or (j == 0 and h_start is not None):
            state = None if not loaded[k] else state
            continue
        if state is None:
            state, f, sysm, mirror, b, p_h, its = m.steady_start(k)
        else:
            dt = c.t[k] - c.t[order[j - 1]]
            if dt <= 0.0:
                dt += period
            try:
                state, f, sysm, mirror, b, p_h, its = m.step(k, state, dt,
                                                             resolution.march == "bdf2")
            except NotConverged:    # an input jump the march cannot follow: steady restart
                if h_start is not None:
                    raise
                m.lu = None
                out.restarts.append(k)
                state, f, sysm, mirror, b, p_h, its = m.steady_start(k)
        if j == n:
            first = out.h_central[k]
        _record(out, k, c, state, f, sysm, mirror, b, p_h, its, m.a_coef)
    out.factorisations, out.split_steps = m.factorisations, m.split_steps
    out.krylov_iterations = m.krylov_iterations
    if h_start is None:
        out.period_error = float(abs(out.h_central[start] - first) / first)
    return out


def _start_index(c: CycleContact, loaded) -> int:
    """The first step of the march: where a loaded stretch begins (the first such stretch), or
    step 0 when the contact is loaded throughout; moved on within the stretch to the step of
    largest |u| if the entrainment there is below 5 % of the stretch's largest (a steady start
    needs entrainment)."""
    n = c.t.size
    begins = np.flatnonzero(loaded & ~np.roll(loaded, 1))
    k0 = int(begins[0]) if begins.size else 0
    stretch = [k0]
    while len(stretch) < n and loaded[(stretch[-1] + 1) % n] and (stretch[-1] + 1) % n != k0:
        stretch.append((stretch[-1] + 1) % n)
    u = np.abs(c.u[stretch])
    return k0 if u[0] > 0.05 * u.max() else int(stretch[int(np.argmax(u))])


def _empty(n, nodes) -> EHLCycle:
    def nan():
        return np.full(n, np.nan)
    return EHLCycle(nan(), nan(), nan(), nan(), nan(), nan(), nan(), nan(), nan(),
                    np.zeros(n, int),
                    np.full((n, nodes), np.nan), np.full((n, nodes), np.nan),
                    np.full((n, nodes), np.nan))


def _record(out: EHLCycle, k, c, state: _State, f, sysm, mirror, b, p_h, its, coef):
    flip = (lambda a: a[::-1]) if mirror else (lambda a: a)
    R = float(c.R[k])
    h = flip(f.H) * b**2 / R
    p = flip(f.load) * p_h
    out.h_central[k] = state.h_c
    out.h_min[k] = float(h.min())
    out.p_max[k] = float(p.max())
    out.p_hertz[k] = p_h
    total = float(f.load.sum() + f.A.sum())
    out.asperity_share[k] = float(f.A.sum()) / total if total > 0 else 0.0
    out.asperity_pressure_max[k] = float(f.A.max()) * p_h
    out.fluid_friction[k], out.asperity_friction[k] = _friction(c, k, f, sysm, b, p_h, R, coef)
    out.mass_error[k] = sysm.mass_error(f) if sysm.c_t > 0 else 0.0
    out.iterations[k] = its
    pick = np.linspace(0, h.size - 1, out.map_x.shape[1]).round().astype(int)
    out.map_x[k], out.map_h[k], out.map_p[k] = state.x[pick], h[pick], p[pick]
