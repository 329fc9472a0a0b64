"""Stand A chain: forward simulation -> readings -> reduction returns the truth (Equations §2, 3.1)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from rig.errors import ParameterError, UnknownNameError
from rig.reduction import equations as eq
from rig.reduction import stand_a
from rig.reduction.geometry import StandAGeometry
from rig.reduction.iteration import ReductionSettings
from rig.reduction.result import Start
from rig.reduction.uncertainty import monte_carlo
from rig.wheel_kinematics import dl_dratio, ratio_for_l, stand_a_rolling_point
from tests.reduction.synthetic import (
    OMEGA_1,
    analytic_coefficients,
    rigid_coefficients,
    stand_a_readings,
    stand_a_truth,
)

G = StandAGeometry()
MU = 0.4


def exact_point(l_over_a, mu, normal_force, coefficients, geometry=G, n1=96_000, b_over_a=1.0):
    """Counts chosen first, so that i_k = N2/N1 is exact and the truth is computed at that i_k."""
    n2 = round(n1 * ratio_for_l(l_over_a * geometry.a, geometry.alpha_1, geometry.l1, geometry.l2))
    truth = stand_a_truth(mu, normal_force, n2 / n1, coefficients, geometry, b_over_a)
    return truth, stand_a_readings(n1, n2, truth, normal_force, geometry=geometry, b_over_a=b_over_a)


@pytest.mark.parametrize("normal_force, l_over_a", [(96.2, 0.3), (96.2, 0.8), (385.0, 0.3), (385.0, -0.4)])
def test_rigid_forward_simulation_returns_mu_v_equal_mu_t_equal_mu(normal_force, l_over_a):
    b_over_a = G.b_over_a(normal_force)
    coefficients = rigid_coefficients(b_over_a)
    truth, readings = exact_point(l_over_a, MU, normal_force, coefficients, b_over_a=b_over_a)
    point = stand_a.reduce(readings, coefficients)
    v, u = point.values, point.uncertainties
    assert point.reasons == {}
    assert v["mu_v"] == pytest.approx(MU, rel=1e-9) and v["mu_T"] == pytest.approx(MU, rel=1e-9)
    assert v["l_m"] == pytest.approx(truth.l, abs=1e-12) and v["c_m"] == pytest.approx(truth.c, abs=1e-12)
    assert v["alpha_prime"] == pytest.approx(truth.alpha, rel=1e-9)
    assert 0 < u["mu_v"] < 0.05 and 0 < u["mu_T"] < 0.1 and 0 < u["l_over_a"] < 0.01


def test_alpha_dependent_model_exercises_the_iteration():
    truth, readings = exact_point(0.5, 0.35, 96.2, analytic_coefficients)
    for start in (0.05, 0.3, 2.0):
        point = stand_a.reduce(readings, analytic_coefficients, settings=ReductionSettings(mu_start=start))
        assert point.values["mu_v"] == pytest.approx(0.35, rel=1e-8)
        assert point.values["mu_T"] == pytest.approx(0.35, rel=1e-7)
        assert point.values["alpha_prime"] == pytest.approx(truth.alpha, rel=1e-8)
        assert 2 <= point.iterations < 15


def test_noisy_readings_recover_mu_within_the_stated_uncertainty():
    rng = np.random.default_rng(np.random.SeedSequence(31))
    truth = stand_a_truth(MU, 96.2, ratio_for_l(0.5 * G.a, G.alpha_1, G.l1, G.l2), analytic_coefficients)
    f1 = OMEGA_1 * 60 * 20.0 / (2 * math.pi)
    n1, n2 = int(f1 + rng.uniform()), int(f1 * truth.ratio + rng.uniform())
    readings = stand_a_readings(n1, n2, truth, 96.2, signal_noise=rng.normal(0, 1e-4),
                                t2_noise=rng.normal(0, G.balance_moment_half_width / math.sqrt(3)))
    point = stand_a.reduce(readings, analytic_coefficients)
    for name, true in (("mu_v", MU), ("mu_T", MU), ("l_m", truth.l), ("c_m", truth.c)):
        assert abs(point.values[name] - true) < 3 * point.uncertainties[name], name


def test_first_order_agrees_with_monte_carlo_within_10_percent():
    truth, readings = exact_point(0.4, MU, 96.2, analytic_coefficients, n1=4_800)
    point = stand_a.reduce(readings, analytic_coefficients)
    names = ("l_over_a", "c_over_a", "alpha_prime", "mu_v", "mu_T")

    def model(x):
        return stand_a.evaluate(x, Start(MU, stand_a.DRIVERS), readings=readings, geometry=G,
                                coefficients=analytic_coefficients,
                                settings=ReductionSettings()).values

    mc = monte_carlo(model, point.propagation.inputs, names, 3000, np.random.default_rng(np.random.SeedSequence(5)))
    for name in names:
        assert mc.u(name) == pytest.approx(point.uncertainties[name], rel=0.10), name


@settings(max_examples=60, deadline=None)
@given(l_over_a=st.floats(-0.99, 0.99), gate=st.floats(0.5, 60.0),
       marks=st.sampled_from([(30, 30), (60, 60), (60, 120)]),
       phases=st.tuples(st.floats(0, 0.999), st.floats(0, 0.999)))
def test_round_trip_counts_return_l_within_the_counting_resolution(l_over_a, gate, marks, phases):
    l_true = l_over_a * G.a
    ratio = ratio_for_l(l_true, G.alpha_1, G.l1, G.l2)
    f1 = OMEGA_1 * marks[0] * gate / (2 * math.pi)  # marks passing the photocell in the gate
    f2 = ratio * OMEGA_1 * marks[1] * gate / (2 * math.pi)
    n1, n2 = math.floor(f1 + phases[0]), math.floor(f2 + phases[1])  # counters: +-1 count
    truth = stand_a_truth(MU, 96.2, ratio, analytic_coefficients)
    readings = stand_a_readings(n1, n2, truth, 96.2, marks=marks, gate_time=gate)
    inputs = stand_a.input_set(readings, G)
    out = stand_a.evaluate(inputs.mapping(inputs.values), Start(MU, stand_a.DRIVERS), readings=readings, geometry=G,
                           coefficients=analytic_coefficients, settings=ReductionSettings())
    z = marks[0] / marks[1]
    ratio_hi, ratio_lo = (f2 + 1) / (f1 - 1) * z, (f2 - 1) / (f1 + 1) * z  # exact extremes of N2 z1/(N1 z2)
    l_lo = stand_a_rolling_point(ratio_hi, G.alpha_1, G.l1, G.l2, G.delta_h)[1]
    l_hi = stand_a_rolling_point(ratio_lo, G.alpha_1, G.l1, G.l2, G.delta_h)[1]
    assert l_lo <= out.values["l_m"] <= l_hi
    first_order = abs(dl_dratio(ratio, G.alpha_1, G.l1, G.l2)) * ratio * (1 / n1 + 1 / n2)  # Equations §2
    assert abs(out.values["l_m"] - l_true) <= 1.1 * first_order + 1e-12


def test_zero_counts_give_nan_with_reason_and_negative_counts_raise():
    truth, readings = exact_point(0.3, MU, 96.2, analytic_coefficients)
    point = stand_a.reduce(dataclasses.replace(readings, counts_2=0), analytic_coefficients)
    assert all(math.isnan(v) for k, v in point.values.items() if k != "F_y_N")
    assert point.values["F_y_N"] == pytest.approx(truth.lateral_force, rel=1e-3)  # the dynamometer still reads
    assert "N2 = 0 below min_counts" in point.reasons["mu_T"]
    assert "hard case 2" in point.row()["reason"]
    with pytest.raises(ParameterError, match="counts_1 = -5"):
        dataclasses.replace(readings, counts_1=-5)
    few = stand_a.reduce(readings, analytic_coefficients, settings=ReductionSettings(min_counts=10**6))
    assert math.isnan(few.values["l_over_a"])


def test_vanishing_spin_gives_nan_with_the_named_reason():
    truth, readings = exact_point(0.3, MU, 96.2, analytic_coefficients)
    ratio = readings.counts_2 / readings.counts_1
    flipped = dataclasses.replace(G, alpha_1=-math.asin(ratio))  # sin(alpha1) + i_k = 0
    point = stand_a.reduce(readings, analytic_coefficients, geometry=flipped)
    assert math.isnan(point.values["l_m"]) and "w01 + w02" in point.reasons["l_m"]


def test_c_zero_makes_mu_v_nan_but_mu_t_still_reported():
    geometry = dataclasses.replace(G, delta_h=0.0)  # c = 0: rigid nu_v = 0 exactly
    coefficients = rigid_coefficients(1.0)
    truth, readings = exact_point(0.4, MU, 96.2, coefficients, geometry=geometry)
    point = stand_a.reduce(readings, coefficients, geometry=geometry)
    assert math.isnan(point.values["mu_v"]) and math.isnan(point.uncertainties["mu_v"])
    assert "nu_v" in point.reasons["mu_v"] and "hard case 8" in point.reasons["mu_v"]
    assert point.values["mu_T"] == pytest.approx(MU, rel=1e-9) and point.uncertainties["mu_T"] > 0


def test_vanishing_denominator_of_eq_35_makes_mu_t_nan():
    def denominator(l_over_a):
        nu_t, _, nu_0 = analytic_coefficients(l_over_a, 0.4, 0.6)
        return eq.mu_t_denominator(nu_t, nu_0, l_over_a * G.a, G.l2, G.a)

    root = brentq(denominator, 0.0, 0.5)  # (|l2| + l)|nu_T| = a nu_0 near l/a ~ 0.05
    coefficients = lambda l, c, alpha: analytic_coefficients(root, 0.4, 0.6)  # noqa: E731 (frozen at the root)
    truth, readings = exact_point(root, MU, 96.2, coefficients)
    point = stand_a.reduce(readings, coefficients)
    assert math.isnan(point.values["mu_T"]) and "eq. (35)" in point.reasons["mu_T"]
    assert point.values["mu_v"] == pytest.approx(MU, rel=1e-9)


def test_unidentifiable_mu_is_nan_with_reason():
    def linear_regime(l, c, alpha):  # forces ~ 1/alpha': F = mu F_N nu does not depend on mu
        return -0.3 / alpha, 0.4 / alpha, 1.0 / alpha

    truth, readings = exact_point(0.3, MU, 96.2, linear_regime)
    point = stand_a.reduce(readings, linear_regime, settings=ReductionSettings(max_iterations=20))
    assert math.isnan(point.values["mu_v"]) and "not identifiable" in point.reasons["mu_v"]
    assert math.isnan(point.values["alpha_prime"]) and math.isnan(point.uncertainties["mu_T"])


def test_budget_names_the_instruments():
    truth, readings = exact_point(0.3, MU, 96.2, analytic_coefficients, n1=4_800)
    point = stand_a.reduce(readings, analytic_coefficients, geometry_u={"a": 0.05e-3})
    by = point.budget.by_source()
    assert by.loc["tangent balance", "mu_T"] > 0 and by.loc["tangent balance", "mu_v"] == 0
    assert by.loc["counter 2 (wheel 2)", "l_over_a"] > 0 and by.loc["counter 1 (wheel 1)", "F_y_N"] == 0
    assert by.loc["geometry", "l_over_a"] > 0 and by.loc["calibration weights", "F_y_N"] > 0
    for name in ("l_over_a", "mu_v", "mu_T"):
        assert point.budget.total()[name] == pytest.approx(point.uncertainties[name] ** 2, rel=1e-9)
    # F_y's uncertainty is the weights' 0.235 N (as a rectangular half width) and the calibration
    assert point.budget.uncertainty_by_source().loc["calibration weights", "F_y_N"] == pytest.approx(
        G.lateral_force_half_width / math.sqrt(3), rel=1e-9)
    with pytest.raises(UnknownNameError, match="did you mean 'radius_x'"):
        stand_a.reduce(readings, analytic_coefficients, geometry_u={"radius_y": 1e-3})


def test_configuration_errors_raise():
    truth, readings = exact_point(0.3, MU, 96.2, analytic_coefficients)
    with pytest.raises(ParameterError, match="coefficients"):
        stand_a.reduce(readings, None)
    with pytest.raises(ParameterError, match="marks_1 = 0"):
        dataclasses.replace(readings, marks_1=0)
    with pytest.raises(ParameterError, match="a = 0"):
        StandAGeometry(a=0.0)


@settings(max_examples=40, deadline=None)
@given(n1=st.integers(0, 10**6), n2=st.integers(0, 10**6), dh=st.floats(0.0, 2e-3),
       signal=st.floats(-1.0, 1.0), t2=st.floats(-2.0, 2.0))
def test_any_counts_and_readings_give_finite_values_or_nan_with_a_reason(n1, n2, dh, signal, t2):
    geometry = dataclasses.replace(G, delta_h=dh)
    truth, readings = exact_point(0.3, MU, 96.2, analytic_coefficients, geometry=geometry)
    readings = dataclasses.replace(readings, counts_1=n1, counts_2=n2,
                                   dynamometer_signal=dataclasses.replace(readings.dynamometer_signal, value=signal),
                                   brake_moment=dataclasses.replace(readings.brake_moment, value=t2))
    point = stand_a.reduce(readings, analytic_coefficients, geometry=geometry)
    for name, value in point.values.items():
        assert math.isfinite(value) or point.reasons.get(name), name
        assert math.isnan(point.uncertainties[name]) or point.uncertainties[name] >= 0.0


class _WithNumericalError:
    """Coefficients that state an error bound (as rig.stands.contact_law.LawCoefficients does with
    an error budget): the reduction must carry it, and only it, as the contact model's source."""

    def __init__(self, coefficients, bound):
        self.coefficients, self.bound, self.asked = coefficients, np.asarray(bound, dtype=float), []

    def __call__(self, l_over_a, c_over_a, alpha):
        return self.coefficients(l_over_a, c_over_a, alpha)

    def numerical_error(self, l_over_a, c_over_a, alpha):
        self.asked.append((l_over_a, c_over_a, alpha))
        return self.bound


