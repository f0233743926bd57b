"""Plot sheets and single panels: written, non-blank, and only the panels the plan declares."""
from __future__ import annotations

import numpy as np
import pytest
from PIL import Image

from camtrain.report import profile
from camtrain.report.sheets import write_plots
from tests.report.conftest import synthetic


def _ink(path) -> float:
    """Share of pixels that are not (near) white: a blank image has none."""
    img = np.asarray(Image.open(path).convert("L"), dtype=float)
    return float(np.mean(img < 200))


def test_full_result_writes_every_sheet_and_panel_png_and_pdf(tmp_path):
    written = write_plots(synthetic(240), None, tmp_path)
    names = {p.relative_to(tmp_path).as_posix() for p in written}
    for sheet in ("kinematics", "contact", "friction", "profile"):
        assert f"sheet_{sheet}.png" in names and f"sheet_{sheet}.pdf" in names
    for panel in ("lift", "velocities", "radii", "film_angle", "film_position", "load", "hertz",
                  "friction_coefficient", "torque", "power", "profile"):
        assert f"panels/{panel}.png" in names and f"panels/{panel}.pdf" in names
    for p in written:
        assert p.stat().st_size > 2000
        if p.suffix == ".pdf":
            assert p.read_bytes().startswith(b"%PDF")
        else:
            assert _ink(p) > 0.01, p


def test_lift_only_result_gives_one_clean_sheet(tmp_path):
    written = write_plots(synthetic(180, level="lift"), None, tmp_path, single_panels=False,
                          formats=("png",))
    assert [p.name for p in written] == ["sheet_kinematics.png"]
    assert _ink(written[0]) > 0.01


def test_no_load_result_has_no_friction_sheet(tmp_path):
    written = write_plots(synthetic(180, level="kinematics"), None, tmp_path,
                          single_panels=False, formats=("png",))
    assert {p.name for p in written} == {"sheet_kinematics.png", "sheet_contact.png",
                                         "sheet_profile.png"}


def test_the_plan_picks_the_panels_not_the_columns(tmp_path):
    """A panel is drawn when an effect that ran declares it (EffectSpec.panels): the Hertz
    stress column alone, without the hertz effect in the plan, draws no Hertz panel."""
    from tests.report.conftest import chain_plan

    r = synthetic(120)
    r.plan = chain_plan("kinematics", "loads", "film", "friction", "power")
    written = write_plots(r, None, tmp_path, formats=("png",))
    names = {p.relative_to(tmp_path).as_posix() for p in written}
    assert "hertz_pmax" in r.columns and "panels/hertz.png" not in names
    assert {"panels/load.png", "panels/film_angle.png", "panels/power.png"} <= names


FULL_CHAIN = ("kinematics", "loads", "hertz", "film", "friction", "power")


def _with_transient_columns(r):
    """The columns a transient film writes (film_steady; the averaged Reynolds pressures)."""
    h = r["film_min"]
    r.add_column("film_steady", 0.8 * h, "m", "steady film")
    r.add_column("film_transient", 0.9 * h, "m", "averaged Reynolds film before the floor")
    r.add_column("film_pressure_max", 0.7 * r["hertz_pmax"], "Pa", "peak fluid pressure")
    r.add_column("asperity_pressure_max", 0.1 * r["hertz_pmax"], "Pa", "peak asperity pressure")
    r.add_column("asperity_load_share", np.full(h.shape, 0.2), "-", "asperity share")
    return r


def _sheet_panels(tmp_path, model: str) -> dict[str, set[str]]:
    """The sheets a synthetic run whose film step ran ``model`` writes, with their panels."""
    from tests.report.conftest import chain_plan

    r = _with_transient_columns(synthetic(120))
    r.plan = chain_plan(*FULL_CHAIN, models={"film": model})
    written = write_plots(r, None, tmp_path / model, formats=("png",))
    names = {p.relative_to(tmp_path / model).as_posix() for p in written}
    return {"sheets": {n for n in names if n.startswith("sheet_")},
            "panels": {n.removeprefix("panels/").removesuffix(".png")
                       for n in names if n.startswith("panels/")}}


def test_a_steady_film_draws_no_transient_sheet_whatever_its_columns(tmp_path):
    """The plan's film step records the model it ran (Step.model): a steady film declares
    none of the transient film's panels, even with film_steady and the pressures in its
    columns."""
    got = _sheet_panels(tmp_path, "steady")
    assert "sheet_transient_film.png" not in got["sheets"]
    assert not {"transient_film", "film_pressures"} & got["panels"]
    assert "sheet_contact.png" in got["sheets"]


@pytest.mark.parametrize("model,panels", [
    ("squeeze", {"transient_film"}),
    ("averaged_reynolds", {"transient_film", "film_pressures"})])
def test_a_transient_film_draws_its_sheet(tmp_path, model, panels):
    got = _sheet_panels(tmp_path, model)
    assert "sheet_transient_film.png" in got["sheets"]
    assert got["panels"] & {"transient_film", "film_pressures"} == panels


def test_the_film_model_of_the_plan_survives_a_saved_result(tmp_path):
    from camtrain.catalogue import declared_panels
    from camtrain.result import Result
    from tests.report.conftest import chain_plan

    r = synthetic(60)
    r.plan = chain_plan(*FULL_CHAIN, models={"film": "averaged_reynolds"})
    back = Result.load(r.save(tmp_path / "r.npz"))
    assert next(s.model for s in back.plan.steps if s.effect == "film") == "averaged_reynolds"
    assert {"transient_film", "film_pressures"} <= declared_panels(back.plan)


def test_every_panel_is_declared_by_an_effect_and_every_declared_panel_exists():
    """The panels the effects declare are those the sheets register (a name misspelt in the
    catalogue would draw nothing), and every panel of a cycle sheet has an effect that feeds
    it (one without would never be drawn)."""
    from camtrain.catalogue import KINDS, LIFT_PANELS
    from camtrain.report.sheets import PANELS, SHEETS

    declared = {p for kind in KINDS.values() for spec in kind.effects
                for p in (*spec.panels, *(q for _, ps in spec.model_panels for q in ps))}
    on_sheets = {p for _, panels in SHEETS.values() for p in panels}
    assert on_sheets == set(PANELS) | {"profile"}
    assert declared == on_sheets
    assert set(LIFT_PANELS) <= declared


def test_progress_reports_every_file_set(tmp_path):
    seen = []
    write_plots(synthetic(120, level="lift"), None, tmp_path, formats=("png",),
                progress=lambda label, done, total: seen.append((label, done, total)))
    assert seen[-1][1] == seen[-1][2] == len(seen)
    assert seen[0][0] == "sheet kinematics"
    # a lift-only run draws no camshaft sheet, and the progress never names one
    assert not any("camshaft" in label or "dynamics" in label for label, *_ in seen)


def test_result_without_angle_grid_draws_nothing(tmp_path):
    from camtrain.result import Result

    assert write_plots(Result(), None, tmp_path) == []


@pytest.mark.parametrize("x,expected", [(0.0, 1.0), (7.3, 5.0), (1500.0, 1000.0), (0.2, 0.2)])
def test_film_magnification_is_a_round_number(x, expected):
    assert profile._nice(x) == pytest.approx(expected)


def test_profile_normals_point_outward():
    t = np.linspace(0, 2 * np.pi, 100, endpoint=False)
    x, y = 2 * np.cos(t), np.sin(t)
    nx, ny = profile._outward_normals(x, y)
    assert np.all(nx * x + ny * y > 0)
    assert np.allclose(np.hypot(nx, ny), 1.0)
