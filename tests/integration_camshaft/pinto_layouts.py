"""The assumed layout of decks/pinto_camshaft.toml as parameters, and the variants tried.

Ball (1988) Ch 6 does not give the axial positions of lobes and bearings, the order of inlet and
exhaust lobes, the direction of the follower loads or the pulley. ``layout`` rewrites the deck's
``[camshaft]`` section from those assumptions; with the defaults it reproduces the shipped deck
(tested), so the sensitivity table in docs/examples.md (``python docs/make_examples.py``) is a
sensitivity of the shipped deck. Phases are stated by Ball: firing order 1-3-4-2, exhaust maximum
123.5 cam deg before the inlet maximum.
"""
from __future__ import annotations

import copy
import tomllib

from tests.conftest import DECKS

DECK = DECKS / "pinto_camshaft.toml"
#: Ball (1988) Figs 6.12-6.14: maximum eccentricity ratio at 25 Hz, front / centre / rear
BALL_MAX_ECCENTRICITY = (0.904, 0.941, 0.926)
#: inlet maximum-lift angle of cylinders 1-4 (firing order 1-3-4-2: 90 cam deg apart)
INLET_PHASE = {1: 0.0, 2: 270.0, 3: 90.0, 4: 180.0}
EXHAUST_LEAD = 123.5      # cam deg, Ball §6.3

DEFAULTS = dict(pitch=98.0, first=50.0, offset=20.0, order="EIIE", axis=90.0, radius=63.7,
                hub=-90.0, rotation="clockwise")

#: (what is varied, changes to DEFAULTS); the first entry is the shipped deck
VARIANTS = [
    ("assumed layout (the deck)", {}),
    ("cylinder pitch 90 mm", {"pitch": 90.0}),
    ("cylinder pitch 106 mm", {"pitch": 106.0}),
    ("lobes ±15 mm from the cylinder centre", {"offset": 15.0}),
    ("lobes ±25 mm from the cylinder centre", {"offset": 25.0}),
    ("lobe order I E E I per bay", {"order": "IEEI"}),
    ("lobe order E I in every cylinder", {"order": "EIEI"}),
    ("follower loads at 70 deg", {"axis": 70.0}),
    ("follower loads at 110 deg", {"axis": 110.0}),
    ("pulley radius 50 mm", {"radius": 50.0}),
    ("pulley radius 80 mm", {"radius": 80.0}),
    ("no pulley load", {"radius": None}),
    ("hub load at -60 deg", {"hub": -60.0}),
    ("hub load at -120 deg", {"hub": -120.0}),
]


def _wrap(angle: float) -> float:
    return (angle + 180.0) % 360.0 - 180.0


def layout(raw: dict | None = None, **changes) -> dict:
    """The deck as a TOML dict with its [camshaft] lobes, bearings and drive from the layout."""
    p = {**DEFAULTS, **changes}
    raw = copy.deepcopy(raw if raw is not None else tomllib.loads(DECK.read_text("utf-8")))
    cs = raw["camshaft"]
    centres = [p["first"] + i * p["pitch"] for i in range(4)]
    lobes = []
    for i, centre in enumerate(centres):
        kinds = p["order"][:2] if (i % 2 == 0 or p["order"] == "EIEI") else p["order"][2:]
        for side, kind in zip((-1.0, 1.0), kinds, strict=True):
            phase = INLET_PHASE[i + 1] - (EXHAUST_LEAD if kind == "E" else 0.0)
            lobes.append({"position": centre + side * p["offset"],
                          "max_lift_angle": _wrap(phase), "follower_axis_angle": p["axis"]})
    cs["lobes"] = lobes
    positions = (0.0, 0.5 * (centres[1] + centres[2]), centres[3] + p["first"])
    for bearing, x in zip(cs["bearings"], positions, strict=True):
        bearing["position"] = x
    cs["rotation"] = p["rotation"]
    if p["radius"] is None:
        cs.pop("drive", None)
    else:
        cs["drive"] = {**cs.get("drive", {"type": "belt", "position": -40.0}),
                       "radius": p["radius"], "hub_load_angle": p["hub"]}
    return raw
