"""Ball's multipol: chains of polynomial segments (Ball 1988 §2.2.3, §4.2.1, App F.1.1).

Segment i (length theta_T,i, local angle theta from its start) carries

    l = l_vs + C1 (theta/theta_T) + C2 (theta/theta_T)^2 + ... + C5 (theta/theta_T)^5

with l_vs the lift at the segment start: the ramp height for the first segment and, unless
given, the end lift of the previous segment after that. A chain runs from the end of a
constant-velocity ramp to the nose. The closing flank is either the opening chain mirrored about
the nose (a symmetric lift) or its own chain, also written from its ramp toward the nose.

Ball requires lift, velocity, acceleration and jerk to be continuous at the joints; the
constructor enforces lift, velocity and acceleration (jerk is reported by ``joint_jumps``, since
five-figure coefficients leave small jerk steps) and raises with the joint named otherwise.
"""
from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from camtrain.lift import _checks as chk
from camtrain.lift.base import DEG, MM, TWO_PI, JointJump, LiftLaw
from camtrain.lift.ramps import Ramps, ramp_kinematics

MAX_SEGMENTS = 5
MAX_ORDER = 5


@dataclass(frozen=True)
class Segment:
    """A multipol segment: length [rad], coefficients C1..Cn [m] (n <= 5), start lift [m]."""

    length: float
    coefficients: Sequence[float]
    start_lift: float | None = None


# App F.1.1 of Ball (1988): desmodromic rig valve lift, one half from the ramp end to the nose.
# Lengths in deg, coefficients in mm. Segment 3 C4 is printed +.08113; only -.08113 makes the
# chain continuous (velocity otherwise steps 0.350 -> 0.220 mm/deg at the joint with segment 4).
BALL_APP_F = ((3.0, (0.03700, 0.0, 0.04894, -0.01224, 0.0)),
              (8.0, (0.35969, 0.52204, 0.0, 0.0, 0.0)),
              (5.0, (0.87736, 0.20392, 0.0, -0.08113, 0.02828)),
              (5.0, (1.10212, 0.0, -0.04167, 0.02153, -0.00490)),
              (34.0, (7.06324, -2.07447, -1.44115, 0.34428, 0.00640)))
BALL_APP_F_RAMP_HEIGHT = 0.3333 * MM


def segment_kinematics(coefs: np.ndarray, length: float, start_lift: float, x: np.ndarray):
    """Lift and first three derivatives w.r.t. the segment angle (Ball 1988 App F.1.1).

    ``coefs`` is C1..C5 (zero-padded), ``x`` = theta/theta_T in [0, 1].
    """
    k = np.arange(1, MAX_ORDER + 1, dtype=float)
    xs = np.asarray(x, dtype=float)[..., None]
    c = np.asarray(coefs)
    lift = start_lift + np.sum(c * xs ** k, axis=-1)
    d1 = np.sum(c * k * xs ** (k - 1.0), axis=-1) / length
    d2 = np.sum(c[..., 1:] * k[1:] * (k[1:] - 1.0) * xs ** (k[1:] - 2.0), axis=-1) / length ** 2
    d3 = np.sum(c[..., 2:] * k[2:] * (k[2:] - 1.0) * (k[2:] - 2.0) * xs ** (k[2:] - 3.0),
                axis=-1) / length ** 3
    return lift, d1, d2, d3


class _Chain:
    """Segments laid end to end from a ramp end (local angle s = 0) toward the nose."""

    def __init__(self, segments: Sequence[Segment], start: float, path: str, max_order: int):
        if not 1 <= len(segments) <= MAX_SEGMENTS:
            raise chk.fail(path, f"has {len(segments)} segments", None,
                           f"1 to {MAX_SEGMENTS} segments")
        n = len(segments)
        self.lengths = np.empty(n)
        self.coefs = np.zeros((n, MAX_ORDER))
        self.starts = np.empty(n)
        lift = start
        for i, seg in enumerate(segments):
            p = f"{path}[{i}]"
            self.lengths[i] = chk.scalar(seg.length, f"{p}.length", "angle", minimum=0.0,
                                         strict=True)
            c = chk.vector(seg.coefficients, f"{p}.coefficients", min_len=1, max_len=MAX_ORDER,
                           kind="length")
            if np.any(c[max_order:] != 0.0):
                raise chk.fail(f"{p}.coefficients", f"have terms above the maximum order "
                               f"{max_order}", [chk.shown(v, "length") for v in c],
                               f"zero coefficients beyond C{max_order}")
            self.coefs[i, :c.size] = c
            if seg.start_lift is not None:
                lift = chk.scalar(seg.start_lift, f"{p}.start_lift", "length")
            self.starts[i] = lift
            lift = lift + c.sum()
        self.edges = np.concatenate(([0.0], np.cumsum(self.lengths)))
        self.total = float(self.edges[-1])

    def state(self, i: int, x: float) -> np.ndarray:
        """(lift, d1, d2, d3) of segment i at x in [0, 1], derivatives w.r.t. s."""
        return np.array(segment_kinematics(self.coefs[i], self.lengths[i], self.starts[i],
                                           np.array(x)), dtype=float)

    def kinematics(self, s: np.ndarray):
        i = np.clip(np.searchsorted(self.edges, s, side="right") - 1, 0, self.lengths.size - 1)
        x = (s - self.edges[i]) / self.lengths[i]
        return segment_kinematics(self.coefs[i], self.lengths[i], self.starts[i], x)


