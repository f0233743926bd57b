"""Williams' lift synthesis: elementary (ch 2) and low-jerk (ch 3, App 1) curves, asymmetric halves.

Targets for the App 1 data: A = 0.0144231778 and F = 0.00445273798 mm/deg^2 and a table of
section-end values. They are derived, not printed in the book: an independent implementation of
ch 3 that agrees with the corrected closed form 3.271/3.272 to 9 significant figures. The closed
forms are re-implemented below as an oracle independent of camtrain's superposition solver.
"""
from __future__ import annotations

import math

import numpy as np
import pytest
from _lift_cases import (
    ACC,
    APP1,
    APP1_EPS,
    APP1_T,
    ELEMENTARY_T,
    JERK,
    app1_half,
    app1_law,
    elementary_law,
    problem,
)

from camtrain.errors import InputError
from camtrain.lift import (
    DEG,
    MM,
    ElementaryHalf,
    LowJerkHalf,
    WilliamsElementaryLift,
    WilliamsLowJerkLift,
)

# end of section: (theta from ramp start deg, lift mm, velocity mm/deg, acceleration mm/deg^2)
APP1_TABLE = [
    (12.000, 0.065374, 0.0108996, 1.82e-6), (28.000, 0.240000, 0.0109286, 1.82e-6),
    (31.250, 0.280458, 0.0172598, 0.00576927), (32.250, 0.301083, 0.0244713, 0.00865391),
    (36.500, 0.511837, 0.0787205, 0.01442318), (36.625, 0.521790, 0.0805234, 0.01442318),
    (40.625, 0.955651, 0.1343995, 0.01153854), (47.125, 2.017140, 0.1836186, 0.00360579),
    (50.125, 2.579493, 0.1900383, 0.00108174), (52.125, 2.961012, 0.1911201, 0.0),
    (54.625, 3.437534, 0.1896696, -0.00102413), (104.625, 9.222739, 0.0155798, -0.00445274),
    (108.125, 9.250000, 0.0, -0.00445000)]


def low_jerk_closed_form(T, e, lam, p, q, F0, s1, L):
    """Williams (2013) eqs. 3.63, 3.194-3.272 with the printed typos of 3.199,
    3.212 and 3.256 corrected; deg and mm throughout. Returns A0, A, F."""
    T0, T1, T2, T3, T4, T5, T6, T7, T8, T9, T10, T11, T12 = T
    e0, e1, e2, e3, e4, e5, e6 = e
    A0 = s1 / (T0**2 / 4 * (1 + e0 / 7) + T0 * T1 * (2 + e0) / 4 + T1**2 * e0 / 2)
    R = [sum(T[i + 1:]) for i in range(13)]
    dV0, dV1, dV2 = A0 * T0 * (2 + e0) / 4, A0 * e0 * T1, A0 * e0 * T2 / 2
    dS2 = 5 * A0 * e0 * T2**2 / 14
    dv = {2: e1 * T2 / 2 - (e2 - e1) * T2**2 / (10 * T3),
          3: (e1 + e2) * T3 / 2,
          4: (1 + e2) * T4 / 2 + (e2 - e1) * T4**2 / (10 * T3) - (e3 - 1) * T4**2 / (10 * T5),
          5: (1 + e3) * T5 / 2,
          6: e3 * T6 + (e4 - e3) * T6 / 2 + (e3 - 1) * T6**2 / (10 * T5)
          - (e5 - e4) * T6**2 / (10 * T7),
          7: (e4 + e5) * T7 / 2,
          8: (e5 + e6) * T8 / 2 + T8**2 / 10 * ((e5 - e4) / T7 + e6 / T9),
          9: e6 * T9 / 2,
          10: -e6 * T10**2 / (10 * T9)}
    ds = {2: e1 * T2**2 / 7 - 4 * (e2 - e1) * T2**3 / (105 * T3),
          3: (e1 / 2 + (e2 - e1) / 6) * T3**2,
          4: e2 * T4**2 / 2 + (1 - e2) * T4**2 / 7 + 13 * (e2 - e1) * T4**3 / (210 * T3)
          - 4 * (e3 - 1) * T4**3 / (105 * T5),
          5: T5**2 / 2 + (e3 - 1) * T5**2 / 6,
          6: e3 * T6**2 / 2 + (e4 - e3) * T6**2 / 7 + 13 * (e3 - 1) * T6**3 / (210 * T5)
          - 4 * (e5 - e4) * T6**3 / (105 * T7),
          7: (e4 / 2 + (e5 - e4) / 6) * T7**2,
          8: (e5 / 2 + (e6 - e5) / 7) * T8**2 + (4 * e6 / (105 * T9)
                                                 + 13 * (e5 - e4) / (210 * T7)) * T8**3,
          9: e6 * T9**2 / 3,
          10: -13 * e6 * T10**3 / (210 * T9)}
    k = p * q / ((p - 1) * (q - 1))
    dv10F = -lam * T10 / 2 + k * (1 - lam) * T10**2 / (10 * T11)
    ds10F = -lam * T10**2 / 7 + 4 * k * (1 - lam) * T10**3 / (105 * T11)
    dv11 = -lam * T11 - (1 - lam) * T11 * (k / 2 + q / ((p - q) * (p - 1) * (p + 1))
                                           - p / ((q - 1) * (p - q) * (q + 1)))
    ds11 = -lam * T11**2 / 2 - (1 - lam) * T11**2 * (
        k / 6 + q / ((p - q) * (p - 1) * (p + 1) * (p + 2))
        - p / ((q - 1) * (p - q) * (q + 1) * (q + 2)))
    dv12, ds12 = -T12 / 2, -5 * T12**2 / 14
    SVA = sum(dv.values())
    SSA = sum(ds.values()) + sum(dv[i] * R[i] for i in dv)
    SVF = dv10F + dv11 + dv12
    SSF = ds10F + ds11 + ds12 + dv10F * (T11 + T12) + dv11 * T12
    V0 = dV0 + dV1 + dV2 - F0 * T12 / 2
    S0 = s1 + dS2 + (dV0 + dV1) * R[1] + dV2 * R[2] - F0 * T12**2 / 7
    delta, gamma = V0 / SVF, SVA / SVF
    A = (L + delta * SSF - S0) / (SSA - gamma * SSF)
    return A0, A, -delta - A * gamma


