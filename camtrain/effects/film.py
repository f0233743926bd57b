"""Film effect: minimum and central EHL film thickness and the film parameter lambda = h/sigma.

Physics: the pair's :class:`camtrain.contact.model.CamContact` and its film law. With a planned
contact load the EHL film of each loaded pair (Ball 1988 eqs. 4.1, 4.2; Hamrock & Dowson 1977
or Chittenden et al. 1985 for point contacts); without, the load-free Blok film (Dowson, Dunn &
Taylor 1983; Ball eq. 4.3). The plan says which, from the products it provides.
"""
from __future__ import annotations

from camtrain.metric_rows import CaseMetric, anywhere, at, one_case


def missing(deck) -> list[str]:
    if deck.lubricant is None:
        return ["lubricant (viscosity, pressure_viscosity)"]
    model = deck.tribology.film_model
    if model != "steady" and deck.spring is not None and deck.cam.width is None:
        return [f"cam.width (the {model} film is a line-contact film per unit width)"]
    return []


#: why each transient film model runs (the plan prints it)
_TRANSIENT = {
    "squeeze": "level-1 transient film (tribology.film_model = squeeze): Teodorescu et al. "
               "(2005) eq. 5 with its squeeze term, marched implicitly in cam angle, so the film "
               "at zero entrainment is what the squeeze leaves",
    "averaged_reynolds": "level-2 transient film (tribology.film_model = averaged_reynolds): "
                         "Göçmen (2013) averaged Reynolds contact with squeeze, flow factors and "
                         "Greenwood-Tripp asperities, load balanced at every angle and marched "
                         "implicitly; friction from the same solution",
    "ehl": "elastic film (tribology.film_model = ehl): transient elastohydrodynamic line contact "
           "(Reynolds with squeeze, elastic surfaces, piezoviscous compressible oil, "
           "Greenwood-Tripp asperities), marched implicitly from the steady solution; friction "
           "from the same solution",
}


def model(deck, planned) -> str:
    """The film model this effect runs (the plan step records it, and the report's panels
    follow from it): the deck's tribology.film_model under planned contact loads on a cam with
    a width, else the steady film (the load-free Blok film, or the steady film a missing
    cam.width leaves), as :func:`reason` says."""
    if "ContactLoad" in planned and deck.cam.width is not None:
        return deck.tribology.film_model
    return "steady"


#: the closed-form films the elastic film writes beside its own (docs/ehl.md "Outputs"):
#: column, function of camtrain.formulas.film_line (contact.transient_ehl.FORMULA_FILMS), what
FORMULA_COLUMNS = (
    ("film_dowson_higginson_min", "dowson_higginson_1977",
     "Dowson-Higginson (1977) minimum film"),
    ("film_pan_hamrock_min", "pan_hamrock_1989_min", "Pan-Hamrock (1989) minimum film"),
    ("film_pan_hamrock_central", "pan_hamrock_1989_cen", "Pan-Hamrock (1989) central film"),
    ("film_moes_central", "moes_1992", "Moes (1992) central film (mean-speed groups)"),
    ("film_dowson_toyoda_central", "dowson_toyoda_1979", "Dowson-Toyoda (1979) central film"),
)


def makes(deck, planned) -> tuple[str, ...]:
    """The optional columns it writes (EffectSpec.optional_columns), from the model it runs: a
    transient film writes the steady film of the same angles beside its own, the averaged
    Reynolds film also its own film before the steady-film floor, the elastic film the
    closed-form films of :data:`FORMULA_COLUMNS`."""
    return {"squeeze": ("film_steady",),
            "ehl": ("film_steady", *(c for c, _, _ in FORMULA_COLUMNS)),
            "averaged_reynolds": ("film_steady", "film_transient")}.get(model(deck, planned), ())


