"""What a person reads is in the deck's units with the unit beside it; --units si gives SI.

cycle.csv, summary.json, lift.csv, the limit checks, report.txt's cycle table, file modes."""
from __future__ import annotations

import csv
import json
import math
import os
import stat

import numpy as np
import pytest
from click.testing import CliRunner

from camtrain import api
from camtrain.cli import main
from camtrain.report.tables import atomic_write
from camtrain.report.text import report_text
from tests.conftest import DECKS


@pytest.fixture(scope="module")
def flat(tmp_path_factory):
    """The Harrison deck on a coarse grid with a film limit that does not round-trip SI."""
    text = (DECKS / "harrison_flat.toml").read_text()
    base = text.split("\n[limits]")[0].replace("angle_points = 720", "angle_points = 240")
    path = tmp_path_factory.mktemp("deck") / "flat.toml"
    path.write_text(base + "\n[limits]\nmin_film = 0.05\nmax_hertz = 650\n")
    loaded = api.load(path)
    return path, loaded, api.run(loaded)


def _run(*args):
    return CliRunner().invoke(main, ["run", *map(str, args)], catch_exceptions=False)


def _table(path):
    with path.open(newline="", encoding="utf-8") as fh:
        rows = list(csv.reader(fh))
    return rows[0], np.array(rows[1:], dtype=float)


def test_cycle_csv_and_summary_in_deck_units(flat, tmp_path):
    path, _, result = flat
    assert _run(path, "--out", tmp_path, "--no-plots", "--quiet").exit_code == 0
    header, data = _table(tmp_path / "cycle.csv")
    col = {h.split("[")[0]: (h, j) for j, h in enumerate(header)}
    expect = {"cam_angle": ("deg", 180 / math.pi), "lift": ("mm", 1e3),
              "film_min": ("µm", 1e6), "hertz_pmax": ("MPa", 1e-6), "load": ("N", 1.0),
              "lambda": ("-", 1.0), "velocity": ("mm/deg", 1e3 * math.pi / 180)}
    for name, (unit, factor) in expect.items():
        head, j = col[name]
        assert head == f"{name}[{unit}]"
        np.testing.assert_allclose(data[:, j], result[name] * factor, rtol=1e-9,
                                   atol=1e-12 * np.nanmax(np.abs(result[name] * factor)))
    summary = json.loads((tmp_path / "summary.json").read_text(encoding="utf-8"))
    assert summary["units"] == "deck"
    # the columns say what cycle.csv writes (cam_angle in deg, not rad)
    for name, (unit, _) in expect.items():
        assert summary["columns"][name]["unit"] == unit
    hertz = summary["metrics"]["hertz_max"]
    assert hertz["unit"] == "MPa"
    assert hertz["value"] == pytest.approx(result.metrics["hertz_max"].value * 1e-6, rel=1e-12)
    assert summary["metrics"]["film_min"]["unit"] == "µm"
    assert "angle_deg" in hertz and "angle_rad" not in hertz


def test_units_si_gives_si_throughout(flat, tmp_path):
    path, _, result = flat
    res = _run(path, "--out", tmp_path, "--no-plots", "--quiet", "--units", "si")
    assert res.exit_code == 0, res.output
    header, data = _table(tmp_path / "cycle.csv")
    assert header[0] == "cam_angle[rad]" and "film_min[m]" in header and "hertz_pmax[Pa]" in header
    j = header.index("film_min[m]")
    np.testing.assert_allclose(data[:, j], result["film_min"], rtol=1e-9)
    summary = json.loads((tmp_path / "summary.json").read_text(encoding="utf-8"))
    assert summary["units"] == "si"
    assert summary["columns"]["cam_angle"]["unit"] == "rad"
    m = summary["metrics"]["hertz_max"]
    assert m["unit"] == "Pa" and m["value"] == result.metrics["hertz_max"].value
    assert m["angle_rad"] == result.metrics["hertz_max"].angle
    limits = {c["limit"]: c for c in summary["limits"]}
    assert limits["min_film"]["unit"] == "m" and limits["min_film"]["bound"] == 5e-8
    assert limits["max_hertz"]["unit"] == "Pa" and limits["max_hertz"]["bound"] == 650e6


