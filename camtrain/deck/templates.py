"""Ball-style template decks: every field prompted, with its unit and default, ready to edit.

The text is generated from the schema, so a template always matches what `check` accepts. Example
values per mechanism come from the data sets of the sources (Harrison, Pinto, Rover).
"""
from __future__ import annotations

import dataclasses
import json

from camtrain.deck.fields import REQUIRED, FieldInfo, Shape, deck_key, section_fields
from camtrain.deck.jsonschema import SCHEMA_FILE
from camtrain.deck.schema import LIFT_FORMS, MECHANISMS, Deck

_HARRISON_LIFT = {
    "lift.form": "four_power",
    "lift.ramps.opening_height": 0.5, "lift.ramps.opening_length": 25.0,
    "lift.ramps.closing_height": 0.5, "lift.ramps.closing_length": 25.0,
    "lift.four_power.half_period": 60.0, "lift.four_power.max_lift": 8.9,
    "lift.four_power.exponents": [2, 9, 78, 80],
    "lift.four_power.coefficients": [-11.6918407, 2.8498942, -0.5894568, 0.5314033],
}
_HARRISON_LOADS = {
    "spring.rate": 38.254, "spring.preload_compression": 6.4, "masses.valve_side": 0.172,
    "lubricant.viscosity": 0.05, "lubricant.pressure_viscosity": 22.0,
    "clearance.valve_clearance": 0.4,
}

#: Ball (1988) App F.1.1 valve-lift multipol of the desmodromic rig, segment 3 C4 sign corrected
_APP_F_SEGMENTS = [
    {"length": 3.0, "coefficients": [0.03700, 0.0, 0.04894, -0.01224, 0.0]},
    {"length": 8.0, "coefficients": [0.35969, 0.52204, 0.0, 0.0, 0.0]},
    {"length": 5.0, "coefficients": [0.87736, 0.20392, 0.0, -0.08113, 0.02828]},
    {"length": 5.0, "coefficients": [1.10212, 0.0, -0.04167, 0.02153, -0.00490]},
    {"length": 34.0, "coefficients": [7.06324, -2.07447, -1.44115, 0.34428, 0.00640]},
]