def reason(deck, planned) -> str:
    model = deck.tribology.film_model
    if "ContactLoad" in planned and deck.cam.width is None:
        return ("lubricant given, contact loads planned but no cam.width: Blok rigid-piezoviscous "
                "film for line contacts, which needs no load per unit width (Ball eq. 4.3)")
    if "ContactLoad" in planned:
        if model == "steady":
            return "lubricant given and contact loads planned: EHL film with the contact load"
        s = deck.solver
        if model == "ehl":
            return (f"lubricant given and contact loads planned: {_TRANSIENT[model]} "
                    f"({s.ehl_nodes} points over +-{s.ehl_inlet:g} Hertz half widths or 20 "
                    f"rigid lengths, {deck.tribology.ehl_cavitation} cavitation, {s.ehl_march}, "
                    f"angle step {s.ehl_angle_step * 57.29577951308232:g} deg)")
        march = s.film_march if model == "averaged_reynolds" else "implicit_euler"
        knobs = (f"{march}, angle step "
                 + (f"{s.film_angle_step * 57.29577951308232:g} deg" if s.film_angle_step
                    else "of the run grid"))
        if model == "averaged_reynolds":
            knobs = (f"{s.film_nodes} nodes over +-{s.film_zone_width:g} Hertz half widths, "
                     f"{deck.tribology.cavitation} cavitation, " + knobs)
        return f"lubricant given and contact loads planned: {_TRANSIENT[model]} ({knobs})"
    text = ("lubricant given, no contact loads: Blok rigid-piezoviscous film, "
            "which needs no load (Ball eq. 4.3)")
    if model != "steady":
        text += f"; the {model} film needs contact loads, so the steady film stands"
    return text


def run(deck, inputs, res):
    from camtrain.components import MAIN, result_component
    from camtrain.contact.model import CamContact
    from camtrain.contact.products import ContactFilm
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    train, loads = inputs[TrainKinematics], inputs.get(ContactLoad)
    pairs = loads.pairs() if loads is not None else ((MAIN, None),)
    fields = []
    for component, load in pairs:
        film = run_pair(CamContact.from_deck(deck, component), train[component], load, res,
                        result_component(component))
        fields.append((component, film))
    return ContactFilm(tuple(fields), with_load=loads is not None)


def run_pair(contact, kin, load, res, component: str | None = None):
    """Columns and metrics of one pair's film; returns its FilmField."""
    import numpy as np

    from camtrain.contact.hertz import is_line
    from camtrain.formulas.friction import film_parameter

    no_width = load is not None and contact.width is None and is_line(kin)
    if no_width:
        # a line contact's EHL film needs the load per unit width: without the cam width the
        # load-free film is the one that can be computed
        res.warn("no cam.width: the film of the line contact is the load-free Blok film "
                 "(Ball eq. 4.3), not the EHL film under the contact load")
        load = None
    tag = f" ({component} pair)" if component else ""
    film = contact.film(kin, None if load is None else np.maximum(load, 0.0))
    what = "out of contact" if load is not None else "non-Hertzian geometry"
    columns = [("film_min", film.min, "m",
                f"minimum film thickness, {film.method} (NaN: {what}){tag}")]
    if film.central is not None:
        columns.append(("film_central", film.central, "m",
                        f"central film thickness, {film.central_method}{tag}"))
    fin = np.isfinite(film.min)
    finite = np.count_nonzero(fin)
    if finite == fin.size:
        lam = film_parameter(film.min, contact.lubricant.roughness)
    else:
        lam = np.empty(film.min.shape)
        lam.fill(np.nan)
        if finite:
            lam[fin] = film_parameter(film.min[fin], contact.lubricant.roughness)
    columns.append(("lambda", lam, "-", "film parameter h_min / sigma (< 1: boundary regime)"
                    + tag))
    res.add_columns(columns, component)
    k = kin.nose
    res.add_metrics(one_case(film_metrics(kin.theta, film.min, k, tag)), component)
    if not np.isfinite(film.min[k]):
        why = ("the pair carries no load there" if load is not None and not load[k] > 0.0
               else "the contact is not Hertzian there")
        res.warn(f"film_min_at_max_lift is undefined (NaN){tag}: {why}")
    if load is None and not no_width:
        res.warn("film without contact loads: Blok rigid-piezoviscous film (Ball eq. 4.3)")
    if film.steady is not None:
        transient_outputs(film, kin, res, component)
    return film


