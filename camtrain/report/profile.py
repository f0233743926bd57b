"""The cam profile drawn to scale with the minimum film laid around it (Ball's periphery plot).

The profile is the locus of contact points in the cam frame (columns contact_x, contact_y); the
film is drawn along the outward normal, magnified by a round factor so the nose and the flanks
can be compared at a glance. Zero-entrainment and loss-of-contact points are marked on it.
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.catalogue import declared_panels, planned_products
from camtrain.report.findings import Findings, in_contact
from camtrain.report.style import COLORS
from camtrain.result import Result


def _nice(x: float) -> float:
    """The largest 1-2-5 number not above x (a magnification people can read)."""
    if x <= 0 or not math.isfinite(x):
        return 1.0
    k = math.floor(math.log10(x))
    for m in (5.0, 2.0, 1.0):
        if m * 10 ** k <= x:
            return m * 10 ** k
    return 10 ** k


def _outward_normals(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    tx = np.roll(x, -1) - np.roll(x, 1)
    ty = np.roll(y, -1) - np.roll(y, 1)
    norm = np.hypot(tx, ty)
    norm[norm == 0] = 1.0
    nx, ny = ty / norm, -tx / norm
    flip = nx * x + ny * y < 0      # the normal must point away from the cam centre
    return np.where(flip, -nx, nx), np.where(flip, -ny, ny)


def draw(ax, r: Result, findings: Findings, base_radius: float | None = None) -> bool:
    """Profile [mm] with the scaled film; returns False when the contact locus is missing."""
    if "profile" not in declared_panels(r.plan):   # the kinematics effect's contact locus
        return False
    from matplotlib.collections import PolyCollection

    theta = r["cam_angle"]
    x, y = r["contact_x"] * 1e3, r["contact_y"] * 1e3
    size = float(np.nanmax(np.hypot(x, y)))
    ax.plot(np.r_[x, x[0]], np.r_[y, y[0]], color="black", lw=1.3, label="cam profile", zorder=3)
    if base_radius:
        t = np.linspace(0, 2 * np.pi, 361)
        rb = base_radius * 1e3
        ax.plot(rb * np.cos(t), rb * np.sin(t), color=COLORS["grey"], lw=0.6, ls="--",
                label=f"base circle r_B = {rb:g} mm", zorder=2)
    ax.plot([0], [0], "+", color="black", ms=8)
    scale_text = ""
    if "ContactFilm" in planned_products(r.plan):
        h_um = np.nan_to_num(r["film_min"] * 1e6, nan=0.0, posinf=0.0)
        contact = in_contact(r)   # with a ContactLoad: no film drawn where contact is lost
        if contact is not None:
            h_um = np.where(contact, h_um, 0.0)
        top = float(np.percentile(h_um, 98)) if np.any(h_um > 0) else 0.0
        if top > 0:
            mag = _nice(0.2 * size / (top * 1e-3))
            shown = np.minimum(h_um, top) * 1e-3 * mag
            nx, ny = _outward_normals(x, y)
            ox, oy = x + nx * shown, y + ny * shown
            quads = [((x[i], y[i]), (x[j], y[j]), (ox[j], oy[j]), (ox[i], oy[i]))
                     for i, j in zip(range(len(x)), np.roll(np.arange(len(x)), -1), strict=True)]
            ax.add_collection(PolyCollection(quads, facecolor=COLORS["film"], edgecolor="none",
                                             alpha=0.55, zorder=1))
            ax.plot(np.r_[ox, ox[0]], np.r_[oy, oy[0]], color=COLORS["film"], lw=0.6,
                    label=f"h_min × {mag:g} (clipped at {top:.3g} µm)", zorder=2)
            scale_text = f"film magnified {mag:g}×"
    i0 = int(np.argmin(np.abs(theta)))
    ax.plot(x[i0], y[i0], "^", color=COLORS["main"], ms=7, label="maximum lift (θ = 0)", zorder=4)
    for k, a in enumerate(findings.zero_entrainment):
        ax.plot(np.interp(a, theta, x), np.interp(a, theta, y), "X", color=COLORS["zero"], ms=8,
                zorder=5, label="zero entrainment" if k == 0 else None)
        ax.annotate(f"{math.degrees(a):+.1f}°", (np.interp(a, theta, x), np.interp(a, theta, y)),
                    textcoords="offset points", xytext=(6, 4), fontsize=7, color=COLORS["zero"])
    for k, (a, b) in enumerate(findings.loss_of_contact):
        for ang in (a, b):
            ax.plot(np.interp(ang, theta, x), np.interp(ang, theta, y), "o", mfc="none",
                    mec=COLORS["second"], ms=8, mew=1.4, zorder=5,
                    label="loss of contact (start, end)" if (k == 0 and ang == a) else None)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x in the cam frame [mm]")
    ax.set_ylabel("y in the cam frame [mm]")
    if scale_text:
        ax.text(0.02, 0.02, scale_text, transform=ax.transAxes, fontsize=7.5,
                color=COLORS["mean"])
    # below the drawing, off the cam and its film (which may fill any corner of the frame)
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=3, fontsize=6.5,
              frameon=False)
    return True
