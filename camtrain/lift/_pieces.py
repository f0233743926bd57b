"""Acceleration-diagram engine for Williams' lift synthesis (Williams 2013 ch 2, ch 3).

A half event (ramp start -> nose) is a chain of pieces, each with a closed-form acceleration in
its normalised local angle tau = t / T in [0, 1]:

    a(tau) = sum_k c_k tau^e_k  -  F_s sin(pi tau / 2)

Powers cover the constant, linear, quintic-fillet and two-index polynomial sections of ch 3; the
sine term is the quarter-sine nose of ch 2. Velocity and lift follow by exact integration with
the start values carried from piece to piece, as Williams' book-keeping method does (§2.2.2,
§3.4), so every joint is continuous in lift and velocity by construction.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Piece:
    """One section: length T [rad], power terms ((c, e), ...) [m/rad^2], quarter-sine amplitude."""

    length: float
    terms: tuple[tuple[float, float], ...]
    sine: float = 0.0
    label: str = ""

    def kinematics(self, tau: np.ndarray, v0: float, s0: float):
        """Lift, velocity, acceleration, jerk at tau (Williams 2013 eqs. 3.13-3.14, 2.26-2.28)."""
        T = self.length
        tau = np.asarray(tau, dtype=float)
        a = np.zeros_like(tau)
        j = np.zeros_like(tau)
        v = np.full_like(tau, v0)
        s = s0 + v0 * T * tau
        with np.errstate(under="ignore"):    # tau^70 early in the polynomial section is 0
            for c, e in self.terms:
                a += c * tau ** e
                if e != 0.0:                 # exponents are 0 or >= 1: tau^(e-1) stays finite
                    j += c * e * tau ** (e - 1.0) / T
                v += c * T * tau ** (e + 1.0) / (e + 1.0)
                s += c * T * T * tau ** (e + 2.0) / ((e + 1.0) * (e + 2.0))
        if self.sine:
            w = 0.5 * np.pi * tau
            k = 2.0 * T / np.pi
            a -= self.sine * np.sin(w)
            j -= self.sine * np.cos(w) / k
            v -= self.sine * k * (1.0 - np.cos(w))
            s -= self.sine * k * k * (w - np.sin(w))
        return s, v, a, j


def constant(T: float, a: float, label: str = "") -> Piece:
    return Piece(T, ((a, 0.0),), label=label)


def linear(T: float, a0: float, a1: float, label: str = "") -> Piece:
    """Acceleration changing linearly from a0 to a1 (Williams 2013 eqs. 2.8, 3.102 ff)."""
    return Piece(T, ((a0, 0.0), (a1 - a0, 1.0)), label=label)


def fillet(T: float, a0: float, j0: float, a1: float, j1: float, label: str = "") -> Piece:
    """Quintic fillet with end accelerations a0, a1, jerks j0, j1 and zero quirks.

    Williams (2013) eqs. 3.1-3.14 (after A. J. Cook), with the corrected 3.11 (jerk, not lift,
    in the bracket) and 3.12; written in tau so the coefficients are c_k T^k.
    """
    d = a1 - a0
    return Piece(T, ((a0, 0.0), (j0 * T, 1.0),
                     (10.0 * d - (4.0 * j1 + 6.0 * j0) * T, 3.0),
                     (-15.0 * d + (7.0 * j1 + 8.0 * j0) * T, 4.0),
                     (6.0 * d - 3.0 * (j1 + j0) * T, 5.0)), label=label)


def quarter_sine(T: float, F: float, label: str = "") -> Piece:
    """a = -F sin(pi t / 2T): Williams (2013) eq. 2.26 (the elementary curve's nose section)."""
    return Piece(T, (), sine=F, label=label)


class Chain:
    """Pieces laid end to end from local angle 0 (ramp start, on the base circle) to the nose."""

    def __init__(self, pieces: Sequence[Piece]):
        self.pieces = [p for p in pieces if p.length > 0.0]
        self.edges = np.concatenate(([0.0], np.cumsum([p.length for p in self.pieces])))
        self.total = float(self.edges[-1])
        v, s = 0.0, 0.0
        self.start = []
        for p in self.pieces:
            self.start.append((v, s))
            s1, v1, _, _ = p.kinematics(np.array(1.0), v, s)
            v, s = float(v1), float(s1)
        self.end_velocity, self.end_lift = v, s

    def end_state(self) -> np.ndarray:
        """(lift, velocity, acceleration, jerk) at the end of the chain."""
        p = self.pieces[-1]
        return np.array(p.kinematics(np.array(1.0), *self.start[-1]), dtype=float)

    def kinematics(self, t: np.ndarray):
        """Lift, velocity, acceleration, jerk at local angles t in [0, total]."""
        t = np.asarray(t, dtype=float)
        out = [np.zeros_like(t) for _ in range(4)]
        idx = np.clip(np.searchsorted(self.edges, t, side="right") - 1, 0, len(self.pieces) - 1)
        for i in np.unique(idx):
            m = idx == i
            p = self.pieces[i]
            vals = p.kinematics((t[m] - self.edges[i]) / p.length, *self.start[i])
            for k in range(4):
                out[k][m] = vals[k]
        return tuple(out)

    def joints(self) -> list[tuple[float, str]]:
        pairs = zip(self.edges[1:-1], self.pieces[:-1], self.pieces[1:], strict=True)
        return [(float(e), f"{a.label} / {b.label}") for e, a, b in pairs]


def solve_nose(build, max_lift: float) -> tuple[float, float]:
    """Solve for (A, F) so the chain ends at the nose with zero velocity and lift ``max_lift``.

    Nose velocity and lift are affine in A and F (every section increment is linear in them,
    Williams 2013 eqs. 2.33-2.72, 3.257-3.272), so three builds give the 2x2 system exactly.
    This replaces the long closed forms, which the tests keep as an oracle.
    """
    base = build(0.0, 0.0)
    ca, cf = build(1.0, 0.0), build(0.0, 1.0)
    m = np.array([[ca.end_velocity - base.end_velocity, cf.end_velocity - base.end_velocity],
                  [ca.end_lift - base.end_lift, cf.end_lift - base.end_lift]])
    rhs = np.array([-base.end_velocity, max_lift - base.end_lift])
    det = np.linalg.det(m)
    if not np.isfinite(det) or abs(det) <= 1e-12 * np.abs(m).max() ** 2:
        raise ZeroDivisionError("the section lengths do not determine A and F")
    A, F = np.linalg.solve(m, rhs)
    return float(A), float(F)