def test_limit_bounds_have_no_float_noise(flat, tmp_path):
    """0.05 µm in the deck is 5e-8 m inside; shown back it must read 0.05, not
    0.049999999999999996."""
    path, _, _ = flat
    res = _run(path, "--out", tmp_path, "--no-plots", "--json")
    summary = json.loads(res.output)
    film = next(c for c in summary["limits"] if c["limit"] == "min_film")
    assert film["bound"] == 0.05 and film["unit"] == "µm"
    assert "0.049999" not in res.output


def test_report_never_truncates_a_number():
    """A value like -4.239e-05 in the cycle table is written whole, not '-4.239e-0'."""
    from tests.report.conftest import chain_plan, synthetic

    result = synthetic(72, level="kinematics")
    theta = result["cam_angle"]
    result.add_column("velocity", np.full_like(theta, -4.239e-05 / (1e3 * math.pi / 180)),
                      "m/rad", "velocity")             # shown as -4.239e-05 mm/deg
    result.add_column("load", np.full_like(theta, -123456.7891), "N", "load")
    result.plan = chain_plan("kinematics", "loads")
    text = report_text(result)
    table = text.split("CYCLE TABLE")[1]
    assert "-4.239e-05" in table
    assert "-4.239e-0 " not in table and not any(
        tok.endswith("e-0") for tok in table.split())


def test_outputs_are_readable_by_others(tmp_path):
    """atomic_write (sweep outputs, lift.csv, junit) respects the umask, not mkstemp's 0600."""
    old = os.umask(0o022)
    try:
        atomic_write(tmp_path / "x.csv", "a\n")
    finally:
        os.umask(old)
    assert stat.S_IMODE((tmp_path / "x.csv").stat().st_mode) == 0o644


@pytest.mark.parametrize("units, angle, film", [("deck", "angle[deg]", "min_film[µm]"),
                                                 ("si", "angle[rad]", "min_film[m]")])
def test_bearing_outputs_in_deck_units(tmp_path, units, angle, film):
    """A journal-bearing deck's load-diagram table and summary speak deg and µm (or SI)."""
    res = _run(DECKS / "bearing_ocvirk_check.toml", "--out", tmp_path, "--no-plots", "--quiet",
               "--units", units)
    assert res.exit_code == 0, res.output
    header, data = _table(tmp_path / "cycle.csv")
    assert header[0] == angle and film in header
    summary = json.loads((tmp_path / "summary.json").read_text(encoding="utf-8"))
    m = summary["metrics"]["min_film"]
    assert m["unit"] == film.split("[")[1].rstrip("]")
    j = header.index(film)
    assert m["value"] == pytest.approx(float(np.nanmin(data[:, j])), rel=1e-6)
    assert summary["columns"]["angle"]["unit"] == angle.split("[")[1].rstrip("]")


def test_cycle_csv_formats_every_value_with_ten_significant_digits():
    """csv_text formats a row at a time; the text is value by value `f"{v:.10g}"`, special
    values included."""
    from camtrain.report.tables import csv_text, cycle_table
    from tests.report.conftest import synthetic

    r = synthetic(97)
    odd = np.array([np.nan, np.inf, -np.inf, -0.0, 5e-324, 1.7976931348623157e308, 1 / 3])
    values = np.resize(odd, 97) * np.linspace(0.5, 1.0, 97)
    r.add_column("odd", values, "-", "special values")
    headers, data = cycle_table(r)
    expected = [",".join(headers)] + [",".join(f"{v:.10g}" for v in row) for row in data]
    assert csv_text(r) == "\n".join(expected) + "\n"
    assert "nan" in csv_text(r) and "inf" in csv_text(r)
