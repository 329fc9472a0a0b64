"""Harris amplitudes (S1)-(S3) and the stroke ratio e = x/2b (S15) for the FAG 7208 of [Oscillating]."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.bearing.amplitude import (
    MAX_DOUBLE_AMPLITUDE,
    KinematicAssumption,
    amplitude_for_stroke_ratio,
    critical_amplitude,
    dither_amplitude,
    rolled_distance,
    stroke_ratio,
)
from rig.bearing.ball_raceway import Ring, raceway_contact
from rig.bearing.fag7208 import FAG_7208, TABLE_2, THETA_CRIT_PUBLISHED_DEG, reproduce_table_2
from rig.errors import ParameterError

K = KinematicAssumption
# Equations §5.1: e = 1 double amplitudes [deg] per assumption for 1.27 / 0.79 / 3.17 kN
SEED_NOTES_E1 = {K.K1: (1.63, 1.39, 2.21), K.K3: (1.42, 1.21, 1.92), K.K2: (1.20, 1.03, 1.63), K.K4: (1.38, 1.18, 1.88)}
SEED_NOTES_E15 = {K.K1: (2.45, 2.09, 3.32), K.K3: (2.12, 1.81, 2.88)}


def b_inner(force: float) -> float:
    return raceway_contact(FAG_7208, Ring.INNER, force).b


@pytest.mark.parametrize("assumption", list(SEED_NOTES_E1))
def test_e1_amplitudes_per_assumption_match_the_equations_page(assumption):
    for case, expected in zip(TABLE_2, SEED_NOTES_E1[assumption]):
        theta = amplitude_for_stroke_ratio(FAG_7208, 1.0, b_inner(case.force_N), assumption)
        assert math.degrees(theta) == pytest.approx(expected, abs=0.006)
    for case, expected in zip(TABLE_2, SEED_NOTES_E15.get(assumption, ())):
        theta = amplitude_for_stroke_ratio(FAG_7208, 1.5, b_inner(case.force_N), assumption)
        assert math.degrees(theta) == pytest.approx(expected, abs=0.006)


def test_acceptance_e1_amplitudes_beside_the_published_ones():
    """ACCEPTANCE (issue 6, item 3): K3 (default) gives 1.42/1.21/1.92 deg beside the published
    1.5/1.2/2.0 (FE model): -5.6 / +0.8 / -4.0 %. The published values lie between K3 and K1
    (within their 0.05-deg rounding) - docs/ball-bearing.md explains the deviation."""
    table = reproduce_table_2()
    deviation = table["theta_e1_deg"] / table["theta_e1_deg_published"] - 1.0
    assert list(deviation.round(3)) == pytest.approx([-0.056, 0.008, -0.040], abs=0.0015)
    k1 = reproduce_table_2(assumption=K.K1)
    for row, upper in zip(table.itertuples(), k1["theta_e1_deg"]):
        assert row.theta_e1_deg - 0.05 <= row.theta_e1_deg_published <= upper


def test_default_assumption_is_k3():
    b = b_inner(1270.0)
    assert stroke_ratio(FAG_7208, 0.02, b) == stroke_ratio(FAG_7208, 0.02, b, K.K3)


def test_k3_track_length_is_the_same_on_both_raceways():
    """Rolling without slip: inner-ring angle relative to the cage times r_i = outer ring's times r_o."""
    theta, g = 0.03, FAG_7208.gamma
    cage = theta * (1.0 - g) / 2.0  # outer ring fixed, inner ring turns theta
    on_inner = (theta - cage) * FAG_7208.contact_radius(Ring.INNER)
    on_outer = cage * FAG_7208.contact_radius(Ring.OUTER)
    assert on_inner == pytest.approx(on_outer)
    assert rolled_distance(FAG_7208, theta) == pytest.approx(on_inner)
    assert rolled_distance(FAG_7208, theta, K.K1) == pytest.approx(cage * FAG_7208.pitch_radius)


def test_harris_critical_amplitude():
    """theta_crit = 720 deg/(Z (1 -/+ gamma)): the published 51.42 deg is 720/14 (Z = 14, gamma
    neglected); with gamma = 0.151 it would be 60.6 (outer, 1 - gamma) or 44.7 deg (inner)."""
    assert math.degrees(critical_amplitude(14, 0.0, Ring.OUTER)) == pytest.approx(THETA_CRIT_PUBLISHED_DEG, abs=0.01)
    assert math.degrees(critical_amplitude(14, FAG_7208.gamma, Ring.OUTER)) == pytest.approx(60.6, abs=0.05)
    assert math.degrees(critical_amplitude(14, FAG_7208.gamma, Ring.INNER)) == pytest.approx(44.7, abs=0.05)


def test_harris_dither_amplitude():
    """theta_dith = 720 b/(pi d_m (1 - gamma)) deg is half the K1 double amplitude at e = 1."""
    b = b_inner(1270.0)
    dith = dither_amplitude(b, FAG_7208.pitch_diameter, FAG_7208.gamma, Ring.OUTER)
    assert math.degrees(dith) == pytest.approx(720.0 * b / (math.pi * 0.060 * (1.0 - FAG_7208.gamma)), rel=1e-12)
    assert 2.0 * dith == pytest.approx(amplitude_for_stroke_ratio(FAG_7208, 1.0, b, K.K1), rel=1e-12)


@settings(max_examples=50, deadline=None)
@given(theta=st.floats(0.0, MAX_DOUBLE_AMPLITUDE), assumption=st.sampled_from(list(K)))
def test_stroke_ratio_inverse_and_small_amplitudes(theta, assumption):
    b = b_inner(790.0)
    e = stroke_ratio(FAG_7208, theta, b, assumption)
    assert math.isfinite(e) and e >= 0.0
    assert amplitude_for_stroke_ratio(FAG_7208, e, b, assumption) == pytest.approx(theta, rel=1e-12, abs=1e-300)


def test_tiny_amplitudes_are_finite():
    b = b_inner(1270.0)
    assert stroke_ratio(FAG_7208, 1e-300, b) == pytest.approx(1e-300 * 0.060 * (1 - FAG_7208.gamma**2) / 4 / (2 * b))
    assert stroke_ratio(FAG_7208, 0.0, b) == 0.0
    assert amplitude_for_stroke_ratio(FAG_7208, 0.0, b) == 0.0


def test_invalid_amplitudes_raise_named_errors():
    b = b_inner(1270.0)
    for theta in (-0.01, 7.0, math.nan, math.inf):
        with pytest.raises(ParameterError, match="theta"):
            stroke_ratio(FAG_7208, theta, b)
    with pytest.raises(ParameterError, match="half_width"):
        stroke_ratio(FAG_7208, 0.01, 0.0)
    with pytest.raises(ParameterError, match=r"^e = -1\.0"):
        amplitude_for_stroke_ratio(FAG_7208, -1.0, b)
    with pytest.raises(ParameterError, match=r"^e = 1000000\.0 .*254\.196"):
        amplitude_for_stroke_ratio(FAG_7208, 1e6, b)
    with pytest.raises(ParameterError, match="assumption"):
        stroke_ratio(FAG_7208, 0.01, b, "K3")
    with pytest.raises(ParameterError, match="balls"):
        critical_amplitude(0, 0.1, Ring.OUTER)
    with pytest.raises(ParameterError, match="gamma"):
        critical_amplitude(14, 1.0, Ring.OUTER)
    with pytest.raises(ParameterError, match="raceway|ring"):
        critical_amplitude(14, 0.1, "outer")