def test_app1_a_and_f():
    """App 1: A0 = 0.00181569016, A = 0.0144231778, F = 0.00445273798 mm/deg^2 (derived,
    not printed). Published to 9-10 significant figures, so the relative tolerance is 1e-8."""
    s = app1_law().solutions["opening"]
    assert s["A0"] / ACC == pytest.approx(0.00181569016, rel=1e-8)
    assert s["A"] / ACC == pytest.approx(0.0144231778, rel=1e-8)
    assert s["F"] / ACC == pytest.approx(0.00445273798, rel=1e-8)


def test_app1_matches_the_corrected_closed_form():
    """The superposition solver equals the corrected closed form 3.271/3.272 to round-off."""
    A0, A, F = low_jerk_closed_form(APP1_T, APP1_EPS, APP1["lam"], APP1["p"], APP1["q"],
                                    APP1["F0"], APP1["s1"], APP1["L"])
    s = app1_law().solutions["opening"]
    assert s["A0"] / ACC == pytest.approx(A0, rel=1e-12)
    assert s["A"] / ACC == pytest.approx(A, rel=1e-9)
    assert s["F"] / ACC == pytest.approx(F, rel=1e-9)


@pytest.mark.parametrize("row", APP1_TABLE)
def test_app1_section_end_values(row):
    """Lift, velocity, acceleration at each section end (derived App 1 table). Printed
    to 6 decimals (lift), 7 (velocity), 8 (acceleration); tolerances are one unit of the last
    digit; the ramp acceleration 1.82e-6 is printed to 3 figures."""
    theta_deg, lift, vel, acc = row
    c = app1_law().evaluate(np.array([(theta_deg - 108.125) * DEG]))
    assert c.lift[0] / MM == pytest.approx(lift, abs=1e-6)
    assert c.d1[0] / MM * DEG == pytest.approx(vel, abs=1e-7)
    assert c.d2[0] / ACC == pytest.approx(acc, abs=1e-8 if abs(acc) > 1e-5 else 5e-9)


