"""Desmodromic valve train: an opening and a closing cam/follower pair (Ball 1988 §3.2.3, App D, F).

The opening cam drives a centrally pivoted follower; the closing cam, whose lift is negative,
drives an end-pivoted follower. Following Ball, the closing lift is negated and the closing pair
is then analysed as a conventional pair (Ball §3.2.3 negates l_v and dl_v/dphi; negating the whole
law, with its second and third derivatives, keeps it self-consistent). The kappa of the closing
follower must therefore be given in the same convention as Ball's App F data (kappa_closing =
kappa_opening - 180 deg there). The loads of each pair follow Ball's App D table.

Note: with kappa_closing = kappa_opening - 180 deg, the closing follower's valve end moves along
the opening direction when its own lift is *negative*; Dyson's equations hold for negative lift,
so ``negate_closing=False`` analyses that exact geometry (the closing cam then dips below its base
circle). With App F's data this exact reading gives a closing-cam nose radius larger than the base
radius, as Ball's §8 text states, while the negated reading gives a smaller one; see
docs/mechanisms.md.
"""
from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from camtrain.errors import field_error
from camtrain.lift.base import LiftCurve
from camtrain.mechanisms.base import Kinematics
from camtrain.mechanisms.pivot_geometry import PivotGeometry
from camtrain.mechanisms.pivoted import pivoted


@dataclass(frozen=True)
class DesmodromicKinematics:
    """Kinematics of the opening pair and of the closing pair (closing lift negated)."""

    opening: Kinematics
    closing: Kinematics


def conventional_closing_lift(closing_lift: LiftCurve) -> LiftCurve:
    """The closing cam's lift as a conventional (positive) law: negated if it is negative.

    Ball §4.2.1 checks the sign of the closing data; a law with both signs is rejected.
    """
    lo, hi = float(np.min(closing_lift.lift)), float(np.max(closing_lift.lift))
    scale = max(abs(lo), abs(hi), 1e-300)
    if hi > 1e-9 * scale and lo < -1e-9 * scale:
        raise field_error("closing_lift", "the closing cam lift must not change sign",
                          (lo, hi), "all <= 0 (Ball's convention) or all >= 0")
    if hi > 1e-9 * scale:
        return closing_lift
    return LiftCurve(theta=closing_lift.theta.copy(), lift=-closing_lift.lift,
                     d1=-closing_lift.d1, d2=-closing_lift.d2, d3=-closing_lift.d3)


def desmodromic(opening_lift: LiftCurve, closing_lift: LiftCurve, opening: PivotGeometry,
                closing: PivotGeometry, *, omega: float, rotation: str | int = "clockwise",
                min_concave_radius: float | None = None,
                negate_closing: bool = True) -> DesmodromicKinematics:
    """Both pairs of a desmodromic train on the same camshaft (same speed and rotation).

    opening_lift: valve lift of the opening pair [m]; closing_lift: lift of the closing pair,
    negative as in Ball's App F (or already negated). Deck: geometry under
    ``mechanism.opening`` and ``mechanism.closing`` with the pivoted-follower field names.
    negate_closing: Ball's convention (default); False analyses the closing lift as given.
    """
    k_open = pivoted(opening_lift, replace(opening, kind="central"), omega=omega,
                     rotation=rotation, min_concave_radius=min_concave_radius)
    closing_law = conventional_closing_lift(closing_lift) if negate_closing else closing_lift
    k_close = pivoted(closing_law, replace(closing, kind="end"),
                      omega=omega, rotation=rotation, min_concave_radius=min_concave_radius)
    return DesmodromicKinematics(opening=replace(k_open, mechanism="desmodromic opening pair"),
                                 closing=replace(k_close, mechanism="desmodromic closing pair"))
