"""Plots show what the warnings report and use the page: the concave flank in the radius
panel, full sheets for four panels, accuracy.png with its zeros marked and no overlapping
labels."""
from __future__ import annotations

import matplotlib
import numpy as np
import pytest

from camtrain.report.findings import find
from camtrain.report.panels import Ctx, radii
from camtrain.report.sheets import _figure, _panel_rects
from camtrain.report.style import RC
from camtrain.result import Result
from camtrain.study.accuracy_plot import pareto_figure, zero_level
from tests.report.conftest import chain_plan


def _concave_result() -> Result:
    """An 18 mm base circle whose flanks turn concave over a narrow band (down to about
    -170 mm radius): a band too narrow to survive a percentile cut of the axis."""
    theta = np.radians(np.linspace(-180.0, 180.0, 1441))
    deg = np.degrees(theta)
    curvature = (1 - 3.0 * np.exp(-((np.abs(deg) - 30.0) / 1.2) ** 2)) / 0.018
    r = Result()
    r.add_axis("cam_angle", theta, "rad", "cam angle")
    radius = np.where(np.abs(curvature) > 1e-3, 1.0 / curvature, np.inf)
    r.add_column("cam_radius", radius, "m", "cam radius")
    r.add_column("equivalent_radius", radius.copy(), "m", "equivalent radius")
    r.add_column("entrainment", np.ones_like(theta), "m/s", "entrainment velocity")
    r.plan = chain_plan("kinematics")
    return r


def test_radius_panel_shows_the_whole_concave_flank():
    r = _concave_result()
    findings = find(r)
    assert findings.concave, "the finding the panel must show"
    with matplotlib.rc_context(RC):
        fig = _figure((6.4, 3.6))
        ax = fig.add_axes([0.1, 0.1, 0.8, 0.8])
        assert radii(ax, r, Ctx(np.degrees(r["cam_angle"]), findings))
    radius_mm = 1e3 * r["cam_radius"][np.isfinite(r["cam_radius"])]
    lo, hi = ax.get_ylim()
    assert lo <= radius_mm.min() < 0 and hi >= radius_mm.max()
    assert any("concave" in t.get_text() for t in ax.get_legend().get_texts())


def test_four_panel_sheets_fill_the_page():
    """The friction sheet and lift.png (four panels) reach the bottom of the A4 page."""
    rects = _panel_rects(4)
    assert min(y for _, y, _, _ in rects) < 0.08
    six = _panel_rects(6)
    assert min(y for _, y, _, _ in six) < 0.08 and len({x for x, *_ in six}) == 2


def _report():
    def knob(times, errors, values):
        return {"rungs": [{"status": "ok", "wall_time": t, "value": v}
                          for t, v in zip(times, values, strict=True)],
                "worst_error": errors}
    return {"title": "t", "tolerance": 1e-3, "knobs": {
        "angle_points": knob([1e-3, 1.1e-3, 1.2e-3, 4e-3], [1e-2, 9e-3, 8.5e-3, 0.0],
                             [180, 360, 720, 1440]),
        "friction_tolerance": knob([1.05e-3, 1.15e-3], [2e-5, 0.0], [1e-3, 1e-6])}}


def test_accuracy_plot_marks_exact_zeros_and_keeps_labels_apart():
    report = _report()
    fig = pareto_figure(report)
    fig.canvas.draw()
    ax = fig.axes[0]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    zero = zero_level(report)
    assert zero == pytest.approx(2e-6, rel=1e-12)
    assert any("exactly 0" in t and f"{zero:.0e}" in t for t in legend)
    assert ax.get_ylim()[0] > 1e-8          # no unexplained floor at 1e-12
    renderer = fig.canvas.get_renderer()
    boxes = [t.get_window_extent(renderer) for t in ax.texts]
    boxes += [t.get_window_extent(renderer) for t in ax.get_xticklabels(which="both")
              if t.get_text() and t.get_visible()]
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert not a.overlaps(b), "labels overlap"
