"""Bare-numpy floor of the Harrison chain: the same physics as ``camtrain run`` on
decks/harrison_flat.toml, written once, flat, with no validation, no objects and no bookkeeping.

It is the yardstick the chain benchmarks divide by (docs/performance.md): four-power lift with
constant-velocity ramps (Ball 1988 §2.2.3, §5.2), flat-faced follower (eqs 3.4-3.6), spring and
valve-side inertia load with the valve clearance (eq. B.4), line Hertz (eqs 3.8-3.10),
Dowson-Higginson minimum and Dowson-Toyoda central film (eqs 4.1, 4.2), Barus shear over the
Hertz zone by the 48-point Gauss-Legendre rule camtrain uses (eq. 4.7 corrected), capped at
mu W, then friction torque, camshaft torque and power (eqs 4.8, 4.9). A test
(tests/test_harrison_floor.py) checks that it reproduces camtrain's columns to 1e-13, so the
floor does the same work, not less.
"""
from __future__ import annotations

import math

import numpy as np

MM = 1e-3
DEG = math.pi / 180.0

#: decks/harrison_flat.toml in SI
HARRISON = dict(
    rpm=2500.0, base_radius=18.0 * MM, width=12.0 * MM,
    half_period=60.0 * DEG, rise=8.9 * MM, exponents=(2.0, 9.0, 78.0, 80.0),
    coefficients=tuple(c * MM for c in (-11.6918407, 2.8498942, -0.5894568, 0.5314033)),
    ramp_height=0.5 * MM, ramp_length=25.0 * DEG,
    rate=38.254e3, preload=6.4 * MM, mass=0.172, clearance=0.4 * MM,
    modulus=207e9, poisson=0.29, eta0=0.050, alpha=22.0e-9, sigma=0.2e-6, mu=0.08,
    film_speed="sum",   # Ball's "entraining velocity" V_c + V_f, as the deck ("mean" = /2)
)

_GL_X, _GL_W = np.polynomial.legendre.leggauss(48)
_GL_COS = np.cos(0.5 * np.pi * _GL_X)
_GL_WEIGHTS = 0.5 * np.pi * _GL_W * _GL_COS


def harrison_floor(points: int, p: dict = HARRISON) -> dict[str, np.ndarray]:
    """Per-angle columns (SI, camtrain's names) and the cycle-mean power of the Harrison chain."""
    theta = -np.pi + 2.0 * np.pi * np.arange(points) / points
    omega = p["rpm"] * 2.0 * np.pi / 60.0
    tp, peak = p["half_period"], p["ramp_height"] + p["rise"]
    start, end = -tp - p["ramp_length"], tp + p["ramp_length"]
    local = start + np.mod(theta - start, 2.0 * np.pi)   # the event in one piece, as camtrain

    # lift law: even power series on |theta| <= tp, constant-velocity ramps outside
    lift, d1, d2 = np.zeros(points), np.zeros(points), np.zeros(points)
    core = np.abs(local) <= tp
    x = np.abs(local[core]) / tp
    sign = np.sign(local[core])
    s0, s1, s2 = np.zeros(x.size), np.zeros(x.size), np.zeros(x.size)
    with np.errstate(under="ignore"):
        for r, c in zip(p["exponents"], p["coefficients"], strict=True):
            p2 = x ** (r - 2.0)
            p1 = p2 * x
            s0 += c * (p1 * x)
            s1 += c * r * p1
            s2 += c * r * (r - 1.0) * p2
    lift[core], d1[core], d2[core] = peak + s0, sign * s1 / tp, s2 / tp ** 2
    slope = p["ramp_height"] / p["ramp_length"]
    opening = (local >= start) & (local < -tp)
    closing = (local > tp) & (local <= end)
    lift[opening], d1[opening] = slope * (local[opening] - start), slope
    lift[closing], d1[closing] = slope * (end - local[closing]), -slope

    # flat-faced follower (clockwise cam, no offset)
    radius = d2 + lift + p["base_radius"]
    v_cam, v_follower = omega * radius, omega * d2
    entrainment = 0.5 * (v_cam + v_follower)
    sliding = v_cam - v_follower
    friction_arm = np.sign(sliding) * (p["base_radius"] + lift)

    # spring + valve-side inertia; zero while the clearance is being taken up
    inside = lift > max(p["clearance"], 5e-8)
    force = p["rate"] * (lift + p["preload"]) + p["mass"] * omega ** 2 * d2
    load = np.where(inside, force, 0.0)

    # line Hertz, EHL films, Barus shear capped at mu W
    e_r = p["modulus"] / (1.0 - p["poisson"] ** 2)
    ok = (load > 0.0) & (radius > 0.0)
    speed = 2.0 * entrainment if p["film_speed"] == "sum" else entrainment
    w, R, u = load[ok] / p["width"], radius[ok], np.abs(speed[ok])
    half_width, pmax = np.zeros(points), np.zeros(points)
    half_width[ok] = np.sqrt(8.0 * w * R / (np.pi * e_r))
    pmax[ok] = np.sqrt(w * e_r / (2.0 * np.pi * R))
    U, G, W = p["eta0"] * u / (e_r * R), p["alpha"] * e_r, w / (e_r * R)
    film_min, film_central = np.full(points, np.nan), np.full(points, np.nan)
    film_min[ok] = R * 2.65 * U ** 0.70 * G ** 0.54 * W ** -0.13
    h = R * 3.06 * U ** 0.69 * G ** 0.56 * W ** -0.10
    film_central[ok] = h
    a = p["alpha"] * pmax[ok]
    log_j = np.log(np.exp(np.multiply.outer(a, _GL_COS)) @ _GL_WEIGHTS)
    shear = p["eta0"] * np.abs(sliding[ok]) / h * half_width[ok] * p["width"]
    friction = np.zeros(points)
    friction[ok] = np.minimum(np.exp(np.log(shear) + log_j), p["mu"] * load[ok])

    torque = friction * friction_arm
    power = torque * omega
    return {"cam_angle": theta, "lift": lift, "velocity": d1, "acceleration": d2,
            "cam_radius": radius, "entrainment": entrainment, "sliding": sliding, "load": load,
            "hertz_pmax": pmax, "hertz_half_width": half_width, "film_min": film_min,
            "film_central": film_central, "lambda": film_min / p["sigma"],
            "friction_force": friction, "friction_torque": torque,
            "cam_torque": load * d1 + torque, "power_loss": power,
            "power_loss_mean": np.array(power.mean())}