def film_metrics(theta, h_min, nose: int, tag: str = "") -> list:
    """Smallest finite minimum film and the film at maximum lift, for a run or every case of a
    sweep batch (:class:`camtrain.metric_rows.CaseMetric`)."""
    import numpy as np


    fin = np.isfinite(h_min)
    i = np.where(fin, h_min, np.inf).argmin(axis=-1)
    return [CaseMetric("film_min", at(h_min, i), "m", "smallest minimum film over the cycle"
                       + tag, at(theta, i), anywhere(fin)),
            CaseMetric("film_min_at_max_lift", at(h_min, nose), "m",
                       "minimum film at the maximum-lift position (Ball Tables 5.1-5.3)" + tag,
                       at(theta, nose))]


def transient_outputs(film, kin, res, component: str | None = None) -> None:
    """Columns, metrics, events and warnings of a transient film law (docs/transient_film.md)."""
    from functools import partial

    import numpy as np

    from camtrain.contact.transient import REGIME_CODES, periodic

    tag = f" ({component} pair)" if component else ""
    col = partial(res.add_column, component=component)
    met = partial(res.add_metric, component=component)
    theta = np.asarray(kin.theta, dtype=float)
    col("film_steady", film.steady, "m",
        "steady EHL film of the same angles, without squeeze (NaN: out of contact)" + tag)
    loaded = np.isfinite(film.min)
    # at the zero itself the steady film is 0: the film there is the law's own (before a floor
    # that only the neighbouring angles' steady films would set)
    own = getattr(film.solution, "own", film.min)
    if np.any(loaded):
        i = int(np.nanargmax(np.where(loaded, film.min, np.nan)))
        met("film_max", film.min[i], "m", "largest film over the loaded cycle (on a flank)" + tag,
            theta[i])
    zeros = _zero_entrainment_angles(theta, kin.entrainment)
    for j, angle in enumerate(zeros):
        h = float(np.interp(angle, theta, np.where(loaded, own, np.nan), period=2.0 * np.pi))
        met(f"film_at_zero_entrainment_{j + 1}", h, "m",
            "transient film where the entrainment passes through zero (the steady film is 0 "
            "there)" + tag, angle)
    sol = film.solution
    if hasattr(sol, "cycle"):     # the elastic film (its own record)
        return elastic_outputs(film, kin, res, component)
    if film.regime is None:       # level 1: its squeeze ratio
        march = sol
        met("film_cycles", march.cycles, "-", "cam revolutions marched to the periodic film"
            + tag)
        return
    tf, grid = sol.film, sol.grid

    def on_run(v):
        return np.where(loaded, periodic(v, grid, theta), np.nan)

    col("film_transient", sol.own, "m",
        "averaged Reynolds minimum film before the steady-film floor (NaN: out of contact)" + tag)
    col("film_regime", [REGIME_CODES[r] for r in film.regime], "-",
        "lubrication regime: 0 hydrodynamic, 1 mixed, 2 boundary (asperity share <= 1 %, "
        "between, >= 90 %), 3 separated" + tag)
    load = tf.fluid_load + tf.asperity_load
    share = np.where(load > 0.0, tf.asperity_load / np.where(load > 0.0, load, 1.0), 0.0)
    col("asperity_load_share", on_run(share), "-",
        "share of the contact load carried by asperities (Greenwood-Tripp)" + tag)
    col("film_pressure_max", on_run(tf.pressure_max), "Pa",
        "peak fluid pressure of the averaged Reynolds film" + tag)
    col("asperity_pressure_max", on_run(tf.asperity_pressure_max), "Pa",
        "peak Greenwood-Tripp asperity pressure" + tag)
    col("squeeze_velocity", on_run(tf.film_rate), "m/s",
        "dh_min/dt of the marched film (< 0: approach)" + tag)
    met("film_balance_error_max", float(np.nanmax(np.where(np.isnan(tf.balance_error), 0.0,
                                                            tf.balance_error))), "-",
        "largest load-balance error |W - W_P - W_A|/W of the film march" + tag)
    met("film_cycles", tf.cycles, "-", "cam revolutions marched to the periodic film" + tag)
    prev = film.regime[-1]
    for i, label in enumerate(film.regime):
        if label != prev:
            res.add_event("regime", float(theta[i]), f"film regime {prev} -> {label}",
                          component=component)
        prev = label
    missed = np.nan_to_num(tf.balance_error) > sol.tolerance
    if np.any(missed):
        res.warn(f"averaged Reynolds film{tag}: the load balance misses its tolerance at "
                 f"{int(np.count_nonzero(missed))} march angles (largest error "
                 f"{np.nanmax(tf.balance_error):.3g}; the root sits on the jump between the "
                 "single-zone and multi-zone pressure solvers: more solver.film_nodes shrink it)")
    if np.any(tf.unbalanced):
        res.warn(f"averaged Reynolds film{tag}: the load exceeds what the film carries above its "
                 f"floor at {int(np.count_nonzero(tf.unbalanced))} march angles (labelled "
                 "boundary)")
    clamped = int(np.count_nonzero(tf.clamped_nodes))
    if clamped:
        res.warn(f"averaged Reynolds film{tag}: flow factors clamped to their fit range "
                 f"(h/sigma < 0.5) at {clamped} march angles")


