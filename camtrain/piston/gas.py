"""Inter-ring gas pressures: the ring pack as volumes joined by ring-gap orifices (Yang 1992 §5.2).

Each inter-ring volume n (between ring n and ring n+1) is isothermal at its land temperature
(Yang's assumption d); gas leaves or enters through the ring gaps, each an isentropic
square-edged orifice (eq. 5.9, with the 1/2 exponent that the OCR lost restored). Volume 0 is the
combustion chamber (the cylinder-pressure table), the last is the crankcase above the oil-control
ring (ambient, Yang's assumption f). In Yang's non-dimensional form (eqs. 5.12-5.14), with
P = p/p_a, M = m/m_0, m_0 = p_a V_1/(R T_0), theta = omega t::

    dM_{n-1}/dtheta = K (A_n/A_1) (P_up / Tbar_up^1/2) psi(P_down/P_up)          (5.12, 5.14)
    dP_n/dtheta     = Tbar_n (V_1/V_n) (dM_{n-1}/dtheta - dM_n/dtheta)            (5.13)
    K = (K_c A_1 / (omega V_1)) (2 k R T_0 / (k - 1))^1/2

with psi(r) = r^(1/k) (1 - r^((k-1)/k))^1/2 above the critical ratio r_c = (2/(k+1))^(k/(k-1))
and psi(r_c) below it (choked flow). R is the *specific* gas constant (Yang calls it universal).
Reverse flow (a lower volume at the higher pressure) uses the higher side as upstream, with its
temperature, and a negative sign.

The cyclic solution is marched by Yang's implicit trapezoid (eq. 6.1, the default, which
conserves mass to its iteration tolerance) or by scipy's LSODA as an independent reference, cycle
after cycle until the start pressure repeats.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

#: Specific gas constant of air and burnt gas [J/(kg K)] (Yang prints no value).
GAS_CONSTANT_AIR = 287.0
#: Atmospheric pressure [Pa]: gauge cylinder tables are made absolute with it.
ATMOSPHERE = 101325.0
ONE_DEGREE = np.pi / 180.0


def critical_pressure_ratio(k: float) -> float:
    """r_c = (2/(k+1))^(k/(k-1)): below it the orifice is choked (Yang §5.2: 0.546 at k = 1.3)."""
    return (2.0 / (k + 1.0)) ** (k / (k - 1.0))


def orifice_flow_function(r, k: float):
    r"""psi(r) = r^(1/k) sqrt(1 - r^((k-1)/k)), held at psi(r_c) below r_c (Yang eqs. 5.12, 5.14).

    r = p_downstream/p_upstream in [0, 1]. psi(r_c) = 0.2267 at k = 1.3 (Yang's 0.227).
    """
    rc = critical_pressure_ratio(k)
    r = np.clip(np.asarray(r, dtype=float), rc, 1.0)
    return r ** (1.0 / k) * np.sqrt(np.maximum(1.0 - r ** ((k - 1.0) / k), 0.0))


def orifice_mass_flow(p_up, p_down, T_up, area, k: float, discharge: float,
                      gas_constant: float = GAS_CONSTANT_AIR):
    r"""Isentropic orifice mass flow [kg/s] from p_up to p_down (Yang eq. 5.9, 1/2 restored).

    .. math:: \dot m = K_c A \sqrt{\frac{2k}{(k-1) R T_s}}\, p_s\, \psi(p/p_s)

    Signed: negative when p_down > p_up (the flow runs the other way, from its own upstream side
    at T_up of that side is the caller's choice; here T_up is used for both directions).
    """
    p_up, p_down = np.asarray(p_up, dtype=float), np.asarray(p_down, dtype=float)
    forward = p_up >= p_down
    hi = np.where(forward, p_up, p_down)
    lo = np.where(forward, p_down, p_up)
    c = discharge * area * np.sqrt(2.0 * k / ((k - 1.0) * gas_constant * np.asarray(T_up)))
    flow = c * hi * orifice_flow_function(lo / hi, k)
    return np.where(forward, flow, -flow)


@dataclass(frozen=True)
class Labyrinth:
    """A ring pack's gas path: N orifices (ring gaps) and N-1 inter-ring volumes.

    Attributes (SI): ``areas`` [m^2] of the N gap orifices, top ring first; ``volumes`` [m^3]
    of the N-1 inter-ring volumes; ``temperatures`` [K] of those volumes (their lands);
    ``k`` ratio of specific heats; ``discharge`` K_c; ``gas_constant`` [J/(kg K)];
    ``p_below`` [Pa absolute] below the last ring (crankcase; ambient in Yang).
    """

    areas: tuple[float, ...]
    volumes: tuple[float, ...]
    temperatures: tuple[float, ...]
    k: float = 1.3
    discharge: float = 0.65
    gas_constant: float = GAS_CONSTANT_AIR
    p_below: float = ATMOSPHERE

    def __post_init__(self):
        if len(self.volumes) != len(self.areas) - 1 or len(self.temperatures) != len(self.volumes):
            raise ValueError("a labyrinth of N orifices needs N-1 volumes and temperatures")


@dataclass(frozen=True)
class GasSolution:
    """Cyclic inter-ring pressures on the crank-angle grid.

    ``theta`` [rad] (0 = TDC firing), ``pressures`` [Pa absolute], shape (N+1, n): the cylinder,
    each inter-ring volume, the crankcase; ``flows`` [kg/s], shape (N, n): through each gap,
    positive downwards (away from the chamber); ``cycles`` marched; ``cyclic_change`` the relative
    change of the start pressures over the last cycle; ``mass_residual`` the relative mass balance
    of each volume over the last cycle (inflow - outflow - storage change).
    """

    theta: np.ndarray
    pressures: np.ndarray
    flows: np.ndarray
    cycles: int
    cyclic_change: float
    mass_residual: np.ndarray


def _flows(P_all, T_all, lab: Labyrinth, K: float, A1: float):
    """Non-dimensional gap flows dM/dtheta (positive downwards) for pressures P_all (N+1,)."""
    out = np.empty(len(lab.areas))
    for n, area in enumerate(lab.areas):
        up, down = P_all[n], P_all[n + 1]
        if up >= down:
            out[n] = K * (area / A1) * up / math.sqrt(T_all[n]) * \
                float(orifice_flow_function(down / up, lab.k))
        else:
            out[n] = -K * (area / A1) * down / math.sqrt(T_all[n + 1]) * \
                float(orifice_flow_function(up / down, lab.k))
    return out


def solve_labyrinth(theta_table, p_cylinder, T_cylinder, lab: Labyrinth, omega: float, *,
                    period: float = 4.0 * np.pi, step: float = ONE_DEGREE, method: str = "trapezoid",
                    tolerance: float = 1e-6, max_cycles: int = 30) -> GasSolution:
    """Cyclic inter-ring pressures for a cylinder-pressure table (Yang §5.2, §6.2.1).

    Args:
        theta_table, p_cylinder: crank angle [rad] and cylinder pressure [Pa absolute]; the table
            is periodic over ``period`` and interpolated linearly (Yang interpolates from 10 deg).
        T_cylinder: chamber gas temperature [K] (scalar; Yang's mean chamber temperature).
        lab: the labyrinth; omega: engine speed [rad/s].
        step: output grid and, for ``method="trapezoid"``, the march step (Yang: 1 deg).
        method: ``"trapezoid"`` (default: Yang eq. 6.1, implicit, iterated to ``tolerance``;
            conserves mass to that tolerance) or ``"lsoda"`` (scipy, adaptive: a reference).
        tolerance: also the cyclic-convergence tolerance on the start pressures.
    """
    from scipy.integrate import solve_ivp, trapezoid

    n_vol = len(lab.volumes)
    T0 = lab.temperatures[0]
    V1, A1 = lab.volumes[0], lab.areas[0]
    K = (lab.discharge * A1 / (abs(omega) * V1)) * math.sqrt(
        2.0 * lab.k * lab.gas_constant * T0 / (lab.k - 1.0))
    pa = ATMOSPHERE
    tt = np.asarray(theta_table, dtype=float)
    pp = np.asarray(p_cylinder, dtype=float) / pa
    Tbar = np.array([T_cylinder / T0, *[t / T0 for t in lab.temperatures], 1.0])
    vol_ratio = np.array([V1 / v for v in lab.volumes])
    P_below = lab.p_below / pa
    n_out = int(round(period / step))
    grid = np.linspace(0.0, period, n_out + 1)

    def p_cyl(th):
        return float(np.interp(th % period, tt, pp, period=period))

    def rhs(th, P):
        P_all = np.concatenate(([p_cyl(th)], P, [P_below]))
        dM = _flows(P_all, Tbar, lab, K, A1)
        return Tbar[1:-1] * vol_ratio * (dM[:-1] - dM[1:])

    P0 = np.full(n_vol, P_below)
    change, cycles = np.inf, 0
    while cycles < max_cycles:
        cycles += 1
        if method == "lsoda":
            sol = solve_ivp(rhs, (0.0, period), P0, method="LSODA", t_eval=grid,
                            rtol=tolerance * 1e-2, atol=tolerance * 1e-3)
            P = sol.y
        elif method == "trapezoid":
            P = _trapezoid(rhs, grid, P0, tolerance)
        else:
            raise ValueError(f"unknown gas march {method!r}; expected 'lsoda' or 'trapezoid'")
        change = float(np.max(np.abs(P[:, -1] - P0) / P0))
        P0 = P[:, -1].copy()
        if change < tolerance:
            break
    P_cyl = np.array([p_cyl(th) for th in grid])
    P_all = np.vstack([P_cyl, P, np.full(grid.size, P_below)])
    dM = np.array([_flows(P_all[:, i], Tbar, lab, K, A1) for i in range(grid.size)]).T
    # mass balance of each volume over the cycle: inflow - outflow = storage change
    inflow = trapezoid(dM[:-1] - dM[1:], grid, axis=1)
    storage = (P[:, -1] - P[:, 0]) / (Tbar[1:-1] * vol_ratio)
    scale = trapezoid(np.abs(dM[:-1]) + np.abs(dM[1:]), grid, axis=1) + 1e-300
    m0 = pa * V1 / (lab.gas_constant * T0)
    return GasSolution(theta=grid, pressures=P_all * pa, flows=dM * m0 * abs(omega),
                       cycles=cycles, cyclic_change=change,
                       mass_residual=np.abs(inflow - storage) / scale)


def _trapezoid(rhs, grid, P0, tolerance):
    """Yang eq. 6.1: implicit trapezoid, each step iterated until P changes by < tolerance."""
    P = np.empty((P0.size, grid.size))
    P[:, 0] = P0
    f_old = rhs(grid[0], P0)
    for i in range(1, grid.size):
        h = grid[i] - grid[i - 1]
        guess = P[:, i - 1] + h * f_old
        for _ in range(100):
            f_new = rhs(grid[i], guess)
            new = P[:, i - 1] + 0.5 * h * (f_old + f_new)
            done = np.max(np.abs(new - guess) / new) < tolerance
            guess = new
            if done:
                break
        P[:, i] = guess
        f_old = rhs(grid[i], guess)
    return P
