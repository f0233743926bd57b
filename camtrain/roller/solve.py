"""The roller's speed through the cycle: quasi-static (J = 0) or inertial (periodic march).

Torque balance of the roller on its pin (Chiu 1992, Tribol. Trans. 35:261; Alakhramsing et al.
2018, Proc. IMechE J 232; Li et al. 2023, Lubricants 11:361):

    J dw_r/dt = F_t(u_s) r_r - T_pin(w_r, W),   u_s = V_s0 - w_r r_r.

``quasi_static`` drops the inertia and solves F_t r_r = T_pin per angle (bisection on
w_r in [0, V_s0/r_r]: the traction falls and the pin torque rises with w_r, so the root is
unique; where the traction at w_r = 0 cannot beat the pin's breakaway torque the roller stands);
the angles of a needle pin in a full film are solved by the same steps compiled per angle
(:mod:`._balance`), the others on arrays.
``inertial`` marches the equation over revolutions to a periodic state
(:mod:`._kernel`, implicit Euler, first order in the step), started from the quasi-static speed.
The pin carries the normal load W (the traction's share of the pin load is left out).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.roller import speeds
from camtrain.roller.pin import NU_N_LIMIT, Pin
from camtrain.roller.product import RollerField
from camtrain.roller.traction import Traction

SOLVERS = ("quasi_static", "inertial")
#: most evaluations of the quasi-static balance per angle (regula falsi with bisection's
#: bracket: BRACKET is reached well before)
HALVINGS = 80
#: bracket on x = w_r / w* at which the quasi-static speed counts as solved
BRACKET = 1e-10
#: balance residual, relative to the pin torque at rolling, at which the speed counts as solved
RESIDUAL = 1e-10
#: smallest slip the quasi-static solver resolves: below it the roller rolls
SLIP_MIN = 1e-12
#: clustering of the tables' normalised grid (finest step near 0 about this/sinh(this) x 2/n)
CLUSTER = 8.0


@dataclass(frozen=True)
class RollerSettings:
    """Solver knobs: ``solver`` (quasi_static | inertial), periodic ``tolerance`` (relative to
    the largest rolling speed), most ``revolutions``, ``substeps`` per grid step, table points,
    the slip above which the roller counts as skidding."""

    solver: str = "quasi_static"
    tolerance: float = 1e-6
    revolutions: int = 50
    substeps: int = 4
    table_points: int = 401
    skid_slip: float = 0.05


def quasi_static_speed(traction: Traction, pin: Pin, radius: float) -> np.ndarray:
    """w_r [rad/s] per angle with F_t r = T_pin (J = 0); see the module docstring."""
    return _quasi_static(traction, pin, radius)[0]


def _quasi_static(traction: Traction, pin: Pin, radius: float):
    """:func:`quasi_static_speed` and the angles the compiled balance solved with its records
    ``(angles, (BalanceAngles, BalanceLaw))`` (None where it solved none)."""
    v0 = traction.v_s0
    w_star = v0 / radius
    if pin.kind == "locked":
        return np.zeros(v0.shape), None
    if pin.kind == "frictionless":
        return w_star.copy(), None
    load = traction.load
    # a pin without torque at the rolling speed lets the roller roll (also unloaded: J = 0)
    free = pin.free_at(w_star, load)
    x = np.where(free, 1.0, 0.0)
    loaded = np.flatnonzero(~free & (load > 0.0) & (v0 != 0.0))
    known = None
    if loaded.size:
        compiled = _compiled_records(traction, pin, radius, loaded)
        if compiled is not None:
            from camtrain.roller._balance import balance_roots

            fast, records = compiled
            x[loaded[fast]] = balance_roots(*records)
            known = (loaded[fast], records)
            loaded = loaded[~fast]
        if loaded.size:
            x[loaded] = _balance_roots(traction, pin, radius, loaded)
    return x * w_star, known


def _compiled_records(traction, pin, radius, idx):
    """The angles of ``idx`` the compiled balance solves (a mask over ``idx``: a needle pin,
    the full-film traction law, a power-law film, the film parameter at or above the mixed limit
    over the whole bracket; :mod:`._balance`) and its records, or None where it solves none."""
    from camtrain.roller._balance import BalanceAngles, BalanceLaw
    from camtrain.roller.traction import LAMBDA_LIMIT

    h_roll, exponent = traction._rolling_film
    if pin.kind != "needle" or traction.law == "contact" or exponent is None:
        return None
    c, trib, hz = traction.contact, traction.contact.tribology, traction.hertz
    shape = traction.load.shape
    sigma = _per_angle(c.lubricant.roughness, shape, idx)
    v0, v_cam, h = traction.v_s0[idx], traction.kin.v_cam[idx], h_roll[idx]
    with np.errstate(divide="ignore", invalid="ignore"):
        h_slide = h * (np.abs(v_cam - 0.5 * v0) / np.abs(v_cam)) ** exponent
        area = traction.area[idx]
        fast = ((v_cam != 0.0) & ((v_cam - 0.5 * v0) * v_cam > 0.0) & np.isfinite(h) & (h > 0.0)
                & (np.minimum(h, h_slide) / sigma >= LAMBDA_LIMIT) & np.isfinite(hz.pmax[idx])
                & (area > 0.0) & np.isfinite(traction.unit_shear[idx]))
    if not np.any(fast):
        return None
    k, load = idx[fast], traction.load[idx][fast]
    area = area[fast]
    mu_b = _per_angle(trib.boundary_friction, shape, k)
    angles = BalanceAngles(
        np.ascontiguousarray(v0[fast]), np.ascontiguousarray(v_cam[fast]), load,
        np.ascontiguousarray(h[fast]), traction.unit_shear[k], area,
        trib.eyring_stress * (area - 0.0) + trib.shear_pressure_coefficient * (load - 0.0),
        mu_b * load)
    law = BalanceLaw(float(radius), float(exponent), traction.law == "eyring",
                     float(trib.eyring_stress), float(pin.pitch_diameter),
                     float(pin.kinematic_viscosity), float(pin.f0), float(pin.f1), RESIDUAL,
                     BRACKET, SLIP_MIN, HALVINGS, NU_N_LIMIT)
    return fast, (angles, law)


def _per_angle(value, shape, idx):
    """A contact parameter at the angles ``idx``: a plain number as it is, a per-case array
    (a sweep batch's) broadcast to the field's ``shape`` and selected."""
    if np.ndim(value) == 0:
        return value
    return np.broadcast_to(value, shape)[idx]


def _balance_roots(traction, pin, radius, idx) -> np.ndarray:
    """x = w_r / w* in [0, 1] at the angles ``idx`` where s (r F_t - T_pin) = 0 (decreasing in
    x): 0 where the roller stands, else the Illinois regula falsi on the bracket [0, 1]
    (Dowell & Jarratt 1971), each angle to a bracket of BRACKET or HALVINGS evaluations."""
    v0 = traction.v_s0[idx]
    s, w_star, load = np.sign(v0), v0 / radius, traction.load[idx]

    def balance(x, k):   # at the angles idx[k]
        return s[k] * (radius * traction.force(v0[k] * (1.0 - x), idx[k])
                       - pin.torque(x * w_star[k], load[k]))

    lo, hi = np.zeros(idx.size), np.ones(idx.size)
    g_lo = s * radius * traction.force(v0, idx) - pin.breakaway(load)
    g_hi = -s * pin.torque(w_star, load)          # rolling: no traction at u_s = 0
    scale = np.abs(g_hi) * RESIDUAL               # a balance this small counts as solved
    found = np.full(idx.size, np.nan)
    stands = g_lo <= 0.0
    g_lo = np.where(stands, 0.0, g_lo)
    active = np.flatnonzero(~stands & (g_hi < 0.0))
    # the asperity traction is Coulomb-like: where it beats the pin at the smallest slip the
    # roller rolls (the root is the jump at u_s = 0)
    rolls = np.zeros(idx.size, dtype=bool)
    if active.size:
        rolls[active] = balance(np.full(active.size, 1.0 - SLIP_MIN), active) >= 0.0
        active = active[~rolls[active]]
    # shrink the bracket around the Newtonian estimate of the slip, r k u_s = T (one probe on
    # each side), so that the regula falsi starts where the traction is nearly linear
    if active.size:
        k = traction.rolling_slope(idx[active])
        with np.errstate(divide="ignore", invalid="ignore"):
            guess = -g_hi[active] / (radius * k * np.abs(v0[active]))
        guess = np.clip(np.nan_to_num(guess, nan=0.5, posinf=0.5), 1e-15, 0.25)
        for factor in (4.0, 0.25):
            x = 1.0 - factor * guess
            g = balance(x, active)
            up = g > 0.0
            lo[active] = np.where(up, np.maximum(lo[active], x), lo[active])
            g_lo[active] = np.where(up & (x >= lo[active]), g, g_lo[active])
            hi[active] = np.where(~up, np.minimum(hi[active], x), hi[active])
            g_hi[active] = np.where(~up & (x <= hi[active]), g, g_hi[active])
    side = np.zeros(idx.size, dtype=int)
    for _ in range(HALVINGS):
        if not active.size:
            break
        a, b, ga, gb = lo[active], hi[active], g_lo[active], g_hi[active]
        x = np.clip(a - ga * (b - a) / (gb - ga), a, b)
        x = np.where((x <= a) | (x >= b), 0.5 * (a + b), x)
        g = balance(x, active)
        up = g > 0.0
        # Illinois: halve the kept end's value when the same end is kept twice
        keep_hi = up & (side[active] == 1)
        keep_lo = ~up & (side[active] == -1)
        lo[active] = np.where(up, x, a)
        g_lo[active] = np.where(up, g, np.where(keep_lo, 0.5 * ga, ga))
        hi[active] = np.where(up, b, x)
        g_hi[active] = np.where(up, np.where(keep_hi, 0.5 * gb, gb), g)
        side[active] = np.where(up, 1, -1)
        close = np.abs(g) <= scale[active]
        found[active[close]] = x[close]
        done = (hi[active] - lo[active] <= BRACKET) | close
        active = active[~done]
    x = np.where(np.isnan(found), 0.5 * (lo + hi), found)
    x = np.where(stands, 0.0, np.where(rolls | (g_hi >= 0.0), hi, x))
    return x


def clustered_grid(points: int) -> np.ndarray:
    """Normalised abscissae in [-1, 1], clustered at 0 (sinh spacing), 0 included."""
    x = np.linspace(-1.0, 1.0, 2 * (points // 2) + 1)
    return np.sinh(CLUSTER * x) / math.sinh(CLUSTER)


def inertial_speed(traction: Traction, pin: Pin, radius: float, inertia: float, omega: float,
                   settings: RollerSettings) -> tuple[np.ndarray, int, float]:
    """w_r per angle of the periodic state, revolutions marched, last relative change."""
    from camtrain.roller._kernel import Scheme, Tables, march

    v0 = np.ascontiguousarray(traction.v_s0, dtype=float)
    grid = clustered_grid(settings.table_points)
    vmax = float(np.max(np.abs(v0)))
    scale = np.abs(v0) + vmax + 1e-12
    table = np.zeros((v0.size, grid.size))       # no traction where unloaded
    loaded = np.flatnonzero(traction.load > 0.0)
    if loaded.size:
        for k, x in enumerate(grid):
            table[loaded, k] = traction.force(scale[loaded] * x, loaded)
    w_ref = vmax / radius + 1e-12
    speed_scale = 2.0 * w_ref
    w = np.broadcast_to(speed_scale * grid, table.shape)
    pin_table = np.ascontiguousarray(pin.torque(w, np.broadcast_to(traction.load[:, None],
                                                                     table.shape)))
    tab = Tables(grid, table, scale, pin_table, speed_scale, v0)
    dt = 2.0 * math.pi / v0.size / abs(omega)
    sch = Scheme(float(radius), float(inertia), dt, int(settings.substeps),
                 float(settings.tolerance), int(settings.revolutions), w_ref)
    start = float(quasi_static_speed(traction, pin, radius)[0])
    out, revs, change = march(tab, sch, start)
    return out, int(revs), float(change)


def solve_roller(traction: Traction, pin: Pin, radius: float, inertia: float,
                 settings: RollerSettings = RollerSettings()) -> RollerField:
    """The roller's motion and losses over the cycle (one pair)."""
    kin = traction.kin
    revs, change = 0, 0.0
    if settings.solver == "inertial" and inertia > 0.0 and pin.kind != "locked":
        w, revs, change = inertial_speed(traction, pin, radius, inertia, kin.omega, settings)
        label = (f"inertial: periodic implicit-Euler march, {settings.substeps} substeps per "
                 f"grid step, {revs} revolutions")
    elif settings.solver in SOLVERS:
        w, known = _quasi_static(traction, pin, radius)
        label = "quasi_static: J = 0, traction x radius = pin torque per angle"
        return motion_of(traction, pin, radius, inertia, w, label, revs, change,
                         settings.skid_slip, known)
    else:
        raise ValueError(f"roller solver {settings.solver!r}: expected one of {SOLVERS}")
    return motion_of(traction, pin, radius, inertia, w, label, revs, change, settings.skid_slip)


def forces(traction: Traction, pin: Pin, w, u_s, known=None):
    """Traction [N] at sliding speeds ``u_s`` and pin torque [N m] at roller speeds ``w``, per
    angle: on the angles the compiled balance solved (``known``, from :func:`_quasi_static`)
    by its compiled laws, the same steps; elsewhere by the array laws. Every pin holds no torque
    at w = 0 and an unloaded contact carries no traction, so those are not evaluated."""
    if known is None:
        return traction.force(u_s), pin.torque(w, traction.load)
    from camtrain.roller._balance import forces_at

    idx, (angles, law) = known
    f_t, t_pin = np.zeros(w.shape), np.zeros(w.shape)
    f_t[idx], t_pin[idx] = forces_at(angles, law, u_s[idx], w[idx])
    rest = np.ones(w.shape, dtype=bool)
    rest[idx] = False
    others = np.flatnonzero(rest & (traction.load > 0.0))
    if others.size:
        f_t[others] = traction.force(u_s[others], others)
    turning = np.flatnonzero(rest & (w != 0.0))
    if turning.size:
        t_pin[turning] = pin.torque(w[turning], traction.load[turning])
    return f_t, t_pin


def motion_of(traction: Traction, pin: Pin, radius, inertia, w, label, revs, change,
              skid_slip, known=None, f_t=None) -> RollerField:
    """Every per-angle quantity of the roller at speeds ``w`` [rad/s] (``known``: see
    :func:`forces`). ``f_t``: the traction [N] the speeds were solved with, when a march
    solved them on tables of it (the elastic train's, :mod:`camtrain.dynamics.spin`): near
    rolling the traction is steep in the sliding, so the law at a speed within the tables'
    error would not be the traction that balanced it; else the law at ``w``."""
    kin = traction.kin
    u_s = speeds.sliding_speed(kin.v_cam, kin.v_follower, w, radius)
    if pin.kind == "frictionless":
        u_s = np.where(traction.load > 0.0, 0.0, u_s)   # exact rolling, no round-off
    u_e = speeds.entrainment_speed(kin.v_cam, u_s)
    slip = speeds.slip(u_s, traction.v_s0)
    if f_t is None:
        f_t, t_pin = forces(traction, pin, w, u_s, known)
    else:
        t_pin = pin.torque(w, traction.load)
    f_r = traction.rolling_force(u_s)
    kinetic = np.zeros(w.shape)
    if inertia:
        dtheta = 2.0 * math.pi / w.size
        dw = (speeds.periodic_next(w) - speeds.periodic_previous(w)) / (2.0 * dtheta) \
            * abs(kin.omega)
        kinetic = inertia * w * dw
    loaded = traction.load > 0.0
    return RollerField(
        omega_roller=w, sliding=u_s, entrainment=u_e, slip=slip,
        slide_roll_ratio=speeds.slide_roll_ratio(u_s, u_e),
        rolls=loaded & ~(np.abs(slip) > skid_slip),   # NaN slip (V_s0 = 0) counts as rolling
        traction=f_t, rolling_force=f_r, pin_torque=t_pin,
        sliding_power=np.abs(f_t * u_s), rolling_power=f_r * np.abs(u_e),
        pin_power=t_pin * w, kinetic_power=kinetic,
        solver=label, revolutions=revs, periodic_change=change, radius=float(radius),
        inertia=float(inertia), skid_slip=float(skid_slip))
