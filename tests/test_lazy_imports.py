"""Import only what a deck uses: the flagship deck's whole run loads none of scipy's heavy
subpackages (optimisers, splines, special functions, integrators) nor numba; a lift-table deck
loads the splines it needs."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEAVY = ("scipy.optimize", "scipy.special", "scipy.interpolate", "scipy.integrate", "numba",
         "matplotlib", "numpy.ma")
CODE = ("import sys; from camtrain import api; api.run(api.load(sys.argv[1])); "
        f"print(' '.join(m for m in {HEAVY!r} if m in sys.modules))")


def _loaded(deck: str) -> set[str]:
    out = subprocess.run([sys.executable, "-c", CODE, str(ROOT / "decks" / deck)], cwd=ROOT,
                         capture_output=True, text=True, check=True).stdout
    return set(out.split())


def test_harrison_run_imports_no_heavy_package():
    assert _loaded("harrison_flat.toml") == set()


def test_table_deck_imports_the_splines_it_needs():
    assert "scipy.interpolate" in _loaded("zeta_intake.toml")


def test_quiet_run_command_imports_no_terminal_plotting_or_compiler(tmp_path):
    """`camtrain run --no-plots --quiet`: nothing is printed or drawn and nothing marches, so
    the whole command loads neither rich, matplotlib, numba nor scipy's heavy subpackages."""
    code = ("import sys, runpy; sys.argv = ['camtrain', 'run', sys.argv[1], '--no-plots', "
            "'--quiet', '--out', sys.argv[2]]\n"
            "try:\n    runpy.run_module('camtrain.cli', run_name='__main__')\n"
            "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
            f"print(' '.join(m for m in {HEAVY + ('rich',)!r} if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code, str(ROOT / "decks" / "harrison_flat.toml"),
                          str(tmp_path / "out")], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    assert set(out.split()) == set()
    assert (tmp_path / "out" / "summary.json").is_file()


def test_run_report_into_a_pipe_imports_no_terminal_library(tmp_path):
    """`camtrain run --no-plots` writing its report into a pipe: the same tables as rich would
    print there (tests/report/test_boxes.py), drawn without importing rich."""
    code = ("import sys, runpy; sys.argv = ['camtrain', 'run', sys.argv[1], '--no-plots', "
            "'--out', sys.argv[2]]\n"
            "try:\n    runpy.run_module('camtrain.cli', run_name='__main__')\n"
            "except SystemExit as exc:\n    assert not exc.code, exc.code\n"
            "print('rich' in sys.modules, file=sys.stderr)")
    env = {k: v for k, v in os.environ.items() if k not in ("FORCE_COLOR", "TTY_COMPATIBLE")}
    res = subprocess.run([sys.executable, "-c", code, str(ROOT / "decks" / "harrison_flat.toml"),
                          str(tmp_path / "out")], cwd=ROOT, capture_output=True, text=True,
                         check=True, env=env)
    assert "key results" in res.stdout and "┏" in res.stdout
    assert res.stderr.strip().splitlines()[-1] == "False"


