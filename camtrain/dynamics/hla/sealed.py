"""The sealed incompressible chamber: its pressure is a constraint reaction, not a state.

With oil of infinite bulk modulus, no free air, no leak-down annulus (no clearance: no pressure
flow and no Couette flow) and the check valve shut, the chamber's continuity equation
(Merritt 1967, eq. 2-21) reduces to dV/dt = 0: the plunger is locked in its body and the
chamber pressure is whatever force keeps it there, the Lagrange multiplier of the constraint
x = const (an index-3 constraint of the train's equations of motion). The implicit step of
:func:`camtrain.dynamics.hla.chamber_step` enforces the constraint at the position level
(V1 = V0), which the Newmark average-acceleration step satisfies exactly, but the trapezoidal
rule does not damp the constrained mode: any inconsistency of the plunger's acceleration
relative to its body persists undamped as a step-to-step alternation of the pressure (the
known behaviour of the trapezoidal rule on index-3 constraints: positions and velocities
converge, the multipliers oscillate without decay; Cardona & Geradin, "Time integration of the
equations of motion in mechanism analysis", Computers & Structures 33(3), 1989, 801-820). The
acceleration is restarted from the equilibrium at every contact change, where the contact's
force jumps (a closing damper); with the chamber's last pressure the restart is inconsistent
by the jump's share on the plunger, and the alternation grows over the revolutions until its
trough reaches the vapour pressure, the chamber cavitates and the plunger ratchets out.

:func:`consistent_restart` restarts such a chamber consistently: the plunger force is changed
so that the extension's acceleration is zero (the constraint differentiated twice), the
pressure with it (not below the vapour pressure). A compressible chamber (its pressure a state),
one with a leak (its pressure a function of the plunger's speed) or with the check valve open
is left as it is: its pressure is continuous across a contact change."""
from __future__ import annotations

import math

from numba import njit


@njit(cache=True)
def is_sealed(hr, hp):
    """Whether the chamber of record ``hr`` with state ``hp`` (pressure, check-valve inflow,
    outflow, pressure rate) is sealed and incompressible: its pressure a constraint reaction."""
    return (hr.on != 0 and hr.air == 0.0 and math.isinf(hr.k_liq) and hr.g_leak == 0.0
            and hr.c_couette == 0.0 and hp[1] == 0.0)


@njit(cache=True)
def restart_force(hr, hp, x_acc, compliance):
    """The change of the plunger force [N] (its own frame) that restarts a sealed
    incompressible chamber (:func:`is_sealed`) consistently: ``x_acc`` the extension's
    acceleration [m/s^2] from the equilibrium with the chamber at its pressure ``hp[0]``,
    ``compliance`` the extension's acceleration per unit plunger force [1/kg] (ratio^2 times
    the plunger's and the body's inverse masses); ``hp[0]`` changed with it. Any other chamber:
    0, nothing changed."""
    if not is_sealed(hr, hp) or compliance <= 0.0:
        return 0.0
    p_new = max(hp[0] - x_acc / (compliance * hr.area), hr.p_floor)
    force = (p_new - hp[0]) * hr.area
    hp[0] = p_new
    return force


@njit(cache=True)
def consistent_restart(hr, hp, acc, minv, f, q):
    """:func:`restart_force` of the chamber between nodes ``f`` (body) and ``q`` (plunger),
    ``acc`` the accelerations from the equilibrium (M^-1 ``minv``; changed in place with the
    force's share, ratio times it on the plunger and against the body)."""
    ratio = hr.ratio
    compliance = ratio * ratio * (minv[f, f] + minv[q, q] - minv[f, q] - minv[q, f])
    force = restart_force(hr, hp, -ratio * (acc[f] - acc[q]), compliance)
    if force != 0.0:
        for i in range(acc.size):
            acc[i] += ratio * force * (minv[i, q] - minv[i, f])
