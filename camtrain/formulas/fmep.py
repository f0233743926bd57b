"""Whole-valvetrain friction mean effective pressure, Patton-Nitschke-Heywood (1989) scaling law.

The correlation is dimensional (mm, rev/min, kPa); the function takes SI and converts.
"""
from __future__ import annotations

import numpy as np

from camtrain.errors import field_error

from ._util import arr, check, out, positive

__all__ = ["PNH_CONSTANTS", "patton_nitschke_heywood_1989"]

#: (C_ff flat follower, C_rf roller follower, C_oh oscillating hydrodynamic, C_om oscillating
#: mixed) per valvetrain configuration, Sandoval (2002) Table 4.2 as reproduced in public code.
#: The OHV roller constant is printed "0.5" there, flagged as a typo, so it is left undefined.
PNH_CONSTANTS = {
    "sohc_finger": (600.0, 0.0227, 0.2, 42.8),
    "sohc_rocker": (400.0, 0.0151, 0.5, 21.4),
    "sohc_direct": (200.0, 0.0076, 0.5, 10.7),
    "dohc_finger": (600.0, 0.0227, 0.2, 25.8),
    "dohc_direct": (133.0, 0.0050, 0.5, 10.7),
    "ohv": (400.0, None, 0.5, 32.1),
}


def patton_nitschke_heywood_1989(omega_crank, bore, stroke, valve_lift, n_cyl, n_bearings,
                                 n_valves, config="dohc_direct", follower="flat"):
    r"""Valvetrain friction mean effective pressure (Patton, Nitschke & Heywood 1989).

    In the correlation's own units (B, S, L_v in mm; N in rev/min; fmep in kPa):

    .. math::
        fmep = \frac{244\,N n_b}{B^2 S n_c} + 4.12
        + \underbrace{C_{ff}\left(1 + \frac{1000}{N}\right)\frac{n_v}{S n_c}}_{flat}
          \;\text{or}\; \underbrace{C_{rf}\frac{N n_v}{S n_c}}_{roller}
        + C_{oh}\frac{L_v^{1.5} N^{0.5} n_v}{B S n_c}
        + C_{om}\left(1 + \frac{1000}{N}\right)\frac{L_v n_v}{S n_c}

    Terms: camshaft bearings (+ seals), follower (boundary or rolling), oscillating
    hydrodynamic, oscillating mixed.

    Args:
        omega_crank: crankshaft speed [rad/s]; bore, stroke, valve_lift: [m];
        n_cyl, n_bearings (camshaft bearings), n_valves: counts;
        config: key of :data:`PNH_CONSTANTS`; follower: ``"flat"`` or ``"roller"``.

    Returns:
        fmep [Pa].

    Reference: Patton, Nitschke & Heywood (1989) SAE 890836; constants per Sandoval (2002)
    Table 4.2 (formulas_and_anchors §4.4, "verify against the scan"). Check: 4-cyl DOHC
    direct, flat, B = S = 86 mm, 10 bearings, 16 valves, L_v = 8 mm: 25.61 / 21.56 / 21.05 /
    22.21 kPa at 1000 / 2000 / 4000 / 6000 rev/min.
    """
    if config not in PNH_CONSTANTS:
        raise field_error("config", "unknown valvetrain configuration", config,
                          ", ".join(PNH_CONSTANTS))
    if follower not in ("flat", "roller"):
        raise field_error("follower", "unknown follower type", follower, "flat or roller")
    c_ff, c_rf, c_oh, c_om = PNH_CONSTANTS[config]
    if follower == "roller" and c_rf is None:
        raise field_error("follower", "no roller-follower constant for this configuration",
                          config, hint="the source value is a suspected typo")
    N = positive("omega_crank", omega_crank) * 60.0 / (2.0 * np.pi)
    B, S = positive("bore", bore) * 1e3, positive("stroke", stroke) * 1e3
    Lv = check("valve_lift", valve_lift, lambda v: np.isfinite(v) & (v >= 0), ">= 0") * 1e3
    nc, nb, nv = arr(n_cyl), arr(n_bearings), arr(n_valves)
    fmep = 244.0 * N * nb / (B**2 * S * nc) + 4.12
    if follower == "flat":
        fmep = fmep + c_ff * (1.0 + 1000.0 / N) * nv / (S * nc)
    else:
        fmep = fmep + c_rf * N * nv / (S * nc)
    fmep = fmep + c_oh * Lv**1.5 * np.sqrt(N) * nv / (B * S * nc)
    fmep = fmep + c_om * (1.0 + 1000.0 / N) * Lv * nv / (S * nc)
    return out(fmep * 1e3)
