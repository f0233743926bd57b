"""The [dynamics] deck section: the plan's choice, its outputs, and bad input named by field."""
from __future__ import annotations

import pytest

from camtrain.errors import InputError
from camtrain.scene import resolve
from tests.dynamics.conftest import deck_of, zeta_raw


def test_plan_takes_the_dynamic_load_and_says_why():
    plan = resolve(deck_of(zeta_raw()))
    steps = {s.effect: s for s in plan.steps}
    assert steps["dynamics"].chosen
    assert "chosen over loads for ContactLoad" in steps["dynamics"].reason
    assert steps["loads"].reason.startswith("ContactLoad comes from dynamics instead")
    without = zeta_raw()
    del without["dynamics"]
    assert "loads" in resolve(deck_of(without)).chosen


@pytest.mark.parametrize(("changes", "field"), [
    ({"dynamics": {"spring_mass": None}}, "dynamics.spring_mass"),
    ({"dynamics": {"spring_elements": 1}}, "dynamics.spring_elements"),
    ({"dynamics": {"follower_mass": 0.2}}, "dynamics.follower_mass"),
    ({"dynamics": {"follower_mass": 0.0}}, "dynamics.follower_mass"),     # adjuster needs it
    ({"dynamics": {"pushrod_stiffness": 1e4}}, "dynamics.pushrod_stiffness"),
    ({"dynamics": {"contact_stiffness": -1.0}}, "dynamics.contact_stiffness"),
    ({"dynamics": {"integrator": "euler"}}, "dynamics.integrator"),
    ({"dynamics": {"follower_mass": 0.0, "link_damping": 10.0}}, "dynamics.link_damping"),
    ({"dynamics": {"seat_damping": -1.0}}, "dynamics.seat_damping"),
    ({"spring": {"progressive_quadratic": 1.0}}, "spring.progressive_quadratic"),
])
def test_bad_dynamics_input_names_the_field(changes, field):
    with pytest.raises(InputError) as err:
        deck_of(zeta_raw(changes))
    assert field in str(err.value)
    assert err.value.exit_code == 2


def test_cli_dynamics_speed_without_the_section_exits_2():
    import subprocess
    import sys

    from tests.conftest import DECKS, ROOT

    out = subprocess.run([sys.executable, "-m", "camtrain.cli", "dynamics-speed",
                          str(DECKS / "zeta_intake.toml")], capture_output=True, text=True,
                         cwd=ROOT)
    assert out.returncode == 2 and "[dynamics]" in out.stderr and "Traceback" not in out.stderr
