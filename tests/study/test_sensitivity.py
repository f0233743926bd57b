"""`camtrain sensitivity`: Sobol' and Morris indices of a metric against their closed form.

The steady film at maximum lift of a flat follower is Dowson & Higginson's (1977) line-contact
film, h = 2.65 (eta u)^0.70 alpha^0.54 E'^0.03 R^0.43 (W / b)^-0.13: with the rigid train's
load (spring and inertia, no friction arm on a flat follower) it is a pure power law of the
viscosity eta, the pressure-viscosity coefficient alpha and the cam width b, with the exponents
0.70, 0.54 and +0.13 of the published formula.

For y = C prod x_i^a_i of independent inputs, with m_i = E[x_i^a_i] and s_i = E[x_i^(2 a_i)]:
V = prod s_j - prod m_j^2; the first-order index S_i = (s_i - m_i^2) prod_(j!=i) m_j^2 / V and
the total index S_Ti = (s_i - m_i^2) prod_(j!=i) s_j / V (Sobol' 2001 for a product of
independent factors). E[x^a] = (hi^a - lo^a) / (a ln(hi/lo)) for a log-uniform input and
(hi^(a+1) - lo^(a+1)) / ((a+1)(hi - lo)) for a uniform one.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from camtrain.errors import InputError
from camtrain.study.sensitivity import parse_input, prepare
from camtrain.study.sensitivity_run import run_study

EXPONENTS = {"viscosity": 0.70, "lubricant.pressure_viscosity": 0.54, "cam_width": 0.13}
BOUNDS = {"viscosity": (0.01, 0.1), "lubricant.pressure_viscosity": (10.0, 30.0),
          "cam_width": (8.0, 16.0)}
METRIC = "film_min_at_max_lift"


def _moment(dist: str, lo: float, hi: float, a: float) -> float:
    if dist == "log-uniform":
        return (hi ** a - lo ** a) / (a * math.log(hi / lo))
    return (hi ** (a + 1) - lo ** (a + 1)) / ((a + 1) * (hi - lo))


def closed_form(dist: str) -> dict[str, tuple[float, float]]:
    """(S1, ST) of each input of the power law."""
    names = list(EXPONENTS)
    m = {n: _moment(dist, *BOUNDS[n], EXPONENTS[n]) for n in names}
    s = {n: _moment(dist, *BOUNDS[n], 2 * EXPONENTS[n]) for n in names}
    var = math.prod(s.values()) - math.prod(m.values()) ** 2
    return {n: ((s[n] - m[n] ** 2) * math.prod(m[k] ** 2 for k in names if k != n) / var,
                (s[n] - m[n] ** 2) * math.prod(s[k] for k in names if k != n) / var)
            for n in names}


def _study(deck, dist: str, method: str, samples: int, out, seed: int = 3):
    specs = [(n, dist, f"{lo:g}:{hi:g}") for n, (lo, hi) in BOUNDS.items()]
    study = prepare(deck, specs, method=method, samples=samples, seed=seed, metrics=(METRIC,))
    return run_study(study, out, plots=False)


@pytest.mark.derived
@pytest.mark.parametrize("dist,samples", [("log-uniform", 1024), ("uniform", 512)])
def test_sobol_indices_of_a_power_law_match_the_closed_form(fast_flat, tmp_path, dist, samples):
    report = _study(fast_flat, dist, "sobol", samples, tmp_path / "s")
    assert report.route.batch
    rows = {r["input"]: r for r in report.indices}
    exact = closed_form(dist)
    for name, (s1, st) in exact.items():
        r = rows[name]
        assert abs(r["S1"] - s1) <= r["S1_conf"], (name, r, s1)
        assert abs(r["ST"] - st) <= r["ST_conf"], (name, r, st)
    # the intervals resolve the inputs: each index clear of the next one down
    order = sorted(exact, key=lambda n: -exact[n][1])
    for hi, lo in zip(order, order[1:], strict=False):
        assert rows[hi]["ST"] - rows[hi]["ST_conf"] > rows[lo]["ST"] + rows[lo]["ST_conf"]


@pytest.mark.derived
@pytest.mark.parametrize("dist", ["log-uniform", "uniform"])
def test_morris_ranks_the_inputs_as_the_sobol_indices(fast_flat, tmp_path, dist):
    report = _study(fast_flat, dist, "morris", 32, tmp_path / "m")
    exact = closed_form(dist)
    by_index = sorted(exact, key=lambda n: -exact[n][1])
    by_mu_star = [r["input"] for r in sorted(report.indices, key=lambda r: -r["mu_star"])]
    assert by_mu_star == by_index


def test_outputs_tables_plots_and_distribution(fast_flat, tmp_path):
    report = _study(fast_flat, "log-uniform", "sobol", 64, tmp_path / "o")
    names = {p.name for p in report.written}
    assert {"sweep.csv", "indices.csv", "indices.md", "convergence.csv", "distribution.csv",
            "sensitivity.json"} <= names
    from camtrain.study.sensitivity_output import write_outputs

    plots = write_outputs(report, tmp_path / "o", plots=True)
    assert {"indices.png", "convergence.png", "distribution.png"} <= {p.name for p in plots}
    ladder = sorted({r["samples"] for r in report.convergence})
    assert ladder == [8, 16, 32, 64]
    assert all(r["evaluations"] == r["samples"] * 5 for r in report.convergence)
    dist = report.distribution[0]
    assert dist["metric"] == METRIC and dist["cases"] == 128   # A and B rows only
    assert dist["p05"] < dist["p50"] < dist["p95"]
    frame = report.frame("indices")
    assert list(frame["input"]) == list(BOUNDS)
    assert report.frame("samples").shape[0] == 64 * 5
    cost = (tmp_path / "o" / "indices.md").read_text(encoding="utf-8")
    assert "at 320 cases" in cost and "half as wide takes about 1280 cases" in cost


def test_resume_and_a_larger_sample_reuse_finished_cases(fast_flat, tmp_path):
    out = tmp_path / "r"
    first = _study(fast_flat, "uniform", "sobol", 32, out)
    specs = [(n, "uniform", f"{lo:g}:{hi:g}") for n, (lo, hi) in BOUNDS.items()]
    again = run_study(prepare(fast_flat, specs, samples=32, seed=3, metrics=(METRIC,)), out,
                      resume=True, plots=False)
    assert again.reused == 32 * 5 and again.indices == first.indices
    # the same seed with twice the samples begins with the same cases
    bigger = run_study(prepare(fast_flat, specs, samples=64, seed=3, metrics=(METRIC,)), out,
                       resume=True, plots=False)
    assert bigger.reused == 32 * 5


def test_relative_and_normal_inputs(fast_flat):
    import tomllib

    from camtrain.study.sweep import resolve_path

    raw = tomllib.loads(fast_flat.read_text(encoding="utf-8"))
    rel = parse_input(raw, "base_radius", "relative", "-10%:+10%")
    assert (rel.distribution, rel.a, rel.b) == ("uniform", pytest.approx(16.2), pytest.approx(19.8))
    normal = parse_input(raw, "viscosity", "normal", "+0%:5%")
    assert normal.a == pytest.approx(0.05) and normal.b == pytest.approx(0.0025)
    q = normal.quantile(np.array([0.5, 0.8413447460685429]))
    assert q == pytest.approx([0.05, 0.0525])
    # Morris' levels reach 0 and 1: a normal input's span there is ±3 standard deviations
    assert normal.quantile(np.array([0.0, 1.0]), morris=True) == pytest.approx([0.0425, 0.0575])
    logu = parse_input(raw, "viscosity", "log-uniform", "-50%:+100%")
    assert logu.quantile(np.array([0.0, 0.5, 1.0])) == pytest.approx([0.025, 0.05, 0.1])
    assert resolve_path(raw, "viscosity").datum == 0.05


@pytest.mark.parametrize("name,kind,text,words", [
    ("viscosity", "uniform", "0.1:0.01", "upper bound must exceed"),
    ("viscosity", "log-uniform", "-1:1", "positive bounds"),
    ("viscosity", "uniform", "-1:1", "out of range"),
    ("viscosity", "normal", "0.05:0.02", "leaves the range"),
    ("viscosity", "uniform", "a:1", "is not a number"),
    ("solver.angle_points", "uniform", "100:200", "whole numbers"),
    ("nope", "uniform", "1:2", "not a parameter name"),
])
def test_bad_inputs_name_option_and_value(fast_flat, name, kind, text, words):
    import tomllib

    raw = tomllib.loads(fast_flat.read_text(encoding="utf-8"))
    with pytest.raises(InputError, match=words):
        parse_input(raw, name, kind, text)


def test_sobol_samples_must_be_a_power_of_two(fast_flat):
    with pytest.raises(InputError, match="power of two"):
        prepare(fast_flat, [("viscosity", "uniform", "0.01:0.1")], samples=1000)


def test_local_dask_cluster_gives_the_same_indices(fast_flat, tmp_path):
    distributed = pytest.importorskip("dask.distributed", reason="dask is not installed "
                                      "(optional extra camtrain[dask])")
    specs = [(n, "log-uniform", f"{lo:g}:{hi:g}") for n, (lo, hi) in BOUNDS.items()]
    study = prepare(fast_flat, specs, samples=64, seed=5, metrics=(METRIC, "power_loss_mean"))
    serial = run_study(study, tmp_path / "serial", plots=False)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster:
        dask = run_study(study, tmp_path / "dask", scheduler=cluster.scheduler_address,
                         plots=False)
    assert dask.route.batch
    # the same indices; to the last bits only, since the cluster's chunks of the batch are
    # cut differently, and a chunk whose cases share a value computes with it as a number,
    # where another chunk computes with a column (numpy's vector and scalar powers may differ
    # in the last bit)
    for mine, theirs in zip(dask.indices, serial.indices, strict=True):
        assert mine.keys() == theirs.keys()
        for key, value in mine.items():
            assert value == (pytest.approx(theirs[key], rel=1e-12, abs=1e-15)
                             if isinstance(value, float) else theirs[key])
