"""Williams' acceleration-based lift synthesis (Williams 2013 ch 2, ch 3, §8.5 and §3.1).

Each half of the event is designed as an acceleration diagram from the ramp start (on the base
circle, zero velocity) to the nose, integrated exactly (``_pieces.py``); the maximum acceleration
A and the nose deceleration F are solved so the half ends at the nose with zero velocity and the
required lift. The closing half is the opening one mirrored unless a separate design is given,
which is how Williams builds asymmetric events (a higher closing ramp, a different flank). All
inputs are SI (rad, m, m/rad^2); the book works in deg and mm (convert with ``DEG``, ``MM``).
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift import _pieces as pc
from camtrain.lift.base import TWO_PI, JointJump, LiftLaw


class _TwoHalves(LiftLaw):
    """Opening chain on [-T_open, 0], closing chain mirrored on [0, T_close]."""

    opening_chain: pc.Chain
    closing_chain: pc.Chain

    @property
    def opening_angle(self) -> float:
        return -self.opening_chain.total

    @property
    def closing_angle(self) -> float:
        return self.closing_chain.total

    def _kinematics(self, theta):
        out = [np.zeros_like(theta) for _ in range(4)]
        to, tc = self.opening_chain.total, self.closing_chain.total
        m = theta <= 0.0
        for k, v in enumerate(self.opening_chain.kinematics(theta[m] + to)):
            out[k][m] = v
        m = (theta > 0.0) & (theta <= tc)
        for k, v in enumerate(self.closing_chain.kinematics(tc - theta[m])):
            out[k][m] = v if k % 2 == 0 else -v          # mirrored: odd derivatives change sign
        return tuple(out)

    def joints(self) -> list[tuple[float, str]]:
        to, tc = self.opening_chain.total, self.closing_chain.total
        out = [(-to, "opening ramp start")]
        out += [(t - to, f"opening {label}") for t, label in self.opening_chain.joints()]
        out += [(0.0, "nose")]
        out += [(tc - t, f"closing {label}") for t, label in self.closing_chain.joints()[::-1]]
        return out + [(tc, "closing ramp end")]

    def joint_jumps(self) -> list[JointJump]:
        """Exact jumps at every joint from the one-sided section end values (right minus left).

        Exact rather than sampled because the polynomial section's jerk varies like t^(p-1)
        near its start (p = 1.35 in App 1), which a sampled limit would blur.
        """
        flip = np.array([1.0, -1.0, 1.0, -1.0])        # d/dtheta = -d/dt on the closing side

        def states(chain):
            ends = [np.array(p.kinematics(np.array(x), *chain.start[i]), dtype=float)
                    for i, p in enumerate(chain.pieces) for x in (0.0, 1.0)]
            return ends[0::2], ends[1::2]                 # starts, ends of every piece

        o_start, o_end = states(self.opening_chain)
        c_start, c_end = states(self.closing_chain)
        to, tc = self.opening_chain.total, self.closing_chain.total
        oc, cc = self.opening_chain, self.closing_chain
        rows = [(-to, np.zeros(4), o_start[0])]
        rows += [(e - to, a, b)
                 for e, a, b in zip(oc.edges[1:-1], o_end[:-1], o_start[1:], strict=True)]
        rows += [(0.0, o_end[-1], flip * c_end[-1])]
        rows += [(tc - e, flip * b, flip * a)
                 for e, a, b in zip(cc.edges[1:-1][::-1], c_end[:-1][::-1], c_start[1:][::-1],
                                    strict=True)]
        rows += [(tc, flip * c_start[0], np.zeros(4))]
        return [JointJump(float(angle), label, *(right - left))
                for (angle, left, right), (_, label) in zip(rows, self.joints(), strict=True)]

    def _finish(self, base: str, max_lift: float) -> None:
        if self.event_angle >= TWO_PI:
            raise chk.fail(f"{base}.durations",
                           "make the event longer than one cam revolution (deg)",
                           chk.shown(self.event_angle, "angle"), "a total < 360 deg")
        self._peak = max_lift
        for side, chain in (("opening", self.opening_chain), ("closing", self.closing_chain)):
            _, v, _, _ = chain.kinematics(np.linspace(0.0, chain.total, 2001))
            if v.min() < -1e-9 * max(v.max(), 1e-12):
                p = base if side == "opening" else f"{base}.closing"
                raise chk.fail(f"{p}.durations", f"make the {side} half move the valve backwards "
                               "before the nose", None, "a velocity >= 0 from ramp to nose",
                               "lengthen the deceleration sections or lower the lift")

    @property
    def max_lift(self) -> float:
        return self._peak


def _solve(build, max_lift: float, path: str) -> tuple[float, float, pc.Chain]:
    try:
        A, F = pc.solve_nose(build, max_lift)
    except ZeroDivisionError:
        raise chk.fail(f"{path}.durations", "do not determine the acceleration A and the "
                       "deceleration F", None, "non-zero acceleration and deceleration sections"
                       ) from None
    for name, value in (("maximum acceleration A", A), ("nose deceleration F", F)):
        if not value > 0.0:
            raise chk.fail(f"{path}.durations", f"give a {name} that is not positive",
                           chk.shown(value, "accel_deg"), "a value > 0 mm/deg^2",
                           "the lift is too large or too small for the section lengths")
    return A, F, build(A, F)


# ------------------------------------------------------------------------------ elementary


@dataclass(frozen=True)
class ElementaryHalf:
    """One half of Williams' elementary curve: T0..T4 [rad], ramp lift s0 [m]."""

    durations: Sequence[float]
    ramp_lift: float