def test_a_stated_model_error_is_a_budget_source_of_its_own_and_moves_no_value():
    from rig.reduction.coefficients import MODEL_SOURCE, NU_ERRORS

    coefficients = rigid_coefficients(1.0)  # alpha'-independent: d mu_v/d nu_v = -mu_v/nu_v exactly (eq. 33)
    truth, readings = exact_point(0.3, MU, 96.2, coefficients)
    plain = stand_a.reduce(readings, coefficients)
    stated = _WithNumericalError(coefficients, [0.0, 0.002, 0.001])
    point = stand_a.reduce(readings, stated)
    assert stated.asked == [(pytest.approx(plain.values["l_over_a"]), pytest.approx(plain.values["c_over_a"]),
                             pytest.approx(plain.values["alpha_prime"]))]  # once, at the reduced state
    for name in ("mu_v", "mu_T", "l_over_a"):
        assert point.values[name] == pytest.approx(plain.values[name], rel=1e-12)
    by_source = point.budget.by_source()
    assert MODEL_SOURCE in by_source.index and MODEL_SOURCE not in plain.budget.by_source().index
    assert NU_ERRORS[0] not in point.budget.variance.index  # a zero bound adds no input
    expected = (plain.values["mu_v"] / plain.values["nu_v"] * 0.002 / math.sqrt(3.0)) ** 2  # rectangular
    assert point.budget.variance.loc[NU_ERRORS[1], "mu_v"] == pytest.approx(expected, rel=1e-3)
    assert point.uncertainties["mu_v"] ** 2 == pytest.approx(plain.uncertainties["mu_v"] ** 2 + expected, rel=1e-3)
