"""Engine friction maps: FLAME and the correlations over speed x load x oil temperature.

Two routes, one result (:class:`FrictionMap`, powers [W] on a (speed, load, temperature) grid):

* :func:`correlation_map`: the correlations alone, vectorised in one call per model (a bare
  engine deck maps in milliseconds). Load: with a pressure diagram, the deck's [load] measure
  (peak pressure or IMEP) scales the diagram per speed and the intake pressure ratio follows the
  scale; without one (a bare deck) the load axis is the intake pressure ratio p_i/p_a itself
  (Chen-Flynn keeps the deck's peak pressure).
* :func:`camtrain.study.friction_sweep.sweep_map`: every point through the sweep machinery
  (``speed``, ``load.value``, ``oil.temperature`` as a cartesian sweep; processes or a Dask
  scheduler), so FLAME runs at each point beside the correlations; the map is read from the
  sweep's records (:func:`map_from_records`).

:func:`write_map` writes friction_map.csv, friction_map.md and the plots (contours of each
model's total over speed x load per temperature; stacked shares of the groups over speed).
"""
from __future__ import annotations

import csv
import dataclasses
import io
import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: FLAME's components as groups of the map, with the metric each is read from
FLAME_GROUPS = (("bearings", "flame_bearings"), ("valve_train", "flame_valve_train"),
                ("piston", "flame_piston"), ("accessories", "flame_accessories"))
LABELS = {"flame": "FLAME", "pnh1989": "PNH 1989", "sandoval_heywood2003": "Sandoval-Heywood",
          "chen_flynn": "Chen-Flynn"}


@dataclass
class FrictionMap:
    """Friction power [W] of each model on the grid ``speeds`` [rpm] x ``loads`` (bar, or p_i/p_a
    on a bare deck: ``load_label``) x ``temperatures`` [degC]; ``groups`` model -> {group: W}
    (Chen-Flynn has none); ``fmep`` model -> Pa."""

    speeds: np.ndarray
    loads: np.ndarray
    temperatures: np.ndarray
    load_label: str
    totals: dict = field(default_factory=dict)
    groups: dict = field(default_factory=dict)
    fmep: dict = field(default_factory=dict)

    @property
    def shape(self) -> tuple[int, int, int]:
        return (self.speeds.size, self.loads.size, self.temperatures.size)


def _at(deck, rpm: float, load: float):
    """The deck at one speed and [load] value (model objects replaced)."""
    from camtrain.units import to_si

    return dataclasses.replace(deck, speed=dataclasses.replace(deck.speed,
                                                               engine=to_si(rpm, "rpm")),
                               load=dataclasses.replace(deck.load, value=to_si(load, "bar")))


def with_load_measure(deck, measure: str | None, speeds):
    """The deck whose load axis is its diagram scaled by ``measure`` (default: its [load]'s);
    None when it has no diagram (the load axis is then p_i/p_a). Every speed needs a table."""
    from camtrain.deck.schema_correlations import LoadSection
    from camtrain.errors import field_error
    from camtrain.units import to_si

    if not deck.pressure:
        return None
    if measure is not None:
        deck = dataclasses.replace(deck, load=LoadSection(measure=measure, value=1e5))
    if deck.load is None:
        return None
    for s in speeds:
        if not any(t.applies_to(to_si(s, "rpm")) for t in deck.pressure):
            raise field_error("--speeds", "no pressure table for this speed", f"{s:g} rpm",
                              "speeds listed in the deck's [[pressure]] tables")
    return deck