class MultipolLift(LiftLaw):
    """Multipol lift, Ball (1988) §2.2.3 and App F.1.1.

    Parameters (SI)
    ---------------
    segments : opening chain, ramp end -> nose (1..5 ``Segment``; lengths rad, coefficients m)
    closing_segments : closing chain, ramp end -> nose; default: ``segments`` mirrored
    ramps : ramp heights [m] and lengths [rad]; a ``None`` opening length is derived as
        height / start velocity of the first segment, so the ramp meets it without a velocity step
    max_order : Ball's "maximum order of polynomials" (1..5); more coefficients are an error
    tolerance : allowed velocity and acceleration jump at a joint, as a fraction of the peak
        |velocity| and |acceleration| of the chain (default 0.5 %); lift joints allow 1 um
    check_continuity : set False to build a discontinuous law anyway (e.g. to report the jumps
        of Ball's printed App F data)
    path : deck prefix for error messages
    """

    form = "multipol"

    def __init__(self, segments: Sequence[Segment],
                 closing_segments: Sequence[Segment] | None = None,
                 ramps: Ramps | None = None, *, max_order: int = MAX_ORDER,
                 tolerance: float = 0.005, check_continuity: bool = True,
                 path: str = "lift") -> None:
        base = f"{path}.{self.form}"
        order = int(chk.scalar(max_order, f"{base}.max_order", minimum=1, maximum=MAX_ORDER))
        ramps = ramps or Ramps()
        oh = chk.scalar(ramps.opening_height, f"{path}.ramps.opening_height", "length",
                        minimum=0.0)
        ch = oh if ramps.closing_height is None else chk.scalar(
            ramps.closing_height, f"{path}.ramps.closing_height", "length", minimum=0.0)
        self.opening = _Chain(segments, oh, f"{base}.segments", order)
        self.mirrored = closing_segments is None
        self.closing = (_Chain(segments, ch, f"{base}.segments", order) if self.mirrored
                        else _Chain(closing_segments, ch, f"{base}.closing_segments", order))
        lengths = []
        for side, chain, h, ln in (("opening", self.opening, oh, ramps.opening_length),
                                   ("closing", self.closing, ch, ramps.closing_length)):
            if ln is None and side == "closing":
                ln = lengths[0] if ramps.opening_length is not None else None
            if ln is None:      # constant-velocity ramp matching the first segment's velocity
                v0 = chain.state(0, 0.0)[1]
                if h > 0.0 and v0 <= 0.0:
                    raise chk.fail(f"{path}.ramps.{side}_length", "cannot be derived", None,
                                   "a length in deg",
                                   "the first segment starts with no upward velocity")
                ln = h / v0 if h > 0.0 else 0.0
            lengths.append(ln)
        self.ramps = Ramps(oh, lengths[0], ch, lengths[1]).resolved(path)
        span = self.opening.total + self.closing.total + lengths[0] + lengths[1]
        if span >= TWO_PI:
            raise chk.fail(f"{base}.segments",
                           "make the event longer than one cam revolution (deg)",
                           chk.shown(span, "angle"), "segments plus ramps < 360 deg")
        self.tolerance = chk.scalar(tolerance, f"{base}.tolerance", minimum=0.0)
        if check_continuity:
            self._check(base)

    @classmethod
    def ball_desmo(cls, corrected: bool = True, **kwargs) -> MultipolLift:
        """Ball (1988) App F.1.1 desmodromic valve lift, mirrored, ramp 0.3333 mm (length derived).

        ``corrected=True`` (default) uses C4 = -0.08113 in segment 3, the only sign that makes the
        chain continuous; ``False`` uses the printed +0.08113 and skips the continuity check.
        """
        segs = [Segment(ln * DEG, [c * MM for c in cs]) for ln, cs in BALL_APP_F]
        if not corrected:
            c = list(segs[2].coefficients)
            c[3] = -c[3]
            segs[2] = Segment(segs[2].length, c)
            kwargs.setdefault("check_continuity", False)
        kwargs.setdefault("ramps", Ramps(BALL_APP_F_RAMP_HEIGHT, None))
        return cls(segs, **kwargs)

    @property
    def opening_angle(self) -> float:
        return -self.opening.total - self.ramps.opening_length

    @property
    def closing_angle(self) -> float:
        return self.closing.total + self.ramps.closing_length

    def _kinematics(self, theta):
        out = [np.zeros_like(theta) for _ in range(4)]
        to, tc, r = self.opening.total, self.closing.total, self.ramps
        m = (theta >= -to) & (theta <= 0.0)
        for k, v in enumerate(self.opening.kinematics(theta[m] + to)):
            out[k][m] = v
        m = (theta > 0.0) & (theta <= tc)
        for k, v in enumerate(self.closing.kinematics(tc - theta[m])):
            out[k][m] = v if k % 2 == 0 else -v          # mirrored: odd derivatives change sign
        for mask, start, length, height, rising in (
                ((theta >= self.opening_angle) & (theta < -to), self.opening_angle,
                 r.opening_length, r.opening_height, True),
                ((theta > tc) & (theta <= self.closing_angle), tc, r.closing_length,
                 r.closing_height, False)):
            if np.any(mask):
                out[0][mask], out[1][mask] = ramp_kinematics(theta[mask], start, length,
                                                             height, rising)
        return tuple(out)

    def joints(self) -> list[tuple[float, str]]:
        return [(j.angle, j.label) for j in self.joint_jumps()]

    def joint_jumps(self) -> list[JointJump]:
        """Exact jumps (right minus left, SI) at every joint, in cam-angle order.

        Uses the one-sided segment end values, so a jump of zero is reported as zero (up to the
        round-off of the coefficient sums).
        """
        flip = np.array([1.0, -1.0, 1.0, -1.0])          # d/dtheta = -d/ds on the closing side
        zero = np.zeros(4)
        r = self.ramps

        def ramp_state(lift, height, length):
            return np.array([lift, height / length if length > 0 else 0.0, 0.0, 0.0])

        o, c, to, tc = self.opening, self.closing, self.opening.total, self.closing.total
        rows = []                                            # (angle, label, left, right)
        if r.opening_length > 0:
            rows.append((self.opening_angle, "opening ramp start", zero,
                         ramp_state(0.0, r.opening_height, r.opening_length)))
        rows.append((-to, "opening ramp / segment 1",
                     ramp_state(r.opening_height, r.opening_height, r.opening_length),
                     o.state(0, 0.0)))
        for i in range(o.lengths.size - 1):
            rows.append((-to + o.edges[i + 1], f"opening segment {i + 1} / segment {i + 2}",
                         o.state(i, 1.0), o.state(i + 1, 0.0)))
        rows.append((0.0, "nose", o.state(o.lengths.size - 1, 1.0),
                     flip * c.state(c.lengths.size - 1, 1.0)))
        for i in range(c.lengths.size - 1, 0, -1):
            rows.append((tc - c.edges[i], f"closing segment {i + 1} / segment {i}",
                         flip * c.state(i, 0.0), flip * c.state(i - 1, 1.0)))
        rows.append((tc, "closing segment 1 / ramp", flip * c.state(0, 0.0),
                     flip * ramp_state(r.closing_height, r.closing_height, r.closing_length)))
        if r.closing_length > 0:
            rows.append((self.closing_angle, "closing ramp end",
                         flip * ramp_state(0.0, r.closing_height, r.closing_length), zero))
        return [JointJump(float(a), label, *(right - left)) for a, label, left, right in rows]

    def _check(self, base: str) -> None:
        theta = np.linspace(self.opening_angle, self.closing_angle, 4001)
        _, d1, d2, _ = self._kinematics(theta)
        limits = (1e-6, self.tolerance * np.max(np.abs(d1)), self.tolerance * np.max(np.abs(d2)))
        names = ("lift", "velocity", "acceleration")
        units = (("mm", 0), ("mm/deg", 1), ("mm/deg^2", 2))
        for jump in self.joint_jumps():
            if jump.label.endswith(("ramp start", "ramp end")):
                continue        # a constant-velocity ramp always steps in velocity off the base
            for k, value in enumerate((jump.lift, jump.d1, jump.d2)):
                if abs(value) > limits[k]:
                    u, order = units[k]
                    shown = value / MM * DEG ** order
                    allowed = limits[k] / MM * DEG ** order
                    where = self._joint_path(base, jump.label)
                    raise chk.fail(where, f"{names[k]} jumps by {shown:+.4g} {u} at the "
                                   f"{jump.label} joint ({jump.angle / DEG:.2f} deg)", None,
                                   f"a jump below {allowed:.3g} {u}",
                                   "check the sign and digits of the coefficients of the "
                                   "segments either side of the joint")

    def _joint_path(self, base: str, label: str) -> str:
        words = label.split()
        closing = words[0] == "closing" and not self.mirrored
        chain = "closing_segments" if closing else "segments"
        digits = [int(w) for w in words if w.isdigit()]
        return f"{base}.{chain}[{min(digits) - 1}]" if digits else f"{base}.{chain}"