#: Example values (deck units) per mechanism; sections with any example are written active.
EXAMPLES: dict[str, dict[str, object]] = {
    "flat": {"title": "Cam and flat-faced follower (Harrison data, Ball 1988)",
             "speed.camshaft": 2500.0, "mechanism.type": "flat", "cam.base_radius": 18.0,
             "cam.width": 12.0, **_HARRISON_LIFT, **_HARRISON_LOADS},
    "domed": {"title": "Cam and domed tappet (Harrison lift)", "speed.camshaft": 2500.0,
              "mechanism.type": "domed", "mechanism.follower_radius": 250.0,
              "mechanism.offset": 0.0, "cam.base_radius": 18.0, "cam.width": 12.0,
              **_HARRISON_LIFT, **_HARRISON_LOADS},
    "finger": {"title": "Ford Pinto inlet cam and end-pivoted finger follower (Ball 1988)",
               "speed.camshaft": 2500.0, "mechanism.type": "finger",
               "mechanism.rotation": "anticlockwise",
               "mechanism.follower_radius": 44.0, "mechanism.A": 51.80, "mechanism.B": 61.80,
               "mechanism.D": 46.20, "mechanism.kappa": 39.7, "mechanism.lambda": 31.9,
               "cam.base_radius": 15.0, "cam.width": 21.0,
               # Ball App E: the Pinto cam lift itself (as seen by the 44 mm follower), not a
               # lift law of another engine, so the flank stays convex and the film real
               "lift.form": "table", "lift.measured_at": "cam", "lift.inspection_radius": 44.0,
               "lift.table.dataset": "pinto_inlet_cam",
               "lift.table.derivative": "smoothing_spline",
               "spring.rate": 40.0, "spring.preload_compression": 11.0,
               "masses.valve_side": 0.148, "clearance.valve_clearance": 0.4,
               "lubricant.viscosity": 0.013, "lubricant.pressure_viscosity": 22.0},
    "rocker": {"title": "Cam and centrally pivoted rocker (Rover 2300, Ball 1988)",
               "speed.camshaft": 2500.0, "mechanism.type": "rocker",
               "mechanism.follower_radius": 35.56, "mechanism.A": 50.06, "mechanism.B": 54.00,
               "mechanism.D": 74.27, "mechanism.kappa": 107.5, "mechanism.lambda": 140.0,
               "cam.base_radius": 14.30, "cam.width": 17.0, "lift.form": "exp_poly",
               "lift.exp_poly.coefficients": [2.317111, -0.8104e-3, -1.526837, -0.1552985,
                                              -1.789897, 0.1171634, -0.2422081],
               "lift.exp_poly.cutoff": 1e-4, "spring.rate": 60.0,
               "spring.preload_compression": 4.0, "masses.valve_side": 0.10,
               "lubricant.viscosity": 0.013, "lubricant.pressure_viscosity": 15.0,
               "materials.cam_poisson": 0.3, "materials.follower_poisson": 0.3},
    "pushrod": {"title": "Push rod, rocker and domed tappet (Harrison lift)",
                "speed.camshaft": 2500.0, "mechanism.type": "pushrod",
                "mechanism.follower_radius": 250.0, "mechanism.pushrod.layout": "simple",
                "mechanism.pushrod.rocker_pushrod_arm": 35.0,
                "mechanism.pushrod.rocker_valve_arm": 50.0,
                "mechanism.pushrod.rocker_arm_angle": 10.0,
                "mechanism.pushrod.valve_axis_angle": 15.0,
                "mechanism.pushrod.pushrod_length": 200.0,
                "mechanism.pushrod.tappet_axis_distance": 40.66,
                "cam.base_radius": 20.0, "cam.width": 12.0, **_HARRISON_LIFT,
                **_HARRISON_LOADS},
    "desmodromic": {"title": "Desmodromic valve train (rig of Ball 1988, App F)",
                    "speed.camshaft": 2000.0, "mechanism.type": "desmodromic",
                    "mechanism.follower_radius": 35.0, "mechanism.A": 26.23,
                    "mechanism.B": 33.29, "mechanism.D": 39.32, "mechanism.kappa": 172.69,
                    "mechanism.lambda": 125.28, "mechanism.closing.A": 17.32,
                    "mechanism.closing.B": 32.39, "mechanism.closing.D": 39.32,
                    "mechanism.closing.kappa": -7.31, "mechanism.closing.lambda": 9.41,
                    "mechanism.closing.follower_radius": 20.0,
                    "mechanism.closing.base_radius": 25.0, "cam.base_radius": 17.5,
                    "cam.width": 12.0, "lift.form": "multipol",
                    "lift.ramps.opening_height": 0.3333,
                    "lift.multipol.segments": _APP_F_SEGMENTS,
                    "spring.rate": 10.0, "spring.preload_compression": 5.0,
                    "masses.valve_side": 0.0745, "lubricant.viscosity": 0.0147,
                    "lubricant.pressure_viscosity": 15.0},
}

#: A roller finger follower of assumed, typical current dimensions (decks/roller_finger.toml)
_RFF_LOADS = {
    "lift.form": "polynomial", "lift.polynomial.half_period": 62.0,
    "lift.polynomial.max_lift": 9.0, "lift.polynomial.exponents": [2, 8, 14, 20, 26],
    "spring.rate": 28.0, "spring.preload_compression": 8.0, "masses.valve_side": 0.075,
    "masses.rocker_inertia": 2.5e-5, "clearance.lash_adjuster": True,
    "clearance.adjuster_load": 20.0, "lubricant.viscosity": 0.0099,
    "lubricant.pressure_viscosity": 22.0,
}
_ARM = {"mechanism.arm.pad_radius": 12.0, "mechanism.arm.pad_width": 5.5,
        "mechanism.arm.pad_friction": 0.1, "mechanism.arm.pivot_radius": 4.0,
        "mechanism.arm.pivot_friction": 0.1}