def test_app1_extremes():
    """Max velocity 0.191120 mm/deg at 52.125 deg; max jerk 2.886e-3 mm/deg^3 at ~31.0 deg, min
    -1.220e-3 at ~40.6 deg (derived; 1/64 deg sampling, angles to +-0.1 deg)."""
    theta = np.arange(0.0, 108.125, 1.0 / 64.0)
    c = app1_law().evaluate((theta - 108.125) * DEG)
    v, j = c.d1 / MM * DEG, c.d3 / JERK
    assert v.max() == pytest.approx(0.191120, abs=1e-6)
    assert theta[np.argmax(v)] == pytest.approx(52.125, abs=0.05)
    assert j.max() == pytest.approx(2.886e-3, abs=1e-6)
    assert theta[np.argmax(j)] == pytest.approx(31.0, abs=0.1)
    assert j.min() == pytest.approx(-1.220e-3, abs=1e-6)
    assert theta[np.argmin(j)] == pytest.approx(40.6, abs=0.1)


def test_app1_is_continuous_to_the_jerk():
    """Every joint continuous in lift, velocity, acceleration and jerk (the design intent; the
    exact section end values agree to round-off, 1e-12 of the scale)."""
    for j in app1_law().joint_jumps():
        e = j.in_mm_deg()
        assert abs(e["lift_mm"]) < 1e-12 and abs(e["d1_mm_per_deg"]) < 1e-12
        assert abs(e["d2_mm_per_deg2"]) < 1e-12 and abs(e["d3_mm_per_deg3"]) < 1e-12, j.label


def test_asymmetric_halves_meet_at_the_nose():
    """Separate closing half with a higher ramp (Williams §1.2.2, §2.8.6): both halves end at L
    with zero velocity, acceleration -F0 and zero jerk, so the nose joint is smooth; the two
    halves solve different A and F."""
    law = WilliamsLowJerkLift(app1_half(), 9.25 * MM, 0.00445 * ACC,
                              closing=app1_half(s1=0.30, T=[12.0, 20.0] + APP1_T[2:]))
    nose = [j for j in law.joint_jumps() if j.label == "nose"][0].in_mm_deg()
    assert all(abs(v) < 1e-12 for k, v in nose.items() if k != "angle_deg")
    c = law.evaluate(np.array([0.0]))
    assert c.d2[0] / ACC == pytest.approx(-0.00445, rel=1e-12)
    assert law.closing_angle / DEG == pytest.approx(112.125)
    assert law.solutions["closing"]["A"] != pytest.approx(law.solutions["opening"]["A"])
    assert law.evaluate(np.array([(112.125 - 32.0) * DEG])).lift[0] / MM == pytest.approx(0.30)


def test_zero_length_sections_option():
    """T8 = T9 = 0 (Williams §3.4.1) with eps5 = eps6 = 0: the fifth fillet takes its start jerk
    from section 7, so the curve stays jerk-continuous; eps5 != 0 would leave an acceleration
    step and is refused naming T8."""
    T = APP1_T[:8] + [0.0, 0.0] + APP1_T[10:]
    eps = APP1_EPS[:5] + [0.0, 0.0]
    law = WilliamsLowJerkLift(app1_half(T=T, eps=eps), 9.25 * MM, 0.00445 * ACC)
    for j in law.joint_jumps():
        assert abs(j.d2) < 1e-12 and abs(j.d3) < 1e-12
    with pytest.raises(InputError) as err:
        WilliamsLowJerkLift(app1_half(T=T), 9.25 * MM, 0.00445 * ACC)
    assert problem(err.value).path == "lift.williams_low_jerk.durations[8]"


