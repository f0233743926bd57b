"""Build the lift law a deck describes (deck model -> camtrain.lift objects, all SI)."""
from __future__ import annotations

from camtrain import lift as L
from camtrain.deck import schema as S


def _ramps(r: S.Ramps | None) -> L.Ramps | None:
    if r is None:
        return None
    return L.Ramps(opening_height=r.opening_height, opening_length=r.opening_length,
                   closing_height=r.closing_height, closing_length=r.closing_length)


def _segments(segs) -> list[L.Segment] | None:
    if segs is None:
        return None
    return [L.Segment(s.length, tuple(s.coefficients), s.start_lift) for s in segs]


def _elementary(h: S.ElementaryHalf | None):
    return None if h is None else L.ElementaryHalf(tuple(h.durations), h.ramp_lift)


def _low_jerk(h: S.LowJerkHalf | None):
    if h is None:
        return None
    return L.LowJerkHalf(tuple(h.durations), tuple(h.fractions), h.lam, h.p, h.q, h.ramp_lift)


def _table(t: S.Table) -> L.TableLift:
    kwargs = {"symmetric": t.symmetric, "method": t.derivative, "noise": t.noise}
    if t.smoothing is not None:
        kwargs["smoothing"] = t.smoothing
    if t.dataset is not None:
        return L.TableLift.dataset(t.dataset, **kwargs)
    if t.file is not None:
        return L.TableLift.from_csv(t.file, **kwargs)
    return L.TableLift(t.angles, t.lifts, **kwargs)


def build_lift_law(lift: S.Lift) -> L.LiftLaw:
    """The lift law of the deck's [lift] section. Raises InputError naming deck fields."""
    form = lift.form
    if form == "four_power":
        p = lift.four_power
        return L.FourPowerLift(p.half_period, p.max_lift, p.exponents, p.coefficients,
                               _ramps(lift.ramps))
    if form == "multipol":
        p = lift.multipol
        return L.MultipolLift(_segments(p.segments), _segments(p.closing_segments),
                              _ramps(lift.ramps), max_order=p.max_order,
                              check_continuity=p.check_continuity, tolerance=p.tolerance)
    if form == "table":
        return _table(lift.table)
    if form == "exp_poly":
        p = lift.exp_poly
        return L.ExpPolyLift(p.coefficients, cutoff=p.cutoff, blend=p.blend)
    if form == "polynomial":
        p = lift.polynomial
        return L.PolynomialLift(p.half_period, p.max_lift, p.exponents, p.coefficients,
                                _ramps(lift.ramps))
    if form == "williams_elementary":
        p = lift.williams_elementary
        return L.WilliamsElementaryLift(_elementary(p.opening), p.max_lift,
                                        _elementary(p.closing))
    if form == "williams_low_jerk":
        p = lift.williams_low_jerk
        return L.WilliamsLowJerkLift(_low_jerk(p.opening), p.max_lift, p.nose_deceleration,
                                     _low_jerk(p.closing))
    if form == "spline":
        p = lift.spline
        return L.SplineLift(p.knots, p.coefficients, p.degree)
    raise AssertionError(form)  # pragma: no cover - the schema admits only these forms
