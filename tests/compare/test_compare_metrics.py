"""Metrics on analytic curves: interpolation error, log axes, x shift, no extrapolation."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.compare.metrics import Interpolation, compare_curve, interpolate
from rig.compare.sidecar import AxisScale
from rig.errors import ParameterError

LOG = AxisScale.LOG


def test_linear_interpolation_error_of_a_parabola_is_the_analytic_one():
    """Linear interpolation of y = x^2 between nodes x_i, x_i + h overshoots by (x - x_i)(x_i + h - x)."""
    h = 0.01
    x_sim = np.linspace(0.0, 3.0, 301)
    x_ref = np.array([0.123, 0.5, 1.005, 2.2222, 2.999])
    node = np.floor(x_ref / h + 1e-12) * h
    expected = (x_ref - node) * (node + h - x_ref)  # simulated - exact
    result = compare_curve(x_sim, x_sim**2, x_ref, x_ref**2)
    np.testing.assert_allclose(result.deviation, expected, atol=1e-13)
    m = result.metrics
    assert (m.n_compared, m.n_skipped, m.x_shift) == (5, 0, None)
    assert m.max_abs_dev == pytest.approx(h**2 / 4, rel=1e-6)  # x_ref = 1.005 is a midpoint
    assert m.x_at_max_abs_dev == 1.005
    assert m.rmse == pytest.approx(np.sqrt(np.mean(expected**2)), rel=1e-9)
    assert m.max_rel_dev == pytest.approx(np.max(expected / x_ref**2), rel=1e-9)


def test_pchip_is_much_closer_than_linear_on_a_smooth_monotone_curve():
    """y = e^x, h = 0.1, points at mid-cells: linear is off by h^2/8 e^x (to O(h^4)); PCHIP far less."""
    x_sim = np.linspace(0.0, 3.0, 31)
    x_ref = np.linspace(0.05, 2.95, 30)
    linear = compare_curve(x_sim, np.exp(x_sim), x_ref, np.exp(x_ref)).metrics
    pchip = compare_curve(x_sim, np.exp(x_sim), x_ref, np.exp(x_ref), method=Interpolation.PCHIP).metrics
    assert linear.max_abs_dev == pytest.approx(0.1**2 / 8 * np.exp(2.95), rel=1e-3)
    assert linear.max_rel_dev == pytest.approx(0.1**2 / 8, rel=1e-3)
    assert pchip.max_abs_dev < linear.max_abs_dev / 20


def test_log_x_interpolation_is_exact_for_a_logarithm():
    """y = ln x is a straight line in log x: interpolating in log x is exact, in x it is not."""
    x_sim = np.logspace(-2, 4, 7)
    x_ref = np.array([0.02, 0.3, 7.0, 45.0, 2000.0])
    in_log = compare_curve(x_sim, np.log(x_sim), x_ref, np.log(x_ref), x_scale=LOG).metrics
    in_linear = compare_curve(x_sim, np.log(x_sim), x_ref, np.log(x_ref)).metrics
    assert in_log.max_abs_dev < 1e-12
    assert in_linear.max_abs_dev > 0.5


def test_log_log_interpolation_is_exact_for_a_power_law():
    x_sim = np.logspace(0, 5, 6)
    x_ref = np.array([3.0, 170.0, 9.9e4])
    got = interpolate(x_sim, 7.0 / x_sim, x_ref, x_scale=LOG, y_scale=LOG)
    np.testing.assert_allclose(got, 7.0 / x_ref, rtol=1e-12)


def test_no_extrapolation_points_outside_are_skipped():
    x_sim = np.linspace(1.0, 2.0, 11)
    x_ref = np.array([0.5, 0.999, 1.0, 1.5, 2.0, 2.001, 3.0])
    result = compare_curve(x_sim, 3 * x_sim, x_ref, 3 * x_ref)
    np.testing.assert_array_equal(result.compared, [False, False, True, True, True, False, False])
    assert (result.metrics.n_compared, result.metrics.n_skipped) == (3, 4)
    assert np.isnan(result.y_sim[[0, 1, 5, 6]]).all()
    assert np.isnan(interpolate(x_sim, x_sim, np.array([0.0, 5.0]), method=Interpolation.PCHIP)).all()
    with pytest.raises(ParameterError, match="no extrapolation"):
        compare_curve(x_sim, x_sim, np.array([2.5, 3.0]), np.array([1.0, 1.0]))


def test_shift_tolerance_recovers_a_shifted_copy():
    """Digitised points of y = (x + 0.05)^2 read at x: the best shift is +0.05 and then they match."""
    x_sim = np.linspace(0.0, 4.0, 4001)
    x_ref = np.linspace(1.0, 3.0, 21)
    y_ref = (x_ref + 0.05) ** 2
    plain = compare_curve(x_sim, x_sim**2, x_ref, y_ref).metrics
    shifted = compare_curve(x_sim, x_sim**2, x_ref, y_ref, shift_tolerance=0.1).metrics
    assert plain.rmse == pytest.approx(np.sqrt(np.mean((0.1 * x_ref + 0.0025) ** 2)), rel=1e-4)
    assert shifted.x_shift == pytest.approx(0.05, abs=1e-5)
    assert shifted.rmse < 1e-6
    assert shifted.n_compared == 21


def test_relative_shift_on_a_log_axis():
    x_sim = np.logspace(-1, 3, 400)
    x_ref = np.logspace(0, 2, 9)
    y_ref = np.sqrt(1.04 * x_ref)
    result = compare_curve(x_sim, np.sqrt(x_sim), x_ref, y_ref, x_scale=LOG, shift_tolerance=0.1)
    assert result.metrics.x_shift == pytest.approx(0.04, abs=1e-4)
    np.testing.assert_allclose(result.x_compared, 1.04 * x_ref, rtol=1e-4)
    with pytest.raises(ParameterError, match="x_shift_tolerance"):
        compare_curve(x_sim, np.sqrt(x_sim), x_ref, y_ref, x_scale=LOG, shift_tolerance=1.0)


def test_shift_band_must_stay_inside_the_simulated_range():
    """With tol = 0.1 the points within 0.1 of the ends are not compared (no extrapolation at any shift)."""
    x_sim = np.linspace(0.0, 1.0, 101)
    x_ref = np.array([0.05, 0.5, 0.95])
    result = compare_curve(x_sim, x_sim, x_ref, x_ref, shift_tolerance=0.1)
    assert (result.metrics.n_compared, result.metrics.n_skipped) == (1, 2)
    assert result.metrics.x_shift == 0.0  # a straight line through the point: shift 0 is a tie-free optimum


def test_max_rel_dev_ignores_zero_references():
    x = np.linspace(0.0, 1.0, 3)
    m = compare_curve(x, x + 0.1, x, x).metrics
    assert m.max_rel_dev == pytest.approx(0.2)  # 0.1 / 0.5; the point y_ref = 0 is left out
    assert np.isnan(compare_curve(x, x, x, 0 * x).metrics.max_rel_dev)


@pytest.mark.parametrize(
    ("x_sim", "y_sim", "words"),
    [([0.0, 0.0, 1.0], [0, 1, 2], "strictly increasing"), ([0.0], [1.0], "at least 2"),
     ([0.0, np.nan], [1.0, 2.0], "finite"), ([0.0, 1.0], [1.0, 2.0, 3.0], "equal numbers")],
)  # fmt: skip
def test_bad_simulated_curve(x_sim, y_sim, words):
    with pytest.raises(ParameterError, match=words):
        compare_curve(np.array(x_sim), np.array(y_sim), np.array([0.5]), np.array([1.0]))


def test_log_axis_needs_positive_x():
    with pytest.raises(ParameterError, match="> 0 on a log-scaled x axis"):
        compare_curve(np.array([0.0, 1.0]), np.array([0.0, 1.0]), np.array([0.5]), np.array([0.5]), x_scale=LOG)


@settings(max_examples=40, deadline=None)
@given(
    st.lists(st.floats(-5, 5, allow_nan=False), min_size=3, max_size=12),
    st.floats(0.0, 0.5),
    st.integers(0, 2**32 - 1),
)
def test_metrics_are_consistent(y_values, tol, seed):
    """RMSE <= max |dev|; a fitted shift never does worse than no shift on the same points; all finite."""
    rng = np.random.default_rng(np.random.SeedSequence(seed))
    x_sim = np.linspace(0.0, 10.0, len(y_values))
    y_sim = np.array(y_values)
    x_ref = np.sort(rng.uniform(1.0, 9.0, 6))
    y_ref = rng.normal(0.0, 2.0, 6)
    fitted = compare_curve(x_sim, y_sim, x_ref, y_ref, shift_tolerance=tol).metrics
    assert np.isfinite([fitted.rmse, fitted.max_abs_dev, fitted.x_shift]).all()
    assert fitted.rmse <= fitted.max_abs_dev + 1e-12
    assert -tol <= fitted.x_shift <= tol
    zero = compare_curve(x_sim, y_sim, x_ref, y_ref, shift_tolerance=tol)
    unshifted = np.sqrt(np.mean((interpolate(x_sim, y_sim, x_ref) - y_ref)[zero.compared] ** 2))
    assert fitted.rmse <= unshifted + 1e-12