def correlation_map(deck, speeds, loads, temperatures, measure: str | None = None
                    ) -> FrictionMap:
    """The correlations of ``deck`` (a validated engine-deck model with [correlations]) on the
    grid, vectorised: speeds [rpm], loads (the [load] value in bar, ``measure`` or the deck's
    [load] measure, on a deck with a pressure diagram; else the intake pressure ratio), oil
    temperatures [degC]."""
    from camtrain.assemble import correlations as build
    from camtrain.assemble.engine import load_factor, pressure_table
    from camtrain.engine.correlations import (
        GROUPS,
        MODELS,
        OperatingPoint,
        chen_flynn_fmep,
        correlation_terms,
        fmep_to_power,
    )

    S, L, T = (np.asarray(v, dtype=float).ravel() for v in (speeds, loads, temperatures))
    c = deck.correlations
    engine = build.correlation_engine(deck)
    omega = (S * 2.0 * math.pi / 60.0)[:, None, None]
    scaled = with_load_measure(deck, measure, S)
    diagram = scaled is not None
    if diagram:
        deck = scaled
        factor = np.array([[load_factor(_at(deck, s, x)) for x in L] for s in S])
        intake = c.intake_pressure_ratio * factor[:, :, None]
        label = f"{deck.load.measure.replace('_', ' ')} [bar]"
    else:
        intake = np.broadcast_to(L[None, :, None], (1, L.size, 1))
        label = "intake pressure ratio p_i/p_a [-]"
    nu = np.array([build.oil_viscosity(deck, t) for t in T])[None, None, :]
    out = FrictionMap(S, L, T, label)
    n0 = None if c.boundary_speed == "per_model" else MODELS[c.boundary_speed].n0
    grid = np.zeros((S.size, L.size, T.size))
    for name in c.models:
        terms = correlation_terms(MODELS[name], engine, OperatingPoint(omega, intake, nu), n0)
        fmep = grid + sum(terms.values())
        out.fmep[name] = fmep
        out.totals[name] = fmep_to_power(fmep, engine.displacement, omega, engine.strokes)
        out.groups[name] = {g: fmep_to_power(grid + sum(v for k, v in terms.items()
                                                        if GROUPS[k] == g),
                                             engine.displacement, omega, engine.strokes)
                            for g in dict.fromkeys(GROUPS.values())}
    if c.chen_flynn is not None:
        if diagram:
            peak = np.array([[float(max(pressure_table(_at(deck, s, x)).gauge()))
                              for x in L] for s in S]) + build.ATMOSPHERE
        else:   # a bare deck: the deck's peak pressure at every point (as the effect)
            peak = np.full((S.size, L.size), build.peak_pressure(deck))
        fmep = grid + chen_flynn_fmep(build.chen_flynn_constants(deck), engine, omega,
                                      peak[:, :, None])
        out.fmep["chen_flynn"] = fmep
        out.totals["chen_flynn"] = fmep_to_power(fmep, engine.displacement, omega,
                                                 engine.strokes)
    return out


def map_from_records(params, records, load_label: str) -> FrictionMap:
    """A map from sweep records (values and metrics in the deck's units) over three swept
    parameters: speed, load, oil temperature, in that order."""
    from camtrain.units import to_si

    axes = [np.array(sorted({float(r["values"][p.name]) for r in records})) for p in params]
    out = FrictionMap(axes[0], axes[1], axes[2], load_label)
    shape = out.shape

    def put(store, key, idx, value):
        store.setdefault(key, np.full(shape, np.nan))[idx] = value

    for r in records:
        if r.get("status") != "ok":
            continue
        idx = tuple(int(np.searchsorted(a, float(r["values"][p.name])))
                    for a, p in zip(axes, params, strict=True))
        m = {k: to_si(float(v[0]), v[1]) for k, v in r["metrics"].items()
             if k.endswith(("_power", "fmep")) or k.startswith("flame_")}
        if "flame_total" in m:
            put(out.totals, "flame", idx, m["flame_total"])
            put(out.fmep, "flame", idx, m.get("fmep", math.nan))
            for g, metric in FLAME_GROUPS:
                put(out.groups.setdefault("flame", {}), g, idx, m.get(metric, math.nan))
        for name in ("pnh1989", "sandoval_heywood2003", "chen_flynn"):
            if f"{name}_power" not in m:
                continue
            put(out.totals, name, idx, m[f"{name}_power"])
            put(out.fmep, name, idx, m[f"{name}_fmep"])
            for g in ("crankshaft", "reciprocating", "valve_train", "auxiliaries"):
                if f"{name}_{g}_power" in m:
                    put(out.groups.setdefault(name, {}), g, idx, m[f"{name}_{g}_power"])
    return out


# ----------------------------------------------------------------------------- outputs

