"""Camshaft-level calculations: summed lobe torque and drive power, harmonic orders, pendulum
dampers (Williams 2013 ch 9-10) and bearing loads from lobe and pulley forces (Ball 1988 §6.3,
Yang 1992 §3.3.1). Journal orbits of the resulting bearing loads: :mod:`camtrain.bearings`.
"""
from .damper import (
                     absorber_mass_ratio,
                     bifilar_length,
                     damper_motion,
                     idler_order,
                     optimum_damper,
                     pendulum_amplitude_ratio,
                     pendulum_effective_inertia,
                     tuned_order,
)
from .harmonics import Harmonics, both_banks_amplitude, harmonic_orders, order_curve
from .loads import lobe_force, pulley_load, shaft_forces, split_beam_loads
from .torque import bank_torque, cam_grid, camshaft_torque, drive_power, second_bank, shift_curve

__all__ = ["cam_grid", "shift_curve", "camshaft_torque", "bank_torque", "second_bank",
           "drive_power", "Harmonics", "harmonic_orders", "order_curve", "both_banks_amplitude",
           "absorber_mass_ratio", "tuned_order", "pendulum_amplitude_ratio",
           "pendulum_effective_inertia", "bifilar_length", "damper_motion", "idler_order",
           "optimum_damper", "split_beam_loads", "lobe_force", "pulley_load", "shaft_forces"]
