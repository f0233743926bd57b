"""Deck mutations for the fuzz tests: every shipped deck and template, damaged the way a user (or a
script) damages a deck, run through `camtrain run`.

Mutation classes (one or more per case): a wrong type, NaN/inf, 0, +-1e300, 1e-300, a unit string
("12 mm"), a missing key or section, an unknown key or section, shuffled and duplicated table rows
(arrays of tables and parallel arrays), and text-level damage of the TOML (a line dropped, doubled
or cut, a bracket inserted).
"""
from __future__ import annotations

import copy
import functools
import math
import random
import tomllib
from pathlib import Path

import tomli_w

ROOT = Path(__file__).resolve().parents[2]
def _template_kinds() -> tuple[str, ...]:
    from camtrain.cli import MECHANISM_CHOICES

    return MECHANISM_CHOICES

JUNK = ("wrong_type", "nan", "inf", "-inf", "zero", "huge", "-huge", "tiny", "unit_string",
        "negative")
CLASSES = ("value", "delete_key", "delete_section", "unknown_key", "unknown_section", "shuffle_rows",
           "duplicate_rows", "text")


@functools.cache
def sources() -> dict[str, str]:
    """Every shipped deck and every template, variants that reach models no shipped deck runs
    (a finite-length journal bearing), and the decks that once broke camtrain (tests/repro), as
    TOML text by name."""
    from camtrain.deck.templates import render_template

    out = {f"deck:{p.stem}": p.read_text() for p in sorted((ROOT / "decks").glob("*.toml"))}
    out.update({f"template:{m}": render_template(m) for m in _template_kinds()})
    bearing = out["deck:bearing_ocvirk_check"]
    out["variant:finite_bearing"] = bearing.replace('model = "short"', 'model = "finite"', 1)
    out.update({f"repro:{p.stem}": p.read_text(encoding="utf-8-sig")
                for p in sorted((ROOT / "tests" / "repro").glob("*.toml"))})
    return out


#: deck kinds whose unmutated run takes seconds rather than a fraction of one: they get one case
#: for every FAST_WEIGHT cases of each fast source
SLOW_KINDS = ("coupled_camshaft", "transient_film", "engine", "finite_bearing")
FAST_WEIGHT = 4


def kind_of(text: str) -> str:
    """The kind of model a deck runs: deck kind, refined by the sections that cost the most."""
    raw = tomllib.loads(text)
    kind = raw.get("kind", "valve_train")
    if kind == "journal_bearing":
        solver = raw.get("solver", {})
        return "finite_bearing" if solver.get("model", "auto") != "short" else kind
    if kind != "valve_train":
        return kind
    flex = raw.get("camshaft", {}).get("flexibility")
    if flex is not None:
        return ("coupled_camshaft" if flex.get("coupling") == "two_way"
                else "elastic_camshaft")
    if raw.get("tribology", {}).get("film_model") in ("squeeze", "averaged_reynolds"):
        return "transient_film"
    for section in ("dynamics", "camshaft"):
        if section in raw:
            return section
    return "valve_train"


@functools.cache
def kinds() -> dict[str, str]:
    """{source name: kind}."""
    return {name: kind_of(text) for name, text in sources().items()}


@functools.cache
def rota() -> tuple[str, ...]:
    """The order in which cases visit the sources: every source in each round, the fast ones
    FAST_WEIGHT times per round (interleaved), the slow ones once."""
    names = sorted(sources())
    out = []
    for turn in range(FAST_WEIGHT):
        out += [n for n in names if turn == 0 or kinds()[n] not in SLOW_KINDS]
    return tuple(out)


def small_grid(raw: dict) -> dict:
    """Fewer angles and cycles where the deck allows, so a case runs in about a second."""
    solver = raw.get("solver")
    kind = raw.get("kind", "valve_train")
    if isinstance(solver, dict):
        if kind == "valve_train":
            solver["angle_points"] = 90
        elif kind == "journal_bearing":
            solver.update(max_cycles=4, period_tolerance=1e-2, step_tolerance=1e-4)
        elif kind == "engine":
            solver["crank_step"] = 4.0
    return raw


def kind_of_case(seed: int) -> str:
    return kinds()[rota()[seed % len(rota())]]


