"""Typed records the compiled marches take instead of long positional argument lists.

Every compiled march of a valve train (:mod:`._kernel`, the single train; the shaft-and-trains
march of :mod:`camtrain.coupled`) takes its data grouped by lifetime: what is set once (the
linear part, the contact laws, the inputs over the batch of steps), the state carried from step
to step, and the outputs. A record is a named tuple: numba compiles it to a plain struct of its
fields (no cost in the loops, cached on disk like any argument), and a new term of a model is a
new field of the record it belongs to, not a new position in every signature. (Measured on a
small Newmark loop, 12 degrees of freedom: named tuples compiled in 1.6-1.9 s against 0.9-1.4 s
positional, 3.0-3.4 s as a jitclass, which numba can moreover not cache on disk; the loops ran
equally fast within the machine's noise. Structured arrays hold only fixed-size fields.) A
record is not free to pass: the small helpers a step calls for every contact (an indicator, a
gap, a coefficient) take the plain arrays they read, unpacked once by their caller; with the
records passed down to them the single train's march ran 1.66x slower.

Records shared by the single train and the coupled march:

* :data:`Unilateral`: the two unilateral contacts of a train (index ``CAM``, ``SEAT`` of
  :mod:`camtrain.dynamics.train`): stiffness ``k`` [N/m], damping ``c`` [N s/m] and offset
  ``off`` [m] of each, as ``TrainModel.uni_k``, ``uni_c``, ``uni_offset``.
"""
from __future__ import annotations

from collections import namedtuple

import numpy as np

__all__ = ["Unilateral", "Train", "Inputs", "CamLaw", "Marched", "TrainState", "Hydraulic",
           "HP_SIZE", "HP_SLOTS", "H_ROWS", "Spin", "unilateral", "linear_law"]

#: the unilateral contacts (cam, seat) of a train: k [N/m], c [N s/m], off [m] (arrays of 2)
Unilateral = namedtuple("Unilateral", "k c off")

#: the single train's linear part M u'' + C u' + K u = f0 (``m`` the lumped masses [kg]), the
#: node each unilateral contact acts on, each contact's closing threshold ``thr`` [N] and its
#: hydraulic lash adjuster ``hla`` (a :data:`Hydraulic`, ``on`` 0 without one). A roller's spin
#: (a :data:`Spin`) is the Newmark march's own argument, not a field: the train goes by value
#: into the step's helpers at every (sub)step, and with the spin's tables in it the single
#: train's march ran 1.6x slower (Zeta intake deck, no roller)
Train = namedtuple("Train", "m K C f0 node thr hla")

#: a hydraulic lash adjuster between the ``f`` (body) and ``q`` (plunger) nodes
#: (:mod:`camtrain.dynamics.hla`, SI, pressures gauge): plunger motion per valve-referred motion
#: ``ratio``, plunger ``area``, chamber ``v_dead`` at full collapse, rest extension ``x_rest``,
#: ``stroke``, valve-referred rest compression ``w0``, end-stop stiffness ``k_stop``, leak
#: conductance ``g_leak`` and Couette coefficient ``c_couette``, ``p_supply``, check valve
#: ``p_crack``, ``check_k`` = C_d A sqrt(2/rho), ``full_open``; oil modulus ``k_liq``, free
#: ``air`` fraction, polytropic ``n_poly``, pressure floor ``p_floor``, chamber scheme ``theta``;
#: the check valve's model ``valve`` (0 the quasi-static orifice, 1 the dynamic ball) and the
#: ball's mass ``ball_m`` [kg], spring rate ``ball_k`` [N/m] and preload ``ball_f0`` [N] on its
#: seat, viscous damping ``ball_c`` [N s/m], pressure area ``seat_area`` [m^2], lift stop
#: ``ball_lift`` [m] and ``curtain_k`` = C_d pi d_seat sqrt(2/rho) (flow per lift and root Pa)
Hydraulic = namedtuple("Hydraulic", "on f q ratio area v_dead x_rest stroke w0 k_stop g_leak "
                       "c_couette p_supply p_crack check_k full_open k_liq air n_poly p_floor "
                       "theta valve ball_m ball_k ball_f0 ball_c seat_area ball_lift curtain_k")