def test_elementary_matches_the_corrected_closed_form():
    """A from eq. 2.72 and F from eq. 2.68 (deg, mm); the printed 2.73 gives a different,
    negative F, which is why camtrain does not use it (a typo in the book)."""
    T0, T1, T2, T3, T4 = ELEMENTARY_T
    s0, L = 0.25, 9.0
    A0 = 2 * s0 / T0**2
    Ab0, Ab = A0 * (T0 + T1 / 2), (T1 + T3) / 2 + T2
    Ah0 = A0 * (T0**2 / 2 + T0 * (T1 + T2 + T3 + T4) + T1**2 / 3 + T1 / 2 * (T2 + T3 + T4))
    Ah = (T1**2 / 6 + T2**2 / 2 + T3**2 / 3 + T1 / 2 * (T2 + T3 + T4) + T2 * (T3 + T4)
          + T3 * T4 / 2)
    Fh = 2 * T4 / math.pi * (math.pi / 2 - 1)
    A = (L - Ah0 + Fh * Ab0) / (Ah - Fh * Ab)
    F = math.pi * (Ab0 + A * Ab) / (2 * T4)
    F_printed = math.pi * (Ab0 + Ab * (L - Ah + Fh * Ab0)) / (2 * T4 * (Ah - Fh * Ab))
    s = elementary_law().solutions["opening"]
    assert s["A0"] / ACC == pytest.approx(A0, rel=1e-12)
    assert s["A"] / ACC == pytest.approx(A, rel=1e-10)
    assert s["F"] / ACC == pytest.approx(F, rel=1e-10)
    assert F_printed < 0 < F


def test_elementary_nose_and_jerk_steps():
    """Nose: lift L, zero velocity, acceleration -F, zero jerk (eq. 2.26-2.31). The jerk steps
    at the section joints are the curve's known defect (Williams §2.2.3)."""
    law = elementary_law()
    c = law.evaluate(np.array([0.0]))
    assert c.lift[0] / MM == pytest.approx(9.0, abs=1e-12)
    assert abs(c.d1[0]) < 1e-15
    assert c.d2[0] == pytest.approx(-law.solutions["opening"]["F"], rel=1e-12)
    steps = [abs(j.d3) for j in law.joint_jumps() if j.label != "nose"]
    assert min(steps[1:-1]) > 0.0


def test_elementary_asymmetric_reports_nose_acceleration_step():
    closing = ElementaryHalf([12 * DEG, 8 * DEG, 10 * DEG, 12 * DEG, 50 * DEG], 0.35 * MM)
    law = WilliamsElementaryLift(ElementaryHalf([t * DEG for t in ELEMENTARY_T], 0.25 * MM),
                                 9.0 * MM, closing=closing)
    nose = [j for j in law.joint_jumps() if j.label == "nose"][0]
    expected = law.solutions["opening"]["F"] - law.solutions["closing"]["F"]
    assert nose.d2 == pytest.approx(expected, rel=1e-9)
    assert abs(nose.lift) < 1e-15 and abs(nose.d1) < 1e-12


@pytest.mark.parametrize("change, path", [
    ({"p": 1.0}, "lift.williams_low_jerk.p"),
    ({"q": 1.35}, "lift.williams_low_jerk.q"),
    ({"T": APP1_T[:11] + [0.0, 3.5]}, "lift.williams_low_jerk.durations[11]"),
    ({"T": APP1_T[:12]}, "lift.williams_low_jerk.durations"),
    ({"T": [-1.0] + APP1_T[1:]}, "lift.williams_low_jerk.durations[0]"),
    ({"T": [100.0] + APP1_T[1:]}, "lift.williams_low_jerk.durations"),
    ({"s1": 10.0}, "lift.williams_low_jerk.ramp_lift"),
    ({"eps": APP1_EPS[:6]}, "lift.williams_low_jerk.fractions"),
])
def test_low_jerk_bad_input(change, path):
    with pytest.raises(InputError) as err:
        WilliamsLowJerkLift(app1_half(**change), 9.25 * MM, 0.00445 * ACC)
    assert problem(err.value).path == path


def test_low_jerk_impossible_lift_and_deceleration():
    for L, F0 in ((0.3, 0.00445), (9.25, float("inf")), (9.25, -1.0)):
        with pytest.raises(InputError) as err:
            WilliamsLowJerkLift(app1_half(), L * MM, F0 * ACC)
        assert problem(err.value).path.startswith("lift.williams_low_jerk.")


def test_closing_half_errors_name_the_closing_fields():
    bad = LowJerkHalf(app1_half().durations, APP1_EPS, 0.23, 1.35, 1.35, 0.24 * MM)
    with pytest.raises(InputError) as err:
        WilliamsLowJerkLift(app1_half(), 9.25 * MM, 0.00445 * ACC, closing=bad)
    assert problem(err.value).path == "lift.williams_low_jerk.closing.q"
