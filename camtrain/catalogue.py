"""The one catalogue of effects, products and deck kinds: plain data, no physics imported.

Reading this file tells what camtrain can compute. An **effect** is one module (``module``)
exposing three functions::

    missing(deck) -> list[str]            # deck data it lacks ([] = it can run)
    reason(deck, planned) -> str          # why it runs, for the plan; ``planned`` = the product
                                          # names the plan provides (to explain optional inputs)
    run(deck, inputs, result) -> product or tuple of products

``needs`` are the products it cannot run without, ``uses`` optional products it takes when the
plan provides them (its ``reason`` says which way it went), ``produces`` what it returns: the
runner checks the returned objects against these names. Effects never import each other; they
meet only through products. Several effects may offer the same product (rigid-train loads and
dynamic loads; steady and transient film): the plan takes the highest ``rank`` whose data are
present (ties: the first listed) and says why. The order of a run is a topological sort over
products. Modules are imported only when a plan is resolved (their top level imports no numpy)
or run.

A **product** is a frozen dataclass living beside its physics; ``PRODUCTS`` maps its name to
where it lives. A **deck kind** is a schema plus its effects (``KINDS``).
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class EffectSpec:
    """One registered effect (see the module docstring)."""

    name: str
    module: str
    description: str
    needs: tuple[str, ...] = ()
    produces: tuple[str, ...] = ()
    uses: tuple[str, ...] = ()
    rank: int = 0
    #: the metrics an engineer reads first from this effect, in this order: the terminal's and
    #: report.txt's "key results" (those the run produced; every metric is in summary.json)
    key_metrics: tuple[str, ...] = ()
    #: "module:function" drawing this effect's own summary tables for the terminal and
    #: report.txt, ``tables(result, deck) -> [Table]`` (per bearing, per component); "" = none
    summary: str = ""
    #: the plot sheets this effect's products feed, by the names the report registers
    #: (camtrain.report.sheets: SHEETS and OTHER_SHEETS); a sheet is written when an effect
    #: that ran declares it and its panels have something to draw
    sheets: tuple[str, ...] = ()
    #: the cycle panels this effect's products feed, by the names the report registers
    #: (camtrain.report.sheets.PANELS, "profile" for the cam drawn to scale): a cycle sheet
    #: holds those of its panels that an effect that ran declares (a panel may still leave
    #: itself out when the run has none of its curves, e.g. a flat follower's pressure angle)
    panels: tuple[str, ...] = ()
    #: the cycle panels this effect feeds only when it ran a given model, as (model, panels)
    #: pairs: the model is the one its plan step records (``Step.model``, the module's
    #: ``model(deck, planned)``; the film's ``tribology.film_model`` as it ran), so a steady
    #: film declares none of the transient film's panels whatever columns a result holds; an
    #: effect that ran several optional parts records them joined by "+" ("lash_adjuster+roller")
    model_panels: tuple[tuple[str, tuple[str, ...]], ...] = ()
    #: the resolution knobs of ``camtrain accuracy`` that change this effect's numbers, by name
    #: (camtrain.study.accuracy_knobs.KNOBS; a knob's own test on the deck narrows it further)
    knobs: tuple[str, ...] = ()
    #: the metrics ``camtrain accuracy`` reads on every rung when the run produced them;
    #: ``{k}`` stands for a component number (``bearing_{k}_min_film``: every bearing's)
    accuracy_metrics: tuple[str, ...] = ()
    #: sections of report.txt this effect's products feed, by name (camtrain.report.text:
    #: "cycle_table", the per-angle table)
    sections: tuple[str, ...] = ()
    #: "module:function" giving the decks this effect reads the runs of, each run through a
    #: plan of its own before the effect (``included(deck) -> [(name, deck model)]``; the
    #: effect reads ``inputs.included[name]`` = (deck model, Result)); "" = none
    includes: str = ""
    #: findings (event kinds, with the warnings that state them: Result.warn's ``finding``) of
    #: effects that run before this one which this effect owns when it runs: the runner drops
    #: them before it runs, and it states its own (the roller's entrainment replaces the
    #: non-rotating face's "zero_entrainment")
    supersedes: tuple[str, ...] = ()
    #: the columns this effect writes for some decks only that the top floors draw or tabulate
    #: (``{k}`` stands for a number: ``inter_ring_pressure_{k}``): those it writes for a deck
    #: are what its module's optional ``makes(deck, planned)`` names (every one when the
    #: module has none); the plan's step records them (``Step.makes``), and a sheet asks
    #: :func:`makes`, never the result's columns
    optional_columns: tuple[str, ...] = ()
    #: the result components this effect writes, by name (``{k}`` a number: ``bearing_{k}``):
    #: the rows of its summary table and the parts of its sheets (:func:`components_of`)
    components: tuple[str, ...] = ()


#: product name -> "module:Class" (imported by the runner to check what an effect returns)
PRODUCTS: dict[str, str] = {
    "TrainKinematics": "camtrain.mechanisms.base:TrainKinematics",
    "ContactLoad": "camtrain.loads.product:ContactLoad",
    "ContactHertz": "camtrain.contact.products:ContactHertz",
    "ContactFilm": "camtrain.contact.products:ContactFilm",
    "ContactFriction": "camtrain.contact.products:ContactFriction",
    "CamTorque": "camtrain.contact.products:CamTorque",
    "RollerMotion": "camtrain.roller.product:RollerMotion",
    "RollerSpin": "camtrain.dynamics.spin.product:RollerSpin",
    "GuideLosses": "camtrain.contact.guides:GuideLosses",
    "ArmContacts": "camtrain.mechanisms.arm_contacts:ArmContacts",
    "CamshaftLoads": "camtrain.camshaft.product:CamshaftLoads",
    "ElasticCamshaft": "camtrain.camshaft.product:ElasticCamshaft",
    "BearingOrbits": "camtrain.bearings.product:BearingOrbits",
    "CrankLoads": "camtrain.engine.loads:CrankLoads",
    "EngineBearings": "camtrain.engine.crank_bearings:EngineBearings",
    "PistonFriction": "camtrain.piston.product:PistonFriction",
    "ValveTrainFriction": "camtrain.engine.valve_trains:ValveTrainFriction",
    "EngineFriction": "camtrain.engine.flame:EngineFriction",
    "FrictionCorrelations": "camtrain.engine.correlations:FrictionCorrelations",
}

#: the lash adjuster's panels (its sheet), declared by the dynamics effect when its train has one
LASH_ADJUSTER_PANELS = ("adjuster_pressure", "adjuster_extension", "adjuster_lift_loss", "check_flow")

VALVE_TRAIN: tuple[EffectSpec, ...] = (
    EffectSpec("kinematics", "camtrain.effects.kinematics",
               "lift law and follower kinematics: lift and derivatives, contact point, r_c, R, "
               "surface, entrainment and sliding velocities",
               produces=("TrainKinematics",),
               key_metrics=("max_lift", "max_velocity", "min_acceleration", "max_acceleration"),
               panels=("lift", "velocity", "acceleration", "jerk", "eccentricity", "pressure_angle",
                       "velocities", "radii", "profile"),
               sheets=("kinematics", "contact", "profile"), sections=("cycle_table",),
               knobs=("angle_points", "table_smoothing"),
               accuracy_metrics=("cam_radius_at_max_lift", "equivalent_radius_at_max_lift")),
    EffectSpec("loads", "camtrain.effects.loads",
               "contact load from the rigid-train D'Alembert balance; loss of contact",
               needs=("TrainKinematics",), produces=("ContactLoad",),
               key_metrics=("load_max", "load_min", "bounce_speed"),
               panels=("load",), optional_columns=("valve_force",),
               sheets=("contact",), accuracy_metrics=("load_max", "bounce_speed")),
    EffectSpec("dynamics", "camtrain.effects.dynamics",
               "contact load of the elastic train in time: separation, spring surge, valve "
               "seating (replaces the rigid-train load when the deck has [dynamics])",
               needs=("TrainKinematics",), produces=("ContactLoad", "RollerSpin"), rank=1,
               key_metrics=("load_max", "dynamic_load_ratio", "separations", "jumps",
                            "separation_angle", "seat_impacts", "seat_impact_speed_max",
                            "valve_acceleration_max", "roller_slip_max_marched"),
               panels=("load", "dynamic_load", "valve_motion", "valve_acceleration", "spring_forces"),
               optional_columns=("spring_force_retainer",),
               sheets=("contact", "dynamics", "lash_adjuster"),
               model_panels=(("lash_adjuster", LASH_ADJUSTER_PANELS),
                             ("lash_adjuster_ball", LASH_ADJUSTER_PANELS + ("check_lift",)),
                             ("roller", ("roller_spin",))),
               knobs=("steps_per_degree", "spring_elements", "dynamics_rtol",
                      "adjuster_cycles"),
               accuracy_metrics=("load_max", "separation_angle", "hla_pressure_max",
                                 "hla_collapse", "hla_refill", "valve_lift_loss_at_max_lift")),
    EffectSpec("hertz", "camtrain.effects.hertz",
               "Hertz contact half-width and maximum pressure",
               needs=("TrainKinematics", "ContactLoad"), produces=("ContactHertz",),
               key_metrics=("hertz_max", "hertz_at_max_lift"),
               panels=("hertz",),
               sheets=("contact",), accuracy_metrics=("hertz_max",)),
    EffectSpec("roller", "camtrain.effects.roller",
               "roller turning on its pin: speed from its torque balance, slip, slide-roll "
               "ratio, pin loss; film and friction at the roller's speed",
               needs=("TrainKinematics", "ContactLoad", "ContactHertz"),
               uses=("RollerSpin",),
               produces=("RollerMotion", "ContactFilm", "ContactFriction"), rank=1,
               key_metrics=("roller_slip_max", "roller_power_total", "roller_power_pin",
                            "roller_power_rolling", "roller_power_sliding",
                            "film_min_at_max_lift"),
               panels=("film_angle", "film_position", "friction_coefficient", "friction_force"),
               sheets=("roller",), supersedes=("zero_entrainment",),
               knobs=("roller_substeps", "roller_table_points", "roller_tolerance"),
               accuracy_metrics=("roller_slip_max", "roller_power_total", "roller_srr_min")),
    EffectSpec("film", "camtrain.effects.film",
               "lubricant film thickness (EHL with load, Blok rigid-piezoviscous without)",
               needs=("TrainKinematics",), uses=("ContactLoad",), produces=("ContactFilm",),
               key_metrics=("film_min_at_max_lift", "film_min"),
               panels=("film_angle", "film_position"),
               model_panels=(("squeeze", ("transient_film",)),
                             ("averaged_reynolds", ("transient_film", "film_pressures")),
                             ("ehl", ("transient_film", "film_pressures", "elastic_films",
                                      "film_map", "pressure_over_hertz"))),
               optional_columns=("film_steady", "film_transient", "film_dowson_higginson_min",
                                 "film_pan_hamrock_min", "film_pan_hamrock_central",
                                 "film_moes_central", "film_dowson_toyoda_central"),
               sheets=("contact", "transient_film", "elastic_film", "profile"),
               knobs=("film_angle_step", "film_nodes", "film_zone_width", "film_tolerance",
                      "ehl_nodes", "ehl_inlet", "ehl_angle_step", "ehl_tolerance"),
               accuracy_metrics=("film_min_at_max_lift", "film_at_zero_entrainment_1",
                                 "film_max")),
    EffectSpec("friction", "camtrain.effects.friction",
               "friction force and coefficient: viscous shear capped by boundary friction",
               needs=("TrainKinematics", "ContactLoad", "ContactHertz", "ContactFilm"),
               produces=("ContactFriction",),
               key_metrics=("boundary_fraction",),
               panels=("friction_coefficient", "friction_force"),
               sheets=("friction",), knobs=("friction_tolerance",)),
    EffectSpec("power", "camtrain.effects.power",
               "friction torque about the cam axis and power loss",
               needs=("TrainKinematics", "ContactLoad", "ContactFriction"),
               produces=("CamTorque",),
               key_metrics=("power_loss_mean", "friction_torque_peak"),
               panels=("torque", "power"),
               sheets=("friction",), accuracy_metrics=("power_loss_mean",)),
    EffectSpec("guides", "camtrain.effects.guides",
               "follower/guide and valve/guide Couette shear losses (Yang 1992 eq. 3.29)",
               needs=("TrainKinematics",), produces=("GuideLosses",)),
    EffectSpec("arm_contacts", "camtrain.effects.arm_contacts",
               "valve pad (sliding, load, Hertz, friction) and pivot friction of a finger "
               "follower or rocker",
               needs=("TrainKinematics", "ContactLoad"), produces=("ArmContacts",),
               key_metrics=("arm_power_mean",),
               accuracy_metrics=("arm_power_mean", "pad_pressure_max")),
    EffectSpec("camshaft_torque", "camtrain.effects.camshaft",
               "camshaft: lobe torques phased and summed, drive power, harmonic orders, second "
               "bank, pendulum dampers",
               needs=("TrainKinematics", "ContactLoad"), uses=("ContactFriction", "CamTorque"),
               produces=("CamshaftLoads",),
               key_metrics=("drive_power_mean", "camshaft_torque_peak"),
               sheets=("camshaft", "lobes")),
    EffectSpec("camshaft_elastic", "camtrain.effects.camshaft_elastic",
               "elastic camshaft: bending in two planes and torsion under the lobe and drive "
               "loads, bearing reactions, deflections and twist per lobe, orders",
               needs=("CamshaftLoads",),
               produces=("ElasticCamshaft",),
               key_metrics=("shaft_deflection_max", "shaft_twist_max"),
               panels=("shaft_reactions", "shaft_orders", "lobe_loads", "lobe_motion", "lobe_twist"),
               sheets=("camshaft", "lobes"), knobs=("shaft_stations",),
               components=("bearing_{k}",),
               accuracy_metrics=("shaft_deflection_max", "shaft_twist_max",
                                 "bearing_{k}_reaction_max", "bearing_{k}_reaction_order_1",
                                 "bearing_{k}_reaction_order_4")),
    EffectSpec("camshaft_coupled", "camtrain.effects.camshaft_coupled",
               "every lobe's elastic valve train on the elastic camshaft, iterated to one "
               "periodic state: lobe loads, bearing reactions, deflections, twist",
               needs=("TrainKinematics", "ContactLoad", "CamshaftLoads"),
               produces=("ElasticCamshaft",), rank=1,
               key_metrics=("shaft_deflection_max", "shaft_twist_max"),
               panels=("shaft_reactions", "shaft_orders", "lobe_loads", "lobe_motion", "lobe_twist"),
               sheets=("camshaft", "lobes"), components=("bearing_{k}",),
               knobs=("shaft_stations", "steps_per_degree", "coupling_iterations"),
               accuracy_metrics=("shaft_deflection_max", "shaft_twist_max",
                                 "bearing_{k}_reaction_max", "bearing_{k}_reaction_order_1",
                                 "bearing_{k}_reaction_order_4")),
    EffectSpec("bearings", "camtrain.effects.bearings",
               "camshaft bearings: lobe and drive forces split as beams (or by the elastic "
               "shaft), journal orbits (Booker mobility), minimum film and power",
               needs=("CamshaftLoads",), uses=("ElasticCamshaft",), produces=("BearingOrbits",),
               key_metrics=("bearings_power_total",),
               summary="camtrain.report.summaries:bearing_orbits",
               sheets=("camshaft", "orbits"), components=("bearing_{k}",),
               knobs=("bearing_mesh", "bearing_model", "orbit_points"),
               accuracy_metrics=("bearings_power_total", "bearing_{k}_min_film",
                                 "bearing_{k}_max_eccentricity", "bearing_{k}_power_mean",
                                 "bearing_{k}_reaction_max", "bearing_{k}_reaction_order_1",
                                 "bearing_{k}_reaction_order_4")),
)

JOURNAL_BEARING: tuple[EffectSpec, ...] = (
    EffectSpec("journal_bearing", "camtrain.effects.journal_bearing",
               "journal orbit, minimum film and power of one bearing under its load diagram",
               produces=("BearingOrbits",),
               key_metrics=("min_film", "max_eccentricity", "power_mean", "petroff_power"),
               sheets=("orbits",), knobs=("bearing_mesh", "bearing_model"),
               accuracy_metrics=("min_film", "max_eccentricity", "power_mean")),
)

ENGINE: tuple[EffectSpec, ...] = (
    EffectSpec("crank_loads", "camtrain.effects.crank_loads",
               "crank-train loads: gas and inertia forces, side thrust, big-end loads in rod "
               "axes, main-bearing loads by the determinate bay split",
               produces=("CrankLoads",),
               key_metrics=("big_end_max_load",),
               sheets=("engine_loads",), knobs=("crank_step", "pressure_interpolation"),
               components=("big_end_{k}", "main_{k}"),
               accuracy_metrics=("big_end_max_load",)),
    EffectSpec("crank_bearings", "camtrain.effects.crank_bearings",
               "big-end and main bearings: orbits to a periodic cycle, steady and Petroff "
               "columns, minimum film and power per bearing and in total",
               needs=("CrankLoads",), produces=("EngineBearings",),
               key_metrics=("total_power_dynamic",),
               summary="camtrain.report.summaries:crank_bearings",
               sheets=("orbits",), components=("big_end_{k}", "main_{k}"),
               knobs=("bearing_mesh", "bearing_model", "period_tolerance", "step_tolerance",
                      "mobility"),
               accuracy_metrics=("big_end_1_min_film_dynamic", "main_3_min_film_dynamic",
                                 "total_power_dynamic", "total_power_steady")),
    EffectSpec("piston", "camtrain.effects.piston",
               "piston assembly: inter-ring gas, compression-ring films (flooded, then starved "
               "passes), oil-control ring and skirt friction, power of every piston",
               produces=("PistonFriction",),
               key_metrics=("piston_power_mean", "piston_power_total"),
               summary="camtrain.report.summaries:piston_rings",
               sheets=("piston",), components=("ring_{k}",),
               optional_columns=("inter_ring_pressure_{k}", "oil_control_ring_friction",
                                 "skirt_friction"),
               knobs=("piston_crank_step", "ring_tolerance", "pass_tolerance",
                      "gas_tolerance"),
               accuracy_metrics=("piston_power_total", "ring_1_min_film_flooded",
                                 "inter_ring_pressure_1_peak")),
    EffectSpec("valve_trains", "camtrain.effects.valve_trains",
               "valve-train decks included by path, run at the camshaft speed: cams, camshaft "
               "bearings and guides",
               produces=("ValveTrainFriction",),
               key_metrics=("valve_train_power_total",),
               includes="camtrain.assemble.valve_trains:included_valve_trains"),
    EffectSpec("flame", "camtrain.effects.flame",
               "FLAME engine total: bearings + valve trains + pistons + accessories, fmep and "
               "shares",
               uses=("EngineBearings", "ValveTrainFriction", "PistonFriction"),
               produces=("EngineFriction",),
               summary="camtrain.report.summaries:flame",
               accuracy_metrics=("flame_total",)),
    EffectSpec("correlations", "camtrain.effects.correlations",
               "friction correlations: Patton-Nitschke-Heywood 1989 and Sandoval-Heywood 2003 "
               "term by term, Chen-Flynn with the user's constants (beside FLAME, or alone on "
               "a bare engine deck)",
               produces=("FrictionCorrelations",),
               key_metrics=("pnh1989_fmep", "sandoval_heywood2003_fmep", "chen_flynn_fmep"),
               summary="camtrain.report.summaries:correlations", sheets=("correlations",)),
)


@dataclass(frozen=True)
class DeckKind:
    """A deck kind: its top-level ``kind`` name, its schema class ("module:Class") and its
    effects."""

    name: str
    schema: str
    effects: tuple[EffectSpec, ...]
    #: "module:function" giving the header rows of report.txt and the sheets,
    #: ``rows(deck, result) -> [(label with unit, value)]``; "" = the valve-train header
    header: str = ""
    #: "module:function" of the cheap geometry check ``camtrain check`` runs for this kind when
    #: none of its effects is a geometry effect, ``check(deck) -> (what was checked, warnings)``;
    #: it raises GeometryError (exit 3) as ``run`` would
    geometry: str = ""
    #: what report.txt and every sheet of this kind are headed (Ball's "CAM OPERATING
    #: CHARACTERISTICS" for a valve train)
    title: str = "CAM OPERATING CHARACTERISTICS"


#: every deck kind, by the name a deck gives in ``kind = "..."`` (valve_train is the default)
KINDS: dict[str, DeckKind] = {k.name: k for k in (
    DeckKind("valve_train", "camtrain.deck.schema:Deck", VALVE_TRAIN),
    DeckKind("journal_bearing", "camtrain.deck.bearing_schema:BearingDeck", JOURNAL_BEARING,
             header="camtrain.report.bearing_plots:bearing_header_rows",
             title="JOURNAL BEARING UNDER A DYNAMIC LOAD"),
    DeckKind("engine", "camtrain.deck.schema_engine:EngineDeck", ENGINE,
             header="camtrain.report.engine_report:engine_header_rows",
             geometry="camtrain.assemble.engine:check_geometry",
             title="ENGINE BEARINGS AND FRICTION"),
)}
DEFAULT_KIND = "valve_train"


def effect_names(kind: str = DEFAULT_KIND) -> tuple[str, ...]:
    """Names of the effects a deck of ``kind`` may list in ``effects``."""
    return tuple(e.name for e in KINDS[kind].effects)


def declared_effects(plan) -> tuple[EffectSpec, ...]:
    """The specs of the effects a plan ran, in run order, for the top floors to read what they
    declared; a plan read back from a saved result is matched by effect name, and no plan (a
    lift-only run) stands for the valve-train effects."""
    if plan is None:
        return KINDS[DEFAULT_KIND].effects
    by_name = {e.name: e for e in KINDS[plan.kind].effects}
    specs = (s.spec if getattr(s, "spec", None) is not None else by_name.get(s.effect)
             for s in plan.steps if s.chosen)
    return tuple(spec for spec in specs if spec is not None)   # an effect since renamed: none


def planned_products(plan) -> frozenset[str]:
    """The products the effects of a plan made (their ``produces``); none without a plan (a
    lift-only run, which has the lift law's columns alone)."""
    if plan is None:
        return frozenset()
    return frozenset(p for spec in declared_effects(plan) for p in spec.produces)


def makes(plan, column: str) -> bool:
    """Whether an effect of the plan wrote ``column``, one of the optional columns the effects
    declare (EffectSpec.optional_columns; each step records those it writes for its deck,
    ``Step.makes``): what a sheet or table asks before it draws or lists an optional curve.
    No plan (a lift-only run) makes none; a name no effect declares is a ValueError."""
    kind = KINDS[getattr(plan, "kind", None) or DEFAULT_KIND]
    declared = {c for spec in kind.effects for c in spec.optional_columns}
    if not any(_named(column, c) for c in declared):
        raise ValueError(f"{column!r} is not an optional column an effect of the "
                         f"{kind.name} kind declares (EffectSpec.optional_columns)")
    if plan is None:
        return False
    return any(_named(column, c) for step in plan.steps if step.chosen
               for c in getattr(step, "makes", ()))


def components_of(plan, product: str, components) -> list[str]:
    """Those of a result's ``components`` that the effect of the plan making ``product``
    writes (EffectSpec.components), in their order: the bearings of a crank-bearing table, the
    rings of a piston sheet."""
    declared = [c for spec in declared_effects(plan) if product in spec.produces
                for c in spec.components] if plan is not None else []
    return [c for c in components if any(_named(c, d) for d in declared)]


def _named(column: str, declared: str) -> bool:
    """``column`` is ``declared``, or one of its numbered names (``{k}``: 1, 2, ...)."""
    head, k, tail = declared.partition("{k}")
    if not k:
        return column == declared
    number = column[len(head):len(column) - len(tail)] if column.endswith(tail) else ""
    return column.startswith(head) and number.isdigit()


#: the panels of a result without a plan: the lift law's columns alone (``camtrain lift``)
LIFT_PANELS = ("lift", "velocity", "acceleration", "jerk")


def declared_panels(plan) -> frozenset[str]:
    """The cycle panels the effects of a plan declare (EffectSpec.panels, and the
    EffectSpec.model_panels of the model each step records it ran); without a plan (a
    lift-only run) the lift law's, LIFT_PANELS."""
    if plan is None:
        return frozenset(LIFT_PANELS)
    by_name = {e.name: e for e in KINDS[plan.kind].effects}
    panels: set[str] = set()
    for step in plan.steps:
        spec = getattr(step, "spec", None) or by_name.get(step.effect)
        if step.chosen and spec is not None:
            panels.update(spec.panels)
            by_model = dict(spec.model_panels)
            for part in (getattr(step, "model", "") or "").split("+"):
                panels.update(by_model.get(part, ()))
    return frozenset(panels)


def kind_of(deck) -> DeckKind:
    """The deck kind whose schema class ``deck`` is (or derives from)."""
    for cls in type(deck).__mro__:
        path = f"{cls.__module__}:{cls.__qualname__}"
        for kind in KINDS.values():
            if kind.schema == path:
                return kind
    raise TypeError(f"{type(deck).__name__} is not the schema of a registered deck kind")
