"""Derive the Pinto inlet *valve* lift table from Ball (1988) App E cam lift.

Ball's improved Pinto design (§5.5) keeps the valve lift and regenerates the cam profile, so the
improved deck needs the datum valve lift, not App E re-read through the improved geometry. This
module derives it with camtrain's own chain: the datum deck's table law of App E (smoothing
spline) -> ``camtrain.mechanisms.valve_lift_from_cam_lift`` through the datum finger geometry
(anticlockwise) -> samples at whole degrees. The test ``test_pinto_valve_dataset.py`` re-derives
it and compares it with the shipped file, so the data set cannot drift from its recipe.

Regenerate with ``python -m tests.tribology.pinto_valve_lift`` from the project root.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
DATUM_DECK = ROOT / "decks" / "pinto_finger.toml"
TARGET = ROOT / "camtrain" / "data" / "ball1988_pinto_inlet_valve_lift.csv"
DECIMALS = 6          # 1 nm: far below App E's 0.1 µm print step, so rounding adds no noise
FINE_POINTS = 3600    # 0.1 deg conversion grid; every 10th point is a whole degree

HEADER = """\
# Ford 2.0 l Pinto inlet VALVE lift, derived by camtrain (not printed in the source).
# Source data: Ball (1988) A tribological study of the design and performance of automotive
# cams, PhD thesis, University of Leeds, Appendix E (cam lift read by a 44.0 mm roller).
# Derivation: App E as the datum deck reads it (periodic smoothing spline), converted to valve
# lift through the datum end-pivoted finger geometry of Ball §5.4 (A 51.80, B 61.80, D 46.20,
# r_f 44.0, r_B 15.0 mm, kappa 39.7, lambda 31.9 deg) with camtrain's own cam-to-valve
# conversion camtrain.mechanisms.valve_lift_from_cam_lift, rotation anticlockwise, maximum
# lift recentred to 0 deg. Sampled at 1 deg steps, lift in mm to 6 decimals.
# Use: Ball's improved design (§5.5) keeps this valve lift and regenerates the cam.
# Regenerated and verified by tests/tribology/pinto_valve_lift.py.
angle_deg,lift_mm
"""


def derive() -> tuple[np.ndarray, np.ndarray]:
    """(angles [deg], valve lift [mm]) at whole degrees, from one base-circle zero to the next."""
    from camtrain import mechanisms as M
    from camtrain.assemble.lift_law import build_lift_law
    from camtrain.deck.load import load_deck
    from camtrain.lift import angle_grid

    deck = load_deck(str(DATUM_DECK)).model
    mech = deck.mechanism
    curve = build_lift_law(deck.lift).evaluate(angle_grid(FINE_POINTS))
    geometry = M.PivotGeometry(A=mech.A, B=mech.B, D=mech.D, follower_radius=mech.follower_radius,
                               base_radius=deck.cam.base_radius, kappa=mech.kappa,
                               lam=mech.lambda_, kind="end")
    valve = M.valve_lift_from_cam_lift(curve, geometry, deck.lift.inspection_radius,
                                       rotation=mech.rotation)
    deg = np.degrees(valve.theta)
    whole = np.isclose(deg, np.round(deg), atol=1e-9)
    angles = np.round(deg[whole]).astype(int)
    lift = np.round(np.clip(valve.lift[whole] * 1e3, 0.0, None), DECIMALS)
    lifted = np.flatnonzero(lift > 0.0)
    first, last = max(lifted[0] - 1, 0), min(lifted[-1] + 1, lift.size - 1)
    return angles[first:last + 1].astype(float), lift[first:last + 1]


def render() -> str:
    angles, lift = derive()
    rows = "".join(f"{a:.1f},{y:.{DECIMALS}f}\n" for a, y in zip(angles, lift, strict=True))
    return HEADER + rows


if __name__ == "__main__":
    TARGET.write_text(render(), encoding="utf-8")
    print(f"wrote {TARGET.name}")
