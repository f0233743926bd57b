"""A small, fast valve train with a camshaft section (Harrison flat-follower data, Ball 1988)."""
from __future__ import annotations

import pytest

from tests.conftest import MINIMAL_DECK

#: Loads, friction and power on the minimal deck; 360 angles keep the run well under a second.
VALVE_TRAIN = MINIMAL_DECK.replace("base_radius = 18", "base_radius = 18\nwidth = 12") + """
[spring]
rate = 38.254
preload_compression = 6.4
[masses]
valve_side = 0.172
[lubricant]
viscosity = 0.05
pressure_viscosity = 22.0
[solver]
angle_points = 360
"""

#: Four lobes of an in-line four (0/270/90/180, as Yang App C.5) between three bearings, a
#: belt pulley in front. Axis angles differ so that x and y both carry load.
CAMSHAFT = """
[camshaft]
method = "{method}"
overhang = "{overhang}"
viscosity = 0.01
{extra}
[[camshaft.lobes]]
position = 30.0
max_lift_angle = 0.0
follower_axis_angle = 90.0
[[camshaft.lobes]]
position = 80.0
max_lift_angle = 270.0
follower_axis_angle = 70.0
[[camshaft.lobes]]
position = 130.0
max_lift_angle = 90.0
follower_axis_angle = 110.0
[[camshaft.lobes]]
position = 230.0
max_lift_angle = 180.0
follower_axis_angle = 90.0
[[camshaft.bearings]]
position = 0.0
diameter = 25.0
length = 18.0
clearance = 0.025
[[camshaft.bearings]]
position = 105.0
diameter = 25.0
length = 18.0
clearance = 0.025
groove_width = 2.0
[[camshaft.bearings]]
position = 210.0
diameter = 25.0
length = 18.0
clearance = 0.025
[camshaft.drive]
position = -35.0
radius = 50.0
hub_load_angle = 90.0
preload = 200.0
"""


def camshaft_deck(method: str = "steady", overhang: str = "nearest", extra: str = "") -> str:
    return VALVE_TRAIN + CAMSHAFT.format(method=method, overhang=overhang, extra=extra)


@pytest.fixture(scope="session")
def steady_run():
    import camtrain.api as ct

    return ct.run(ct.loads(camshaft_deck("steady")))
