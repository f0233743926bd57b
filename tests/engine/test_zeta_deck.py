"""Ford Zeta crankshaft bearings through the engine deck against Yang (1992) Tables 2.1-2.4.

Yang's printed cells are the reference data ``camtrain/data/yang1992_zeta_crank_tables.csv``
(docs/references/yang1992.md §4.2). Only the Petroff cells are reproducible: they need only the
bearings and viscosities (App. B.4, B.6). The steady and dynamic cells need the crank-train data
of App. B.1, which are lost in the source; the deck carries outside and assumed values (flagged
in it), so those cells are strict xfails naming the missing data, and the tests assert Yang's
relative statements instead (§2.4: the big-end loses less than any main; main 3 is worst;
grooved mains lose more and run thinner than ungrooved ones).
"""
from __future__ import annotations

import csv
from functools import cache
from pathlib import Path

import pytest

import camtrain
import camtrain.api as ct

from .engine_decks import ZETA, deck

CELLS = Path(camtrain.__file__).parent / "data" / "yang1992_zeta_crank_tables.csv"
TABLES = {"2.1": (3000.0, "none"), "2.2": (3000.0, "central"), "2.3": (6000.0, "none"),
          "2.4": (6000.0, "central")}
MISSING = ("Yang's Zeta crank-train data (App. B.1: rod length, piston and rod masses, bay "
           "length) are lost in the source; the deck's are outside or assumed values, and they "
           "decide the loads, hence every steady and dynamic cell")


def printed(table: str) -> dict:
    with CELLS.open(encoding="utf-8") as fh:
        rows = [r for r in csv.DictReader(line for line in fh if not line.startswith("#"))
                if r["table"] == table]
    return {r["bearing"]: {k: float(v) for k, v in r.items() if k.endswith(("kW", "um")) and v}
            for r in rows}


@cache
def run(table: str, factor: str = "as_printed", methods=("dynamic", "steady", "petroff")):
    rpm, grooving = TABLES[table]
    return ct.run(deck(ZETA, speed__engine=rpm, bearings__main__grooving=grooving,
                       solver__mobility_factor=factor, solver__methods=list(methods)))


def _cell_tol(v):
    """Half a unit of the 4th decimal (kW) plus 1e-4 relative (as the Petroff tests of
    tests/bearings/test_bearings_published.py: one cell computes 0.004 W below its rounding
    boundary)."""
    return 0.5e-4 + 1e-4 * v


@pytest.mark.parametrize("table", TABLES)
def test_every_petroff_cell_of_tables_2_1_to_2_4(table):
    """Petroff column, printed to 4 decimals in kW, through the deck (viscosity per speed from
    App. B.6, central groove = two 7.175 mm lands)."""
    r = run(table, methods=("petroff",))
    cells = printed(table)
    for k in range(1, 5):
        got = r.metrics[f"big_end_{k}_power_petroff"].value / 1e3
        assert got == pytest.approx(cells["big_end"]["petroff_kW"], abs=_cell_tol(got))
    for k in range(1, 6):
        got = r.metrics[f"main_{k}_power_petroff"].value / 1e3
        assert got == pytest.approx(cells[f"main_{k}"]["petroff_kW"], abs=_cell_tol(got))
    # totals: Yang added the rounded cells, nine half-units
    assert r.metrics["total_power_petroff"].value / 1e3 == pytest.approx(
        cells["total"]["petroff_kW"], abs=9 * 0.5e-4)


def test_partial_grooving_is_the_mean_of_the_extremes():
    """FLAME's partial groove (Yang Part IV, Table 7.1): the mean of ungrooved and grooved."""
    r = ct.run(deck(ZETA, solver__methods=["petroff"]))
    mean = 0.5 * (printed("2.1")["main_1"]["petroff_kW"] + printed("2.2")["main_1"]["petroff_kW"])
    assert r.metrics["main_1_power_petroff"].value / 1e3 == pytest.approx(mean, abs=1e-4)


@pytest.mark.parametrize("table", TABLES)
def test_big_end_loses_less_than_any_main_and_main_3_is_worst(table):
    """Yang §2.4 (Figs 2.14, 2.15): the big-end wastes less energy than any main; Main No. 3
    is worst. Asserted on the deck's dynamic and steady columns."""
    r = run(table)
    for method in ("dynamic", "steady"):
        be = r.metrics[f"big_end_1_power_{method}"].value
        mains = [r.metrics[f"main_{k}_power_{method}"].value for k in range(1, 6)]
        assert be < min(mains), method
        assert max(mains) == mains[2], method


