"""Deck sections of loads, materials, lubricant, tribology options, solver knobs and design
limits. Part of the deck schema (schema.py)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from camtrain.deck.fields import When, option, quantity
from camtrain.errors import Problem

# --------------------------------------------------------------------------- loads

@dataclass(frozen=True, kw_only=True)
class Spring:
    """Valve spring. Omit the section and no contact loads are computed (Ball: Blok film only)."""

    rate: float = quantity("Spring rate k", "N/mm", gt=0, example=38.254)
    preload_compression: float = quantity(
        "Initial spring compression delta at zero valve lift", "mm", ge=0, example=6.4)
    progressive_quadratic: float = quantity(
        "Progressive spring, quadratic term c2: force += c2 x^2 (x = total compression)",
        "N/mm²", default=0.0)
    progressive_cubic: float = quantity(
        "Progressive spring, cubic term c3: force += c3 x^3 (x = total compression)", "N/mm³",
        default=0.0)


@dataclass(frozen=True, kw_only=True)
class Masses:
    """Moving masses, reduced as in Ball (1988) Table 3.1."""

    valve_side: float = quantity(
        "Equivalent mass at the valve: valve + retainer + collets + 1/3 spring (+ bucket for a "
        "flat follower)", "kg", gt=0, example=0.172)
    follower: float = quantity(
        "Follower (rocker) equivalent mass referred to radius B", "kg", default=0.0, ge=0,
        applies="finger, rocker")
    rocker_inertia: float = quantity(
        "Rocker (or finger) moment of inertia about its pivot, roller excluded; the rigid and "
        "the elastic train count it at the valve as I / B^2 (a sheet-metal finger: about "
        "2.5e-5)", "kg·m²", default=0.0, ge=0, applies="finger, rocker, pushrod", example=2.5e-5)


@dataclass(frozen=True, kw_only=True)
class Clearance:
    """Valve clearance (lash) or a hydraulic lash adjuster."""

    valve_clearance: float = quantity("Valve clearance at the base-circle position", "mm",
                                      default=0.0, ge=0)
    lash_adjuster: bool = option("A hydraulic lash adjuster keeps zero clearance",
                                 default=False)
    adjuster_load: float = quantity("Base-circle load of the lash adjuster", "N", default=0.0,
                                    ge=0, applies="lash_adjuster = true")


@dataclass(frozen=True, kw_only=True)
class Materials:
    """Elastic properties of cam and follower."""

    cam_modulus: float = quantity("Young's modulus of the cam", "GPa", default=207.0, gt=0)
    cam_poisson: float = quantity("Poisson's ratio of the cam", "-", default=0.29, gt=0, lt=0.5)
    follower_modulus: float = quantity("Young's modulus of the follower", "GPa", default=207.0,
                                       gt=0)
    follower_poisson: float = quantity("Poisson's ratio of the follower", "-", default=0.29,
                                       gt=0, lt=0.5)


@dataclass(frozen=True, kw_only=True)
class Lubricant:
    """The oil at the contact: its viscosity given directly, or from a fit at the oil temperature."""

    viscosity: float | None = quantity(
        "Dynamic viscosity at ambient pressure and oil temperature; omit to take it from "
        "viscosity_fit at temperature", "Pa·s", default=None, gt=0, example=0.05)
    pressure_viscosity: float = quantity("Pressure-viscosity coefficient alpha", "1/GPa", ge=0,
                                         example=22.0)
    roughness: float = quantity("Composite RMS surface roughness sigma (for lambda = h/sigma)",
                                "µm", default=0.2, gt=0)
    temperature: float | None = quantity("Oil temperature at the contact", "°C", default=None,
                                         gt=-60, lt=400)
    viscosity_fit: Literal["vogel", "two_point"] | None = option(
        "Viscosity-temperature law through the fit points: vogel (three or more points, Vogel "
        "1921) or two_point (exponential, Reynolds 1886)", default=None)
    fit_temperatures: tuple[float, ...] | None = quantity(
        "Temperatures of the fit points", "°C", default=None, gt=-60, lt=400,
        applies="viscosity_fit")
    fit_viscosities: tuple[float, ...] | None = quantity(
        "Dynamic viscosities at the fit temperatures", "Pa·s", default=None, gt=0,
        applies="viscosity_fit")

    schema_rules = (
        When("viscosity_fit", (None,), require=("viscosity",)),
        When("viscosity_fit", (None,), negate=True,
             require=("temperature", "fit_temperatures", "fit_viscosities")))

    def __post_init__(self) -> None:
        # the run chain reads ``viscosity``: fill it from the fit (bad fit data -> problems())
        if self.viscosity is None and not self._fit_problems("lubricant"):
            object.__setattr__(self, "viscosity", self.fitted_viscosity())

    def fitted_viscosity(self) -> float:
        """eta(temperature) [Pa s] from the fit points (Vogel 1921 or Reynolds 1886 two-point)."""
        from camtrain.formulas.viscosity import reynolds_two_point, vogel, vogel_fit
        T = [t + 273.15 for t in self.fit_temperatures]
        eta = list(self.fit_viscosities)
        T0 = self.temperature + 273.15
        if self.viscosity_fit == "vogel":
            return float(vogel(T0, *vogel_fit(T, eta)))
        return float(reynolds_two_point(T0, T[0], eta[0], T[1], eta[1]))

    def _fit_problems(self, path: str) -> list[Problem]:
        if self.viscosity_fit is None:
            return [] if self.viscosity is not None else [Problem(
                f"{path}.viscosity", "is missing", None,
                "a viscosity in Pa·s, or viscosity_fit with temperature and fit points")]
        out = []
        if self.temperature is None:
            out.append(Problem(f"{path}.temperature", "is required with viscosity_fit", None,
                               "the oil temperature in °C"))
        t, e = self.fit_temperatures or (), self.fit_viscosities or ()
        need = 3 if self.viscosity_fit == "vogel" else 2
        if len(t) != len(e) or len(t) < need or (self.viscosity_fit == "two_point"
                                                   and len(t) != 2):
            out.append(Problem(f"{path}.fit_temperatures", "and fit_viscosities must be pairs",
                               f"{len(t)} temperatures, {len(e)} viscosities",
                               f"{'at least 3' if need == 3 else 'exactly 2'} of each"))
        elif len(set(t)) != len(t) or any((b - a) * (y - x) >= 0 for a, b, x, y in
                                            zip(t, t[1:], e, e[1:], strict=False)):
            out.append(Problem(f"{path}.fit_viscosities", "must fall as the temperature rises",
                               list(e), "distinct temperatures, viscosity falling with them"))
        return out

    def problems(self, path: str) -> list[Problem]:
        out = self._fit_problems(path)
        if self.viscosity_fit is not None and not out:
            try:
                eta = self.fitted_viscosity()
            except Exception as exc:  # a Vogel fit that has no solution for these points
                return [Problem(f"{path}.fit_viscosities", "cannot be fitted", None, "",
                                str(exc))]
            if self.viscosity is not None and abs(self.viscosity - eta) > 1e-9 * eta:
                out.append(Problem(f"{path}.viscosity", "conflicts with viscosity_fit",
                                   self.viscosity, f"omit it (the fit gives {eta:.6g} Pa·s)"))
        return out


@dataclass(frozen=True, kw_only=True)
class Solver:
    """Resolution knobs (each trades accuracy for time; see `camtrain accuracy`)."""

    angle_points: int = quantity("Number of cam angles over one revolution", "-", default=1440,
                                 ge=16, le=1_000_000)
    friction_tolerance: float = quantity(
        "Relative tolerance of the friction/load iteration of pivoted followers", "-",
        default=1e-6, gt=0, lt=0.1)
    friction_max_iterations: int = quantity("Maximum friction/load iterations", "-", default=50,
                                            ge=1, le=10_000)
    # transient film (tribology.film_model = squeeze / averaged_reynolds); docs/transient_film.md
    film_nodes: int = quantity("Nodes across the contact zone of the averaged Reynolds film", "-",
                               default=401, ge=11, le=100_001,
                               applies="film_model = averaged_reynolds")
    film_zone_width: float = quantity(
        "Half width of the averaged Reynolds solution zone in Hertz half widths (at the local "
        "load, at least 10 % of the mean load)", "-", default=4.0, gt=0, le=1000,
        applies="film_model = averaged_reynolds")
    film_angle_step: float | None = quantity(
        "Cam-angle step of the transient film march; omit to march on the run's angle grid "
        "(inputs interpolated periodically when given)", "deg", default=None, gt=0, le=10,
        applies="film_model = squeeze, averaged_reynolds")
    film_tolerance: float = quantity(
        "Load-balance tolerance |W - W_P - W_A| / W of the averaged Reynolds film", "-",
        default=1e-6, gt=0, lt=0.1, applies="film_model = averaged_reynolds")
    film_march: Literal["implicit_euler", "bdf2"] = option(
        "Time scheme of the transient film march: implicit_euler (first order) or bdf2 (second "
        "order; averaged_reynolds only)", default="implicit_euler",
        applies="film_model = squeeze, averaged_reynolds")
    film_cycles_max: int = quantity("Most cam revolutions marched to reach the periodic film",
                                    "-", default=6, ge=1, le=100,
                                    applies="film_model = squeeze, averaged_reynolds")
    film_period_tolerance: float = quantity(
        "Cycle-to-cycle change of the film that ends the periodic march", "-", default=1e-6,
        gt=0, lt=0.1, applies="film_model = squeeze, averaged_reynolds")
    # elastic (transient EHL) film, tribology.film_model = ehl; docs/ehl.md
    ehl_nodes: int = quantity("Grid points across the elastic film's contact domain", "-",
                              default=512, ge=32, le=16_384, applies="film_model = ehl")
    ehl_inlet: float = quantity(
        "Half length of the elastic film's domain in Hertz half widths (widened to 20 rigid "
        "lengths sqrt(2 R h) where the contact is light)", "-", default=4.5, ge=1.5, le=100,
        applies="film_model = ehl")
    ehl_angle_step: float = quantity("Cam-angle step of the elastic film's time march", "deg",
                                     default=0.5, gt=0, le=5, applies="film_model = ehl")
    ehl_tolerance: float = quantity(
        "Newton tolerance of the elastic film (largest scaled residual per step)", "-",
        default=1e-6, gt=0, lt=0.01, applies="film_model = ehl")
    ehl_march: Literal["bdf2", "implicit_euler"] = option(
        "Time scheme of the elastic film: bdf2 (second order) or implicit_euler (first order)",
        default="bdf2", applies="film_model = ehl")
    ehl_linear_solver: Literal["auto", "krylov", "dense"] = option(
        "Linear solver of the elastic film's Newton directions: krylov (matrix-free GMRES with "
        "a multilevel preconditioner; cost per direction ~ n log n), dense (the Jacobian's LU; "
        "cost ~ n^3 per factorisation, kept while it converges: cheaper below about 384 "
        "points), or auto (dense below 384 ehl_nodes, krylov from there). The same equations "
        "to the same ehl_tolerance: the films agree to about 1e-5", default="auto",
        applies="film_model = ehl")


@dataclass(frozen=True, kw_only=True)
class Tribology:
    """Tribology model options (Ball 1988 ch. 4; the choices behind his printed results)."""

    entrainment: Literal["mean", "sum", "half_mean"] = option(
        "Entrainment speed in the film formulas: mean (V_c + V_f)/2, sum V_c + V_f as Ball's "
        "'entraining velocity', or half_mean (V_c + V_f)/4, Göçmen's literal |U/2| (reproduces "
        "his base-circle film)", default="mean")
    film_formula: Literal["auto", "dowson_higginson_1977", "dowson_higginson_1966",
                          "dowson_dunn_taylor_1983", "hamrock_dowson_1977_min",
                          "chittenden_1985_min"] = option(
        "Minimum-film formula: auto (Dowson-Higginson for line, Hamrock-Dowson for point "
        "contact with loads; Blok rigid-piezoviscous without loads) or a named formula",
        default="auto")
    friction_model: Literal["cap", "lambda", "lambda_cap", "greenwood_tripp"] = option(
        "Friction: cap (lesser of viscous shear and boundary friction), lambda (boundary "
        "friction where h/sigma < 1), lambda_cap (both), greenwood_tripp (asperity load share "
        "with boundary shear plus viscous shear of the rest, Teodorescu et al. 2005)",
        default="cap")
    boundary_friction: float = quantity(
        "Boundary friction coefficient (cap and start of the friction/load iteration)", "-",
        default=0.08, ge=0, le=1)
    viscosity_law: Literal["barus", "roelands"] = option(
        "Pressure-viscosity law in the shear integral over the Hertz zone: barus (Ball, Yang) or "
        "roelands (Roelands 1966, z matched to pressure_viscosity at ambient pressure; lower "
        "viscosity at Hertz pressures)", default="barus")
    hertz: Literal["exact", "ball_1988"] = option(
        "Point-contact Hertz: exact ellipticity, or Ball's eq. 3.7", default="exact")
    film_model: Literal["steady", "squeeze", "averaged_reynolds", "ehl"] = option(
        "Film of the cam contact: steady (closed-form EHL per angle), squeeze (Teodorescu et al. "
        "2005 film with the squeeze term, marched in cam angle), averaged_reynolds (Göçmen 2013 "
        "averaged Reynolds with squeeze, flow factors and Greenwood-Tripp asperities, marched in "
        "cam angle; friction from the same solution), ehl (transient elastohydrodynamic line "
        "contact with mass-conserving cavitation, marched in time; friction from the same "
        "solution; docs/ehl.md); see docs/transient_film.md", default="steady")
    ehl_cavitation: Literal["elrod_adams", "reynolds", "half_sommerfeld"] = option(
        "Cavitation of the elastic film: elrod_adams (mass-conserving, Elrod & Adams 1974), "
        "reynolds (Reynolds exit condition, not mass-conserving) or half_sommerfeld (full-film "
        "pressure with its negative part dropped from the load, deflection and friction; a "
        "bound for comparison with the older literature, neither mass-conserving nor faithful "
        "at the outlet)", default="elrod_adams",
        applies="film_model = ehl")
    ehl_viscosity: Literal["roelands", "barus"] = option(
        "Pressure-viscosity law inside the elastic film: roelands (Roelands 1966, z matched to "
        "pressure_viscosity) or barus", default="roelands", applies="film_model = ehl")
    ehl_density: Literal["dowson_higginson", "incompressible"] = option(
        "Density of the oil inside the elastic film: dowson_higginson (Dowson & Higginson 1966) "
        "or incompressible", default="dowson_higginson", applies="film_model = ehl")
    squeeze_load_exponent: Literal["consistent", "printed"] = option(
        "Sign of the W* exponent of Teodorescu's film formula: consistent (-0.059, as every EHL "
        "regression) or printed (+0.059 as printed in the paper)", default="consistent",
        applies="film_model = squeeze")
    cavitation: Literal["reynolds", "half_sommerfeld"] = option(
        "Cavitation condition of the averaged Reynolds film: reynolds (pressure and its gradient "
        "vanish at the rupture) or half_sommerfeld (negative pressures dropped)", default="reynolds",
        applies="film_model = averaged_reynolds")
    squeeze_terms: Literal["full", "min_only"] = option(
        "Squeeze term of the averaged Reynolds film: full (exact local dh/dt, with the change of "
        "the cam radius) or min_only (dh_min/dt alone, as Göçmen)", default="full",
        applies="film_model = averaged_reynolds")
    flow_factors: bool = option(
        "Patir-Cheng / Wu-Zheng flow factors in the averaged Reynolds film (false: all 1)",
        default=True, applies="film_model = averaged_reynolds")
    film_floor: Literal["dowson_higginson", "none"] = option(
        "Film reported by averaged_reynolds: the larger of it and the steady EHL film "
        "(dowson_higginson, Göçmen eq. 2.1; the marched state is not reset) or its own (none)",
        default="dowson_higginson", applies="film_model = averaged_reynolds")
    # Greenwood-Tripp / Teodorescu et al. (2005) parameters. The paper prints none of them;
    # the defaults are typical values for run-in steel surfaces (see docs/tribology.md).
    asperity_density_product: float = quantity(
        "Greenwood-Tripp roughness parameter zeta beta sigma (asperity density x tip radius x "
        "rms roughness)", "-", default=0.04, gt=0, lt=1, applies="friction_model = "
        "greenwood_tripp")
    roughness_slope: float = quantity(
        "Greenwood-Tripp ratio sigma / beta (rms roughness over asperity tip radius)", "-",
        default=1e-3, gt=0, lt=1, applies="friction_model = greenwood_tripp")
    eyring_stress: float = quantity(
        "Eyring (limiting) shear stress tau_0 of the oil (Teodorescu eq. 12)", "MPa",
        default=2.0, ge=0, applies="friction_model = greenwood_tripp")
    shear_pressure_coefficient: float = quantity(
        "Rise of the limiting shear stress with mean pressure, gamma (Teodorescu eq. 12)", "-",
        default=0.08, ge=0, lt=1, applies="friction_model = greenwood_tripp")
    boundary_shear_coefficient: float = quantity(
        "Pressure coefficient m of the asperity boundary shear strength (Teodorescu eq. 8)",
        "-", default=0.17, ge=0, lt=1, applies="friction_model = greenwood_tripp")


# --------------------------------------------------------------------------- design limits

@dataclass(frozen=True, kw_only=True)
class Limits:
    """Design limits, checked over the cycle by `camtrain run --check`; omit a limit to skip it."""

    max_hertz: float | None = quantity("Largest allowed maximum Hertz stress p_max", "MPa",
                                       default=None, gt=0, example=650.0)
    min_film: float | None = quantity(
        "Smallest allowed minimum film thickness h_min anywhere in contact (zero-entrainment "
        "points give zero film in a quasi-static analysis)", "µm", default=None, ge=0, example=0.05)
    min_film_at_max_lift: float | None = quantity(
        "Smallest allowed h_min at the maximum-lift position (Ball's representative nose film)",
        "µm", default=None, ge=0, example=0.1)
    min_lambda: float | None = quantity("Smallest allowed film parameter lambda = h_min/sigma",
                                        "-", default=None, ge=0, example=0.3)
    min_bounce_margin: float | None = quantity(
        "Smallest allowed margin of the run speed below the valve-bounce speed, "
        "100 (1 - n/n_bounce)", "%", default=None, gt=-100, lt=100, example=10.0)
    max_power_loss: float | None = quantity("Largest allowed cycle-mean frictional power loss",
                                            "W", default=None, gt=0, example=60.0)
    max_load: float | None = quantity("Largest allowed cam/follower contact load", "N",
                                      default=None, gt=0, example=2000.0)
    max_friction_torque: float | None = quantity("Largest allowed peak friction torque", "N·m",
                                                 default=None, gt=0, example=2.0)
