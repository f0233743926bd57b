"""The plot panels: each draws one Ball-style graph into an axes.

A sheet calls the panels the effects that ran declare (EffectSpec.panels, and the
EffectSpec.model_panels of the model a step ran: the transient film's panels for a transient
film). Every panel function takes (ax, result, ctx) and draws the curves the effects that
declare it write; an optional curve (EffectSpec.optional_columns, a rigid train's valve force,
a spring chain's retainer force) when the plan made it (:func:`optional`). It returns False,
drawing nothing, when its curve says nothing (a flat follower's pressure angle, identically
zero), and the sheet leaves it out. Values are shown in display units.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from camtrain.catalogue import makes, planned_products
from camtrain.report.display import LABELS, display_unit, typeset
from camtrain.report.findings import Findings, central_film, entrainment, in_contact
from camtrain.report.style import COLORS, angle_axis, finish_axes, headroom
from camtrain.result import Result


@dataclass
class Ctx:
    theta: np.ndarray          # cam angle [deg]
    findings: Findings


def made(r: Result) -> frozenset[str]:
    """The products the run's effects made (the plan's declarations): a panel of one product
    draws when the plan made it."""
    return planned_products(r.plan)


def optional(r: Result, *names: str) -> list[str]:
    """Those of the optional columns ``names`` the plan made (EffectSpec.optional_columns)."""
    return [n for n in names if makes(r.plan, n)]


def shown(r: Result, name: str) -> tuple[np.ndarray, str]:
    col = r.columns[name]
    unit, factor = display_unit(name, col.unit)
    return col.values * factor, typeset(unit)


def _cycle(ax, r: Result, ctx: Ctx, names, ylabel: str | None = None, colors=None,
           labels=None, legend: bool | None = None, zero: bool = False) -> bool:
    present = list(names)
    unit, data = "", []
    for i, name in enumerate(present):
        y, unit = shown(r, name)
        label = (labels or {}).get(name, LABELS.get(name, name))
        color = (colors or [COLORS["main"], COLORS["second"], COLORS["third"],
                            COLORS["fourth"]])[i % 4]
        ax.plot(ctx.theta, _finite(y), color=color, label=label)
        data.append(_finite(y))
    _fit_y(ax, data)
    ax.set_ylabel(f"{ylabel or LABELS.get(present[0], present[0])} [{unit or '-'}]")
    if zero:
        _zero_line(ax)
    angle_axis(ax)
    finish_axes(ax, legend=len(present) > 1 if legend is None else legend)
    return True


def _fit_y(ax, data, bottom: float | None = None) -> None:
    """y-limits from the curves only (shaded spans must not stretch the axis)."""
    vals = np.concatenate([d[np.isfinite(d)] for d in data]) if data else np.array([])
    if not vals.size:
        return
    lo, hi = float(vals.min()), float(vals.max())
    lo = min(lo, 0.0) if bottom is None else bottom
    span = hi - lo if hi > lo else max(abs(hi), 1.0)
    ax.set_ylim(lo - (0.05 * span if lo < 0 else 0.0), hi + 0.05 * span)


def _finite(y: np.ndarray) -> np.ndarray:
    return np.where(np.isfinite(y), y, np.nan)


def _plain(value: float, _pos=None) -> str:
    """A tick label as a plain number with a true minus sign (no typeset mathematics)."""
    return f"{value:g}".replace("-", "\N{MINUS SIGN}")


def _zero_line(ax) -> None:
    ax.axhline(0.0, color=COLORS["grey"], lw=0.6, zorder=1)


def _mark_zero_entrainment(ax, ctx: Ctx, label: bool = True) -> None:
    for i, a in enumerate(ctx.findings.zero_entrainment):
        ax.axvline(math.degrees(a), color=COLORS["zero"], lw=0.7, ls=":",
                   label="zero entrainment" if (label and i == 0) else None)


def _shade(ax, ranges, color: str, label: str) -> None:
    for i, (a, b) in enumerate(ranges):
        ax.axvspan(math.degrees(a), math.degrees(b), color=color, alpha=0.45, lw=0,
                   label=label if i == 0 else None, zorder=0)


# --------------------------------------------------------------------------- kinematics

def lift(ax, r, ctx):
    # the kinematics effect writes the valve's lift; a lift-only run has the lift law's alone
    name = "valve_lift" if "TrainKinematics" in made(r) else "lift"
    return _cycle(ax, r, ctx, [name])


def velocity(ax, r, ctx):
    return _cycle(ax, r, ctx, ["velocity"], zero=True)


def acceleration(ax, r, ctx):
    return _cycle(ax, r, ctx, ["acceleration"], zero=True)


def jerk(ax, r, ctx):
    return _cycle(ax, r, ctx, ["jerk"], zero=True)


def eccentricity(ax, r, ctx):
    return _cycle(ax, r, ctx, ["eccentricity"], zero=True)


def pressure_angle(ax, r, ctx):
    if not np.any(r["pressure_angle"]):
        return False        # identically zero (flat follower): a blank panel says nothing
    return _cycle(ax, r, ctx, ["pressure_angle"], zero=True)


def velocities(ax, r, ctx):
    """Surface velocities of the contact (Ball's panel h), entrainment and sliding."""
    ue = entrainment(r)
    series = [(r[name], LABELS[name]) for name in ("v_cam", "v_follower")]
    if ue is not None:
        series.append((ue, "entrainment (V_c + V_f)/2"))
    series.append((r["sliding"], LABELS["sliding"]))
    colors = [COLORS["main"], COLORS["second"], COLORS["third"], COLORS["fourth"]]
    for (y, label), color in zip(series, colors, strict=False):
        ax.plot(ctx.theta, _finite(y), color=color, label=label)
    _zero_line(ax)
    _mark_zero_entrainment(ax, ctx)
    ax.set_ylabel("surface velocity [m/s]")
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


def radii(ax, r, ctx):
    """Cam radius r_c and equivalent radius R on a symmetric-log scale: linear near the
    base-circle size, logarithmic beyond, so a concave flank (r_c < 0, shaded) is shown
    whole next to the large radii near flat spots; only infinite radii are left out."""
    present = ["cam_radius", "equivalent_radius"]
    finite_vals = []
    for i, name in enumerate(present):
        y, unit = shown(r, name)
        y = _finite(y)
        finite_vals.append(y[np.isfinite(y)])
        ax.plot(ctx.theta, y, color=[COLORS["main"], COLORS["second"]][i], label=LABELS[name])
    _shade(ax, ctx.findings.concave, COLORS["no_contact"], "concave flank (r_c < 0)")
    vals = np.concatenate(finite_vals) if finite_vals else np.array([])
    if vals.size:
        lo, hi = float(min(vals.min(), 0.0)), float(max(vals.max(), 0.0))
        scale = float(np.median(np.abs(vals[vals != 0]))) if np.any(vals) else 1.0
        ax.set_yscale("symlog", linthresh=scale, linscale=1.0)
        ax.yaxis.set_major_formatter(_plain)    # 10, 100 rather than typeset powers
        ax.set_ylim(lo * 1.3 if lo < 0 else -0.05 * scale, hi * 1.3 if hi > 0 else scale)
    _zero_line(ax)
    ax.set_ylabel(f"radius of curvature [{unit}] (symlog)")
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


# --------------------------------------------------------------------------- film

def film_angle(ax, r, ctx):
    """h_min and h_cen against cam angle, λ on a second axis, boundary regions shaded."""
    present = ["film_min", *(["film_central"] if central_film(r) else [])]
    _shade(ax, ctx.findings.boundary, COLORS["boundary"], "boundary (λ < 1)")
    _shade(ax, ctx.findings.loss_of_contact, COLORS["no_contact"], "loss of contact")
    _shade(ax, ctx.findings.clearance, COLORS["clearance"], "no load (clearance)")
    data = []
    for name, color in zip(present, (COLORS["main"], COLORS["film"]), strict=False):
        y, unit = shown(r, name)
        ax.plot(ctx.theta, _finite(y), color=color, label=LABELS[name])
        data.append(_finite(y))
    _mark_zero_entrainment(ax, ctx)
    ax.set_ylabel(f"film thickness [{unit}]")
    _fit_y(ax, data, bottom=0.0)
    angle_axis(ax)
    sigma = _roughness(r)
    if sigma is not None:
        # λ is h_min/σ: a second scale on the same curve says it without another line
        ax.secondary_yaxis("right", functions=(lambda h: h / sigma, lambda lam: lam * sigma)) \
            .set_ylabel("λ = h_min/σ [-]")
        finish_axes(ax, legend=True)
    elif "ContactFilm" in made(r):   # the film effect writes lambda beside the film
        tw = ax.twinx()
        tw.plot(ctx.theta, _finite(r["lambda"]), color=COLORS["second"], lw=0.9, ls="--",
                label="λ (right axis)")
        tw.set_ylabel("λ [-]")
        tw.set_ylim(bottom=0.0)
        tw.grid(False)
        h1, l1 = ax.get_legend_handles_labels()
        h2, l2 = tw.get_legend_handles_labels()
        headroom(tw)
        finish_axes(ax, legend=True, handles=(h1 + h2, l1 + l2))
    else:
        finish_axes(ax, legend=True)
    return True


def _roughness(r: Result) -> float | None:
    """σ [µm] when λ = h_min/σ holds at every angle (then λ is just a rescaled h_min)."""
    h, lam = r["film_min"] * 1e6, r["lambda"]
    ok = np.isfinite(h) & np.isfinite(lam) & (lam > 0) & (h > 0)
    if ok.sum() < 2:
        return None
    ratio = h[ok] / lam[ok]
    sigma = float(np.median(ratio))
    return sigma if np.allclose(ratio, sigma, rtol=1e-6) else None


def film_position(ax, r, ctx):
    """Film against the contact position on the follower face (Ball's panel g)."""
    x, xu = shown(r, "eccentricity")
    h, hu = shown(r, "film_min")
    contact = in_contact(r)
    mask = np.ones_like(h, dtype=bool) if contact is None else contact
    opening = mask & (ctx.theta <= 0)
    closing = mask & (ctx.theta >= 0)
    ax.plot(np.where(opening, x, np.nan), np.where(opening, h, np.nan), color=COLORS["main"],
            label="opening flank (θ < 0)")
    ax.plot(np.where(closing, x, np.nan), np.where(closing, h, np.nan), color=COLORS["second"],
            label="closing flank (θ > 0)")
    theta_rad = r["cam_angle"]
    for i, a in enumerate(ctx.findings.zero_entrainment):
        ax.plot(np.interp(a, theta_rad, x), np.interp(a, theta_rad, h), "x",
                color=COLORS["zero"], ms=6, mew=1.5, label="zero entrainment" if i == 0 else None)
    ax.set_xlabel(f"contact position on the follower e [{xu}]")
    ax.set_ylabel(f"h_min [{hu}]")
    ax.set_ylim(bottom=0.0)
    finish_axes(ax, legend=True)
    return True


# --------------------------------------------------------------------------- loads and friction

def load(ax, r, ctx):
    _shade(ax, ctx.findings.loss_of_contact, COLORS["no_contact"], "loss of contact")
    _shade(ax, ctx.findings.clearance, COLORS["clearance"], "no load (clearance)")
    return _cycle(ax, r, ctx, ["load", *optional(r, "valve_force")], ylabel="force", legend=True,
                  zero=True)


def hertz(ax, r, ctx):
    return _cycle(ax, r, ctx, ["hertz_pmax"])


def friction_coefficient(ax, r, ctx):
    _shade(ax, ctx.findings.boundary, COLORS["boundary"], "boundary (λ < 1)")
    return _cycle(ax, r, ctx, ["friction_coefficient"], legend=bool(ctx.findings.boundary))


def friction_force(ax, r, ctx):
    return _cycle(ax, r, ctx, ["friction_force"], zero=True)


def torque(ax, r, ctx):
    return _cycle(ax, r, ctx, ["friction_torque", "cam_torque"], ylabel="camshaft torque",
                  zero=True)


def power(ax, r, ctx):
    y, unit = shown(r, "power_loss")
    ax.plot(ctx.theta, _finite(y), color=COLORS["main"], label="instantaneous")
    mean = float(np.nanmean(y))
    ax.axhline(mean, color=COLORS["mean"], ls="--", lw=0.9, label=f"cycle mean {mean:.2f} {unit}")
    ax.set_ylabel(f"friction power [{unit}]")
    ax.set_ylim(bottom=min(0.0, float(np.nanmin(y))))
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


# --------------------------------------------------------------------------- transient film

def transient_film(ax, r, ctx):
    """Transient film against the steady film over the cycle (docs/transient_film.md); the
    plan declares it when its film effect ran a transient model (EffectSpec.model_panels), and
    the averaged Reynolds film adds its own film before the steady-film floor."""
    labels = {"film_min": "transient film", "film_steady": "steady EHL film",
              "film_transient": "averaged Reynolds (before the floor)"}
    names = ["film_min", *optional(r, "film_steady", "film_transient")]
    data = []
    for name, color, style in zip(names, (COLORS["main"], COLORS["second"], COLORS["third"]),
                                  ("-", "--", ":"), strict=False):
        y, unit = shown(r, name)
        ax.plot(ctx.theta, _finite(y), color=color, ls=style, label=labels[name])
        data.append(_finite(y))
    _mark_zero_entrainment(ax, ctx)
    ax.set_ylabel(f"film thickness [{unit}]")
    _fit_y(ax, data, bottom=0.0)
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


def film_pressures(ax, r, ctx):
    """Peak fluid and asperity pressure of the averaged Reynolds film over the cycle, with the
    asperity share of the load on a second axis (declared for the films that solve for their
    pressure: averaged Reynolds and elastic, EffectSpec.model_panels)."""
    data = []
    for name, color, label in (("film_pressure_max", COLORS["main"], "peak fluid pressure"),
                               ("asperity_pressure_max", COLORS["second"],
                                "peak asperity pressure")):
        y, unit = shown(r, name)
        ax.plot(ctx.theta, _finite(y), color=color, label=label)
        data.append(_finite(y))
    ax.set_ylabel(f"pressure [{unit}]")
    _fit_y(ax, data, bottom=0.0)
    tw = ax.twinx()
    tw.plot(ctx.theta, _finite(r["asperity_load_share"]), color=COLORS["grey"], lw=0.8,
            ls="--", label="asperity share of load (right)")
    tw.set_ylabel("W_A / W [-]")
    tw.set_ylim(0.0, 1.0)
    tw.grid(False)
    h1, l1 = ax.get_legend_handles_labels()
    h2, l2 = tw.get_legend_handles_labels()
    handles = (h1 + h2, l1 + l2)
    angle_axis(ax)
    finish_axes(ax, legend=True, handles=handles)
    return True


#: name -> (title, function); the order is the order on the sheets
def dynamic_load(ax, r, ctx):
    """The elastic train's contact load over the rigid train's (its quasi-static limit)."""
    _shade(ax, ctx.findings.loss_of_contact, COLORS["no_contact"], "loss of contact")
    return _cycle(ax, r, ctx, ["load", "rigid_load"], ylabel="contact load", zero=True,
                  labels={"load": "elastic train", "rigid_load": "rigid train"}, legend=True)


def valve_motion(ax, r, ctx):
    """Valve lift of the elastic train over the cam's (rigid) valve lift, and the follower."""
    return _cycle(ax, r, ctx, ["valve_lift", "valve_lift_dynamic", "follower_lift"],
                  ylabel="lift", labels={"valve_lift": "rigid (cam)",
                                         "valve_lift_dynamic": "valve, elastic",
                                         "follower_lift": "follower, elastic"}, legend=True)


def valve_acceleration(ax, r, ctx):
    return _cycle(ax, r, ctx, ["valve_acceleration", "follower_acceleration"],
                  ylabel="acceleration", zero=True, legend=True,
                  labels={"valve_acceleration": "valve", "follower_acceleration": "follower"})


def spring_forces(ax, r, ctx):
    """Spring force at the head and the retainer (they differ by surge) and the seat force."""
    return _cycle(ax, r, ctx, ["spring_force", *optional(r, "spring_force_retainer"),
                               "seat_force"],
                  ylabel="force", legend=True,
                  labels={"spring_force": "spring at the head",
                          "spring_force_retainer": "spring at the retainer",
                          "seat_force": "valve seat"})


def roller_spin(ax, r, ctx):
    """The roller's slip marched with the elastic train (the run's roller slip: the roller
    effect takes the marched speed, so its own slip column is this curve)."""
    return _cycle(ax, r, ctx, ["roller_slip_marched"], ylabel="slip", zero=True,
                  labels={"roller_slip_marched": "marched with the train"})


PANELS = {
    "lift": ("Lift", lift),
    "velocity": ("Velocity", velocity),
    "acceleration": ("Acceleration", acceleration),
    "jerk": ("Jerk", jerk),
    "eccentricity": ("Contact position on the follower", eccentricity),
    "pressure_angle": ("Pressure angle", pressure_angle),
    "velocities": ("Contact surface velocities", velocities),
    "radii": ("Radii of curvature", radii),
    "film_angle": ("Film thickness against cam angle", film_angle),
    "film_position": ("Film thickness along the follower", film_position),
    "load": ("Contact load", load),
    "hertz": ("Maximum Hertz stress", hertz),
    "friction_coefficient": ("Friction coefficient", friction_coefficient),
    "friction_force": ("Friction force", friction_force),
    "torque": ("Camshaft torque", torque),
    "power": ("Frictional power loss", power),
    "transient_film": ("Transient film against the steady film", transient_film),
    "film_pressures": ("Film and asperity pressures", film_pressures),
    "dynamic_load": ("Contact load: elastic and rigid train", dynamic_load),
    "valve_motion": ("Valve and follower motion", valve_motion),
    "valve_acceleration": ("Valve and follower acceleration", valve_acceleration),
    "spring_forces": ("Spring and seat forces", spring_forces),
    "roller_spin": ("Roller slip in the elastic train", roller_spin),
}
