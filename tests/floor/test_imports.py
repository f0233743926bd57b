"""The import structure of camtrain: no import circle, no effect importing another effect, no
import from a lower floor to a higher one.

Every import counts, also those inside functions: a circle through a lazy import is still two
modules that need each other, and effects meet only through products."""
from __future__ import annotations

import ast
from pathlib import Path

from camtrain.catalogue import KINDS

PACKAGE = Path(__file__).resolve().parents[2] / "camtrain"


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def modules() -> dict[str, Path]:
    return {module_name(p): p for p in PACKAGE.rglob("*.py")}


def imports_of(name: str, path: Path, known: set[str], lazy: bool = True) -> set[str]:
    """camtrain modules that ``name`` imports (anywhere in the file, or at module level only
    when ``lazy`` is False)."""
    out = set()
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    tree = ast.parse(path.read_text())
    nodes = ast.walk(tree) if lazy else _module_level(tree)
    for node in nodes:
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names if a.name in known}
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                root = package.split(".")
                root = root[:len(root) - node.level + 1]
                base = ".".join(root + ([base] if base else []))
            for a in node.names:
                full = f"{base}.{a.name}"
                out.add(full if full in known else base)
    return {m for m in out if m in known and m != name}


def _module_level(tree):
    """Statements run when the module loads: the body, into if/try blocks, not functions."""
    todo = list(tree.body)
    while todo:
        node = todo.pop()
        yield node
        if isinstance(node, ast.If | ast.Try | ast.With):
            for part in ("body", "orelse", "finalbody", "handlers"):
                todo.extend(getattr(node, part, []))
        elif isinstance(node, ast.ExceptHandler):
            todo.extend(node.body)


def graph(lazy: bool = True) -> dict[str, set[str]]:
    mods = modules()
    known = set(mods)
    return {name: imports_of(name, path, known, lazy) for name, path in mods.items()}


def cycles(g: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index, low, stack, on, out = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in g[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                out.append(sorted(comp))

    for v in sorted(g):
        if v not in index:
            visit(v)
    return out


def _without_package_inits(g):
    """Edges into a package's ``__init__`` from its own submodules are how Python loads a
    submodule, not a dependency of the code; they are left out."""
    return {v: {w for w in ws if not v.startswith(w + ".")} for v, ws in g.items()}


def test_no_import_circle_in_camtrain():
    assert cycles(_without_package_inits(graph(lazy=True))) == []


def test_the_circle_finder_finds_circles():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]


def test_no_effect_imports_another_effect():
    effects = {spec.module for kind in KINDS.values() for spec in kind.effects}
    g = graph()
    bad = {e: sorted(g[e] & effects) for e in effects if g[e] & effects}
    assert bad == {}


def test_the_walk_sees_imports():
    """The walk itself: it finds an effect's lazy imports and a relative import."""
    g = graph()
    assert "camtrain.contact.model" in g["camtrain.effects.friction"]
    assert "camtrain.camshaft.loads" in g["camtrain.camshaft"]


#: the floors of docs/architecture.md ("Layers"), lowest first: module prefixes (under
#: camtrain.) on each; a module may import its own floor and those below, never one above
FLOORS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("base", ("__init__", "formulas", "numerics", "progress", "interrupts", "errors", "units",
              "components", "identity_cache", "output_lock", "data", "catalogue", "plan",
              "display_units", "metric_rows", "lazy")),
    ("physics", ("lift", "mechanisms", "loads", "dynamics", "contact", "camshaft", "bearings",
                 "engine", "lubrication", "piston", "coupled", "roller")),
    ("deck", ("deck",)),
    ("assemble", ("assemble",)),
    ("result", ("result", "tabulate")),
    ("effects", ("effects",)),
    ("run", ("scene", "runner")),
    ("top", ("api", "warmup", "report", "study", "design", "cli")),
)

#: (importer, imported) arrows up that stay, each with its reason
UPWARD_ALLOWED: dict[tuple[str, str], str] = {}


def floor_of(module: str) -> int:
    """The floor index of a camtrain module (by its longest matching prefix)."""
    rest = "__init__" if module == "camtrain" else module.removeprefix("camtrain.")
    best = None
    for index, (_, prefixes) in enumerate(FLOORS):
        for p in prefixes:
            hit = rest == p or rest.startswith(p + ".") or (p == "cli" and rest.startswith(p))
            if hit and (best is None or len(p) > best[1]):
                best = (index, len(p))
    if best is None:
        raise AssertionError(f"{module} is on no floor: add it to FLOORS and the docs' table")
    return best[0]


def upward_imports(g) -> dict[tuple[str, str], str]:
    return {(m, d): f"{FLOORS[floor_of(m)][0]} -> {FLOORS[floor_of(d)][0]}"
            for m, deps in g.items() for d in deps if floor_of(d) > floor_of(m)}


def test_no_import_from_a_lower_floor_to_a_higher_one():
    """Every import counts, lazy ones inside functions too."""
    up = upward_imports(graph(lazy=True))
    assert {k: v for k, v in up.items() if k not in UPWARD_ALLOWED} == {}
    assert set(UPWARD_ALLOWED) <= set(up), "an allowed arrow is gone: take it off the list"


def test_the_floor_check_sees_an_arrow_up():
    assert upward_imports({"camtrain.contact.transient": {"camtrain.deck.schema_tribology"},
                           "camtrain.deck.load": {"camtrain.catalogue"}}) == {
        ("camtrain.contact.transient", "camtrain.deck.schema_tribology"): "physics -> deck"}


def test_the_film_march_defaults_of_the_physics_are_the_decks():
    """The transient film marches a contact built without a deck on the defaults of
    camtrain.contact.film_march, which the deck's [solver] fields repeat."""
    import dataclasses

    from camtrain.contact.film_march import DEFAULTS
    from camtrain.deck.schema_tribology import Solver

    deck = Solver()
    for f in dataclasses.fields(DEFAULTS):
        assert getattr(deck, f.name) == getattr(DEFAULTS, f.name), f.name
