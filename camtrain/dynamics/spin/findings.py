"""The marched roller's columns and metrics, as rows for the dynamics effect (SI)."""
from __future__ import annotations

import numpy as np

from camtrain.roller import speeds


def spin_rows(kin, tables, spin) -> list[tuple]:
    """(name, values, unit, description) of the roller's speed, slip, sliding and traction
    marched with the train (``spin`` = speed, sliding, traction on the grid, 3 x grid)."""
    w, sliding, traction = spin
    slip = speeds.slip(sliding, tables.v_s0)
    return [
        ("roller_speed_marched", w, "rad/s", "roller speed on its pin w_r, marched with the "
         "elastic train"),
        ("roller_slip_marched", slip, "-", "roller slip 1 - w_r r_r / (V_c - V_f) marched with "
         "the elastic train (0 rolling, 1 locked; NaN where V_c = V_f)"),
        ("roller_sliding_marched", sliding, "m/s", "cam-roller sliding speed u_s = V_s0 - "
         "w_r r_r marched with the elastic train"),
        ("roller_traction_marched", traction, "N", "traction on the roller at the marched "
         "contact force (signed as u_s)")]


def spin_metrics(kin, tables, spin, load) -> list[tuple]:
    """(name, value, unit, description[, angle]) of the marched roller: its largest slip where
    the cam carries load, the spin inertia marched."""
    w, sliding, _ = spin
    loaded = np.asarray(load) > 0.0
    slip = np.where(loaded, np.abs(np.nan_to_num(speeds.slip(sliding, tables.v_s0), nan=0.0)),
                    0.0)
    i = int(np.argmax(slip))
    return [
        ("roller_slip_max_marched", float(slip[i]), "-", "largest slip of the loaded roller "
         "marched with the elastic train", float(kin.theta[i])),
        ("roller_spin_inertia", tables.inertia, "kg*m^2", "roller's spin inertia about its pin "
         "in the elastic train's march")]