#: Roller followers: template names beyond the mechanism types (each names its type)
EXAMPLES.update({
    "roller_finger": {
        "title": "Roller finger follower on a lash adjuster (assumed current dimensions)",
        "speed.camshaft": 1500.0, "mechanism.type": "finger", "mechanism.follower": "roller",
        "mechanism.follower_radius": 8.75, "mechanism.layout.pivot": [-32.0, -29.0],
        "mechanism.layout.roller_centre": [0.0, -25.75],
        "mechanism.layout.pad_centre": [20.0, -28.0], "mechanism.layout.valve_direction": -90.0,
        "mechanism.roller.mass": 0.012, **_ARM, "cam.base_radius": 17.0, "cam.width": 9.0,
        **_RFF_LOADS},
    "roller_rocker": {
        "title": "Centre-pivot roller rocker (assumed dimensions)",
        "speed.camshaft": 1500.0, "mechanism.type": "rocker", "mechanism.follower": "roller",
        "mechanism.follower_radius": 8.75, "mechanism.layout.pivot": [25.0, 32.0],
        "mechanism.layout.roller_centre": [0.0, 25.75],
        "mechanism.layout.pad_centre": [62.0, 27.0], "mechanism.layout.valve_direction": -90.0,
        "mechanism.roller.mass": 0.012, **_ARM, "mechanism.arm.pad_shape": "spherical",
        "mechanism.arm.pad_width": None, "cam.base_radius": 17.0, "cam.width": 9.0,
        **_RFF_LOADS, "masses.rocker_inertia": 6.0e-5},
    "roller_tappet": {
        "title": "Roller tappet (direct-acting translating roller; Harrison lift)",
        "speed.camshaft": 1500.0, "mechanism.type": "domed", "mechanism.follower": "roller",
        "mechanism.follower_radius": 12.0, "cam.base_radius": 18.0, "cam.width": 12.0,
        **_HARRISON_LIFT, **_HARRISON_LOADS},
    "pushrod_roller": {
        "title": "Push rod, rocker and roller lifter (Harrison lift)",
        "speed.camshaft": 1500.0, "mechanism.type": "pushrod", "mechanism.follower": "roller",
        "mechanism.follower_radius": 12.0, "mechanism.pushrod.layout": "simple",
        "mechanism.pushrod.rocker_pushrod_arm": 35.0,
        "mechanism.pushrod.rocker_valve_arm": 50.0,
        "mechanism.pushrod.rocker_arm_angle": 10.0,
        "mechanism.pushrod.valve_axis_angle": 15.0,
        "mechanism.pushrod.pushrod_length": 200.0,
        "mechanism.pushrod.tappet_axis_distance": 40.66,
        "cam.base_radius": 20.0, "cam.width": 12.0, **_HARRISON_LIFT, **_HARRISON_LOADS},
})
EXAMPLES["roller_rocker"] = {k: v for k, v in EXAMPLES["roller_rocker"].items() if v is not None}


def _fmt(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_fmt(v) for v in value) + "]"
    return str(value)


def _deck_default(value: object, info: FieldInfo) -> object:
    """A schema default (SI) shown in deck units."""
    from camtrain.units import UNITS

    factor = UNITS[info.unit][0]
    if isinstance(value, float) and factor != 1.0:
        return round(value / factor, 12)
    return value


def _not_here(info: FieldInfo, mechanism: str) -> bool:
    """True when a field names the mechanisms it applies to and this is not one of them."""
    applies = {a.strip() for a in info.applies.split(",")} if info.applies else set()
    return bool(applies & set(MECHANISMS)) and mechanism not in applies


def _prompt(info: FieldInfo, shape: Shape, default: object, mechanism: str) -> str:
    unit = f" [{info.unit}]" if info.unit != "-" else ""
    if default is REQUIRED:
        status = "required"
    elif default is None or default == ():
        status = "optional"
    else:
        status = f"default {_fmt(_deck_default(default, info))}"
    text = f"# {info.doc}{unit} ({status})"
    if shape.kind == "choice":
        text += "\n#   choices: " + ", ".join(_fmt(c) for c in shape.choices)
    if info.applies:
        mark = " -- does not apply here, skip" if _not_here(info, mechanism) else ""
        text += f"\n#   for {info.applies} only{mark}"
    return text


#: The stand-alone bearing template: the Ocvirk check case (constant 500 N on a 25 x 18 mm
#: short bearing; formulas reference §4.3), so a fresh template runs and can be verified.
BEARING_EXAMPLE: dict[str, object] = {
    "kind": "journal_bearing", "title": "Journal bearing under a load diagram (Ocvirk check)",
    "bearing.diameter": 25.0, "bearing.length": 18.0, "bearing.clearance": 0.025,
    "bearing.viscosity": 0.01, "speed.journal": 1500.0,
    "load.angles": [0.0, 90.0, 180.0, 270.0], "load.load_x": [0.0, 0.0, 0.0, 0.0],
    "load.load_y": [-500.0, -500.0, -500.0, -500.0],
    # the check reproduces Ocvirk's closed form, so it names the short film; a new bearing
    # leaves model at its default (auto: the finite film above land b/d 0.05)
    "solver.model": "short",
}


