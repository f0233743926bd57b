"""The header block of every sheet and of report.txt: key inputs and the power loss (as Ball's)."""
from __future__ import annotations

import importlib
import math

from camtrain.catalogue import DEFAULT_KIND, KINDS, kind_of, planned_products
from camtrain.report.display import fmt
from camtrain.result import Result
from camtrain.units import from_si


def speed_rpm(deck) -> float:
    return deck.speed.omega * 60.0 / (2.0 * math.pi)


def header_rows(deck, result: Result | None) -> list[tuple[str, str]]:
    """(label with unit, value) rows; inputs a deck does not give are left out."""
    if deck is not None:
        header = kind_of(deck).header
        if header:  # a deck kind with a header of its own (e.g. journal_bearing)
            module, function = header.split(":")
            return getattr(importlib.import_module(module), function)(deck, result)
    rows: list[tuple[str, str]] = []
    made = planned_products(result.plan) if result is not None else frozenset()
    if deck is not None:
        m, cam = deck.mechanism, deck.cam
        rows.append(("Follower", m.type))
        rows.append(("Cam base radius (mm)", fmt(from_si(cam.base_radius, "mm"))))
        if result is not None and (result.plan is None or "TrainKinematics" in made):
            # the lift law's peak: every valve-train run (a lift-only run too) has it
            rows.append(("Maximum lift (mm)", fmt(result.metrics["max_lift"].value * 1e3)))
        if cam.width is not None:
            rows.append(("Cam width (mm)", fmt(from_si(cam.width, "mm"))))
        if m.follower_radius is not None:
            rows.append(("Follower radius (mm)", fmt(from_si(m.follower_radius, "mm"))))
        rows.append(("Camshaft speed (rpm)", f"{speed_rpm(deck):g}"))
        if deck.spring is not None:
            rows.append(("Spring stiffness (N/mm)", fmt(from_si(deck.spring.rate, "N/mm"))))
            rows.append(("Initial spring disp. (mm)",
                         fmt(from_si(deck.spring.preload_compression, "mm"))))
        if deck.masses is not None:
            rows.append(("Equiv. mass at valve (kg)", fmt(deck.masses.valve_side)))
        if deck.lubricant is not None:
            lub = deck.lubricant
            rows.append(("Lubricant viscosity (Pa·s)", fmt(lub.viscosity)))
            rows.append(("Press.-visc. coeff. (1/GPa)", fmt(from_si(lub.pressure_viscosity,
                                                                    "1/GPa"))))
            rows.append(("Roughness σ (µm)", fmt(from_si(lub.roughness, "µm"))))
        mat = deck.materials
        rows.append(("Young's mod. cam/foll. (GPa)",
                     f"{fmt(from_si(mat.cam_modulus, 'GPa'))} / "
                     f"{fmt(from_si(mat.follower_modulus, 'GPa'))}"))
        rows.append(("Poisson's ratio cam/foll.",
                     f"{fmt(mat.cam_poisson)} / {fmt(mat.follower_poisson)}"))
    if result is not None and (deck is not None or "ContactLoad" in made):
        p = result.metrics.get("power_loss_mean")
        rows.append(("Frictional power loss (W)", "not computed" if p is None else f"{p.value:.2f}"))
    return rows


def title_line(deck) -> str:
    if deck is None:
        return "camtrain run"
    # a deck kind whose speed is not a camshaft speed names it (the engine deck: "rpm engine")
    return f"{deck.title} — {speed_rpm(deck):g} {getattr(deck, 'speed_label', 'rpm camshaft')}"


def report_heading(deck) -> str:
    """What report.txt and the sheets of this deck's kind are headed (``DeckKind.title``)."""
    return (KINDS[DEFAULT_KIND] if deck is None else kind_of(deck)).title
