"""One step of the transient EHL march (:mod:`.ehl_transient`): its grid and Hertzian units,
the guess from the previous step, damped semismooth Newton with a kept LU, the steady and rigid
starts, and the split of a step that does not converge."""
from __future__ import annotations

import math
import warnings

import numpy as np
import scipy.linalg as sla

from camtrain.formulas.film_line import moes_1992
from camtrain.formulas.hertz import hertz_line_half_width, hertz_line_max_pressure

from .asperity import asperity_pressure_coefficient, gt_functions
from .ehl_cycle_records import CycleContact, CycleResolution, _content_on, _State
from .ehl_elastic import UnitKernel
from .ehl_line import EHLResolution, LineContact, NotConverged, solve_ehl_line
from .ehl_oil import ScaledOil
from .ehl_step_krylov import REUSE_ITERATIONS, krylov_direction
from .ehl_transient_system import StepSystem

CHORD_CONTRACTION = 0.5
RIGID_LENGTHS = 20.0
#: the domain's half length is rounded up to a power of this factor [m]: steps whose inputs
#: differ a little share their nodes (the film content needs no interpolation), and equal inputs
#: give equal grids whatever came before (the film does not depend on the march's path)
GRID_SLACK = 1.25
#: the cavitation kink's smoothing delta over sqrt(tolerance) (:mod:`.ehl_transient_system`;
#: measured on the Göçmen cam: 0.2 needs three times the steady restarts of 2)
SMOOTHING = 2.0
#: a film-fraction node whose row the smoothed pressure leads is updated in its pressure
#: (:meth:`.StepSystem.updated`; False: every node in s)
PRESSURE_LED = True
#: a steady restart uses at least this share of the cycle's largest entrainment
REVERSAL_FLOOR = 0.05
#: a Newton iteration whose last STALL_WINDOW fresh directions gave no descent (the full step
#: or none taken, see ``newton``) and whose residual norm fell by less than 1 - STALL_FACTOR over them
#: is cycling: it stops there (measured on the Goecmen cam: such iterations cycle just above the
#: tolerance to ``max_iterations``, and the step is split after all)
STALL_WINDOW, STALL_FACTOR = 5, 0.9
#: ... or, within STALL_NEAR times the tolerance, fell by less than 1 - STALL_FACTOR over the last
#: STALL_WINDOW iterations whatever their steps (measured on the Goecmen cam: iterations that
#: reach 1-16 times the tolerance and sit there, the asperity lag's update undoing each Newton
#: step's gain, ran to ``max_iterations`` and were split; none of the iterations that converge,
#: slowly or not, ever did: stopping them leaves every film as it was)
STALL_NEAR = 100.0
#: share of the change of the asperity pressure taken into its deflection per Newton iterate
ASPERITY_RELAXATION = 0.5


def _cycling(history: list, norm: float, tol: float) -> bool:
    """Whether the norm is now above STALL_FACTOR times the norm before the last
    ``STALL_WINDOW`` iterations of ``history`` ((norm before, no descent) each) and these all
    gave no descent, or the norm is within ``STALL_NEAR`` times the tolerance ``tol``."""
    if len(history) < STALL_WINDOW:
        return False
    last = history[-STALL_WINDOW:]
    stuck = norm > STALL_FACTOR * last[0][0]
    return stuck and (norm < STALL_NEAR * tol or all(blind for _, blind in last))


def _stopped_at_kink(s: np.ndarray, s_new: np.ndarray) -> np.ndarray:
    """The update with every node of the film-fraction branch (s < 0) stopped at the kink
    (s = 0: theta = 1, P = 0) instead of crossing it in one iterate; it enters the pressure branch
    at the next. The smoothed law's linearisation holds within about delta of the kink: on the
    film-fraction side dP/ds = (1 + s/r)/2 ~ delta^2/(4 s^2), so the linear model sees pressure
    as nearly free there and proposes pressurising a cavitated film front by several p_h
    (measured on the Goecmen flank at the outlet front of a starved film: ds = 3.2 at 512 points,
    12 at 2,048, the film then negative), and the line search cut the whole step, load balance
    included, to 1/8-1/32 for 20-40 iterations. The projection is the kind of the bound s >= -1
    (theta >= 0) beside it: it changes the path of an iteration, not its fixed point."""
    return np.where(s < 0.0, np.minimum(s_new, 0.0), s_new)


