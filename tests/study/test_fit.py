"""`camtrain fit`: constants recovered from data camtrain generated with noise added, intervals
with the right coverage, constants that enter only as a product flagged.

The data are the minimum film of decks/harrison_flat.toml (at 180 angles) between -34 and 34
deg cam (inside the zero-entrainment points at ±39.6 deg), with Gaussian noise of 1 % of the
film's rms added. Dowson & Higginson's film h ∝ (eta u)^0.70 alpha^0.54 (W/b)^-0.13 makes the
viscosity eta and the spring preload (through the load W, which varies along the flank)
separately identifiable, while eta and alpha enter only as the product eta^0.70 alpha^0.54.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy import stats

from camtrain.errors import InputError
from camtrain.study.executors import SerialExecutor
from camtrain.study.fit import fit
from camtrain.study.fit_data import DataSet, Series, read_data
from camtrain.study.fit_model import Predictor, parse_constant
from camtrain.study.runner import prepare_datum

TRUE = {"viscosity": 0.05, "spring.preload_compression": 6.4}
ANGLES = np.arange(-34.0, 34.5, 1.0)
DRAWS = 40


def _film(deck) -> np.ndarray:
    import camtrain.api as ct

    result = ct.run(ct.load(deck))
    return np.interp(ANGLES, np.degrees(result["cam_angle"]), result["film_min"]) * 1e6


def _dataset(values) -> DataSet:
    return DataSet("film.csv", "cam_angle", "deg", tuple(ANGLES),
                   (Series("film_min", "µm", tuple(values)),))


def _fit(deck, values, specs, sets, confidence=0.95):
    datum = prepare_datum(deck, sets)
    constants = [parse_constant(datum.raw, n, b) for n, b in specs]
    predictor = Predictor(datum, constants, [_dataset(values)], SerialExecutor())
    return fit(predictor, confidence)


@pytest.mark.derived
def test_fit_recovers_constants_with_the_right_coverage(fast_flat):
    """Over repeated noise draws the 95 % intervals hold the true constants about 95 % of the
    time and the 50 % intervals about half of the time (binomial bounds at 2.5 sd of 40
    draws), so the intervals are neither too narrow nor too wide."""
    exact = _film(fast_flat)
    sigma = 0.01 * np.sqrt(np.mean(exact ** 2))
    rng = np.random.default_rng(2026)
    specs = [("viscosity", "0.01:0.2"), ("spring.preload_compression", "2:12")]
    t_ratio = stats.t.ppf(0.75, ANGLES.size - 2) / stats.t.ppf(0.975, ANGLES.size - 2)
    inside95 = {n: 0 for n in TRUE}
    inside50 = {n: 0 for n in TRUE}
    for _ in range(DRAWS):
        noisy = exact + sigma * rng.standard_normal(exact.size)
        f = _fit(fast_flat, noisy, specs, ["viscosity=0.03", "spring.preload_compression=4"])
        assert not f.unidentifiable
        for c, v, h in zip(f.constants, f.value, f.half_width, strict=True):
            err = abs(v - TRUE[c.name])
            inside95[c.name] += err <= h
            inside50[c.name] += err <= h * t_ratio
    for name in TRUE:
        assert 34 <= inside95[name] <= 40, (name, inside95, inside50)
        assert 12 <= inside50[name] <= 28, (name, inside95, inside50)


@pytest.mark.derived
def test_without_noise_the_fit_returns_the_constants(fast_flat):
    f = _fit(fast_flat, _film(fast_flat), [("viscosity", "0.01:0.2"),
                                           ("spring.preload_compression", "2:12")],
             ["viscosity=0.03", "spring.preload_compression=4"])
    assert f.value == pytest.approx([0.05, 6.4], rel=1e-5)


@pytest.mark.derived
def test_constants_entering_only_as_a_product_are_not_identifiable(fast_flat):
    exact = _film(fast_flat)
    f = _fit(fast_flat, exact * (1 + 0.01 * np.sin(ANGLES)),
             [("viscosity", "0.01:0.2"), ("lubricant.pressure_viscosity", "5:40")],
             ["viscosity=0.03"])
    assert set(f.unidentifiable) == {"viscosity", "lubricant.pressure_viscosity"}
    assert f.singular[-1] < 1e-6
    assert np.isinf(f.half_width).all()
    assert abs(f.correlation[0, 1]) == pytest.approx(1.0, abs=1e-6)
    # the data fix eta^0.70 alpha^0.54, i.e. eta^1 alpha^(0.54/0.70)
    assert f.combinations == [f"viscosity^1 · lubricant.pressure_viscosity^{0.54 / 0.70:.3g}"]
    # and the product itself is recovered
    product = f.value[0] ** 0.70 * f.value[1] ** 0.54
    assert product == pytest.approx(0.05 ** 0.70 * 22.0 ** 0.54, rel=0.01)


def test_run_fit_writes_tables_deck_and_plot(fast_flat, tmp_path):
    import camtrain.api as ct
    from camtrain.study.fit_run import run_fit

    data = tmp_path / "film.csv"
    rows = "".join(f"{a},{h}\n" for a, h in zip(ANGLES, _film(fast_flat), strict=True))
    data.write_text("# solver.angle_points = 180\ncam_angle[deg],film_min[µm]\n" + rows,
                    encoding="utf-8")
    report = run_fit(fast_flat, [data], [("viscosity", "0.01:0.2")], tmp_path / "out",
                     sets=["viscosity=0.02"])
    names = {p.name for p in report.written}
    assert {"fit.csv", "fit.json", "residuals.csv", "singular_values.csv", "calibrated.toml",
            "fit.png"} <= names
    calibrated = ct.load(tmp_path / "out" / "calibrated.toml")
    assert calibrated.model.lubricant.viscosity == pytest.approx(0.05, rel=1e-5)
    assert report.frame("constants").loc["viscosity", "value"] == pytest.approx(0.05, rel=1e-5)
    assert len(report.frame("residuals")) == ANGLES.size


def test_speed_data_fit_a_metric(fast_flat, tmp_path):
    import camtrain.api as ct
    from camtrain.study.fit_run import run_fit

    speeds = [1000.0, 1500.0, 2000.0, 2500.0]
    power = []
    for s in speeds:
        text = fast_flat.read_text(encoding="utf-8").replace("camshaft = 2500.0",
                                                             f"camshaft = {s}")
        power.append(ct.run(ct.loads(text)).metrics["power_loss_mean"].value)
    data = tmp_path / "power.csv"
    data.write_text("speed[rpm],power_loss_mean[W]\n"
                    + "".join(f"{s},{p}\n" for s, p in zip(speeds, power, strict=True)),
                    encoding="utf-8")
    report = run_fit(fast_flat, [data], [("tribology.boundary_friction", "0.02:0.2")],
                     tmp_path / "out", sets=["tribology.boundary_friction=0.05"], plots=False)
    assert report.fit.value[0] == pytest.approx(0.08, rel=1e-4)


@pytest.mark.parametrize("text,words", [
    ("cam_angle,film_min[µm]\n1,2\n", "has no unit"),
    ("angle[deg],film_min[µm]\n1,2\n", "not an abscissa"),
    ("cam_angle[deg],film_min[furlong]\n1,2\n", "not a unit camtrain knows"),
    ("cam_angle[deg],film_min[µm]\n1,x\n", "not all numbers"),
    ("cam_angle[deg],film_min[µm]\n", "at least one row"),
    ("speed[deg],power_loss_mean[W]\n1,2\n", "does not measure a speed"),
    ("cam_angle[mm],film_min[µm]\n1,2\n", "does not measure an angle"),
])
def test_bad_data_files_are_named(tmp_path, text, words):
    path = tmp_path / "d.csv"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(InputError, match=words):
        read_data(path)


def test_wrong_unit_and_unknown_quantity(fast_flat, tmp_path):
    from camtrain.study.fit_run import run_fit

    for header, words in (("cam_angle[deg],film_min[N]", "does not measure"),
                          ("cam_angle[deg],nothing[µm]", "is not a column")):
        data = tmp_path / "d.csv"
        data.write_text(f"{header}\n0,1\n1,1\n2,1\n", encoding="utf-8")
        with pytest.raises(InputError, match=words):
            run_fit(fast_flat, [data], [("viscosity", "0.01:0.2")], tmp_path / "o")


def test_start_outside_the_bounds_is_refused(fast_flat):
    datum = prepare_datum(fast_flat)
    with pytest.raises(InputError, match="outside the bounds"):
        parse_constant(datum.raw, "viscosity", "0.1:0.2")