def _zero_entrainment_angles(theta, u) -> list[float]:
    """Angles where the periodic entrainment changes sign (linear interpolation)."""
    import numpy as np

    u = np.asarray(u, dtype=float)
    nxt = np.roll(u, -1)
    t_next = np.roll(theta, -1).copy()
    t_next[-1] += 2.0 * np.pi
    out = []
    for i in np.flatnonzero((u == 0.0) | (np.sign(u) * np.sign(nxt) < 0)):
        a = theta[i] if u[i] == 0.0 else theta[i] + u[i] / (u[i] - nxt[i]) * (t_next[i]
                                                                               - theta[i])
        out.append(float(a))
    return out


def cases_refused(deck, swept: tuple[str, ...]) -> str:
    """Why :func:`run_cases` cannot take this deck's cases ("" when it can): it computes the
    steady EHL film under a contact load of a contact with a width."""
    model = deck.tribology.film_model
    if model != "steady":
        return f"the {model} film is marched over the cycle case by case"
    if deck.spring is None or deck.masses is None or deck.cam.width is None:
        return "the load-free Blok film (no contact load or no cam.width) runs case by case"
    return ""


def run_cases(deck, inputs, cases):
    """:func:`run` over a leading case axis (:class:`camtrain.assemble.cases.Cases`): the main
    pair's steady film of every case by its contact model, and the metrics."""
    from camtrain.components import MAIN
    from camtrain.contact.products import ContactFilm
    from camtrain.loads.product import ContactLoad
    from camtrain.mechanisms.base import TrainKinematics

    kin = inputs[TrainKinematics].main
    film = cases.contact.film(kin, inputs.get(ContactLoad).carried)
    cases.add_metrics(film_metrics(kin.theta, film.min, kin.nose))
    return ContactFilm(((MAIN, film),), with_load=True)


