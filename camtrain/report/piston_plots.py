"""The piston-assembly sheet of an engine run: cylinder and inter-ring gas pressure, every
compression ring's film (flooded and starved), the friction force of every piston component
(Yang 1992 Figs 6.4, 6.6-6.7, 6.14) and, with a FLAME total, the friction by component.
Matplotlib is imported on use (Agg backend)."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from camtrain.result import Result

FLAME_BARS = (("flame_bearings", "bearings"), ("flame_valve_train", "valve train"),
              ("flame_piston", "pistons"), ("flame_accessories", "accessories"))


def _rings(result: Result) -> list[str]:
    return sorted(c for c in result.components if c.startswith("ring_"))


def piston_sheet(result: Result, out_dir: Path, *, title: str = "",
                 formats=("png",)) -> list[Path]:
    """``sheet_piston.<fmt>``: gas pressures, ring films, friction per component and (with a
    FLAME total) the friction power by component. Empty without a piston run."""
    if "ring_angle" not in result.columns:
        return []
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    flame = [(label, result.metrics[k].value) for k, label in FLAME_BARS if k in result.metrics]
    n = 4 if flame else 3
    fig = Figure(figsize=(8.27, 2.4 * n + 0.6))
    th = np.degrees(result["ring_angle"])
    ax = fig.add_subplot(n, 1, 1)
    ax.plot(th, result["cylinder_pressure"] / 1e5, lw=0.8, label="cylinder")
    k = 1
    while f"inter_ring_pressure_{k}" in result.columns:
        ax.plot(th, result[f"inter_ring_pressure_{k}"] / 1e5, lw=0.9,
                label=f"between rings {k} and {k + 1}")
        k += 1
    ax.set_ylabel("gas pressure [bar g]", fontsize=8)
    ax.legend(fontsize=7, frameon=False)
    ax = fig.add_subplot(n, 1, 2)
    for comp in _rings(result):
        part = result.component(comp)
        line, = ax.semilogy(th, part["min_film"] * 1e6, lw=0.9,
                            label=comp.replace("_", " ") + " (starved)")
        ax.semilogy(th, part["min_film_flooded"] * 1e6, lw=0.7, ls="--", color=line.get_color(),
                    label=comp.replace("_", " ") + " (flooded)")
    ax.set_ylabel("minimum film [µm]", fontsize=8)
    ax.legend(fontsize=7, frameon=False, ncol=2)
    ax = fig.add_subplot(n, 1, 3)
    for comp in _rings(result):
        ax.plot(th, result.component(comp)["friction"], lw=0.8, label=comp.replace("_", " "))
    for name, label in (("oil_control_ring_friction", "oil-control ring"),
                        ("skirt_friction", "skirt")):
        if name in result.columns:
            ax.plot(th, result[name], lw=0.8, label=label)
    ax.set_ylabel("friction force [N]", fontsize=8)
    ax.set_xlabel("crank angle from firing TDC [deg]", fontsize=8)
    ax.legend(fontsize=7, frameon=False, ncol=4)
    for a in fig.axes:
        a.tick_params(labelsize=7)
        a.set_xlim(0.0, 720.0)
    if flame:
        ax = fig.add_subplot(n, 1, 4)
        ax.barh([label for label, _ in flame], [v / 1e3 for _, v in flame])
        ax.set_xlabel("friction power [kW]", fontsize=8)
        ax.tick_params(labelsize=7)
    fig.suptitle(f"Piston assembly{': ' + title if title else ''}", fontsize=9)
    fig.tight_layout()
    written = []
    for ext in formats:
        path = Path(out_dir) / f"sheet_piston.{ext}"
        path.parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(path, dpi=110)
        written.append(path)
    return written
