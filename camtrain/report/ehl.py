"""Outputs of a steady EHL line contact: the profiles' key numbers, a CSV and a plot."""
from __future__ import annotations

import io
from pathlib import Path

import numpy as np

from camtrain.report.tables import atomic_write


def key_numbers(solution, friction) -> list[tuple[str, float, str]]:
    """(name, value, unit) of what a person checks, in µm, mm, MPa, N/mm."""
    s = solution
    rows = [("Hertz half-width b", s.b * 1e3, "mm"), ("Hertz pressure p_h", s.p_h / 1e6, "MPa"),
            ("central film h_c", s.h_central * 1e6, "µm"), ("minimum film h_min", s.h_min * 1e6,
                                                           "µm"),
            ("minimum film at x", s.x_min * 1e3, "mm"), ("peak pressure", s.p_max / 1e6, "MPa")]
    if s.x_spike is not None:
        rows += [("spike position x", s.x_spike * 1e3, "mm"),
                 ("spike pressure", s.p_spike / 1e6, "MPa")]
    rows += [("sliding friction", friction.sliding / 1e3, "N/mm"),
             ("rolling (Poiseuille) force", friction.rolling / 1e3, "N/mm"),
             ("friction coefficient", friction.coefficient, "-"),
             ("Newton iterations", float(s.iterations), "-")]
    return rows


def profile_csv(solution) -> str:
    buf = io.StringIO()
    buf.write("x [mm],p [MPa],h [µm],eta [Pa s]\n")
    np.savetxt(buf, np.column_stack((solution.x * 1e3, solution.p / 1e6, solution.h * 1e6,
                                     solution.eta)), delimiter=",", fmt="%.8g")
    return buf.getvalue()


def profile_figure(solution):
    import matplotlib

    matplotlib.use("Agg", force=False)
    from matplotlib.figure import Figure

    s = solution
    fig = Figure(figsize=(7.0, 4.5))
    ax = fig.add_subplot()
    X = s.x / s.b
    ax.plot(X, s.p / 1e6, label="pressure")
    ax.plot(X, s.p_h / 1e6 * np.sqrt(np.maximum(1 - X**2, 0)), ":", label="Hertz")
    ax.set_xlabel("x / b [-]")
    ax.set_ylabel("p [MPa]")
    twin = ax.twinx()
    twin.plot(X, s.h * 1e6, color="C3", label="film")
    twin.set_ylabel("h [µm]")
    twin.set_ylim(0, 4 * s.h_central * 1e6)
    ax.legend(loc="upper left")
    fig.tight_layout()
    return fig


def write_ehl(solution, friction, out_dir: Path) -> list[Path]:
    """ehl.csv (profiles) and ehl.png in ``out_dir``; returns the files written."""
    out_dir.mkdir(parents=True, exist_ok=True)
    csv = out_dir / "ehl.csv"
    atomic_write(csv, profile_csv(solution))
    png = out_dir / "ehl.png"
    staged = out_dir / ".ehl.png.partial"
    try:                           # staged and renamed: never a half-written plot
        profile_figure(solution).savefig(staged, dpi=120, format="png")
        staged.replace(png)
    finally:
        staged.unlink(missing_ok=True)
    return [csv, png]