def elastic_outputs(film, kin, res, component: str | None = None) -> None:
    """Columns, metrics, the film map and warnings of the elastic film (docs/ehl.md)."""
    import numpy as np

    from camtrain.contact.transient import REGIME_CODES, periodic

    tag = f" ({component} pair)" if component else ""
    sol = film.solution
    cyc, grid = sol.cycle, sol.grid
    theta = np.asarray(kin.theta, dtype=float)
    loaded = np.isfinite(film.min)

    def on_run(v):
        return np.where(loaded, periodic(v, grid, theta), np.nan)

    share = on_run(cyc.asperity_share)
    res.add_columns([
        ("film_regime", [REGIME_CODES[r] for r in film.regime], "-",
         "lubrication regime: 0 hydrodynamic, 1 mixed, 2 boundary (asperity share <= 1 %, "
         "between, >= 90 %), 3 separated" + tag),
        ("asperity_load_share", share, "-",
         "share of the contact load carried by asperities (Greenwood-Tripp)" + tag),
        ("film_pressure_max", on_run(cyc.p_max), "Pa",
         "peak fluid pressure of the elastic film" + tag),
        ("asperity_pressure_max", on_run(cyc.asperity_pressure_max), "Pa",
         "peak Greenwood-Tripp asperity pressure of the elastic film" + tag),
        ("film_pressure_over_hertz", on_run(cyc.p_max / cyc.p_hertz), "-",
         "peak fluid pressure of the elastic film over the dry Hertz pressure" + tag),
    ], component)
    ok = np.isfinite(cyc.h_min)
    rows = [("film_balance_error_max", float(np.nanmax(np.where(ok, cyc.mass_error, 0.0))), "-",
             "largest mass-balance error of a step of the elastic film" + tag),
            ("film_period_error", cyc.period_error, "-",
             "change of the central film over one revolution of the elastic film" + tag),
            ("film_newton_iterations", float(cyc.iterations.sum()), "-",
             "Newton iterations of the elastic film over the cycle" + tag),
            ("film_pressure_max_cycle", float(np.nanmax(cyc.p_max)), "Pa",
             "largest fluid pressure of the elastic film over the cycle" + tag)]
    res.add_metrics(rows, component)
    res.add_columns([(column, sol.formulas[formula], "m",
                      f"{what} of the march's load per width, radius, |mean entrainment|, oil "
                      f"and modulus, steady (0: no entrainment; NaN: out of contact){tag}")
                     for column, formula, what in FORMULA_COLUMNS], component)
    _film_map(res, cyc, grid, component, tag)
    if cyc.restarts:
        angles = ", ".join(f"{np.degrees(grid[k]):.1f}" for k in cyc.restarts[:5])
        res.warn(f"elastic film{tag}: the march restarted from the steady solution at "
                 f"{len(cyc.restarts)} angles ({angles} deg ...): the inputs (radius, load) "
                 "jump there faster than the time step follows")


def _film_map(res, cyc, grid, component, tag) -> None:
    """The film map (angle x position) on an axis of its own, one row per (angle, position):
    cycle_<axis>.csv in the outputs."""
    import numpy as np

    keep = np.isfinite(cyc.map_h).all(axis=1)
    if not np.any(keep):
        return
    nodes = cyc.map_h.shape[1]
    axis = "film_map_point" if component is None else f"{component}_film_map_point"
    res.add_axis(axis, np.arange(int(keep.sum()) * nodes, dtype=float), "-",
                 "row of the elastic film map (angle, position)" + tag)
    angle = np.repeat(grid[keep], nodes)
    for name, values, unit, what in (
            ("film_map_angle", angle, "rad", "cam angle of the film map row"),
            ("film_map_x", cyc.map_x[keep].ravel(), "m",
             "position along the contact (in the rolling direction, from the contact point)"),
            ("film_map_film", cyc.map_h[keep].ravel(), "m", "film thickness h(x)"),
            ("film_map_pressure", cyc.map_p[keep].ravel(), "Pa", "fluid pressure p(x)")):
        res.add_column(name, values, unit, what + tag, component=component, axis=axis)