#: length of a chamber state ``hp`` (:data:`TrainState`): the slots of :data:`HP_SLOTS`
HP_SIZE = 8
#: the chamber state's slots: pressure [Pa, gauge], check-valve flow, leak flow [m^3/s], the last
#: step's pressure rate [Pa/s] (the chamber solve's first guess), the volumes [m^3] through the
#: check valve and through the annulus since the last output sample, the check ball's lift [m]
#: and speed [m/s] (zero with the quasi-static valve)
HP_SLOTS = ("pressure", "check_flow", "leak_flow", "rate", "check_volume", "leak_volume",
            "ball_lift", "ball_speed")

#: a roller turning on its pin, marched with the train (:mod:`camtrain.dynamics.spin`, SI):
#: ``radius``, spin ``inertia``; tables: normalised ``grid``, load levels ``loads``, ``traction``
#: (angles, loads, grid) at sliding speeds ``sliding_scale[angle] * grid``, ``pin`` torque
#: (loads, grid) at roller speeds ``speed_scale * grid``, ``v_s0`` per grid angle; at the step
#: times of the batch: the fractional grid position ``pos`` and the load ratio ``ratio``
Spin = namedtuple("Spin", "on radius inertia grid loads traction sliding_scale pin speed_scale "
                  "v_s0 pos ratio")

#: the contacts' inputs b [m] and b' [m/s] (contacts, steps + 1) at the step times of a batch,
#: the step ``dt`` [s], the output ``stride`` (steps per sample) and the batch's start time t0
Inputs = namedtuple("Inputs", "b bd dt stride t0")

#: the cam contact's load-deflection law: ``law`` 0 linear, 1 the Hertz line contact of
#: constants ``hz``, the cam's radius of curvature ``rad`` and load ratio ``rat`` at the steps
CamLaw = namedtuple("CamLaw", "law hz rad rat")

#: the march's samples every stride: displacement, velocity, acceleration (n, samples), contact
#: forces (2, samples), its events: time, kind (2 j + closing), approach speed, and the
#: adjuster's ``h`` (:data:`H_ROWS`, samples), the roller's speed [rad/s], sliding speed [m/s]
#: and traction [N] ``r`` (3, samples)
Marched = namedtuple("Marched", "u v a f ev_t ev_kind ev_rate h r")

#: the adjuster's sampled rows: chamber pressure [Pa], check-valve and leak flows [m^3/s],
#: plunger extension [m], the volumes [m^3] through the check valve and the annulus over the
#: sample's interval (their sums over a revolution are exact step sums), the check ball's lift
H_ROWS = ("pressure", "check_flow", "leak_flow", "extension", "check_volume", "leak_volume",
          "ball_lift")

#: the single train's state, updated in place: u, v, a, the contact states ``act``; the
#: explicit scheme's previous displacement ``u_prev`` and contact indicators ``psi_prev``; the
#: adjuster's chamber ``hp`` (:data:`HP_SLOTS`, :data:`HP_SIZE` long); the roller's ``wr`` =
#: (speed [rad/s], sliding speed [m/s], traction [N])
TrainState = namedtuple("TrainState", "u v a act u_prev psi_prev hp wr")


def unilateral(model) -> Unilateral:
    """The unilateral contacts of a :class:`camtrain.dynamics.train.TrainModel`."""
    return Unilateral(model.uni_k, model.uni_c, model.uni_offset)


def linear_law() -> CamLaw:
    """A linear cam contact (no geometry)."""
    return CamLaw(0, np.zeros(5), np.zeros(0), np.zeros(0))