def render_bearing_template() -> str:
    """A complete, commented ``kind = "journal_bearing"`` deck that `camtrain check` accepts."""
    from camtrain.deck.bearing_schema import BearingDeck

    lines = [
        f"# camtrain deck: {BEARING_EXAMPLE['title']}",
        "# Every field has a prompt: what it is [unit in this file] (required / default / "
        "optional).",
        "# Loads are the force the journal puts on the bearing, in the bush frame, one value "
        "per angle;",
        "# the diagram repeats every load.period. Units are the ones written here; SI inside.",
        "# Check it with `camtrain check FILE`, run it with `camtrain run FILE --out DIR`.",
        "",
    ]
    _render_section(BearingDeck, "", BEARING_EXAMPLE, "journal_bearing", lines, active=True)
    return "\n".join(lines).rstrip() + "\n"


#: The engine template: Yang's (1992) Ruston 6VEB-X Mk III, complete in his Appendix A
#: (decks/ruston_6veb.toml is the same engine with every source note). Yang's pressure table
#: (bar, read as gauge: 1.21 bar through the gas exchange is the boost of this turbocharged
#: engine) is written absolute, plus one standard atmosphere, the crankcase pressure an
#: absolute table is referred to: the same gauge pressures, stated without ambiguity.
_ATMOSPHERE_BAR = 1.01325
_RUSTON_BAR = [47.37, 64.12, 48.61, 34.82, 25.51, 18.62, 14.48, 11.52, 9.03, 7.59, 6.59, 5.90,
               5.41, 5.00, 4.72, 4.10, 3.14, 2.45, 1.76, 1.41, 1.35] + [1.21] * 38 + [
               1.41, 1.41, 1.76, 2.10, 2.45, 3.14, 4.10, 6.10, 8.65, 12.45, 18.62, 26.55, 34.82]
ENGINE_EXAMPLE: dict[str, object] = {
    "kind": "engine", "title": "Ruston 6VEB-X Mk III crank train (Yang 1992 App. A)",
    "speed.engine": 600.0, "engine.strokes": 4, "engine.bore": 260.35,
    "engine.crank_radius": 184.15, "engine.rod_length": 782.32, "engine.piston_mass": 82.07,
    "engine.rod_mass": 81.62, "engine.bay_lengths": [444.5] * 6, "engine.flywheel_mass": 0.0,
    "cylinders": [{"bay": i + 1, "position": 222.25, "firing_angle": float(a)}
                  for i, a in enumerate((0, 120, 600, 240, 480, 360))],
    "crank_components": [{"bay": i + 1, "position": 222.25, "angle": float(a),
                          "moment": 139.19, "moment_unit": "N·m"}
                         for i, a in enumerate((0, 240, 120, 120, 240, 0))],
    "pressure": [{"speeds": [600.0], "reference": "absolute", "unit": "bar", "angle_step": 10.0,
                  "values": [round(v + _ATMOSPHERE_BAR, 5) for v in _RUSTON_BAR]}],
    **{f"bearings.{b}.{k}": v for b in ("big_end", "main") for k, v in (
        ("diameter", 203.2), ("length", 57.15), ("clearance", 0.08255), ("viscosity", [0.015]))},
    "solver.bearing_model": "short",   # as Yang: reproduces his printed numbers
}


def render_engine_template() -> str:
    """A complete, commented ``kind = "engine"`` deck that `camtrain check` accepts."""
    from camtrain.deck.schema_engine import EngineDeck

    lines = [
        f"# camtrain deck: {ENGINE_EXAMPLE['title']}",
        "# Every field has a prompt: what it is [unit in this file] (required / default / "
        "optional).",
        "# Crank angles are from the firing TDC of cylinder 1 in the sense of rotation; bays "
        "and mains are",
        "# numbered from the front. Units are the ones written here; SI inside.",
        "# Check it with `camtrain check FILE`, run it with `camtrain run FILE --out DIR`.",
        "",
    ]
    _render_section(EngineDeck, "", ENGINE_EXAMPLE, "engine", lines, active=True)
    return "\n".join(lines).rstrip() + "\n"


#: first line of every template: editors (taplo, Even Better TOML) validate the deck against
#: the schema file written by `camtrain schema --out camtrain-deck.schema.json` beside it
SCHEMA_LINE = f"#:schema ./{SCHEMA_FILE}\n"


