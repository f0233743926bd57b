"""Plot sheets (matplotlib, imported only here, with the non-interactive Agg backend)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from camtrain.result import Result


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


#: name, label, unit shown, factor from SI
LIFT_PANELS = (
    ("lift", "lift", "mm", 1e3),
    ("velocity", "velocity dl/dθ", "mm/deg", 1e3 * np.pi / 180.0),
    ("acceleration", "acceleration d²l/dθ²", "mm/deg²", 1e3 * (np.pi / 180.0) ** 2),
    ("jerk", "jerk d³l/dθ³", "mm/deg³", 1e3 * (np.pi / 180.0) ** 3),
)


def lift_sheet(result: Result, title: str, out: Path) -> list[Path]:
    """Lift, velocity, acceleration and jerk against cam angle; PNG and PDF."""
    plt = _pyplot()
    theta = np.degrees(result["cam_angle"])
    fig, axes = plt.subplots(4, 1, figsize=(8.27, 11.0), sharex=True)
    for ax, (name, label, unit, factor) in zip(axes, LIFT_PANELS, strict=True):
        ax.plot(theta, result[name] * factor, lw=1.2, color="tab:blue")
        ax.set_ylabel(f"{label} [{unit}]")
        ax.grid(True, alpha=0.3)
        ax.axhline(0.0, color="0.5", lw=0.6)
    axes[-1].set_xlabel("cam angle from maximum lift [deg]")
    axes[-1].set_xlim(-180, 180)
    fig.suptitle(title)
    fig.tight_layout()
    paths = [out.with_suffix(".png"), out.with_suffix(".pdf")]
    for p in paths:
        fig.savefig(p, dpi=130)
    plt.close(fig)
    return paths
