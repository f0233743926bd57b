"""The test tiers and the references they cite resolve inside the repository."""
from __future__ import annotations

import re
import subprocess
import sys

from tests.conftest import ROOT
from tests.tiers import FILES, TESTS, TIERS, tier_of

SOURCES = r"(Ball|Yang|Williams|Teodorescu|G[öo]çmen|Gocmen|Raimondi|Ocvirk|Pinto|Moes|Dowson)"


def test_every_listed_file_and_test_exists():
    for path in FILES:
        assert (ROOT / path).exists(), path
    for key in TESTS:
        module, name = key.split("::")
        hits = list(ROOT.glob(f"tests/**/{module}"))
        assert hits, key
        assert any(f"def {name}" in h.read_text(encoding="utf-8") for h in hits), key
    assert set(FILES.values()) | set(TESTS.values()) <= set(TIERS)


def test_tier_rules():
    assert tier_of("tests/golden/test_golden.py::test_x[harrison_flat]", set()) == "golden"
    assert tier_of("tests/tribology/test_harrison.py::test_power_loss_against_ball", set()) \
        == "literature"
    assert tier_of("tests/tribology/test_harrison.py::test_cycle_extremes", set()) == "derived"
    assert tier_of("tests/test_cli.py::test_help", set()) == "behaviour"
    assert tier_of("tests/test_cli.py::test_help", {"convergence"}) == "convergence"


def test_literature_modules_name_their_source():
    for path, tier in FILES.items():
        if tier == "literature" and path.endswith(".py"):
            text = (ROOT / path).read_text(encoding="utf-8")
            assert re.search(SOURCES + r".{0,80}(table|fig|eq|§|app)", text, re.S | re.I), path


def test_cited_reference_pages_exist():
    cited = set()
    for path in (ROOT / "tests").rglob("*.py"):
        cited |= set(re.findall(r"docs/references/([\w]+)\.md", path.read_text(encoding="utf-8")))
    assert cited, "no test cites docs/references"
    for name in cited:
        assert (ROOT / "docs" / "references" / f"{name}.md").exists(), name


def test_check_lists_guide_friction_with_its_reason():
    out = subprocess.run([sys.executable, "-m", "camtrain.cli", "check",
                          str(ROOT / "decks" / "zeta_intake.toml")],
                         capture_output=True, text=True, check=True, cwd=ROOT,
                         env={"PYTHONPATH": str(ROOT), "COLUMNS": "200"}).stdout
    line = next(ln for ln in out.splitlines() if "guides " in ln and "yes" in ln)
    assert "[guides] and lubricant given" in line and "Yang 1992 eq. 3.29" in line
