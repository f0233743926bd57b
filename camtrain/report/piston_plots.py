"""The piston-assembly sheet of an engine run, an A4 page in the house style: cylinder and
inter-ring gas pressure, every compression ring's film (flooded and starved; a ring at the film
march's floor is shaded as dry, not plotted as a film), the friction force of every piston
component (Yang 1992 Figs 6.4, 6.6-6.7, 6.14) and, with a FLAME total, the friction power by
component with its value and share, the total and the fmep. Matplotlib is imported on use."""
from __future__ import annotations

from pathlib import Path

import numpy as np

from camtrain.catalogue import makes
from camtrain.result import Result

CRANK_LABEL = "crank angle from firing TDC [deg]"
_COLORS = ("#1f4e79", "#c0504d", "#4f8a3c", "#8064a2", "#7f7f7f", "#d08c00")


def _rings(result: Result) -> list[str]:
    return sorted(c for c in result.components if c.startswith("ring_"))


def piston_sheet(result: Result, out_dir: Path, *, deck=None, sha: str | None = None,
                 formats=("png",)) -> list[Path]:
    """``sheet_piston.<fmt>``: gas pressures, ring films, friction per component and (with a
    FLAME total) the friction power by component (the piston effect declares it)."""
    from camtrain.report.canvas import save_sheet
    from camtrain.report.house import LEGEND_RIGHT_IN, grid, house_page
    from camtrain.report.summaries import flame_parts

    parts = flame_parts(result)
    heading = "Piston assembly" + (" and FLAME engine friction" if parts else "")
    with house_page(deck, result, heading, sha) as fig:
        spec = grid(fig, 4 if parts else 3, 1, hspace=0.42, left_in=0.95,
                    right_in=LEGEND_RIGHT_IN)
        th = np.degrees(result["ring_angle"])
        _gas(fig.add_subplot(spec[0]), result, th)
        _films(fig.add_subplot(spec[1]), result, th)
        _friction(fig.add_subplot(spec[2]), result, th)
        if parts:
            _flame(fig.add_subplot(spec[3]), result, parts)
        Path(out_dir).mkdir(parents=True, exist_ok=True)
        return save_sheet(fig, Path(out_dir) / "sheet_piston", formats)


def _crank_axis(ax) -> None:
    ax.set_xlim(0.0, 720.0)
    ax.set_xticks(np.arange(0.0, 721.0, 90.0))
    ax.set_xlabel(CRANK_LABEL)


def _gas(ax, result: Result, th) -> None:
    from camtrain.report.house import legend_beside

    ax.plot(th, result["cylinder_pressure"] / 1e5, color=_COLORS[0], label="cylinder")
    k = 1
    while makes(result.plan, f"inter_ring_pressure_{k}"):   # one between each two rings
        ax.plot(th, result[f"inter_ring_pressure_{k}"] / 1e5, color=_COLORS[k],
                label=f"between rings {k} and {k + 1}")
        k += 1
    ax.set_ylabel("gas pressure [bar gauge]")
    ax.set_title("Gas pressure")
    _crank_axis(ax)
    legend_beside(ax)


def _films(ax, result: Result, th) -> None:
    """Every ring's minimum film on a log scale; where the starved film sits at the march's
    floor the ring runs dry: shaded, not drawn."""
    from camtrain.piston.film_floor import at_floor
    from camtrain.report.house import legend_beside

    for i, comp in enumerate(_rings(result)):
        part, color = result.component(comp), _COLORS[i % len(_COLORS)]
        name = comp.replace("_", " ")
        starved = part["min_film"]
        dry = at_floor(starved)
        ax.semilogy(th, np.where(dry, np.nan, starved * 1e6), color=color,
                    label=f"{name} (starved)")
        flooded = part["min_film_flooded"]
        ax.semilogy(th, np.where(at_floor(flooded), np.nan, flooded * 1e6), color=color,
                    ls="--", lw=0.9, label=f"{name} (flooded)")
        for k, (a, b) in enumerate(_runs(th, dry)):
            ax.axvspan(a, b, color=color, alpha=0.15, lw=0,
                       label=f"{name} dry (no oil film)" if k == 0 else None)
    ax.set_ylabel("minimum film [µm]")
    ax.set_title("Compression-ring films")
    _crank_axis(ax)
    legend_beside(ax)


def _runs(x: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    """(first, last) abscissa of every run of True in ``mask``."""
    edges = np.flatnonzero(np.diff(np.concatenate(([0], mask.astype(np.int8), [0]))))
    return [(float(x[a]), float(x[b - 1])) for a, b in zip(edges[::2], edges[1::2], strict=True)]


def _friction(ax, result: Result, th) -> None:
    from camtrain.report.house import legend_beside

    series = [(result.component(c)["friction"], c.replace("_", " ")) for c in _rings(result)]
    for name, label in (("oil_control_ring_friction", "oil-control ring"),
                        ("skirt_friction", "skirt")):
        if makes(result.plan, name):     # the deck has the oil-control ring's, the skirt's
            series.append((result[name], label))
    for i, (y, label) in enumerate(series):
        ax.plot(th, y, color=_COLORS[i % len(_COLORS)], lw=0.9, label=label)
    ax.axhline(0.0, color="#404040", lw=0.5)
    ax.set_ylabel("friction force [N]")
    ax.set_title("Friction force on one piston")
    _crank_axis(ax)
    legend_beside(ax)


def _flame(ax, result: Result, parts: list[tuple[str, float]]) -> None:
    """The FLAME components as bars with their power and share; total and fmep in the title."""
    from camtrain.report.display import fmt

    total = result.metrics["flame_total"].value
    labels = [label for label, _ in parts]
    values = np.array([power for _, power in parts])
    bars = ax.barh(labels, values, color=_COLORS[0])
    for bar, value in zip(bars, values, strict=True):
        share = 100.0 * value / total if total else float("nan")
        ax.text(bar.get_width() + 0.01 * values.max(), bar.get_y() + bar.get_height() / 2,
                f"{fmt(value)} W ({share:.1f} %)", va="center", fontsize=7.5)
    ax.set_xlim(0.0, 1.3 * values.max())
    ax.invert_yaxis()
    ax.set_xlabel("friction power [W]")
    fmep = result.metrics.get("fmep")
    speed = result.metrics.get("engine_speed")
    title = f"FLAME engine friction: total {fmt(total)} W"
    if fmep is not None:
        title += f", fmep {fmt(fmep.value * 1e-3)} kPa"
    ax.set_title(title if speed is None else f"{title} at {fmt(speed.value)} rpm")
    ax.grid(axis="y", visible=False)
