"""Camshaft bearing loads: lobe and pulley forces shared between bearings as statically
determinate beams (Ball 1988 §6.3; Yang 1992 §3.3.1, Fig. 3.6).

The shaft is cut at every bearing: each bay between adjacent bearings is a simply supported
beam carrying only the forces that act inside it; a force exactly on a bearing goes to that
bearing. The forces beyond the end bearings (the belt pulley, an overhung cam) are handled by
``overhang``:

* ``"nearest"`` - wholly on the end bearing (Ball adds the pulley load to the front bearing;
  Yang's overhang "systems" have a single adjacent bearing). Default, as the sources.
* ``"lever"`` - the end bay as a beam with an overhang: the end bearing carries F (1 + a/L) and
  the next one -F a/L (a overhang distance, L bay length).

Every force is a 2-D vector in the plane normal to the shaft, resolved along x (normal to the
cylinder-bore axis) and y (along it), as arrays over the camshaft angle. Bearing loads are the
forces the shaft puts on each bearing (the load on its film) [N].
"""
from __future__ import annotations

import math

import numpy as np

from camtrain.errors import field_error

__all__ = ["split_beam_loads", "lobe_force", "pulley_load", "shaft_forces"]


def split_beam_loads(bearing_positions, force_positions, force_x, force_y,
                     overhang: str = "nearest"):
    """Share axial point forces between bearings (statically determinate bays).

    Args:
        bearing_positions: axial bearing positions [m], strictly increasing (>= 1 bearing).
        force_positions: axial position of each force [m].
        force_x, force_y: force components, shape (n_forces,) or (n_forces, n_angles) [N].
        overhang: "nearest" or "lever" (see module notes).

    Returns:
        (bearing_x, bearing_y), each shape (n_bearings, ...) [N]. Their sum equals the sum of
        the forces (vertical equilibrium) in every mode.
    """
    zb = np.asarray(bearing_positions, dtype=float).ravel()
    zf = np.asarray(force_positions, dtype=float).ravel()
    fx = np.asarray(force_x, dtype=float)
    fy = np.asarray(force_y, dtype=float)
    if zb.size < 1 or not np.all(np.isfinite(zb)) or np.any(np.diff(zb) <= 0):
        raise field_error("bearing_positions", "must be finite and strictly increasing",
                          zb.tolist())
    if fx.shape != fy.shape or fx.shape[:1] != zf.shape:
        raise field_error("force_x", "one force row per force position", fx.shape,
                          f"({zf.size}, ...)")
    if overhang not in ("nearest", "lever"):
        raise field_error("overhang", "unknown overhang rule", overhang, "nearest or lever")
    share = np.zeros((zb.size, zf.size))  # fraction of force j carried by bearing i
    for j, z in enumerate(zf):
        if not math.isfinite(z):
            raise field_error("force_positions", "must be finite", z)
        if zb.size == 1:
            share[0, j] = 1.0
            continue
        if z <= zb[0] or z >= zb[-1]:
            end, nxt = (0, 1) if z <= zb[0] else (zb.size - 1, zb.size - 2)
            if overhang == "nearest":
                share[end, j] = 1.0
            else:
                a, span = abs(z - zb[end]), abs(zb[nxt] - zb[end])
                share[end, j] = 1.0 + a / span
                share[nxt, j] = -a / span
            continue
        i = int(np.searchsorted(zb, z, side="right")) - 1
        span = zb[i + 1] - zb[i]
        share[i, j] = (zb[i + 1] - z) / span
        share[i + 1, j] = (z - zb[i]) / span
    return np.tensordot(share, fx, axes=1), np.tensordot(share, fy, axes=1)


def lobe_force(normal_load, friction_force, follower_axis_angle):
    """Force of one follower on its cam lobe, resolved in the engine frame [N].

    Args:
        normal_load: contact normal load W >= 0 [N] (array over the cam angle), acting on the
            cam along the follower axis, away from the follower.
        friction_force: friction on the cam along the follower face [N], signed positive in the
            counter-clockwise tangential sense (z x axis).
        follower_axis_angle: direction from the camshaft axis towards the follower [rad] in the
            (x, y) frame; pi/2 for a follower straight up the bore axis, shifted by the valve
            inclination (Yang: 20 deg) or the V-bank half angle.

    Returns:
        (Fx, Fy) on the camshaft at the lobe [N].
    """
    w = np.asarray(normal_load, dtype=float)
    f = np.asarray(friction_force, dtype=float)
    a = np.asarray(follower_axis_angle, dtype=float)
    ux, uy = np.cos(a), np.sin(a)
    return -w * ux - f * uy, -w * uy + f * ux


def pulley_load(drive_torque, pulley_radius, hub_load_angle, preload: float = 0.0):
    """Belt-pulley hub load on the camshaft [N] (components) - a simple belt model.

    Both spans are taken parallel, pulling along ``hub_load_angle``. The tight-minus-slack
    tension is |T| / r (torque balance); the slack side carries ``preload`` (0 reproduces
    Ball's estimate from the pulley diameter and the drive torque, §6.3; Yang cites a
    torque/force balance, Childs 1991, without data). Hub load = |T|/r + 2 preload.
    """
    r = float(pulley_radius)
    if not (r > 0 and math.isfinite(r)):
        raise field_error("pulley_radius", "must be > 0", r)
    if not (preload >= 0):
        raise field_error("preload", "must be >= 0", preload)
    mag = np.abs(np.asarray(drive_torque, dtype=float)) / r + 2.0 * preload
    return mag * math.cos(hub_load_angle), mag * math.sin(hub_load_angle)


def shaft_forces(lobe_positions, lobe_forces, drive_torque, drive=None):
    """Every force on the camshaft: each lobe's (x, y) and, when ``drive`` = (position, pitch
    radius, hub-load angle, preload) is given, the drive's hub load (:func:`pulley_load`) from
    the summed torque. Returns (positions [m], fx, fy), fx and fy shaped (n_forces, n_angles)."""
    positions = [float(p) for p in lobe_positions]
    fx = [np.asarray(f[0], dtype=float) for f in lobe_forces]
    fy = [np.asarray(f[1], dtype=float) for f in lobe_forces]
    if drive is not None:
        position, radius, angle, preload = drive
        hx, hy = pulley_load(drive_torque, radius, angle, preload)
        positions.append(float(position))
        fx.append(np.asarray(hx, dtype=float))
        fy.append(np.asarray(hy, dtype=float))
    n = np.asarray(drive_torque).size
    if not positions:
        return [], np.zeros((0, n)), np.zeros((0, n))
    return positions, np.array(fx), np.array(fy)