def _lifted_approach(sysm, f, H0: float) -> float:
    """H0 raised until the guess's film ``f.H`` has half its central film (or its deepest
    negative one) as minimum. The previous step's deflection on a new grid can dip below zero
    (Göçmen deck, 1,024 points: -0.04 b^2/R at 4 nodes), where the row scale frozen at the guess
    is 1/(zero film), ~1e298: every residual overflowed (numpy's 'overflow encountered in dot'
    in the GMRES norm), the direction was zero and the step ran 40 iterations before it was
    split. The guess changes, not the step's solution."""
    lowest = float(f.H.min())
    central = float(np.interp(0.0, sysm.X, f.H))
    return H0 - lowest + 0.5 * max(central, -lowest)


class _LagRelaxation:
    """The share of the asperity pressure's change taken into its deflection per Newton
    iterate: ``ASPERITY_RELAXATION`` at first, then Aitken's dynamic relaxation (Irons & Tuck
    1969; the secant on the lag's residual r = A(H) - A_lag, as in partitioned fluid-structure
    coupling, Kuettler & Wall 2008): w_k = -w_{k-1} r_{k-1}.(r_k - r_{k-1}) / |r_k - r_{k-1}|^2,
    kept within [0.1, 1]. The fixed point A_lag = A(H) is the same whatever the weights."""

    def __init__(self):
        self.w, self.r = ASPERITY_RELAXATION, None

    def weight(self, r: np.ndarray) -> float:
        if self.r is not None:
            dr = r - self.r
            denom = float(dr @ dr)
            if denom > 0.0:
                self.w = min(1.0, max(0.1, -self.w * float(self.r @ dr) / denom))
        self.r = r.copy()
        return self.w