def render_template(mechanism: str) -> str:
    """A complete, commented deck for ``mechanism`` that `camtrain check` accepts as it is,
    starting with the ``#:schema`` line editors read.

    ``"journal_bearing"`` gives the stand-alone bearing deck instead of a valve train.
    """
    return SCHEMA_LINE + _render_template(mechanism)


def _render_template(mechanism: str) -> str:
    if mechanism == "journal_bearing":
        return render_bearing_template()
    if mechanism == "engine":
        return render_engine_template()
    if mechanism not in EXAMPLES:
        raise KeyError(mechanism)
    ex = EXAMPLES[mechanism]
    lines = [
        f"# camtrain deck: {ex['title']}",
        "# Every field has a prompt: what it is [unit in this file] (required / default / "
        "optional).",
        "# Units are the ones written here (mm, deg, rpm, N/mm, kg, GPa, Pa·s, 1/GPa, µm); "
        "camtrain works in SI inside.",
        "# Cam angles are cam degrees from the maximum-lift (nose) position, negative on the "
        "opening flank.",
        "# Check it with `camtrain check FILE`, run it with `camtrain run FILE --out DIR`.",
        "",
    ]
    _render_section(Deck, "", ex, str(ex["mechanism.type"]), lines, active=True)
    return "\n".join(lines).rstrip() + "\n"


def _has_example(prefix: str, ex: dict) -> bool:
    return any(k.startswith(prefix + ".") for k in ex)


def _render_section(cls: type, prefix: str, ex: dict, mechanism: str, lines: list[str],
                    active: bool) -> None:
    c = "" if active else "# "
    scalars = [(f, s, i) for f, s, i in section_fields(cls) if s.section is None]
    nested = [(f, s, i) for f, s, i in section_fields(cls) if s.section is not None]
    for f, shape, info in scalars:
        key = deck_key(f)
        path = f"{prefix}.{key}" if prefix else key
        lines.append(_prompt(info, shape, _default(f), mechanism))
        if _not_here(info, mechanism) and path not in ex:
            lines.append(f"# {key} =")
        elif path in ex:
            lines.append(f"{c}{key} = {_fmt(ex[path])}")
        elif f.default is not dataclasses.MISSING and f.default not in (None, ()):
            lines.append(f"{c}{key} = {_fmt(_deck_default(f.default, info))}")
        else:
            example = info.example if info.example is not None else ""
            lines.append(f"# {key} = {_fmt(example) if example != '' else ''}".rstrip())
        lines.append("")
    for f, shape, info in nested:
        key = deck_key(f)
        path = f"{prefix}.{key}" if prefix else key
        sub_active = active and (f.default is dataclasses.MISSING or _has_example(path, ex)
                                 or (prefix == "" and f.default is not None))
        if prefix == "lift" and key in LIFT_FORMS:
            sub_active = active and ex.get("lift.form") == key
        if shape.kind == "sections":
            _render_array(shape.section, path, info, ex, mechanism, lines)
            continue
        head = f"{'' if sub_active else '# '}[{path}]"
        note = f"  # {info.doc}"
        if info.applies:
            note += f" (for {info.applies} only; otherwise skip)"
        elif not sub_active:
            note += " (optional; uncomment to use)"
        lines.append("#" + "-" * 78)
        lines.append(head + note)
        lines.append("")
        _render_section(shape.section, path, ex, mechanism, lines, sub_active)


def _render_array(cls: type, path: str, info: FieldInfo, ex: dict, mechanism: str,
                  lines: list[str]) -> None:
    entries = ex.get(path)
    if not entries:
        lines.append(f"# [[{path}]]  # {info.doc}; repeat the block for each entry")
        for f, shape, finfo in section_fields(cls):
            lines.append(_prompt(finfo, shape, _default(f), mechanism))
            lines.append(f"# {deck_key(f)} = ")
        lines.append("")
        return
    lines.append(f"# {info.doc}: one [[{path}]] block per entry")
    for f, shape, finfo in section_fields(cls):
        lines.append(_prompt(finfo, shape, _default(f), mechanism))
    for entry in entries:
        lines.append(f"[[{path}]]")
        lines += [f"{k} = {_fmt(v)}" for k, v in entry.items()]
        lines.append("")


def _default(f: dataclasses.Field) -> object:
    return REQUIRED if f.default is dataclasses.MISSING else f.default
