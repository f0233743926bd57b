"""The command lines of `camtrain sensitivity` and `camtrain fit`: files, messages, exit codes."""
from __future__ import annotations

import json

from click.testing import CliRunner

from camtrain.cli import main


def _invoke(args):
    return CliRunner().invoke(main, [str(a) for a in args])


def test_sensitivity_command_writes_its_files(fast_flat, tmp_path):
    out = tmp_path / "s"
    res = _invoke(["sensitivity", fast_flat, "-p", "viscosity", "--log-uniform", "0.02:0.08",
                   "-p", "tribology.boundary_friction", "--relative", "-25%:+25%",
                   "-m", "power_loss_mean", "-n", "32", "-j", "1", "--out", out])
    assert res.exit_code == 0, res.output
    assert "vectorised batch" in res.output and "| power_loss_mean [W] |" in res.output
    for name in ("indices.csv", "indices.md", "convergence.csv", "distribution.csv",
                 "sweep.csv", "sensitivity.json", "plots/indices.png",
                 "plots/convergence.png", "plots/distribution.png"):
        assert (out / name).is_file(), name
    study = json.loads((out / "sensitivity.json").read_text(encoding="utf-8"))
    assert study["evaluations"] == 32 * 4
    assert study["inputs"][1]["a"] == 0.06 and study["inputs"][1]["b"] == 0.1
    res = _invoke(["sensitivity", fast_flat, "-p", "viscosity", "--log-uniform", "0.02:0.08",
                   "-p", "tribology.boundary_friction", "--relative", "-25%:+25%",
                   "-m", "power_loss_mean", "-n", "32", "-j", "1", "--out", out, "--resume",
                   "-q"])
    assert res.exit_code == 0, res.output


def test_sensitivity_bad_arguments_exit_2(fast_flat, tmp_path):
    res = _invoke(["sensitivity", fast_flat, "-p", "viscosity", "--uniform", "0.02:0.08",
                   "-n", "100", "--out", tmp_path])
    assert res.exit_code == 2 and "power of two" in res.output
    res = _invoke(["sensitivity", fast_flat, "-p", "viscosity", "-n", "64"])
    assert res.exit_code == 2 and "--uniform LOW:HIGH" in res.output
    res = _invoke(["sensitivity", fast_flat, "-p", "viscosity", "--uniform", "0.02:0.08",
                   "-m", "nothing", "-n", "4", "--out", tmp_path / "m", "-q"])
    assert res.exit_code == 2 and "nothing" in res.output and "power_loss_mean" in res.output
    assert "Traceback" not in res.output
    assert not (tmp_path / "m").exists()     # refused before anything ran or was written


def test_a_metric_with_failed_cases_is_named_not_estimated(fast_flat, tmp_path):
    # a flat follower on a small base circle needs a concave flank: those cases fail
    res = _invoke(["sensitivity", fast_flat, "-p", "base_radius", "--uniform", "10:18",
                   "-m", "power_loss_mean", "-n", "16", "-j", "1", "--out", tmp_path, "-q"])
    assert res.exit_code == 0, res.output
    assert "power_loss_mean: indices not estimated" in res.output
    assert "cases give no value" in res.output


def test_fit_command(fast_flat, tmp_path):
    import camtrain.api as ct

    result = ct.run(ct.load(fast_flat))
    import numpy as np

    angles = np.arange(-30.0, 31.0, 2.0)
    torque = np.interp(angles, np.degrees(result["cam_angle"]), result["friction_torque"])
    data = tmp_path / "torque.csv"
    data.write_text("cam_angle[deg],friction_torque[N·m]\n"
                    + "".join(f"{a},{t}\n" for a, t in zip(angles, torque, strict=True)),
                    encoding="utf-8")
    out = tmp_path / "f"
    res = _invoke(["fit", fast_flat, "--data", data, "-p", "tribology.boundary_friction",
                   "--bounds", "0.02:0.2", "--set", "tribology.boundary_friction=0.05",
                   "--out", out, "--no-plots"])
    assert res.exit_code == 0, res.output
    assert "tribology.boundary_friction = 0.08" in res.output
    fitted = json.loads((out / "fit.json").read_text(encoding="utf-8"))
    assert abs(fitted["constants"][0]["value"] - 0.08) < 1e-6
    res = _invoke(["fit", fast_flat, "--data", data, "-p", "viscosity", "--out", out])
    assert res.exit_code == 2 and "--bounds LOW:HIGH" in res.output


def test_api_gives_dataframes(fast_flat, tmp_path):
    import pandas as pd

    import camtrain.api as ct

    report = ct.sensitivity(fast_flat, [("viscosity", "log-uniform", "0.02:0.08"),
                                        ("cam_width", "uniform", "10:14")],
                            tmp_path / "s", metrics=["film_min_at_max_lift"], samples=16,
                            plots=False)
    for table in ("indices", "convergence", "distribution", "samples"):
        assert isinstance(report.frame(table), pd.DataFrame)
    assert list(report.frame("indices")["input"]) == ["viscosity", "cam_width"]
    data = tmp_path / "power.csv"
    power = ct.run(ct.load(fast_flat)).metrics["power_loss_mean"].value
    data.write_text(f"speed[rpm],power_loss_mean[W]\n2500,{power}\n2500,{power}\n",
                    encoding="utf-8")
    fitted = ct.fit(fast_flat, [data], [("tribology.boundary_friction", "0.02:0.2")],
                    tmp_path / "f", sets=["tribology.boundary_friction=0.1"], plots=False)
    constants = fitted.frame("constants")
    assert abs(constants.loc["tribology.boundary_friction", "value"] - 0.08) < 1e-6
    assert fitted.frame("correlation").shape == (1, 1)
