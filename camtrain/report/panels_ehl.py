"""Panels of the elastic film sheet (tribology.film_model = ehl; docs/ehl.md): the film map
over cam angle and position, the elastic films beside the formula films (the deck's own, and
the closed-form minimum and central films as bands), and the peak pressure
against the dry Hertz pressure. The plan declares them when its film effect ran the elastic
film (EffectSpec.model_panels, from the model its step records)."""
from __future__ import annotations

import numpy as np

from camtrain.report.panels import _finite, _fit_y, _mark_zero_entrainment, optional, shown
from camtrain.report.style import COLORS, angle_axis, finish_axes


def film_map(ax, r, ctx):
    """The film h(x) against cam angle (rows of the map axis), as a colour map; none when no
    angle of the march was loaded (the elastic film then writes no map)."""
    if "film_map_angle" not in r.columns:
        return False
    angle = np.degrees(r["film_map_angle"])
    x, unit_x = shown(r, "film_map_x")
    h, unit_h = shown(r, "film_map_film")
    p = r["film_map_pressure"]
    rows = np.unique(angle).size
    A, X, H, Pm = (v.reshape(rows, -1) for v in (angle, x, h, p))
    # the loaded zone of a typical angle (pressure above 1 % of the row's peak; the median
    # over the rows, the light flanks reach much further), with twice as much around it
    zone = Pm > 0.01 * np.nanmax(Pm, axis=1, keepdims=True)
    reach = 3.0 * float(np.nanmedian(np.nanmax(np.abs(np.where(zone, X, 0.0)), axis=1)))
    central = float(np.nanmedian(np.nanmin(H, axis=1)))
    logs = np.log10(np.maximum(H, 1e-300))
    # each angle has its own grid (scaled by its Hertz half-width): the rows are resampled on
    # one position axis, so that the map's cell centres increase along both axes
    span = reach if reach > 0.0 else float(np.nanmax(np.abs(X)))
    across = np.linspace(-span, span, 2 * X.shape[1] + 1)
    order = np.argsort(A[:, 0], kind="stable")
    resampled = np.array([_row_on(across, X[i], logs[i]) for i in order])
    mesh = ax.pcolormesh(A[order, 0], across, resampled.T, shading="nearest", cmap="viridis",
                         rasterized=True, vmin=np.log10(0.5 * central),
                         vmax=np.log10(30.0 * central))
    cax = ax.inset_axes([0.93, 0.1, 0.015, 0.8])
    cbar = ax.figure.colorbar(mesh, cax=cax)
    cbar.set_label(f"log10 film [{unit_h}]", fontsize=7)
    cbar.ax.tick_params(labelsize=6)
    if reach > 0.0:
        ax.set_ylim(-reach, reach)
    ax.set_ylabel(f"position along the contact [{unit_x}]")
    angle_axis(ax)
    finish_axes(ax, legend=False)
    return True


def _row_on(across, x, values):
    """One angle's values at the positions ``across`` (NaN outside its own grid)."""
    keep = np.isfinite(x) & np.isfinite(values)
    if np.count_nonzero(keep) < 2:
        return np.full(across.size, np.nan)
    xs, vs = x[keep], values[keep]
    rank = np.argsort(xs)
    return np.interp(across, xs[rank], vs[rank], left=np.nan, right=np.nan)


#: the closed-form films the elastic film declares beside its own (EffectSpec.optional_columns
#: of the film effect; docs/ehl.md "Outputs"), drawn as two bands: minimum and central films
FORMULA_BANDS = (
    (("film_dowson_higginson_min", "film_pan_hamrock_min"), "second",
     "formula minimum films (Dowson-Higginson 1977, Pan-Hamrock 1989)"),
    (("film_pan_hamrock_central", "film_moes_central", "film_dowson_toyoda_central"), "main",
     "formula central films (Pan-Hamrock 1989, Moes 1992, Dowson-Toyoda 1979)"),
)


def elastic_films(ax, r, ctx):
    """Central and minimum elastic film with the steady formula film, and the spread of the
    closed-form minimum and central films of the same inputs as bands (where the plan made
    them). A formula's zero film at zero entrainment is left out of the log axis."""
    unit = ""
    for name, color, style, label in (
            ("film_central", COLORS["main"], "-", "elastic central film"),
            ("film_min", COLORS["second"], "-", "elastic minimum film"),
            ("film_steady", COLORS["third"], "--", "steady formula film")):
        y, unit = shown(r, name)
        ax.plot(ctx.theta, _finite(y), color=color, ls=style, label=label)
    for names, color, label in FORMULA_BANDS:
        made = optional(r, *names)
        if not made:
            continue
        films = np.array([shown(r, n)[0] for n in made])
        films = np.where(np.isfinite(films) & (films > 0.0), films, np.nan)
        drawn = np.isfinite(films).all(axis=0)
        ax.fill_between(ctx.theta, films.min(axis=0), films.max(axis=0), where=drawn,
                        color=COLORS[color], alpha=0.3, lw=0.0, label=label)
    _mark_zero_entrainment(ax, ctx)
    ax.set_yscale("log")
    ax.set_ylabel(f"film thickness [{unit}]")
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


def pressure_over_hertz(ax, r, ctx):
    """Peak fluid pressure of the elastic film over the dry Hertz pressure."""
    y, _ = shown(r, "film_pressure_over_hertz")
    ax.plot(ctx.theta, _finite(y), color=COLORS["main"], label="peak pressure / Hertz")
    ax.axhline(1.0, color=COLORS["grey"], lw=0.8, ls="--", label="Hertz")
    _fit_y(ax, [_finite(y), np.array([1.0])], bottom=0.0)
    ax.set_ylabel("p_max / p_Hertz [-]")
    angle_axis(ax)
    finish_axes(ax, legend=True)
    return True


EHL_PANELS = {
    "film_map": ("Elastic film along the contact over the cycle", film_map),
    "elastic_films": ("Elastic films and the formula films", elastic_films),
    "pressure_over_hertz": ("Peak film pressure against Hertz", pressure_over_hertz),
}
