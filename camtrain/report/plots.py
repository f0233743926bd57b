"""The lift-law sheet of ``camtrain lift``: the kinematics sheet in the common style."""
from __future__ import annotations

from pathlib import Path

from camtrain.result import Result


def lift_sheet(result: Result, title: str, out: Path, deck=None) -> list[Path]:
    """Lift, velocity, acceleration and jerk against cam angle; PNG and PDF at ``out``."""
    from camtrain.report.sheets import kinematics_sheet

    return kinematics_sheet(result, deck, title, out)


def _pyplot():
    """matplotlib.pyplot on the Agg backend (kept for callers elsewhere in camtrain)."""
    from camtrain.report.style import pyplot

    return pyplot()
