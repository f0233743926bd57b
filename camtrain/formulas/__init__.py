"""camtrain formula layer: pure, vectorised functions, one per published result, SI units.

Modules:
    elastic    reduced modulus and radius, entrainment/sliding speeds, entrainment radii
    hertz      line and elliptical Hertz contact (exact and curve-fit ellipticity, Ball 3.7)
    film_line  line-contact film formulas; film_point: point-contact film formulas
    film       film-thickness registry, dispatcher and applicability listing
    viscosity  Barus, Roelands, Reynolds, Walther, Vogel
    density    Dowson-Higginson pressure-density law (imported as a module)
    friction   Barus shear over the Hertz zone (closed form, overflow-safe), boundary cap
    mixed      Greenwood-Tripp asperity load/area, Teodorescu boundary + viscous friction
    guides     follower/guide and valve/guide friction (Yang 1992)
    cycle      torque about the cam axis, friction power, cycle means
    bearings   Petroff, Martin shear power, Ocvirk short bearing
    fmep       Patton-Nitschke-Heywood valvetrain friction mean effective pressure
    engine_friction  whole-engine correlations term by term: Patton-Nitschke-Heywood 1989,
               Sandoval-Heywood 2003 (viscosity scaling, oil-grade Vogel fits), Chen-Flynn
               (imported as a module: ``from camtrain.formulas import engine_friction``)

Every function accepts scalars or numpy arrays (broadcast together) and returns a float for
scalar input. User-causable bad input raises :class:`camtrain.errors.InputError` via
``field_error``; programming misuse (unknown option strings) raises ``ValueError``.
"""
from .bearings import (
    martin_1985_shear_power,
    ocvirk_attitude_angle,
    ocvirk_eccentricity,
    ocvirk_load,
    ocvirk_min_film,
    petroff_power,
    petroff_torque,
)
from .cycle import cam_torque, cycle_mean, friction_power, friction_torque
from .elastic import (
    contact_modulus,
    curvature_sum,
    entrainment_radii,
    entrainment_speed,
    reduced_modulus,
    reduced_radius,
    sliding_speed,
)
from .film import (
    FILM_METHODS,
    film_groups,
    film_thickness,
    film_thickness_methods,
    film_thicknesses,
)
from .film_line import (
    dowson_dunn_taylor_1983,
    dowson_higginson_1966,
    dowson_higginson_1977,
    dowson_toyoda_1979,
    martin_1916,
    moes_1992,
    pan_hamrock_1989_cen,
    pan_hamrock_1989_min,
    rahnejat_1984,
)
from .film_point import (
    chittenden_1985_cen,
    chittenden_1985_min,
    hamrock_dowson_1977_cen,
    hamrock_dowson_1977_min,
    hamrock_dowson_ellipticity,
)
from .fmep import PNH_CONSTANTS, patton_nitschke_heywood_1989
from .friction import (
    FRICTION_MODELS,
    VISCOSITY_LAWS,
    ball_1988_friction,
    ball_1988_shear_force,
    barus_ellipse_integral,
    barus_line_integral,
    barus_line_integral_closed_form,
    film_parameter,
    friction_coefficient,
    log_barus_ellipse_integral,
    log_barus_line_integral,
    log_roelands_ellipse_integral,
    log_roelands_line_integral,
    yang_1992_friction,
    yang_1992_shear_force,
)
from .guides import couette_guide_friction, couette_guide_power, yang_1992_guide_boundary
from .hertz import (
    HERTZ_POINT_METHODS,
    ball_1988_point_max_pressure,
    ellipticity_exact,
    hertz_line,
    hertz_line_half_width,
    hertz_line_max_pressure,
    hertz_point,
    hertz_point_max_pressure,
)
from .mixed import (
    evans_johnson_shear_stress,
    greenwood_tripp_1970_area,
    greenwood_tripp_1970_load,
    greenwood_tripp_f52_fit,
    greenwood_tripp_function,
    greenwood_tripp_tabulated,
    teodorescu_2005_friction,
)
from .viscosity import (
    barus,
    barus_log,
    reynolds_two_point,
    reynolds_viscosity,
    roelands,
    roelands_z,
    vogel,
    vogel_fit,
    walther_two_point,
)

__all__ = [
    "ball_1988_friction", "ball_1988_point_max_pressure", "ball_1988_shear_force", "barus",
    "barus_ellipse_integral", "barus_line_integral", "barus_line_integral_closed_form",
    "log_roelands_ellipse_integral", "log_roelands_line_integral", "VISCOSITY_LAWS",
    "barus_log", "cam_torque",
    "chittenden_1985_cen", "chittenden_1985_min", "contact_modulus", "couette_guide_friction",
    "couette_guide_power", "curvature_sum", "cycle_mean", "dowson_dunn_taylor_1983",
    "dowson_higginson_1966", "dowson_higginson_1977", "dowson_toyoda_1979", "ellipticity_exact",
    "entrainment_radii", "entrainment_speed", "evans_johnson_shear_stress", "film_groups",
    "FILM_METHODS", "film_parameter", "film_thickness", "film_thickness_methods", "film_thicknesses",
    "friction_coefficient", "FRICTION_MODELS", "friction_power", "friction_torque",
    "greenwood_tripp_1970_area", "greenwood_tripp_1970_load", "greenwood_tripp_f52_fit",
    "greenwood_tripp_function", "greenwood_tripp_tabulated", "hamrock_dowson_1977_cen",
    "hamrock_dowson_1977_min",
    "hamrock_dowson_ellipticity", "hertz_line", "hertz_line_half_width", "hertz_line_max_pressure",
    "hertz_point", "hertz_point_max_pressure", "HERTZ_POINT_METHODS", "log_barus_ellipse_integral",
    "log_barus_line_integral", "martin_1916", "martin_1985_shear_power", "moes_1992",
    "ocvirk_attitude_angle", "ocvirk_eccentricity", "ocvirk_load", "ocvirk_min_film",
    "pan_hamrock_1989_cen", "pan_hamrock_1989_min", "patton_nitschke_heywood_1989",
    "petroff_power", "petroff_torque", "PNH_CONSTANTS", "rahnejat_1984", "reduced_modulus",
    "reduced_radius", "reynolds_two_point", "reynolds_viscosity", "roelands", "roelands_z",
    "sliding_speed", "teodorescu_2005_friction", "vogel", "vogel_fit", "walther_two_point",
    "yang_1992_friction", "yang_1992_guide_boundary", "yang_1992_shear_force",
]
