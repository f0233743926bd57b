"""The roller's spin marched with the elastic train: its speed on the pin as a state of the march.

A roller follower turns on its pin under the traction of the cam contact (Chiu 1992, Tribol.
Trans. 35:261; Alakhramsing et al. 2018, Proc. IMechE J 232; the equation of
:mod:`camtrain.roller.solve`):

    J dw_r/dt = r_r F_t(u_s, W) - T_pin(w_r, W),   u_s = V_s0 - w_r r_r,

with W the cam contact's normal force of the marched train (the valve-referred cam force times
the load ratio at that instant), V_s0 = V_c - V_f the sliding speed of the non-rotating follower,
r_r the roller radius, J its spin inertia about the pin. The traction F_t is the roller
effect's own law (film and friction of the contact at the roller's entrainment, any
``roller.traction``) and T_pin its pin's friction torque; both are tabulated once per run
(:func:`camtrain.assemble.roller.spin_tables`): the traction per grid angle on a grid of
loads and sliding speeds, the pin torque on a grid of loads and roller speeds
(:class:`RollerTables`). Between table nodes: linear in the sliding and the roller speed and
between grid angles; between load levels (uniform in W^(1/3), fine at light load) the
traction geometrically (ln F linear in W^(1/3): the Barus shear of Ball 1988 eq. 4.7 grows
exponentially with the Hertz pressure, which goes as sqrt(W), so a linear blend of F would
overshoot between coarse levels; the error is second order in the level spacing, measured in
tests/roller/test_roller_spin_march.py), the pin torque linearly in W (exact for the needle
bearing's M_0 + f_1 W d_m); held at the ends.

Marching (:func:`.step.spin_step`, called from the Newmark step of
:mod:`camtrain.dynamics._kernel` after each accepted (sub)step): backward (implicit) Euler over
the (sub)step at the end state's contact force. The residual J (w1 - w0)/h - r F_t + T_pin
increases with w1 (the traction falls and the pin torque rises with it), so the root is unique;
it is bracketed between the last speed and rolling, narrowed by bisection over the tables'
nodes to one linear piece, and found there by regula falsi. Backward Euler is L-stable: the
stiff rolling mode of a light roller, relaxation time J / (r^2 dF_t/du_s) of microseconds, is
damped at any step instead of ringing (the trapezoidal rule would not damp it); it is first
order in the step.

The train carries no tangential contact force (its contacts are normal springs): the spin is
driven by the marched normal force and does not act back on the train (the periodic check
of the march also holds the roller's speed, so the march may take a revolution more). The
roller's mass as it swings with the arm is in the train's masses already
(:func:`camtrain.assemble.mechanism.roller_inertia`, reduced to the valve through the arm B);
its spin inertia J is not.
"""
from camtrain.dynamics.spin.record import (
    RollerTables,
    no_roller,
    spin_record,
    spin_start,
    step_positions,
)

__all__ = ["RollerTables", "no_roller", "spin_record", "spin_start", "step_positions"]
