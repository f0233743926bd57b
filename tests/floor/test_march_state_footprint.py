"""The footprint of a state marched with the elastic train (docs/architecture.md, "a state in
the elastic train's time march"): its physics, compiled steps and hook functions live in its
own package; a shared module only imports the package or names the state's record fields where
the architecture says a new state must (a record field, the record's construction, one guarded
call per hook point, the outputs).

:data:`FOOTPRINTS` declares, per march-state physics, every camtrain module outside its package
that imports the package or names its record fields, with its role; the architecture page shows
the same table. A new import of the package, or a new use of its fields, anywhere else fails
here (counted from the source: every import, lazy ones too, and the fields as attributes,
keywords, function names or named-tuple fields)."""
from __future__ import annotations

import ast
from pathlib import Path

from tests.floor.test_imports import PACKAGE, imports_of, module_name

ARCHITECTURE = PACKAGE.parent / "docs" / "architecture.md"

#: physics -> (its package, the names of its record fields and of the train's element, the
#: modules outside the package that may import it or name them: module -> role)
FOOTPRINTS: dict[str, tuple[str, frozenset[str], dict[str, str]]] = {
    "hydraulic lash adjuster": (
        "camtrain.dynamics.hla",
        frozenset({"hla", "hp", "hp_end", "hp_s", "ipl", "plunger", "hla_ratio", "hydraulic"}),
        {
            "camtrain.dynamics.records": "record fields: Train.hla, TrainState.hp, Marched.h",
            "camtrain.dynamics._kernel": "one call per hook point (hla/in_train.py)",
            "camtrain.dynamics.integrators": "the record's construction (march_record), its "
                                             "warm start (chamber_from), the sampled rows",
            "camtrain.assemble.dynamics": "the element from the deck (with_lash_adjuster)",
            "camtrain.effects.dynamics": "outputs (findings, columns, metrics)",
            "camtrain.coupled.records": "record fields: System.hla, State.hp, hp_end, "
                                        "Work.hp_s, Layout.ipl, Samples.hla",
            "camtrain.coupled._step": "one guarded call per hook point (adjuster_step.py), "
                                      "the chamber state carried over a step",
            "camtrain.coupled._lowrank": "one guarded call (adjuster_step.solve_chambers), "
                                         "the plunger's coordinate in the update",
            "camtrain.coupled._revolution": "one guarded sample call, the chamber state kept "
                                            "for the staggered passes",
            "camtrain.coupled.march": "the record's construction",
            "camtrain.coupled.adjusters": "the coupled march's adjuster adapter: start, way to "
                                          "the periodic state",
            "camtrain.coupled.adjuster_step": "the coupled step's adjuster hook functions",
            "camtrain.study.lash_adjuster": "its own study (the leak-down test, the lift lost "
                                            "against the constant-load adjuster)",
        },
    ),
    "roller spin": (
        "camtrain.dynamics.spin",
        frozenset({"wr", "spin"}),
        {
            "camtrain.dynamics.records": "the Spin record (beside Train), TrainState.wr",
            "camtrain.dynamics._kernel": "one guarded call per hook point (spin/in_train.py)",
            "camtrain.dynamics.integrators": "the record's construction (spin_record, "
                                             "spin_start)",
            "camtrain.assemble.roller": "the tables from the deck (spin_tables)",
            "camtrain.assemble.dynamics": "the tables on the train (setup's ``spin`` switch)",
            "camtrain.assemble.coupled": "setup(..., spin=False): the coupled march carries "
                                         "no spin",
            "camtrain.study.lash_adjuster": "setup(..., spin=False): the lift-loss study "
                                            "marches the train without it",
            "camtrain.effects.dynamics": "outputs (columns, metrics, the RollerSpin product)",
            "camtrain.effects.roller": "reads the RollerSpin product",
        },
    ),
}


def _named(tree: ast.AST) -> set[str]:
    """Attribute names, keyword names, function names and named-tuple field names of a
    module."""
    out: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Attribute):
            out.add(node.attr)
        elif isinstance(node, ast.keyword) and node.arg:
            out.add(node.arg)
        elif isinstance(node, ast.FunctionDef):
            out.add(node.name)
        elif (isinstance(node, ast.Call) and getattr(node.func, "id", "") == "namedtuple"
              and len(node.args) > 1 and isinstance(node.args[1], ast.Constant)):
            out.update(str(node.args[1].value).replace(",", " ").split())
    return out


def footprint(paths: dict[str, Path], package: str, names: frozenset[str]) -> set[str]:
    """The modules (of ``paths``: module name -> file) outside ``package`` that import a
    module of it or name one of ``names``."""
    known = set(paths)
    inside = {m for m in known if m == package or m.startswith(package + ".")}
    found = set()
    for name, path in paths.items():
        if name in inside:
            continue
        imports = imports_of(name, path, known)
        if imports & inside or names & _named(ast.parse(path.read_text(encoding="utf-8"))):
            found.add(name)
    return found


def _camtrain() -> dict[str, Path]:
    return {module_name(p): p for p in PACKAGE.rglob("*.py")}


def test_each_march_state_touches_only_its_declared_hooks():
    paths = _camtrain()
    for physics, (package, names, hooks) in FOOTPRINTS.items():
        found = footprint(paths, package, names)
        assert found - set(hooks) == set(), f"{physics}: not a declared hook"
        assert set(hooks) - found == set(), f"{physics}: a declared hook is gone"


def test_the_architecture_page_shows_every_hook():
    page = ARCHITECTURE.read_text(encoding="utf-8")
    for physics, (_, _, hooks) in FOOTPRINTS.items():
        for module in hooks:
            path = module.replace(".", "/") + ".py"
            assert f"`{path}`" in page, f"{physics}: {path} not in docs/architecture.md"


def test_the_footprint_sees_a_new_import_and_a_new_field(tmp_path):
    """It can fail: a synthetic camtrain with a report module importing the adjuster, another
    reading a chamber state's field, and a harmless one."""
    root = tmp_path / "camtrain"
    files = {
        "dynamics/hla/__init__.py": "",
        "dynamics/hla/chamber.py": "def step():\n    pass\n",
        "report/lazy.py": "def f():\n    from camtrain.dynamics.hla import chamber\n",
        "report/fields.py": "def g(state):\n    return state.hp[0]\n",
        "report/plain.py": "def h(x):\n    return x.pressure\n",
    }
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    paths = {"camtrain." + rel.removesuffix(".py").removesuffix("/__init__").replace("/", "."):
             root / rel for rel in files}
    package, names, _ = FOOTPRINTS["hydraulic lash adjuster"]
    assert footprint(paths, package, names) == {"camtrain.report.lazy",
                                                "camtrain.report.fields"}