class _Marcher:
    def __init__(self, contact: CycleContact, res: CycleResolution):
        self.c, self.res = contact, res
        self.kernel = UnitKernel(res.nodes)
        self.lu = None
        self.pre, self.pre_grid = None, None     # the kept matrix-free preconditioner
        self.ratio = None        # Poiseuille over transport per row, frozen for each step
        self.reuse = True
        self.factorisations = 0
        self.krylov_iterations = 0
        self.split_steps = 0
        rough = contact.sigma > 0.0
        self.a_coef = (asperity_pressure_coefficient(contact.E_r, contact.zeta_beta_sigma,
                                                     contact.sigma_over_beta) if rough else 0.0)

    # ----------------------------------------------------------------- one step
    def system(self, w, R, u, dt, a0, state: _State | None, steady=False):
        c, res = self.c, self.res
        b = float(hertz_line_half_width(w, R, c.E_r))
        p_h = float(hertz_line_max_pressure(w, R, c.E_r))
        h_est = self._moes(w, R, abs(u))
        if state is not None:                 # a squeeze film may be far thicker than Moes'
            h_est = max(h_est, state.h_c)
        L = b * max(res.inlet, RIGID_LENGTHS * math.sqrt(2.0 * R * h_est) / b)
        L = GRID_SLACK ** math.ceil(math.log(L) / math.log(GRID_SLACK))
        X = np.linspace(-L / b, L / b, res.nodes)
        kernel, dense = self.kernel.at(X[1] - X[0])
        x = X * b
        scale = R / b**2
        if steady or state is None:
            Q_hist, c_t = np.zeros_like(X), 0.0
        else:
            Q_n = _content_on(x, state.x, state.q, state.R) * scale
            Q_hist = Q_n
            if a0 != 1.0:
                Q_m = _content_on(x, state.x_old, state.q_old, state.R_old) * scale
                Q_hist = 2.0 * Q_n - 0.5 * Q_m
            c_t = b / dt
        mirror = u < 0.0
        if mirror:
            Q_hist = Q_hist[::-1].copy()
        lam = 12.0 * c.oil.eta0 * 1.0 * R**2 / (b**3 * p_h)
        asperity = None
        if self.a_coef > 0.0:
            sig_H = c.sigma * scale

            def asperity(H, sig_H=sig_H, p_h=p_h):
                lam_ = np.maximum(H / sig_H, -3.9)     # an iterate may pass through H < 0
                F25, F15 = gt_functions(lam_, (2.5, 1.5))
                A = self.a_coef * F25 / p_h
                dA = -2.5 * self.a_coef * F15 / (p_h * sig_H)  # F_n' = -n F_n-1
                return A, dA
        sysm = StepSystem(X, kernel, dense, ScaledOil(c.oil, p_h), lam, abs(u), c_t, a0,
                          Q_hist, res.scheme, res.cavitation, asperity,
                          pressure_scale=self._pressure_scale(state, p_h))
        sysm.smoothing = SMOOTHING * math.sqrt(res.tolerance) * sysm.pressure_scale
        return sysm, b, p_h, x, mirror

    @staticmethod
    def _pressure_scale(state, p_h) -> float:
        """The pressure scale of the tolerance and the smoothing, in p_h: 1 for an elastic
        contact, the previous step's peak pressure for a light (rigid) one, whose pressures are
        far below Hertz (a tolerance in units of p_h would be loose there)."""
        if state is None:
            return 1.0
        peak = float(np.max(state.s)) * state.p_h / p_h
        return min(1.0, max(peak, 1e-6))

    def _moes(self, w, R, u):
        c = self.c
        u = max(u, 1e-3)
        return float(moes_1992(w, R, u, c.oil.eta0, c.oil.alpha, c.E_r))

    def guess(self, sysm, x, p_h, b, R, mirror, state: _State):
        """(s, H0, A): the previous step's solution on this grid, in this step's units, with
        its asperity pressure as the first lagged asperity deflection."""
        s = np.interp(x, state.x, state.s, left=0.0, right=0.0)
        s = np.where(s > 0.0, s * state.p_h / p_h, s)
        s[[0, -1]] = 0.0
        A = np.zeros_like(s) if state.a is None else \
            np.interp(x, state.x, state.a, left=0.0, right=0.0) / p_h
        if mirror:
            s, A = s[::-1].copy(), A[::-1].copy()
        H_c = state.h_c * R / b**2
        V0 = np.interp(0.0, sysm.X, sysm.kernel.deflection(np.maximum(s, 0.0) + A))
        return s, H_c - V0, A

    def newton(self, sysm: StepSystem, s, H0, stall: bool = True, A0=None):
        """(s, H0, fields, iterations, converged): semismooth Newton, backtracking on the
        residual norm; where a fresh direction gives no descent (a node on the kink between the
        pressure and the film-fraction branch) the full step is taken (non-monotone). ``stall``:
        give up once the residual stalls (``STALL_WINDOW``; a time step is then split). ``A0``:
        the first lagged asperity pressure (None: that of the film without it). A guess that
        already meets the tolerance (a steady stretch of the cycle) takes no iteration."""
        tol = self.res.tolerance * sysm.pressure_scale
        A_first = np.zeros_like(s) if A0 is None else A0
        f = sysm.fields(s, H0, A_first)
        if f.H.min() <= 0.0:            # a guess without a film at some node
            H0 = _lifted_approach(sysm, f, H0)
            f = sysm.fields(s, H0, A_first)
        A_lag, relax = (f.A if A0 is None else A0), _LagRelaxation()
        self.reuse = True
        sysm.scale = sysm.row_scale(f)      # frozen for the step: a smooth residual
        self.ratio = sysm.poiseuille_over_transport(f)[1:-1] if PRESSURE_LED else None
        F, f = sysm.residual(s, H0, A_lag)
        norm = np.abs(F).max()
        if norm < tol and float(np.abs(f.A - A_lag).max()) < tol:
            return s, H0, f, 0, True
        history = []                   # (norm, a step without descent) per iteration
        for it in range(1, self.res.max_iterations + 1):
            if stall and _cycling(history, norm, tol):
                break                  # the split step is cheaper
            fresh, step = self._direction(sysm, s, H0, f, F, A_lag)
            if not np.all(np.isfinite(step)):
                if fresh:
                    break
                self.lu = None
                continue
            s_new, H0_new, F_new, f_new, norm_new, t = self._damped(sysm, s, H0, step, norm,
                                                                    fresh, A_lag)
            if not fresh and not norm_new < CHORD_CONTRACTION * norm:
                self.lu = None
                continue
            history.append((norm, fresh and not norm_new < norm))      # no descent
            s, H0, F, f, norm = s_new, H0_new, F_new, f_new, norm_new
            lag = float(np.abs(f.A - A_lag).max())
            if lag > 0.0:              # under-relaxed: the asperity deflection lags
                A_lag = A_lag + relax.weight(f.A - A_lag) * (f.A - A_lag)
                F, f = sysm.residual(s, H0, A_lag)
                norm = np.abs(F).max()
            if norm < tol and lag < tol:
                return s, H0, f, it, True
            if t < 1.0:
                self.lu = None
        return s, H0, f, self.res.max_iterations, False

    def _direction(self, sysm, s, H0, f, F, A_lag):
        """(fresh, Newton direction): matrix-free GMRES (``krylov``, always fresh), or the
        kept dense LU (``dense``: a chord step while it is kept, else a new factorisation)."""
        if self.res.krylov:
            return True, self._krylov(sysm, s, H0, f, F, A_lag)
        fresh = self.lu is None
        if fresh:
            with warnings.catch_warnings():     # singular: a non-finite step, handled
                warnings.simplefilter("ignore", sla.LinAlgWarning)
                self.lu = sla.lu_factor(sysm.jacobian(s, f), check_finite=False)
            self.factorisations += 1
        return fresh, sla.lu_solve(self.lu, -F, check_finite=False)

    def _krylov(self, sysm, s, H0, f, F, A_lag):
        """A matrix-free direction; the preconditioner (its coarse LU and band LU) is kept
        across iterations and steps on the same grid while GMRES converges with it in at most
        ``REUSE_ITERATIONS`` iterations (the analogue of the kept dense LU); once it fails, each
        direction of the time step builds its own."""
        same_grid = self.pre_grid == (sysm.X[0], sysm.X.size)
        kept = self.pre if self.reuse and same_grid else None
        step, its, pre, ok = krylov_direction(sysm, s, H0, f, F, A_lag, kept)
        self.krylov_iterations += its
        if kept is not None and (not ok or its > REUSE_ITERATIONS):
            self.reuse = False         # not again within this time step
            step, its, pre, ok = krylov_direction(sysm, s, H0, f, F, A_lag)
            self.krylov_iterations += its
            kept = None
        if kept is None:
            self.factorisations += 1
        self.pre, self.pre_grid = pre, (sysm.X[0], sysm.X.size)
        return step

    def _damped(self, sysm, s, H0, step, norm, backtrack, A_lag):
        """The step scaled by t = 1, 1/2, ... until the film stays positive and the residual
        falls (a trial that overflows is not good; its warnings are silenced)."""
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            return self._damped_trials(sysm, s, H0, step, norm, backtrack, A_lag)

    def _damped_trials(self, sysm, s, H0, step, norm, backtrack, A_lag):
        low = {"reynolds": 0.0, "half_sommerfeld": -np.inf}.get(sysm.cavitation, -1.0)
        t, full, kink = 1.0, None, sysm.cavitation == "elrod_adams"
        while True:
            s_new = s.copy()
            moved = np.maximum(sysm.updated(s[1:-1], t * step[:-1], self.ratio), low)
            s_new[1:-1] = _stopped_at_kink(s[1:-1], moved) if kink else moved
            H0_new = H0 + t * step[-1]
            F_new, f_new = sysm.residual(s_new, H0_new, A_lag)
            norm_new = np.abs(F_new).max()
            good = f_new.H.min() > 0 and norm_new < (1.0 - 1e-4 * t) * norm  # NaN: not good
            if good or not backtrack:
                return s_new, H0_new, F_new, f_new, norm_new, t
            if full is None:         # the full step's trial, kept for the fallback below
                full = s_new, H0_new, F_new, f_new
            if t < 1e-3:             # no descent: the full step (see newton), as tried first
                s_new, H0_new, F_new, f_new = full
                if not (f_new.H.min() > 0 and np.all(np.isfinite(F_new))):
                    return s, H0, F_new, f_new, norm, 0.0
                return s_new, H0_new, F_new, f_new, np.abs(F_new).max(), 0.5
            t *= 0.5

    # ----------------------------------------------------------------- march
    def steady_start(self, k: int):
        """The steady solution at step k: the steady solver's pressure (Reynolds exit) as the
        guess of this problem's own steady step (its cavitation, no time term). Where the
        entrainment is below ``REVERSAL_FLOOR`` of the cycle's largest (a restart at a reversal,
        where no steady film exists), the steady film at that floor, with u's sign."""
        c = self.c
        w, R, u = float(c.w[k]), float(c.R[k]), float(c.u[k])
        floor = REVERSAL_FLOOR * float(np.abs(c.u).max())
        if abs(u) < floor:
            u = math.copysign(floor, u if u != 0.0 else 1.0)
        sysm, b, p_h, x, mirror = self.system(w, R, u, 1.0, 1.0, None, steady=True)
        try:
            line = LineContact(w, R, c.E_r, abs(u), abs(u), c.oil)
            sol = solve_ehl_line(line, EHLResolution(nodes=max(self.res.nodes, 256)))
            s = np.interp(sysm.X, sol.x / b, sol.p / p_h, left=0.0, right=0.0)
            H_c = sol.h_central * R / b**2
        except (NotConverged, ValueError):
            s = np.sqrt(np.maximum(1.0 - sysm.X**2, 0.0))
            H_c = self._moes(w, R, abs(u)) * R / b**2
        s[[0, -1]] = 0.0
        H0 = H_c - np.interp(0.0, sysm.X, sysm.kernel.deflection(s))
        s, H0, f, its, ok = self.newton(sysm, s, H0, stall=False)
        if not ok:
            raise NotConverged(f"transient EHL: no steady solution at the start (step {k})")
        first = self._state(sysm, f, s, b, p_h, R, x, mirror, None)
        first_system, first_mirror, first_b, first_p_h = sysm, mirror, b, p_h
        # once more on the grid the march would take after this film (its domain follows the
        # film): the start and the return to it then differ by the march, not by the grid
        sysm, b, p_h, x, mirror = self.system(w, R, u, 1.0, 1.0, first, steady=True)
        if np.array_equal(x, first.x):
            return first, f, sysm, mirror, b, p_h, its
        s2, H0_2, A2 = self.guess(sysm, x, p_h, b, R, mirror, first)
        s2, H0_2, f2, more, ok = self.newton(sysm, s2, H0_2, stall=False, A0=A2)
        if not ok:      # the first grid's solution stands (the march regrids at its 1st step)
            self.lu = None
            return first, f, first_system, first_mirror, first_b, first_p_h, its
        return (self._state(sysm, f2, s2, b, p_h, R, x, mirror, None), f2, sysm, mirror, b,
                p_h, its + more)

    def rigid_start(self, h0: float) -> _State:
        """A rigid gap h0 + x^2/(2R) at step 0, flooded, without pressure."""
        c = self.c
        w, R = float(c.w[0]), float(c.R[0])
        b = float(hertz_line_half_width(w, R, c.E_r))
        half = max(self.res.inlet, RIGID_LENGTHS * math.sqrt(2.0 * R * h0) / b)
        x = np.linspace(-half, half, self.res.nodes) * b
        return _State(x, np.zeros_like(x), h0 + x**2 / (2.0 * R), R,
                      float(hertz_line_max_pressure(w, R, c.E_r)), h0)

    def _state(self, sysm, f, s, b, p_h, R, x, mirror, prev: _State | None) -> _State:
        flip = (lambda a: a[::-1].copy()) if mirror else (lambda a: a)
        H = flip(f.H)
        h = H * b**2 / R
        q = flip(f.Q) * b**2 / R
        st = _State(x, flip(s), q, R, p_h, float(np.interp(0.0, x, h)), a=flip(f.A) * p_h)
        if prev is not None:
            st.q_old, st.x_old, st.R_old = prev.q, prev.x, prev.R
        return st

    def step(self, k: int, state: _State, dt: float, bdf: bool, depth: int = 0):
        """Solve step k from ``state`` over dt; returns (state, fields, system, mirror, b,
        p_h, iterations)."""
        c = self.c
        w, R, u = float(c.w[k]), float(c.R[k]), float(c.u[k])
        a0 = 1.5 if bdf and state.q_old is not None else 1.0
        sysm, b, p_h, x, mirror = self.system(w, R, u, dt, a0, state)
        s, H0, A0 = self.guess(sysm, x, p_h, b, R, mirror, state)
        s, H0, f, its, ok = self.newton(sysm, s, H0, A0=A0)
        if ok:
            return self._state(sysm, f, s, b, p_h, R, x, mirror, state), f, sysm, mirror, \
                b, p_h, its
        if depth >= 3:
            raise NotConverged(f"transient EHL: Newton did not converge at t = {c.t[k]:.6g} s "
                               f"(w = {w:.4g} N/m, R = {R:.4g} m, u = {u:.4g} m/s) after {its} "
                               f"iterations, step split {depth} times")
        self.split_steps += 1
        self.lu = None
        half = self._midpoint(k)
        mid, *_ = half.step(1, state, 0.5 * dt, False, depth + 1)
        self.factorisations += half.factorisations
        self.krylov_iterations += half.krylov_iterations
        self.split_steps += half.split_steps
        mid.q_old = None
        return self.step(k, mid, 0.5 * dt, False, depth + 1)

    def _midpoint(self, k: int) -> _Marcher:
        """A marcher of two steps: step k-1 and the inputs halfway to step k."""
        c = self.c
        j = k - 1
        mid = {n: np.array([getattr(c, n)[j], 0.5 * (getattr(c, n)[j] + getattr(c, n)[k])])
               for n in ("t", "w", "R", "u", "u_s")}
        sub = _Marcher.__new__(_Marcher)
        sub.__dict__.update(self.__dict__)
        sub.c = CycleContact(**{**c.__dict__, **mid})
        sub.lu, sub.factorisations, sub.split_steps, sub.krylov_iterations = None, 0, 0, 0
        sub.pre = None
        return sub
