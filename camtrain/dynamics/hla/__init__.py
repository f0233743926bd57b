"""Hydraulic lash adjuster (HLA): plunger, high-pressure chamber, leak-down annulus, check valve.

The adjuster is a plunger of area A_p sliding in a body; between them a high-pressure chamber of
volume V = V_dead + A_p x (x the plunger's extension from full collapse, 0..stroke). Its states
are the plunger's position and velocity (a node of the elastic train, or the plunger of the
leak-down test) and the chamber's gauge pressure p. Physics, each one function below:

* **Chamber compliance**: the pressure-rise equation (V / K_e(p)) dp/dt = -dV/dt + Q_in - Q_out
  (Merritt 1967, *Hydraulic Control Systems*, eq. 2-21, the continuity of a control volume). The
  effective bulk modulus is the named model ``free_air_polytropic``: oil of constant bulk
  modulus K_l carrying a volume fraction alpha of free (undissolved) air at atmospheric pressure,
  the air compressed polytropically (p V^n constant). A unit volume of mixture at atmospheric
  pressure occupies phi(p) = (1 - alpha) exp(-p/K_l) + alpha (p_atm/(p + p_atm))^(1/n) at gauge
  pressure p, and K_e = -phi / (dphi/dp) (the series compliance of liquid and gas of Merritt's
  eq. 2-26 with the gas volume following the gas law; the same free-air mixture model as the
  survey of Gholizadeh, Burton & Schoenau, Int. J. Fluid Power 12(2), 2011, eq. 16 with n = 1
  isothermal, n = 1.4 adiabatic). Air dissolving and coming out of solution is not modelled.
* **Leak-down**: laminar flow through the plunger-body annulus of diameter d, radial clearance c,
  length L, relative eccentricity e: Q_out = pi d c^3 (1 + 1.5 e^2) / (12 mu L) (p - p_res) +
  pi d c / 2 x' (pressure flow of the eccentric annulus and the Couette flow dragged by the
  plunger sliding at x' relative to the body; Merritt 1967 eq. 3-40 with the eccentricity factor
  of White, *Viscous Fluid Flow*, 3rd ed. §3-3.6), into the low-pressure reservoir at the
  supply (gallery) pressure.
* **Check valve** (``quasi_static``, the default): a ball held on its seat by a spring opens
  once the supply pressure exceeds the chamber's by the cracking pressure; its open area grows
  linearly from nothing at cracking to the full area ``full_open`` above it (the ball's spring
  lift, quasi-static), and the flow is a sharp-edged orifice, Q_in = C_d A_v sqrt(2 (p_s - p) /
  rho) (Merritt 1967 eq. 3-9). Closed: no reverse flow.
* **Check valve** (``ball``): the ball's own motion, m y'' = (p_s - p) A_seat - F_0 - k y - c y'
  (Newton's second law; A_seat = pi d^2/4 of the seat's bore d, F_0 the spring's preload on the
  seat, so it cracks at F_0/A_seat), between its seat and its lift stop (both inelastic); the
  flow through the curtain pi d y (at most pi d^2/4) as a sharp-edged orifice either way
  (Merritt eq. 3-9), back out of the chamber while the ball is off its seat above the supply.
  Its lift and speed are states of the chamber, marched in the chamber's implicit step
  (:func:`.chamber.ball_end`); the massless ball is the quasi-static orifice
  (:func:`.element.quasi_static_equivalent`).
* **Plunger**: its spring (rate and preload at the rest extension) pushes it out of the body; its
  mass; stops at full collapse (x = 0) and full extension (x = stroke), stiff linear springs.

Marching: the chamber's equation is stiff (with the check valve open the pressure follows the
supply in microseconds), so the march takes it implicitly: over a step h,
ln phi(p1) - ln phi(p0) = ln(V1/V0) - h [theta (Q_in - Q_out)/V at the end + (1 - theta) (...)
at the start] (the compliance integrated exactly for the volume change), theta = 1 backward
Euler (``backward_euler``, L-stable, the default) or 1/2 (``trapezoidal``, second order, not
damping the stiff check-valve mode). The residual falls monotonically with p1, so the scalar
Newton iteration with a bracket (:func:`chamber_step`) always finds its root.

A plunger moving ``ratio`` times the valve-referred motion (1 in a bucket tappet; the push rod's
ratio in a push-rod lifter; the lever ratio at the pivot of a finger follower) acts on the train
with its force times ``ratio`` (virtual work).
"""
from camtrain.dynamics.hla.chamber import (
    ball_end,
    chamber_advance,
    chamber_start,
    chamber_step,
    extension,
    hydraulic_record,
    no_adjuster,
    plunger_force,
)
from camtrain.dynamics.hla.element import (
    BULK_MODELS,
    CHAMBER_SCHEMES,
    CHECK_VALVES,
    P_ATM,
    LashAdjuster,
    ball_cracking_pressure,
    chamber_stiffness,
    check_valve_flow,
    couette_coefficient,
    curtain_area,
    effective_bulk_modulus,
    leak_conductance,
    leakdown_time,
    mixture_volume,
    pivot_ratio,
    quasi_static_equivalent,
)
from camtrain.dynamics.hla.leakdown import leakdown_test
from camtrain.dynamics.hla.placement import (
    SeriesAdjuster,
    _spring_at_rest,
    chamber_from,
    march_record,
    rigid_adjuster,
    with_element,
    with_lash_adjuster,
)

__all__ = ["LashAdjuster", "BULK_MODELS", "CHAMBER_SCHEMES", "P_ATM", "effective_bulk_modulus",
           "mixture_volume", "leak_conductance", "couette_coefficient", "check_valve_flow",
           "chamber_stiffness", "leakdown_time", "leakdown_test", "hydraulic_record",
           "no_adjuster", "pivot_ratio", "with_lash_adjuster", "rigid_adjuster", "chamber_step",
           "extension", "plunger_force", "_spring_at_rest", "CHECK_VALVES", "ball_end",
           "chamber_advance", "chamber_start", "ball_cracking_pressure", "curtain_area",
           "quasi_static_equivalent", "SeriesAdjuster", "with_element", "march_record",
           "chamber_from"]