def _paths(node, prefix=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield prefix + (k,), v
            yield from _paths(v, prefix + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            if isinstance(v, dict):
                yield from _paths(v, prefix + (i,))


def _parent(raw, path):
    node = raw
    for key in path[:-1]:
        node = node[key]
    return node


def _junk(rng: random.Random, old):
    kind = rng.choice(JUNK)
    if kind == "wrong_type":
        return rng.choice(["text", True, [1, 2], {"a": 1}, 7 if isinstance(old, str) else "7"])
    if kind == "unit_string":
        return rng.choice(["12 mm", "0.4mm", "2500 rpm", "1e3 Pa"])
    value = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf, "zero": 0.0, "huge": 1e300,
             "-huge": -1e300, "tiny": 1e-300,
             "negative": -abs(old) if isinstance(old, int | float) and old else -1.0}[kind]
    if isinstance(old, list) and old and all(isinstance(x, int | float) for x in old):
        i = rng.randrange(len(old))
        return old[:i] + [value] + old[i + 1:]
    return value


def mutate(raw: dict, rng: random.Random, cls: str) -> str:
    """Apply one mutation of class ``cls`` to ``raw`` in place; returns what was done."""
    paths = [(p, v) for p, v in _paths(raw)]
    leaves = [(p, v) for p, v in paths if not isinstance(v, dict)]
    tables = [(p, v) for p, v in paths if isinstance(v, dict)]
    row_lists = [(p, v) for p, v in paths if isinstance(v, list) and len(v) > 1]
    if cls == "value" and leaves:
        path, old = rng.choice(leaves)
        _parent(raw, path)[path[-1]] = new = _junk(rng, old)
        return f"{'.'.join(map(str, path))} = {new!r}"
    if cls == "delete_key" and leaves:
        path, _ = rng.choice(leaves)
        del _parent(raw, path)[path[-1]]
        return f"del {'.'.join(map(str, path))}"
    if cls == "delete_section" and tables:
        path, _ = rng.choice(tables)
        parent = _parent(raw, path)
        if isinstance(parent, list):
            parent.pop(path[-1])
        else:
            del parent[path[-1]]
        return f"del [{'.'.join(map(str, path))}]"
    if cls == "unknown_key":
        target = rng.choice(tables)[1] if tables else raw
        target[rng.choice(["widht", "Base_radius", "x", "unit", "é"])] = 1.0
        return "unknown key"
    if cls == "unknown_section":
        raw[rng.choice(["limts", "extra", "Cam", "solver2"])] = {"a": 1}
        return "unknown section"
    if cls in ("shuffle_rows", "duplicate_rows") and row_lists:
        path, rows = rng.choice(row_lists)
        rows = list(rows)
        if cls == "shuffle_rows":
            rng.shuffle(rows)
        else:
            i = rng.randrange(len(rows))
            rows.insert(i, copy.deepcopy(rows[i]))
        _parent(raw, path)[path[-1]] = rows
        return f"{cls} {'.'.join(map(str, path))}"
    return "none"


def damage_text(text: str, rng: random.Random) -> str:
    """Text-level damage: a line dropped, doubled or cut, or a stray bracket."""
    lines = text.splitlines()
    live = [i for i, line in enumerate(lines) if line.strip() and not line.startswith("#")]
    if not live:
        return text + "\n["
    i = rng.choice(live)
    how = rng.choice(["drop", "double", "cut", "bracket", "title_markup"])
    if how == "drop":
        lines.pop(i)
    elif how == "double":
        lines.insert(i, lines[i])
    elif how == "cut":
        lines[i] = lines[i][: rng.randrange(len(lines[i]) + 1)]
    elif how == "bracket":
        lines.insert(i, "[")
    else:
        lines = [f'title = "T [/x] [bold]{rng.random():.3f}"' if ln.startswith("title") else ln
                 for ln in lines]
    return "\n".join(lines) + "\n"


def case(seed: int) -> tuple[str, str, str]:
    """(source name, deck text, what was done) of fuzz case ``seed`` (deterministic)."""
    rng = random.Random(seed)
    srcs = sources()
    order = rota()
    name = order[seed % len(order)]
    raw = small_grid(tomllib.loads(srcs[name]))
    done = []
    for _ in range(rng.choice((1, 1, 2, 3))):
        cls = rng.choice(CLASSES)
        if cls == "text":
            continue
        done.append(mutate(raw, rng, cls))
    text = tomli_w.dumps(raw)
    if rng.random() < 0.15:
        text = damage_text(text, rng)
        done.append("text damage")
    return name, text, "; ".join(done)
