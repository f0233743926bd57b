"""The FLAME table a sweep over speed writes (flame.csv, flame.md, the stacked plot), on Yang's
Table 7.1 as records (docs/references/yang1992.md §4.5)."""
from __future__ import annotations

import pytest

from camtrain.study.flame_table import flame_rows, write_flame
from camtrain.study.sweep import Parameter

TABLE_7_1 = {2000: (0.275, 0.446, 1.480, 0.551, 2.751), 3000: (0.552, 0.667, 2.080, 0.825, 4.124),
             6000: (1.604, 1.153, 4.472, 1.807, 9.036)}
SPEED = Parameter("speed", "speed.engine", "rpm", False, 3000.0, (2000.0, 3000.0, 6000.0))
NAMES = ("flame_bearings", "flame_valve_train", "flame_piston", "flame_accessories",
         "flame_total")


def _records():
    out = []
    for i, (rpm, row) in enumerate(sorted(TABLE_7_1.items(), reverse=True)):
        metrics = {n: (v * 1e3, "W") for n, v in zip(NAMES, row, strict=True)}
        metrics["fmep"] = (1.0e5, "Pa")
        out.append({"index": i, "values": {"speed": float(rpm)}, "status": "ok",
                    "message": "", "metrics": metrics})
    out.append({"index": 9, "values": {"speed": 9000.0}, "status": "failed", "message": "x",
                "metrics": {}})
    return out


def test_rows_are_ordered_by_speed_with_yangs_shares():
    """Yang Part IV: shares without accessories 17/20/63 % at 3000 rpm and 22/16/62 % at
    6000 rpm (whole percent) come out of the table's rows; failed cases are left out."""
    rows = flame_rows([SPEED], _records())
    assert [r["x"] for r in rows] == [2000.0, 3000.0, 6000.0]
    for rpm, shares in ((3000.0, (17, 20, 63)), (6000.0, (22, 16, 62))):
        row = next(r for r in rows if r["x"] == rpm)
        got = [100 * row["shares"][k] for k in NAMES[:3]]
        assert got == pytest.approx(shares, abs=0.5)


def test_files_are_written(tmp_path):
    written = write_flame(tmp_path, [SPEED], _records(), plots=True, title="Zeta")
    assert {p.name for p in written} == {"flame.csv", "flame.md", "flame_stacked.png"}
    md = (tmp_path / "flame.md").read_text()
    assert "| 3000 | 0.552 | 0.667 | 2.080 | 0.825 | 4.124 | 100.0 | 17 / 20 / 63 |" in md
    assert (tmp_path / "flame.csv").read_text().splitlines()[0].startswith("speed[rpm],")


def test_records_in_deck_units_are_read_in_their_units(tmp_path):
    """A sweep's records carry each metric in the deck's display unit (fmep in MPa, powers in
    W or kW): the table converts by the unit, so 0.0712 MPa is 71.2 kPa (before, it divided
    the MPa value by 1e3 and printed 0.0)."""
    records = _records()
    for r in records:
        if r["metrics"]:
            r["metrics"]["fmep"] = (0.07125, "MPa")
            r["metrics"]["flame_total"] = (r["metrics"]["flame_total"][0] / 1e3, "kW")
    write_flame(tmp_path, [SPEED], records, plots=False)
    md = (tmp_path / "flame.md").read_text()
    assert "| 3000 | 0.552 | 0.667 | 2.080 | 0.825 | 4.124 | 71.2 | 17 / 20 / 63 |" in md


def test_nothing_without_a_flame_total(tmp_path):
    records = [{"index": 0, "values": {"speed": 1.0}, "status": "ok", "message": "",
                "metrics": {"power_loss_mean": (1.0, "W")}}]
    assert write_flame(tmp_path, [SPEED], records) == []
    assert not (tmp_path / "flame.md").exists()