@pytest.mark.parametrize("rpm", [3000.0, 6000.0])
def test_grooved_mains_lose_more_and_run_thinner(rpm):
    """Yang §2.4: centrally grooved mains lose more power than ungrooved ones (main 1: 0.064
    -> 0.081 kW at 3000 rpm, 0.185 -> 0.247 at 6000) and run thinner films (the groove puts
    the load on two lands)."""
    tables = [t for t, (s, _) in TABLES.items() if s == rpm]
    plain, grooved = run(tables[0]), run(tables[1])
    for k in range(1, 6):
        for m in ("power_dynamic", "power_steady"):
            assert grooved.metrics[f"main_{k}_{m}"].value > plain.metrics[f"main_{k}_{m}"].value
        assert (grooved.metrics[f"main_{k}_min_film_dynamic"].value
                < plain.metrics[f"main_{k}_min_film_dynamic"].value)


def _all_cells(r, cells, method) -> list[tuple[str, float, float]]:
    out = [("big_end", r.metrics[f"big_end_1_power_{method}"].value / 1e3,
            cells["big_end"][f"{method}_kW"]),
           ("big_end h", r.metrics[f"big_end_1_min_film_{method}"].value * 1e6,
            cells["big_end"][f"{method}_hmin_um"])]
    for k in range(1, 6):
        out.append((f"main_{k}", r.metrics[f"main_{k}_power_{method}"].value / 1e3,
                    cells[f"main_{k}"][f"{method}_kW"]))
        out.append((f"main_{k} h", r.metrics[f"main_{k}_min_film_{method}"].value * 1e6,
                    cells[f"main_{k}"][f"{method}_hmin_um"]))
    return out


@pytest.mark.xfail(strict=True, reason=MISSING)
@pytest.mark.parametrize("method", ["dynamic", "steady"])
@pytest.mark.parametrize("table", TABLES)
def test_steady_and_dynamic_cells(table, method):
    """Every power and film cell of one method of one table, with the physics as printed, to
    2 % (print precision is 4 decimals; 2 % allows the mobility formula). With the deck's
    assumed crank-train data the cells lie within about 7 % (docs/engine.md); Yang's program's
    half mobility, needed for his Ruston film, puts the Zeta films 40-60 % above his."""
    r = run(table)
    bad = [(name, got, want) for name, got, want in _all_cells(r, printed(table), method)
           if got != pytest.approx(want, rel=0.02)]
    assert not bad, bad


def test_big_end_dynamic_film_above_steady_at_3000_below_at_6000():
    """Yang §2.4: the big-end h_min is dynamic > steady at 2000-4000 rpm and dynamic < steady
    at 5000 rpm and above (Tables 2.1/2.3: 1.507 > 0.940 um, 0.938 < 1.410 um)."""
    low, high = run("2.1").metrics, run("2.3").metrics
    assert (low["big_end_1_min_film_dynamic"].value
            > low["big_end_1_min_film_steady"].value)
    assert (high["big_end_1_min_film_dynamic"].value
            < high["big_end_1_min_film_steady"].value)


def test_petroff_factor_rises_with_speed():
    """Yang §2.4: dynamic / Petroff rises with speed, ungrooved 1.74 -> 2.0 and centrally
    grooved 2.3 -> 2.8 (his tables: 1.785 -> 1.848 and 2.42 -> 2.58); asserted as the rise from
    3000 to 6000 rpm and the grooved factor above the ungrooved one."""
    def factor(t):
        m = run(t).metrics
        return m["total_power_dynamic"].value / m["total_power_petroff"].value

    assert factor("2.3") > factor("2.1") and factor("2.4") > factor("2.2")
    assert factor("2.2") > factor("2.1") and factor("2.4") > factor("2.3")


def test_dynamic_and_steady_totals_close_at_3000_apart_at_6000():
    """Yang §2.4: the dynamic and steady totals are nearly equal at 2000 and 3000 rpm
    (Table 2.1: 0.5140 / 0.5068, 1.4 %) and slightly different at high speed (Table 2.3:
    1.4681 / 1.5258, 3.8 %): within 2 % at 3000 rpm, further apart at 6000."""
    def gap(t):
        m = run(t).metrics
        return abs(m["total_power_dynamic"].value / m["total_power_steady"].value - 1.0)

    assert gap("2.1") < 0.02 and gap("2.2") < 0.02
    assert gap("2.3") > gap("2.1") and gap("2.4") > gap("2.2")
