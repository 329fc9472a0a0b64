"""The mu <-> alpha' fixed point on maps with known fixed points (hard case 8)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.reduction.iteration import ReductionSettings, solve_mu

SETTINGS = ReductionSettings()


def fixed_map(g):
    calls = []

    def estimate(mu):
        calls.append(mu)
        return g(mu), {"mu_in": mu}, ""

    return estimate, calls


def test_alpha_independent_model_converges_in_three_evaluations_and_a_probe():
    estimate, calls = fixed_map(lambda mu: 0.42)
    fp = solve_mu(estimate, SETTINGS)
    assert fp.reason == "" and fp.mu == pytest.approx(0.42, rel=1e-12) and len(calls) == 4
    assert fp.state["mu_in"] == fp.mu  # the state at the fixed point, not at the probe


@given(power=st.floats(-0.8, 3.0), target=st.floats(0.05, 1.5), start=st.floats(0.01, 3.0))
def test_power_law_maps_converge_to_their_fixed_point_from_any_start(power, target, start):
    # g = t (t/mu)^p is mu_v when nu_v ~ alpha'^p (p ~ 1 near full sliding, c = 0): slope -p at the fixed point
    estimate, _ = fixed_map(lambda mu: target * (target / mu) ** power)
    fp = solve_mu(estimate, ReductionSettings(mu_start=start))
    assert fp.reason == ""
    assert fp.mu == pytest.approx(target, rel=1e-7)
    assert fp.state["mu_in"] == fp.mu


@given(power=st.floats(-0.8, 3.0), target=st.floats(0.05, 1.5),
       start=st.one_of(st.floats(0.5, 0.9), st.floats(1.1, 2.0)))  # a start on the fixed point needs one estimate
def test_a_known_slope_makes_the_first_step_newtons(power, target, start):
    # a perturbed evaluation restarts at the nominal fixed point with its probed slope: on a power law
    # (ln g linear in ln mu, slope -p) the first step lands on the fixed point, the second estimate confirms it
    estimate, calls = fixed_map(lambda mu: target * (target / mu) ** power)
    fp = solve_mu(estimate, SETTINGS, probe=False, mu_start=target * start, slope=-power)
    assert fp.mu == pytest.approx(target, rel=1e-9) and len(calls) == 2
    estimate, calls = fixed_map(lambda mu: target * (target / mu) ** power)
    assert solve_mu(estimate, SETTINGS, probe=False, mu_start=target * start).mu == pytest.approx(target, rel=1e-7)


def test_the_probe_reports_the_slope_at_the_fixed_point():
    estimate, _ = fixed_map(lambda mu: 0.3 * (0.3 / mu) ** 0.6)  # d ln g/d ln mu = -0.6 everywhere
    assert solve_mu(estimate, SETTINGS).slope == pytest.approx(-0.6, rel=1e-9)


def test_nonlinear_falling_map_like_mu_v_of_alpha():
    # g(mu) = F/(F_N nu_v(k mu)) with nu_v rising in alpha': fixed point of mu (0.3 + 0.1 mu) = 0.1318...
    estimate, calls = fixed_map(lambda mu: 0.04 / (0.3 + 0.1 * mu) * 1.0)
    fp = solve_mu(estimate, SETTINGS)
    exact = (-0.3 + math.sqrt(0.09 + 4 * 0.1 * 0.04)) / (2 * 0.1)
    assert fp.mu == pytest.approx(exact, rel=1e-8) and len(calls) < 12


def test_mu_parallel_to_g_is_not_identifiable():
    estimate, calls = fixed_map(lambda mu: mu)  # every mu is a fixed point: linear regime
    fp = solve_mu(estimate, SETTINGS)
    assert math.isnan(fp.mu) and "not identifiable: d ln g/d ln mu = 1" in fp.reason
    estimate, _ = fixed_map(lambda mu: 0.3 * (mu / 0.3) ** 0.9)  # slope 0.9: amplification 10 is accepted
    assert solve_mu(estimate, SETTINGS).mu == pytest.approx(0.3)


def test_runaway_map_returns_nan_with_reason():
    # linear regime: F_y independent of mu, so g(mu) = mu (1 + tiny): no fixed point to find
    estimate, calls = fixed_map(lambda mu: 1.001 * mu)
    fp = solve_mu(estimate, ReductionSettings(max_iterations=30))
    assert math.isnan(fp.mu) and "did not converge in 30" in fp.reason and len(calls) == 30


def test_nan_estimate_stops_with_the_estimates_reason():
    fp = solve_mu(lambda mu: (math.nan, {}, "nu_v ~ 0"), SETTINGS)
    assert math.isnan(fp.mu) and fp.reason == "nu_v ~ 0" and fp.iterations == 1
    fp = solve_mu(lambda mu: (-0.2, {}, ""), SETTINGS)
    assert "non-positive friction estimate -0.2" in fp.reason


@pytest.mark.parametrize("kwargs", [dict(mu_start=0.0), dict(damping=1.5), dict(max_iterations=0),
                                    dict(tolerance=0.0), dict(min_counts=0), dict(relative_step=-1.0)])
def test_settings_are_validated(kwargs):
    name = next(iter(kwargs))
    with pytest.raises(ParameterError, match=f"{name} = "):
        ReductionSettings(**kwargs)
