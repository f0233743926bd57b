"""The exported JSON Schema (`camtrain schema`) accepts every shipped deck and template of every
kind, and rejects each invalid deck that camtrain rejects for a reason a schema can state:
both are run over the same cases."""
from __future__ import annotations

import copy
import dataclasses
import json
import tomllib

import pytest
from click.testing import CliRunner

jsonschema = pytest.importorskip("jsonschema")

from camtrain.catalogue import KINDS  # noqa: E402
from camtrain.cli import MECHANISM_CHOICES, main  # noqa: E402
from camtrain.deck.fields import section_fields  # noqa: E402
from camtrain.deck.jsonschema import deck_json_schema, kind_schema  # noqa: E402
from camtrain.deck.load import validate  # noqa: E402
from camtrain.deck.templates import render_template  # noqa: E402
from camtrain.errors import InputError  # noqa: E402
from camtrain.units import UNITS  # noqa: E402
from tests.conftest import DECKS  # noqa: E402


@pytest.fixture(scope="module")
def validator():
    """The schema exactly as `camtrain schema` prints it."""
    res = CliRunner().invoke(main, ["schema"])
    assert res.exit_code == 0, res.output
    schema = json.loads(res.output)
    jsonschema.Draft202012Validator.check_schema(schema)
    return jsonschema.Draft202012Validator(schema)


def _errors(validator, raw) -> list[str]:
    return [e.message for e in validator.iter_errors(raw)]


def _raw(name: str) -> dict:
    return tomllib.loads((DECKS / name).read_text(encoding="utf-8"))


SHIPPED = sorted(p.name for p in DECKS.glob("*.toml"))


@pytest.mark.parametrize("deck", SHIPPED)
def test_every_shipped_deck_validates(validator, deck):
    raw = _raw(deck)
    validate(raw, deck, DECKS)        # camtrain accepts it ...
    assert _errors(validator, raw) == []      # ... and so does the schema


@pytest.mark.parametrize("mechanism", MECHANISM_CHOICES)
def test_every_template_validates_and_names_the_schema(validator, mechanism):
    text = render_template(mechanism)
    assert text.startswith("#:schema ./camtrain-deck.schema.json\n")
    raw = tomllib.loads(text)
    validate(raw, mechanism)
    assert _errors(validator, raw) == []


def test_schema_covers_every_kind_and_explicit_valve_train(validator):
    schema = deck_json_schema()
    assert set(schema["$defs"]) == set(KINDS)
    raw = _raw("harrison_flat.toml")
    raw["kind"] = "valve_train"
    validate(raw, "x")
    assert _errors(validator, raw) == []


def _section_classes(cls, seen=None):
    seen = seen if seen is not None else []
    if cls not in seen:
        seen.append(cls)
        for _, shape, _ in section_fields(cls):
            if shape.section is not None:
                _section_classes(shape.section, seen)
    return seen


@pytest.mark.parametrize("kind", list(KINDS))
def test_defaults_are_written_in_deck_units(kind):
    """Every field with a plain default carries it as a ``default`` keyword, in deck units."""
    import importlib

    from camtrain.deck.jsonschema import section_schema

    module, name = KINDS[kind].schema.split(":")
    checked = 0
    for cls in _section_classes(getattr(importlib.import_module(module), name)):
        props = section_schema(cls)["properties"]
        for f, shape, info in section_fields(cls):
            d = f.default
            if d is dataclasses.MISSING or d is None or dataclasses.is_dataclass(d):
                continue
            key = info.key or f.name
            assert "default" in props[key], f"{cls.__name__}.{key}"
            if shape.kind == "number" and not isinstance(d, bool):
                assert props[key]["default"] == pytest.approx(d / UNITS[info.unit][0], rel=1e-12)
            checked += 1
    assert checked > 0
    assert kind_schema(kind)["properties"]["kind"]["enum"] == [kind]


def _set(raw, path, value):
    *head, last = path.split(".")
    for k in head:
        raw = raw.setdefault(k, {})
    if value is _DELETE:
        del raw[last]
    else:
        raw[last] = value


_DELETE = object()
NINE = [-60.0, -45.0, -30.0, -15.0, 0.0, 15.0, 30.0, 45.0, 60.0]

