"""The adjuster's data and its closed forms: the effective bulk modulus of oil with free air,
the annulus' leak conductance, the check valve's flow, the closed chamber's stiffness, the lever
ratio at a pivot and the leak-down time (the package docstring names the sources)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

P_ATM = 101_325.0
BULK_MODELS = ("free_air_polytropic",)
CHAMBER_SCHEMES = {"backward_euler": 1.0, "trapezoidal": 0.5}
#: check-valve models and their code in the compiled record
CHECK_VALVES = {"quasi_static": 0, "ball": 1}


@dataclass(frozen=True)
class LashAdjuster:
    """One hydraulic lash adjuster in its own frame (SI: m, m^2, m^3, Pa, kg, N/m, N).

    ``plunger_diameter`` d, ``radial_clearance`` c, ``leak_length`` L, ``eccentricity`` e (0..1)
    of the annulus; ``viscosity`` mu [Pa s]; ``dead_volume`` the chamber at full collapse;
    ``stroke``; ``rest_extension`` x on the base circle; ``plunger_mass``; ``spring_rate``,
    ``spring_preload`` (at the rest extension); ``supply_pressure`` (gallery, gauge),
    ``cracking_pressure``, ``check_area`` (full open area), ``full_open`` (pressure above
    cracking at full opening), ``discharge_coefficient``, ``oil_density``; ``bulk_modulus`` of
    the oil (inf: incompressible), ``air_fraction`` (free air by volume at atmospheric pressure),
    ``polytropic_index``; ``stop_stiffness`` of the two end stops; ``vapour_pressure``
    (absolute, the floor of the chamber's pressure); ``scheme`` of the chamber equation.

    ``check_valve`` names the valve's model: ``quasi_static`` (the orifice of ``cracking_pressure``,
    ``check_area``, ``full_open``) or ``ball`` (its own dynamics: ``ball_mass``,
    ``ball_spring_rate`` and ``ball_preload`` on the seat, ``seat_diameter`` (pressure area and
    curtain), ``ball_lift`` (lift stop), ``ball_damping_ratio``; the cracking pressure follows as
    preload over seat area, :func:`ball_cracking_pressure`)."""

    plunger_diameter: float
    radial_clearance: float
    leak_length: float
    viscosity: float
    dead_volume: float
    stroke: float
    rest_extension: float
    plunger_mass: float
    spring_rate: float
    spring_preload: float
    supply_pressure: float
    cracking_pressure: float = 2.0e3
    check_area: float = 1.5e-6
    full_open: float = 2.0e4
    discharge_coefficient: float = 0.6
    oil_density: float = 850.0
    bulk_modulus: float = 1.6e9
    air_fraction: float = 0.0
    polytropic_index: float = 1.0
    eccentricity: float = 0.0
    stop_stiffness: float = 2.0e8
    vapour_pressure: float = 2.0e3
    bulk_model: str = "free_air_polytropic"
    scheme: str = "backward_euler"
    check_valve: str = "quasi_static"
    ball_mass: float = 6.4e-5
    ball_spring_rate: float = 100.0
    ball_preload: float = 6.3e-3
    seat_diameter: float = 2.0e-3
    ball_lift: float = 0.3e-3
    ball_damping_ratio: float = 0.0

    @property
    def area(self) -> float:
        return math.pi * self.plunger_diameter ** 2 / 4.0

    @property
    def rest_volume(self) -> float:
        return self.dead_volume + self.area * self.rest_extension

    def conductance(self) -> float:
        return leak_conductance(self.plunger_diameter, self.radial_clearance, self.leak_length,
                                self.viscosity, self.eccentricity)

    def rest_force(self) -> float:
        """Force [N] the adjuster pushes with on the base circle: chamber at the supply pressure
        (the annulus fills it to the reservoir's pressure) on the plunger, plus its spring."""
        return self.supply_pressure * self.area + self.spring_preload

    @property
    def seat_area(self) -> float:
        """Pressure area of the check ball on its seat [m^2]: the seat's bore."""
        return math.pi * self.seat_diameter ** 2 / 4.0

    def ball_frequency(self) -> float:
        """Natural angular frequency sqrt(k/m) [rad/s] of the check ball on its spring."""
        return math.sqrt(self.ball_spring_rate / self.ball_mass)

    def stiffness(self, pressure: float | None = None) -> float:
        """Closed-chamber stiffness K_e A^2 / V [N/m] at the rest extension and ``pressure``
        (gauge; default the supply pressure)."""
        p = self.supply_pressure if pressure is None else pressure
        k_e = effective_bulk_modulus(p, self.bulk_modulus, self.air_fraction,
                                     self.polytropic_index)
        return chamber_stiffness(k_e, self.area, self.rest_volume)


# --------------------------------------------------------------------------- formulas

def mixture_volume(p, bulk_modulus, air_fraction, polytropic_index=1.0):
    """phi(p): volume at gauge pressure p [Pa] of a unit volume of oil with free air at
    atmospheric pressure (the free-air mixture of the module docstring)."""
    p = np.asarray(p, dtype=float)
    liquid = (1.0 - air_fraction) * np.exp(-p / bulk_modulus)
    air = air_fraction * (P_ATM / (p + P_ATM)) ** (1.0 / polytropic_index)
    return liquid + air


def effective_bulk_modulus(p, bulk_modulus, air_fraction, polytropic_index=1.0):
    """K_e = -phi/phi' [Pa] of oil (modulus K_l) with free air (volume fraction alpha at
    atmospheric pressure, polytropic index n) at gauge pressure p: Merritt (1967) eq. 2-26 with
    the gas law, the ``free_air_polytropic`` model (= K_l without air, n p_abs with air
    only)."""
    p = np.asarray(p, dtype=float)
    p_abs = p + P_ATM
    liquid = (1.0 - air_fraction) * np.exp(-p / bulk_modulus)
    air = air_fraction * (P_ATM / p_abs) ** (1.0 / polytropic_index)
    with np.errstate(divide="ignore"):   # incompressible oil without air: infinite
        return (liquid + air) / (liquid / bulk_modulus + air / (polytropic_index * p_abs))


def leak_conductance(diameter, clearance, length, viscosity, eccentricity=0.0):
    """G = pi d c^3 (1 + 1.5 e^2) / (12 mu L) [m^3/(s Pa)]: laminar pressure flow through an
    annulus of radial clearance c, eccentric by e c (Merritt 1967 eq. 3-40; White, Viscous Fluid
    Flow §3-3.6 for the factor 1 + 1.5 e^2)."""
    return (math.pi * diameter * clearance ** 3 * (1.0 + 1.5 * eccentricity ** 2)
            / (12.0 * viscosity * length))


def couette_coefficient(diameter, clearance):
    """pi d c / 2 [m^2]: the flow dragged through the annulus per unit sliding speed (the mean
    of the linear Couette profile; independent of the eccentricity)."""
    return 0.5 * math.pi * diameter * clearance


def check_valve_flow(p, adj: LashAdjuster):
    """Quasi-static check valve: flow [m^3/s] from the supply into the chamber at gauge pressure
    p (zero below cracking; the open area linear in the pressure above cracking up to the full
    area; sharp-edged orifice, Merritt 1967 eq. 3-9)."""
    p = np.asarray(p, dtype=float)
    drop = adj.supply_pressure - p
    above = np.clip((drop - adj.cracking_pressure) / adj.full_open, 0.0, 1.0)
    return adj.discharge_coefficient * adj.check_area * above * np.sqrt(
        2.0 * np.maximum(drop, 0.0) / adj.oil_density)


def curtain_area(lift, seat_diameter):
    """Flow area [m^2] of a check ball lifted ``lift`` off a seat of bore d: the curtain
    pi d y, at most the bore's own area pi d^2/4 (the seat then throttles no more)."""
    return np.minimum(math.pi * seat_diameter * np.maximum(lift, 0.0),
                      math.pi * seat_diameter ** 2 / 4.0)


def ball_cracking_pressure(adj: LashAdjuster) -> float:
    """Cracking pressure [Pa] of the ball check valve: its spring's preload over the seat's
    area (the supply lifts the ball once (p_s - p) A_seat exceeds the preload)."""
    return adj.ball_preload / adj.seat_area


def quasi_static_equivalent(adj: LashAdjuster) -> LashAdjuster:
    """The quasi-static orifice a massless ball tends to: the ball in force balance, lift y =
    ((p_s - p) A_seat - F_0)/k, so its curtain pi d y grows linearly from the cracking pressure
    F_0/A_seat to the lift stop at k y_max/A_seat above it (the full open area pi d y_max, or
    the bore's when smaller)."""
    from dataclasses import replace

    if adj.ball_lift > adj.seat_diameter / 4.0:
        raise ValueError("the curtain of a lift above a quarter of the seat's bore is not linear "
                         "in the lift: no quasi-static orifice of linear area matches it")
    return replace(adj, check_valve="quasi_static", cracking_pressure=ball_cracking_pressure(adj),
                   full_open=adj.ball_spring_rate * adj.ball_lift / adj.seat_area,
                   check_area=float(curtain_area(adj.ball_lift, adj.seat_diameter)))


def chamber_stiffness(bulk_modulus, area, volume):
    """k = K_e A_p^2 / V [N/m]: the closed chamber as a spring."""
    return bulk_modulus * area * area / volume


def pivot_ratio(rocker_ratio: float) -> float:
    """Motion of an end pivot per valve motion at a fixed cam contact, for a lever whose valve
    moves ``rocker_ratio`` times the cam contact's motion (pivot at 0, cam at a, valve at l:
    R = l/a; a pivot drop s moves the valve by s (l - a)/a): a / (l - a) = 1 / (R - 1)."""
    if rocker_ratio <= 1.0:
        raise ValueError(f"an end-pivot adjuster needs a lever ratio above 1 (got "
                         f"{rocker_ratio:g}): the valve must be farther from the pivot than the "
                         "cam contact")
    return 1.0 / (rocker_ratio - 1.0)


# --------------------------------------------------------------------------- leak-down test

def leakdown_time(adj: LashAdjuster, load: float, travel: float, start: float = 0.0) -> float:
    """Closed form [s]: time for the plunger under a constant ``load`` [N] to collapse from
    ``start`` to ``start + travel`` [m] below its rest extension, the chamber's pressure
    quasi-static (A p = load - spring), the check valve shut and the reservoir at atmospheric
    pressure: -(A + C_c) x' = G p (continuity with the Couette drag C_c), so with the spring
    F_s = F_0 + k s: t = A (A + C_c) / (G k) ln((load - F_s(start)) / (load - F_s(end))), and
    t = A (A + C_c) travel / (G (load - F_0)) for k = 0. Neglects the chamber's compliance
    (exact for k = 0 once the pressure has built)."""
    a = adj.area
    factor = a * (a + couette_coefficient(adj.plunger_diameter, adj.radial_clearance)) \
        / adj.conductance()
    f0 = adj.spring_preload + adj.spring_rate * start
    f1 = f0 + adj.spring_rate * travel
    if load <= f1:
        raise ValueError(f"a load of {load:g} N does not collapse the plunger against its "
                         f"spring ({f1:g} N at the end of the travel)")
    if adj.spring_rate == 0.0:
        return factor * travel / (load - f0)
    return factor / adj.spring_rate * math.log((load - f0) / (load - f1))