def elementary_pieces(T: np.ndarray, A0: float, A: float, F: float) -> list[pc.Piece]:
    """Williams (2013) §2.1, Fig 2.1: constant-acceleration ramp, linear rise to A, constant A,
    linear fall to 0, quarter-sine deceleration to -F at the nose (eqs. 2.1-2.31, with the
    corrected 2.15 and 2.22)."""
    return [pc.constant(T[0], A0, "ramp"), pc.linear(T[1], A0, A, "rise to A"),
            pc.constant(T[2], A, "constant A"), pc.linear(T[3], A, 0.0, "fall to 0"),
            pc.quarter_sine(T[4], F, "quarter sine")]


def elementary_ramp_acceleration(T0: float, s0: float) -> float:
    """A0 = 2 s0 / T0^2, Williams (2013) eq. 2.7."""
    return 2.0 * s0 / T0**2 if T0 > 0.0 else 0.0


class WilliamsElementaryLift(_TwoHalves):
    """Williams' elementary lift curve (Williams 2013 ch 2), mirrored or with its own closing half.

    Parameters (SI)
    ---------------
    opening : ``ElementaryHalf`` (durations T0..T4 [rad], ramp lift s0 [m])
    max_lift : L [m], common to both halves
    closing : optional ``ElementaryHalf``; default the opening half mirrored. Each half solves
        its own F, so unequal halves leave an acceleration step at the nose (see
        ``joint_jumps``); the book's other defects (jerk steps at every joint) are inherent.
    path : deck prefix for error messages
    """

    form = "williams_elementary"

    def __init__(self, opening: ElementaryHalf, max_lift: float,
                 closing: ElementaryHalf | None = None, *, path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        L = chk.scalar(max_lift, f"{base}.max_lift", "length", minimum=0.0, strict=True)
        self.solutions = {}
        chains = []
        for side, half in (("opening", opening), ("closing", closing or opening)):
            p = base if (side == "opening" or closing is None) else f"{base}.closing"
            T = chk.vector(half.durations, f"{p}.durations", min_len=5, max_len=5, kind="angle")
            for i, t in enumerate(T):
                chk.scalar(t, f"{p}.durations[{i}]", "angle", minimum=0.0)
            chk.scalar(T[4], f"{p}.durations[4]", "angle", minimum=0.0, strict=True)
            s0 = chk.scalar(half.ramp_lift, f"{p}.ramp_lift", "length", minimum=0.0,
                            maximum=L)
            if s0 > 0.0 and T[0] == 0.0:
                raise chk.fail(f"{p}.durations[0]", "is zero but the ramp has a lift", 0.0,
                               "a ramp length in deg > 0")
            A0 = elementary_ramp_acceleration(T[0], s0)
            A, F, chain = _solve(lambda a, f, T=T, A0=A0: pc.Chain(elementary_pieces(T, A0, a, f)),
                                 L, p)
            self.solutions[side] = {"A0": A0, "A": A, "F": F}
            chains.append(chain)
        self.opening_chain, self.closing_chain = chains
        self._finish(base, L)


# ------------------------------------------------------------------------------ low jerk


@dataclass(frozen=True)
class LowJerkHalf:
    """One half of Williams' low-jerk curve (Williams 2013 ch 3, Fig 3.2, App 1).

    durations : T0..T12 [rad] (13 values; T11, the polynomial, must be > 0)
    fractions : eps0..eps6 (eps0 of A0 held on the second ramp, eps1..eps6 of A)
    lam : lambda, fraction of F at the start of the polynomial
    p, q : indices of the polynomial (real, > 1, distinct)
    ramp_lift : s1, lift at the end of T1 [m]
    """

    durations: Sequence[float]
    fractions: Sequence[float]
    lam: float
    p: float
    q: float
    ramp_lift: float


def low_jerk_ramp_acceleration(T0: float, T1: float, eps0: float, s1: float) -> float | None:
    """Ramp acceleration A0 giving lift s1 at the end of T1, Williams (2013) eq. 3.63.

    None if the ramp sections cannot produce the lift (zero lengths); 0 for a zero ramp lift.
    """
    unit_lift = 0.25 * T0**2 * (1.0 + eps0 / 7.0) + 0.25 * T0 * T1 * (2.0 + eps0) \
        + 0.5 * T1**2 * eps0
    if s1 == 0.0:
        return 0.0
    return s1 / unit_lift if unit_lift > 0.0 else None


def polynomial_section(T: float, lam: float, p: float, q: float, F: float) -> pc.Piece:
    """a = a11 + b11 t + c11 t^p + d11 t^q from -lam F to -F with zero end jerk and quirk.

    Williams (2013) eqs. 3.147, 3.153-3.155, in the normalised form (C = c11 T^p, D = d11 T^q)
    that avoids T^q overflowing for q = 70.
    """
    g = F * (1.0 - lam)
    b11T = -g * p * q / ((p - 1.0) * (q - 1.0))
    C = -g * q / ((p - 1.0) * (p - q))
    D = g * p / ((q - 1.0) * (p - q))
    return pc.Piece(T, ((-lam * F, 0.0), (b11T, 1.0), (C, p), (D, q)), label="polynomial")


def low_jerk_sections(h: LowJerkHalf, T: np.ndarray, A0: float, A: float, F: float,
                      F0: float) -> list[tuple[str, float, float, float, str]]:
    """(kind, length, start acceleration, end acceleration, name) of the 14 sections, Fig 3.2."""
    e = list(h.fractions)
    return [("fillet", T[0] / 2, 0.0, A0, "first ramp (rise)"),
            ("fillet", T[0] / 2, A0, e[0] * A0, "first ramp (fall)"),
            ("const", T[1], e[0] * A0, e[0] * A0, "constant-acceleration ramp"),
            ("fillet", T[2], e[0] * A0, e[1] * A, "first fillet"),
            ("linear", T[3], e[1] * A, e[2] * A, "linear increase"),
            ("fillet", T[4], e[2] * A, A, "second fillet"),
            ("linear", T[5], A, e[3] * A, "linear acceleration"),
            ("fillet", T[6], e[3] * A, e[4] * A, "third fillet"),
            ("linear", T[7], e[4] * A, e[5] * A, "linear decrease"),
            ("fillet", T[8], e[5] * A, e[6] * A, "fourth fillet"),
            ("linear", T[9], e[6] * A, 0.0, "linear decrease to zero"),
            ("fillet", T[10], 0.0, -h.lam * F, "fifth fillet"),
            ("poly", T[11], -h.lam * F, -F, "polynomial"),
            ("fillet", T[12], -F, -F0, "sixth fillet")]


def low_jerk_pieces(h: LowJerkHalf, T: np.ndarray, A0: float, A: float, F: float, F0: float,
                    path: str) -> list[pc.Piece]:
    """Pieces of one half; fillet end jerks taken from the neighbouring sections (§3.2, §3.4.1).

    Zero-length sections are dropped (Williams' T8 = T9 = 0 option); one that would change the
    acceleration is an error, since it would leave a step.
    """
    secs = low_jerk_sections(h, T, A0, A, F, F0)
    scale = max(abs(A0), abs(A), abs(F), abs(F0), 1e-300)
    kept = []
    for i, (kind, length, a0, a1, name) in enumerate(secs):
        if length > 0.0:
            kept.append((kind, length, a0, a1, name))
        elif abs(a1 - a0) > 1e-12 * scale:
            idx = 0 if i < 2 else i - 1
            raise chk.fail(f"{path}.durations[{idx}]", f"is zero but the {name} changes the "
                           "acceleration", 0.0, "a length > 0 deg, or fractions that make the "
                           "section's start and end accelerations equal")

    def end_jerk(sec, at_start):
        kind, length, a0, a1, _ = sec
        if kind == "linear":
            return (a1 - a0) / length
        if kind == "poly" and at_start:
            return -F * (1.0 - h.lam) * h.p * h.q / (length * (h.p - 1.0) * (h.q - 1.0))
        return 0.0

    pieces = []
    for i, sec in enumerate(kept):
        kind, length, a0, a1, name = sec
        if kind == "fillet":
            j0 = end_jerk(kept[i - 1], False) if i > 0 and kept[i - 1][0] != "fillet" else 0.0
            j1 = (end_jerk(kept[i + 1], True)
                  if i + 1 < len(kept) and kept[i + 1][0] != "fillet" else 0.0)
            pieces.append(pc.fillet(length, a0, j0, a1, j1, name))
        elif kind == "poly":
            pieces.append(polynomial_section(length, h.lam, h.p, h.q, F))
        elif kind == "linear":
            pieces.append(pc.linear(length, a0, a1, name))
        else:
            pieces.append(pc.constant(length, a0, name))
    return pieces


class WilliamsLowJerkLift(_TwoHalves):
    """Williams' low-jerk lift curve (Williams 2013 ch 3; asymmetric halves §3.1, §8.5).

    Parameters (SI)
    ---------------
    opening : ``LowJerkHalf`` for the opening half (ramp start -> nose)
    max_lift : L [m], common to both halves
    nose_deceleration : F0 [m/rad^2] (magnitude), common to both halves so they meet with equal
        acceleration, zero jerk and zero quirk at the nose
    closing : optional ``LowJerkHalf``; default the opening half mirrored
    path : deck prefix for error messages

    After construction ``solutions[side]`` holds A0 (eq. 3.63), A and F (eqs. 3.271-3.272, here
    solved by superposition) in m/rad^2.
    """

    form = "williams_low_jerk"

    def __init__(self, opening: LowJerkHalf, max_lift: float, nose_deceleration: float,
                 closing: LowJerkHalf | None = None, *, path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        L = chk.scalar(max_lift, f"{base}.max_lift", "length", minimum=0.0, strict=True)
        F0 = chk.scalar(nose_deceleration, f"{base}.nose_deceleration", "accel_deg",
                        minimum=0.0, strict=True)
        self.solutions = {}
        chains = []
        for side, h in (("opening", opening), ("closing", closing or opening)):
            p = base if (side == "opening" or closing is None) else f"{base}.closing"
            T = chk.vector(h.durations, f"{p}.durations", min_len=13, max_len=13, kind="angle")
            for i, t in enumerate(T):
                chk.scalar(t, f"{p}.durations[{i}]", "angle", minimum=0.0)
            chk.scalar(T[11], f"{p}.durations[11]", "angle", minimum=0.0, strict=True)
            chk.vector(h.fractions, f"{p}.fractions", min_len=7, max_len=7)
            chk.scalar(h.lam, f"{p}.lam")
            pp = chk.scalar(h.p, f"{p}.p", minimum=1.0, strict=True)
            qq = chk.scalar(h.q, f"{p}.q", minimum=1.0, strict=True)
            if pp == qq:
                raise chk.fail(f"{p}.q", "equals p", qq, "two different polynomial indices")
            s1 = chk.scalar(h.ramp_lift, f"{p}.ramp_lift", "length", minimum=0.0, maximum=L)
            A0 = low_jerk_ramp_acceleration(T[0], T[1], float(h.fractions[0]), s1)
            if A0 is None:
                raise chk.fail(f"{p}.durations[0]", "and the following ramp length give no ramp "
                               "lift", None, "ramp sections of non-zero length")

            def build(a, f, h=h, T=T, A0=A0, p=p):
                return pc.Chain(low_jerk_pieces(h, T, A0, a, f, F0, p))

            A, F, chain = _solve(build, L, p)
            self.solutions[side] = {"A0": A0, "A": A, "F": F}
            chains.append(chain)
        self.opening_chain, self.closing_chain = chains
        self._finish(base, L)
