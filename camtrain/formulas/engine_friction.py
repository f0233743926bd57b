r"""Engine friction correlations: Patton-Nitschke-Heywood (1989), Sandoval-Heywood (2003) and
Chen-Flynn (1965), one function per published term.

The PNH and Sandoval-Heywood terms are dimensional fits, written in their own units (bore B,
stroke S, bearing diameters D and lengths L, valve lift L_v in mm; speed N in rev/min; mean
piston speed S_p in m/s; fmep in kPa). Every function here takes SI (m, rad/s, m/s, Pa) and
returns the friction mean effective pressure in Pa: it converts on the way in and out.

Sources. Patton, Nitschke & Heywood, "Development and Evaluation of a Friction Model for
Spark-Ignition Engines", SAE 890836 (1989); Sandoval & Heywood, "An Improved Friction Model for
Spark-Ignition Engines", SAE 2003-01-0725 (2003), and Sandoval's MIT thesis of the same title
(2002). The constants were transcribed from two independent public implementations that cite
the thesis equation by equation and agree term by term (the term docstrings name each term's
group); the SAE scans were not available to check them digit by digit (docs/engine.md, "Friction
correlations", lists what was and was not checked). Chen & Flynn, "Development of a Single
Cylinder Compression Ignition Research Engine", SAE 650733 (1965): the form only, its constants
are fits to one engine each.

Viscosity scaling (Sandoval-Heywood): the hydrodynamic terms are multiplied by
r = sqrt(nu / nu_0), nu_0 = 10.6 cSt, the oil of the original data; PNH 1989 has r = 1.
Boundary factor: the terms of boundary and mixed friction carry (1 + N_0 / N), with N_0 = 1000
rev/min in PNH 1989 and 500 rev/min in Sandoval-Heywood.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import field_error

from ._util import arr, out
from .fmep import PNH_CONSTANTS

__all__ = [
    "VALVE_TRAIN_CONSTANTS", "OIL_GRADES", "NU_REFERENCE", "BOUNDARY_SPEEDS",
    "boundary_factor", "viscosity_ratio", "mean_piston_speed", "oil_grade_viscosity",
    "crankshaft_seals", "main_bearings", "turbulent_dissipation", "piston_skirt",
    "piston_rings", "rod_bearings", "ring_gas_loading", "camshaft_bearings",
    "valve_train_constant", "flat_follower", "roller_follower", "oscillating_hydrodynamic",
    "oscillating_mixed", "auxiliaries", "chen_flynn",
]

#: nu_0 of the viscosity ratio [m^2/s] (10.6 cSt; Sandoval 2002, the oil of the PNH data).
NU_REFERENCE = 10.6e-6
#: N_0 of the boundary factor (1 + N_0/N) [rev/min] per named option.
BOUNDARY_SPEEDS = {"pnh1989": 1000.0, "sandoval_heywood2003": 500.0}
#: Ring gas-loading speed coefficient K [s/m] (PNH 1989).
RING_GAS_K = 2.38e-2

#: (C_ff flat follower, C_rf roller follower, C_oh oscillating hydrodynamic, C_om oscillating
#: mixed) per valve-train layout (PNH 1989; Sandoval 2002 Table 4.2 as transcribed): the one
#: table of camtrain.formulas.fmep. The OHV roller constant is printed "0.5" in the public
#: copies: 22 to 100 times the other roller constants (0.005-0.0227), and it would make a roller
#: OHV train lose more than a flat one at every speed above about 1400 rev/min (0.5 N = 400
#: (1 + 1000/N)); a suspected misprint, so it is left undefined (a deck asking for it gets a
#: message, not a number).
VALVE_TRAIN_CONSTANTS = PNH_CONSTANTS

#: Vogel fits of multigrade and monograde oils, nu [cSt] = k exp(theta_1 / (T + theta_2)), T in
#: degC, and the high-shear / low-shear viscosity ratio: grade -> (k, theta_1, theta_2, ratio)
#: (Sandoval 2002, as transcribed).
OIL_GRADES = {
    "5W20": (0.04576, 1224.0, 134.1, 0.94),
    "5W40": (0.15, 1018.74, 125.91, 0.80),
    "10W30": (0.1403, 869.72, 104.4, 0.76),
    "15W40": (0.1223, 933.46, 103.89, 0.90),
    "20W50": (0.0639, 1255.46, 117.7, 0.84),
    "SAE10": (0.0258, 1345.42, 144.58, 1.0),
    "SAE30": (0.0246, 1432.29, 132.94, 1.0),
    "SAE50": (0.0384, 1349.94, 115.16, 1.0),
}

_RPM = 60.0 / (2.0 * math.pi)      # rad/s -> rev/min
_MM = 1e3                           # m -> mm
_KPA = 1e3                          # kPa -> Pa


def _rpm(omega):
    return arr(omega) * _RPM


def boundary_factor(omega, n0_rpm):
    r"""Low-speed boundary factor :math:`1 + N_0/N` (N, N_0 in rev/min; omega in rad/s)."""
    return out(1.0 + arr(n0_rpm) / _rpm(omega))


def viscosity_ratio(nu, nu0=NU_REFERENCE):
    r"""Sandoval-Heywood viscosity scaling :math:`r = \sqrt{\nu/\nu_0}` (kinematic, m^2/s)."""
    return out(np.sqrt(arr(nu) / arr(nu0)))


def mean_piston_speed(stroke, omega):
    r"""Mean piston speed :math:`\bar S_p = 2 S N / 60` [m/s] (stroke [m], omega [rad/s])."""
    return out(2.0 * arr(stroke) * _rpm(omega) / 60.0)


def oil_grade_viscosity(grade: str, temperature, high_shear: bool = False):
    r"""Kinematic viscosity [m^2/s] of an oil grade at ``temperature`` [degC] by its Vogel fit,
    :math:`\nu = k \exp[\theta_1/(T + \theta_2)]` cSt; ``high_shear`` multiplies by the grade's
    high-shear ratio (Sandoval 2002)."""
    if grade not in OIL_GRADES:
        raise field_error("grade", "unknown oil grade", grade, ", ".join(OIL_GRADES))
    k, th1, th2, ratio = OIL_GRADES[grade]
    T = arr(temperature)
    if np.any(T + th2 <= 0):
        raise field_error("temperature", "at or below the Vogel asymptote of the grade",
                          float(np.min(T)), f"> {-th2:g} °C")
    nu = k * np.exp(th1 / (T + th2)) * (ratio if high_shear else 1.0)
    return out(nu * 1e-6)


# ----------------------------------------------------------------------------- crankshaft

def crankshaft_seals(bore, stroke, main_diameter, cylinders):
    r"""Front and rear crankshaft seals (PNH 1989; crankshaft group):
    :math:`1.22\times10^5\, D_b / (B^2 S n_c)` kPa. Independent of speed and oil."""
    B, S, D = arr(bore) * _MM, arr(stroke) * _MM, arr(main_diameter) * _MM
    return out(1.22e5 * D / (B**2 * S * arr(cylinders)) * _KPA)


def main_bearings(omega, bore, stroke, main_diameter, main_length, n_main, cylinders, r=1.0):
    r"""Hydrodynamic main bearings (crankshaft group):
    :math:`3.03\times10^{-4}\, r N D_b^3 L_b n_b / (B^2 S n_c)` kPa."""
    B, S = arr(bore) * _MM, arr(stroke) * _MM
    D, L = arr(main_diameter) * _MM, arr(main_length) * _MM
    return out(3.03e-4 * arr(r) * _rpm(omega) * D**3 * L * arr(n_main)
               / (B**2 * S * arr(cylinders)) * _KPA)


def turbulent_dissipation(omega, main_diameter, n_main, cylinders):
    r"""Turbulent dissipation of the oil pumped through the mains (crankshaft group):
    :math:`1.35\times10^{-10}\, D_b^2 N^2 n_b / n_c` kPa."""
    D = arr(main_diameter) * _MM
    return out(1.35e-10 * D**2 * _rpm(omega) ** 2 * arr(n_main) / arr(cylinders) * _KPA)


# ----------------------------------------------------------------------------- reciprocating

def piston_skirt(omega, bore, stroke, r=1.0):
    r"""Hydrodynamic piston skirt (reciprocating group):
    :math:`2.94\times10^2\, r \bar S_p / B` kPa."""
    Sp = mean_piston_speed(stroke, omega)
    return out(2.94e2 * arr(r) * Sp / (arr(bore) * _MM) * _KPA)


def piston_rings(omega, bore, n0_rpm):
    r"""Ring tension, mixed lubrication (reciprocating group):
    :math:`4.06\times10^4\, (1 + N_0/N) / B^2` kPa."""
    B = arr(bore) * _MM
    return out(4.06e4 * boundary_factor(omega, n0_rpm) / B**2 * _KPA)


def rod_bearings(omega, bore, stroke, rod_diameter, rod_length, r=1.0):
    r"""Hydrodynamic connecting-rod bearings (reciprocating group):
    :math:`3.03\times10^{-4}\, r N D_r^3 L_r / (B^2 S)` kPa."""
    B, S = arr(bore) * _MM, arr(stroke) * _MM
    D, L = arr(rod_diameter) * _MM, arr(rod_length) * _MM
    return out(3.03e-4 * arr(r) * _rpm(omega) * D**3 * L / (B**2 * S) * _KPA)


def ring_gas_loading(omega, stroke, intake_ratio, compression_ratio, r=1.0, k=RING_GAS_K):
    r"""Gas pressure behind the rings (PNH 1989; Sandoval-Heywood 2003):
    :math:`6.89\,(p_i/p_a)\,[0.088\, r\, r_c + 0.182\, r_c^{1.33 - K \bar S_p}]` kPa, with
    p_i/p_a the intake manifold over atmospheric pressure, r_c the compression ratio and
    K = 2.38e-2 s/m (``k``, SI the same)."""
    Sp = mean_piston_speed(stroke, omega)
    rc = arr(compression_ratio)
    return out(6.89 * arr(intake_ratio) * (0.088 * arr(r) * rc
                                           + 0.182 * rc ** (1.33 - arr(k) * Sp)) * _KPA)


# ----------------------------------------------------------------------------- valve train

def _layout(layout: str):
    if layout not in VALVE_TRAIN_CONSTANTS:
        raise field_error("layout", "unknown valve-train layout", layout,
                          ", ".join(VALVE_TRAIN_CONSTANTS))
    return VALVE_TRAIN_CONSTANTS[layout]


def camshaft_bearings(omega, bore, stroke, n_camshaft_bearings, cylinders, r=1.0):
    r"""Camshaft bearings (valve-train group):
    :math:`244\, r N n_b / (B^2 S n_c)` kPa, n_b the camshaft bearings."""
    B, S = arr(bore) * _MM, arr(stroke) * _MM
    return out(244.0 * arr(r) * _rpm(omega) * arr(n_camshaft_bearings)
               / (B**2 * S * arr(cylinders)) * _KPA)


def valve_train_constant():
    r"""Camshaft seals and the rest (valve-train group): the constant 4.12 kPa."""
    return 4.12 * _KPA


def flat_follower(omega, stroke, n_valves, cylinders, layout, n0_rpm):
    r"""Flat (sliding) follower, mixed lubrication (valve-train group):
    :math:`C_{ff}\,(1 + N_0/N)\, n_v / (S n_c)` kPa, C_ff of the layout."""
    c_ff = _layout(layout)[0]
    return out(c_ff * boundary_factor(omega, n0_rpm) * arr(n_valves)
               / (arr(stroke) * _MM * arr(cylinders)) * _KPA)


def roller_follower(omega, stroke, n_valves, cylinders, layout):
    r"""Roller follower, rolling friction (valve-train group):
    :math:`C_{rf}\, N n_v / (S n_c)` kPa, C_rf of the layout (none for OHV: see
    :data:`VALVE_TRAIN_CONSTANTS`)."""
    c_rf = _layout(layout)[1]
    if c_rf is None:
        raise field_error("follower", "no roller-follower constant for this layout", layout,
                          "a layout other than ohv (its printed constant 0.5 is a suspected "
                          "misprint)")
    return out(c_rf * _rpm(omega) * arr(n_valves) / (arr(stroke) * _MM * arr(cylinders))
               * _KPA)


def oscillating_hydrodynamic(omega, bore, stroke, valve_lift, n_valves, cylinders, layout,
                             r=1.0):
    r"""Oscillating parts, hydrodynamic (valve-train group):
    :math:`C_{oh}\, r L_v^{1.5} N^{0.5} n_v / (B S n_c)` kPa."""
    c_oh = _layout(layout)[2]
    B, S, Lv = arr(bore) * _MM, arr(stroke) * _MM, arr(valve_lift) * _MM
    return out(c_oh * arr(r) * Lv**1.5 * np.sqrt(_rpm(omega)) * arr(n_valves)
               / (B * S * arr(cylinders)) * _KPA)


def oscillating_mixed(omega, stroke, valve_lift, n_valves, cylinders, layout, n0_rpm):
    r"""Oscillating parts, mixed lubrication (valve-train group):
    :math:`C_{om}\,(1 + N_0/N)\, L_v n_v / (S n_c)` kPa."""
    c_om = _layout(layout)[3]
    Lv = arr(valve_lift) * _MM
    return out(c_om * boundary_factor(omega, n0_rpm) * Lv * arr(n_valves)
               / (arr(stroke) * _MM * arr(cylinders)) * _KPA)


# ----------------------------------------------------------------------------- auxiliaries

def auxiliaries(omega):
    r"""Oil pump, water pump and non-charging alternator (PNH 1989; Sandoval-Heywood 2003):
    :math:`6.23 + 5.22\times10^{-3} N - 1.79\times10^{-7} N^2` kPa."""
    N = _rpm(omega)
    return out((6.23 + 5.22e-3 * N - 1.79e-7 * N**2) * _KPA)


# ----------------------------------------------------------------------------- Chen-Flynn

def chen_flynn(peak_pressure, piston_speed, a, b, c, d=0.0):
    r"""Chen-Flynn friction mean effective pressure (Chen & Flynn 1965):
    :math:`a + b\, p_{max} + c\, \bar S_p + d\, \bar S_p^2` [Pa].

    SI throughout: a [Pa], b [-], c [Pa s/m], d [Pa s^2/m^2], p_max [Pa], S_p [m/s]. There are
    no universal constants: each published set is a fit to one engine (e.g. 0.137 bar +
    0.005 p_max + 0.162 bar s/m S_p for one SI engine); the caller gives its own."""
    Sp = arr(piston_speed)
    return out(arr(a) + arr(b) * arr(peak_pressure) + arr(c) * Sp + arr(d) * Sp**2)