def _modules_after(code: str, prefix: str) -> set[str]:
    """The modules under ``prefix`` loaded once ``code`` ran in a new interpreter."""
    probe = f"{code}\nimport sys\nprint(' '.join(m for m in sys.modules if m.startswith({prefix!r})))"
    out = subprocess.run([sys.executable, "-c", probe], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    return set(out.splitlines()[-1].split())


def test_a_command_loads_only_its_own_module():
    """The study commands are loaded on first use: `template` loads none of them, `sweep
    --help` its own alone."""
    run = ("from camtrain.cli import main\ntry:\n    main({args!r})\n"
           "except SystemExit as exc:\n    assert not exc.code, exc.code\n")
    assert _modules_after(run.format(args=["template", "flat"]), "camtrain.cli") == {"camtrain.cli"}
    assert _modules_after(run.format(args=["sweep", "--help"]), "camtrain.cli") == \
        {"camtrain.cli", "camtrain.cli_sweep"}


def test_help_lists_every_command_with_its_one_line_help():
    from click.testing import CliRunner

    from camtrain.cli import LAZY_COMMANDS, main

    out = CliRunner().invoke(main, ["--help"]).output
    listed = out.split("Commands:")[1]
    with main.make_context("camtrain", ["--help"], resilient_parsing=True) as ctx:
        for name in LAZY_COMMANDS:
            command = main.get_command(ctx, name)
            assert command.name == name
            line = next(x for x in listed.splitlines() if x.strip().split()[:1] == [name])
            assert " ".join((command.short_help or command.help).split()[:3]) in line
        assert main.list_commands(ctx) == sorted(main.commands)


def test_a_misspelt_command_is_matched_against_the_lazy_ones():
    from click.testing import CliRunner

    from camtrain.cli import main

    res = CliRunner().invoke(main, ["swep"])
    assert res.exit_code == 2
    assert "No such command 'swep'. Did you mean 'sweep'?" in res.output


DEFERRED_SCHEMAS = {f"camtrain.deck.schema_{m}" for m in (
    "camshaft", "dynamics", "lash_adjuster", "design", "roller", "follower", "guides", "pushrod",
    "desmodromic", "lift_multipol", "lift_table", "lift_exp_poly", "lift_polynomial",
    "lift_williams", "lift_spline")}


def test_a_deck_loads_only_the_schemas_of_its_sections():
    """harrison_flat (a four-power lift) has none of the deferred sections ([camshaft],
    [dynamics], [design], [roller], [guides], [mechanism.roller|layout|arm|pushrod|closing],
    the other lift forms): loading it imports none of their modules; a deck with [dynamics]
    and a lift table imports those (and the lash adjuster's, which its [dynamics] holds)."""
    load = "from camtrain.deck.load import load_deck\nload_deck({deck!r})\n"
    flat = _modules_after(load.format(deck="decks/harrison_flat.toml"), "camtrain.deck.schema_")
    assert flat & DEFERRED_SCHEMAS == set()
    hla = _modules_after(load.format(deck="decks/zeta_intake_hla.toml"), "camtrain.deck.schema_")
    assert hla & DEFERRED_SCHEMAS == {"camtrain.deck.schema_dynamics",
                                      "camtrain.deck.schema_lash_adjuster",
                                      "camtrain.deck.schema_lift_table"}


def test_a_misspelt_key_is_still_matched_against_the_deferred_sections():
    """The hint of an unknown key walks the whole schema, deferred sections included."""
    import tomllib

    from camtrain.deck.load import validate
    from camtrain.errors import InputError
    from tests.conftest import MINIMAL_DECK

    raw = tomllib.loads(MINIMAL_DECK)
    raw["cam"]["integrator"] = "newmark"
    raw["dynamcs"] = {}
    try:
        validate(raw, "deck.toml")
    except InputError as exc:
        messages = [p.render() for p in exc.problems]
    else:  # pragma: no cover - the deck is invalid
        raise AssertionError("an invalid deck was accepted")
    assert any("cam.integrator: is not a known key. did you mean `dynamics.integrator`?" in m
               for m in messages), messages
    assert any("dynamcs: is not a known key. did you mean `dynamics`?" in m for m in messages)


def test_lazy_package_names_stay_what_they_name_whatever_was_imported_first():
    """A package's lazy name must not be one of its modules' names: importing that module from
    elsewhere would set the package's attribute to the module (the builder `pivoted` of
    camtrain/mechanisms/pivoted.py is bound eagerly for that reason). Every submodule first,
    then every public name: none is a module."""
    code = ("import importlib, pkgutil, types\n"
            "for name in ('camtrain.lift', 'camtrain.mechanisms'):\n"
            "    package = importlib.import_module(name)\n"
            "    for m in pkgutil.iter_modules(package.__path__):\n"
            "        importlib.import_module(f'{name}.{m.name}')\n"
            "    bad = [n for n in package.__all__\n"
            "           if isinstance(getattr(package, n), types.ModuleType)]\n"
            "    assert not bad, (name, bad)\n"
            "    assert not set(package._LAZY) & {m.name for m in pkgutil.iter_modules(package.__path__)}\n"
            "print('ok')")
    out = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout
    assert out.split() == ["ok"]