#: (case, base deck or template, [(dotted path, new value or _DELETE)])
INVALID = [
    ("four_power form without its section", "harrison_flat.toml",
     [("lift.four_power", _DELETE)]),
    ("both camshaft and engine speed", "harrison_flat.toml", [("speed.engine", 5000.0)]),
    ("no speed at all", "harrison_flat.toml", [("speed.camshaft", _DELETE)]),
    ("section of another lift form", "harrison_flat.toml",
     [("lift.multipol", {"segments": [{"length": 60.0, "coefficients": [1.0, 0, 0, 0, 0]}]})]),
    ("unknown top-level key", "harrison_flat.toml", [("bogus", 1)]),
    ("unknown kind", "harrison_flat.toml", [("kind", "valvetrain")]),
    ("number given as text", "harrison_flat.toml", [("cam.base_radius", "18")]),
    ("bound violated", "harrison_flat.toml", [("cam.base_radius", -18.0)]),
    ("bad choice", "harrison_flat.toml", [("mechanism.type", "bucket")]),
    ("flat follower with a radius", "harrison_flat.toml", [("mechanism.follower_radius", 50.0)]),
    ("offset on a non-domed follower", "harrison_flat.toml", [("mechanism.offset", 2.0)]),
    ("finger without its pivot geometry", "pinto_finger.toml", [("mechanism.kappa", _DELETE)]),
    ("desmodromic without its closing pair", "desmo_rig.toml", [("mechanism.closing", _DELETE)]),
    ("roller finger without layout or pivot geometry", "roller_finger.toml",
     [("mechanism.layout", _DELETE)]),
    ("cylindrical valve pad without its width", "roller_finger.toml",
     [("mechanism.arm.pad_width", _DELETE)]),
    ("roller section on a sliding follower", "roller_finger.toml",
     [("mechanism.follower", "sliding")]),
    ("layout on a translating follower", "roller_finger.toml", [("mechanism.type", "domed")]),
    ("viscosity fit without temperature and points", "harrison_flat.toml",
     [("lubricant.viscosity", _DELETE), ("lubricant.viscosity_fit", "two_point")]),
    ("no viscosity at all", "harrison_flat.toml", [("lubricant.viscosity", _DELETE)]),
    ("lift table angles without lifts", "harrison_flat.toml",
     [("lift", {"form": "table", "table": {"angles": NINE}})]),
    ("lift table with two sources", "harrison_flat.toml",
     [("lift", {"form": "table", "table": {"dataset": "zeta_intake", "angles": NINE,
                                           "lifts": [0.0, 1, 4, 8, 9, 8, 4, 1, 0.0]}})]),
    ("push rod simple layout without its tappet distance", "template:pushrod",
     [("mechanism.pushrod.tappet_axis_distance", _DELETE)]),
    ("bank-2 lobe without the V angle", "pinto_camshaft.toml", [("camshaft.lobes", "bank2")]),
    ("bearing deck with a valve-train section", "bearing_ocvirk_check.toml",
     [("cam", {"base_radius": 18.0})]),
    ("bearing deck with journal speed 0", "bearing_ocvirk_check.toml", [("speed.journal", 0.0)]),
    ("bearing deck without its load", "bearing_ocvirk_check.toml", [("load", _DELETE)]),
    ("valve-train section in a bearing deck named valve_train", "bearing_ocvirk_check.toml",
     [("kind", "valve_train")]),
]


def test_valid_table_deck_passes_both(validator):
    raw = _raw("harrison_flat.toml")
    raw["lift"] = {"form": "table", "table": {"angles": NINE,
                                              "lifts": [0.0, 1, 4, 8, 9, 8, 4, 1, 0.0]}}
    validate(raw, "t")
    assert _errors(validator, raw) == []


@pytest.mark.parametrize("case, base, edits", INVALID, ids=[c[0] for c in INVALID])
def test_camtrain_and_schema_both_reject(validator, case, base, edits):
    raw = tomllib.loads(render_template(base.split(":")[1])) if base.startswith("template:") \
        else _raw(base)
    raw = copy.deepcopy(raw)
    for path, value in edits:
        if value == "bank2":        # the first lobe moved to the other bank of a V engine
            raw["camshaft"]["lobes"][0]["bank"] = 2
            raw["camshaft"].pop("v_angle", None)
            continue
        _set(raw, path, value)
    with pytest.raises(InputError):
        validate(raw, case, DECKS)
    assert _errors(validator, raw), f"the schema accepts: {case}"


def test_bank_two_lobe_with_v_angle_passes_both(validator):
    raw = _raw("pinto_camshaft.toml")
    raw["camshaft"]["lobes"][0]["bank"] = 2
    raw["camshaft"]["v_angle"] = 60.0
    validate(raw, "v", DECKS)
    assert _errors(validator, raw) == []


def test_every_shipped_deck_names_the_schema_file_shipped_beside_it():
    """Editors (taplo, Even Better TOML) validate a deck against the file its `#:schema` line
    names, relative to the deck: decks/camtrain-deck.schema.json, which is what `camtrain
    schema --out decks/camtrain-deck.schema.json` writes today."""
    from camtrain.deck.jsonschema import SCHEMA_FILE

    for deck in DECKS.glob("*.toml"):
        assert deck.read_text(encoding="utf-8").startswith(f"#:schema ./{SCHEMA_FILE}\n"), deck
    shipped = json.loads((DECKS / SCHEMA_FILE).read_text(encoding="utf-8"))
    assert shipped == deck_json_schema(), "rerun camtrain schema --out decks/" + SCHEMA_FILE