def map_csv(fmap: FrictionMap) -> str:
    """One row per grid point and model: total kW, fmep kPa and each group's kW."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    groups = sorted({g for gs in fmap.groups.values() for g in gs})
    w.writerow(["speed [rpm]", fmap.load_label, "oil temperature [°C]", "model", "total [kW]",
                "fmep [kPa]"] + [f"{g} [kW]" for g in groups])
    for name, total in fmap.totals.items():
        for (i, j, k), value in np.ndenumerate(total):
            row = [f"{fmap.speeds[i]:g}", f"{fmap.loads[j]:g}", f"{fmap.temperatures[k]:g}",
                   name, f"{value / 1e3:.4f}", f"{fmap.fmep[name][i, j, k] / 1e3:.2f}"]
            row += [f"{fmap.groups[name][g][i, j, k] / 1e3:.4f}" if g in fmap.groups.get(
                name, {}) else "" for g in groups]
            w.writerow(row)
    return buf.getvalue()


def map_markdown(fmap: FrictionMap, title: str = "") -> str:
    """Per oil temperature and model: total friction power [kW], speed down, load across."""
    lines = [f"# Engine friction map{': ' + title if title else ''}", ""]
    for k, t in enumerate(fmap.temperatures):
        for name, total in fmap.totals.items():
            lines += [f"## {LABELS.get(name, name)}, oil {t:g} °C: friction power kW", "",
                      "| rpm \\ " + fmap.load_label + " | "
                      + " | ".join(f"{x:g}" for x in fmap.loads) + " |",
                      "|---" * (fmap.loads.size + 1) + "|"]
            for i, s in enumerate(fmap.speeds):
                lines.append(f"| {s:g} | " + " | ".join(f"{total[i, j, k] / 1e3:.3f}"
                                                       for j in range(fmap.loads.size)) + " |")
            lines.append("")
    return "\n".join(lines)


def map_plots(fmap: FrictionMap, out_dir: Path) -> list[Path]:
    """plots/friction_map_contour.png (total kW over speed x load, a row per model, a column
    per temperature) and plots/friction_map_shares.png (stacked group shares over speed at the
    middle load and temperature, a panel per model with groups)."""
    from camtrain.report.plots import _pyplot

    plt = _pyplot()
    out_dir.mkdir(parents=True, exist_ok=True)
    names = list(fmap.totals)
    nt = fmap.temperatures.size
    written = []
    if fmap.speeds.size > 1 and fmap.loads.size > 1:
        fig, axes = plt.subplots(len(names), nt, figsize=(3.4 * nt, 2.8 * len(names)),
                                 squeeze=False)
        for r, name in enumerate(names):
            for k in range(nt):
                ax = axes[r][k]
                z = fmap.totals[name][:, :, k].T / 1e3
                cs = ax.contourf(fmap.speeds, fmap.loads, z, levels=12, cmap="viridis")
                ax.contour(fmap.speeds, fmap.loads, z, levels=6, colors="k", linewidths=0.4)
                fig.colorbar(cs, ax=ax, label="kW")
                ax.set_title(f"{LABELS.get(name, name)}, {fmap.temperatures[k]:g} °C",
                             fontsize=9)
                ax.set_xlabel("speed [rpm]", fontsize=8)
                ax.set_ylabel(fmap.load_label, fontsize=8)
        fig.tight_layout()
        path = out_dir / "friction_map_contour.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    with_groups = [n for n in names if fmap.groups.get(n)]
    if with_groups:
        j, k = fmap.loads.size // 2, nt // 2
        fig, axes = plt.subplots(1, len(with_groups), figsize=(4.2 * len(with_groups), 3.6),
                                 squeeze=False)
        for ax, name in zip(axes[0], with_groups, strict=True):
            parts = fmap.groups[name]
            total = sum(v[:, j, k] for v in parts.values())
            ax.stackplot(fmap.speeds, *[100 * v[:, j, k] / total for v in parts.values()],
                         labels=[g.replace("_", " ") for g in parts], alpha=0.85)
            ax.set_ylim(0, 100)
            ax.set_xlabel("speed [rpm]")
            ax.set_ylabel("share of the total [%]")
            ax.set_title(f"{LABELS.get(name, name)} ({fmap.loads[j]:g}, "
                         f"{fmap.temperatures[k]:g} °C)", fontsize=9)
            ax.legend(loc="lower left", fontsize=7)
        fig.tight_layout()
        path = out_dir / "friction_map_shares.png"
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    return written


def write_map(fmap: FrictionMap, out_dir, *, plots: bool = True, title: str = "") -> list[Path]:
    """friction_map.csv, friction_map.md and (with ``plots``) the two plots in plots/."""
    from camtrain.report.tables import atomic_write

    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    atomic_write(out_dir / "friction_map.csv", map_csv(fmap))
    atomic_write(out_dir / "friction_map.md", map_markdown(fmap, title))
    written = [out_dir / "friction_map.csv", out_dir / "friction_map.md"]
    if plots:
        written += map_plots(fmap, out_dir / "plots")
    return written


def write_sweep_map(out_dir, params, records, *, plots: bool = True,
                    title: str = "") -> list[Path]:
    """The map files of a three-parameter sweep (``speed``, ``load.value`` or
    ``correlations.intake_pressure_ratio``, ``oil.temperature``, in that order) whose cases
    carry correlation or FLAME totals; nothing otherwise."""
    names = [p.path for p in params]
    loads = {"load.value": "load [bar]",
             "correlations.intake_pressure_ratio": "intake pressure ratio p_i/p_a [-]"}
    if len(params) != 3 or names[0] != "speed.engine" or names[1] not in loads \
            or names[2] != "oil.temperature":
        return []
    if not any(r.get("status") == "ok" and any(k.endswith("_power") or k == "flame_total"
                                               for k in r.get("metrics", {})) for r in records):
        return []
    fmap = map_from_records(params, records, loads[names[1]])
    return write_map(fmap, out_dir, plots=plots, title=title)
