"""The hard cases (docs: Hard cases; issue 2, acceptance 5): finite, bounded, continuous."""

import warnings

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rig.contact.solve import solve, solve_creepage
from rig.errors import ParameterError

alphas = st.floats(1e-3, 1e5).map(float)
ratios = st.floats(0.1, 10.0)
offsets = st.floats(-20.0, 20.0)
shapes = st.sampled_from(["ellipse", "line"])
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _check(result, static_ratio=None):
    """Finite; |force| <= mu F_N, or <= mu0 F_N with static friction: eqs. (27)-(28) normalise by
    the kinetic mu, and material that sticks may hold up to mu0 p (docs/contact-model.md)."""
    values = np.array([result.nu_T, result.nu_v, result.nu_0, result.nu_Mo, result.stick_fraction])
    assert np.all(np.isfinite(values)), values
    bound = max(1.0, static_ratio or 1.0) + 1e-6
    assert abs(result.nu_T) <= bound and abs(result.nu_v) <= bound, "force above the friction limit"
    assert result.nu_0 >= -1e-9, "negative pivoting loss"
    assert 0.0 <= result.stick_fraction <= 1.0


@SETTINGS
@given(shape=shapes, b=ratios, alpha=alphas, c=offsets, l=offsets,
       psi=st.one_of(st.none(), st.floats(1.0, 10.0)), ks=st.one_of(st.none(), st.floats(1.0, 3.0)))
def test_kinematic_model_stays_finite_and_bounded(shape, b, alpha, c, l, psi, ks):
    effects = {k: v for k, v in (("psi", psi), ("static_ratio", ks)) if v is not None}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        r = solve("kinematic", shape=shape, b_over_a=b, alpha=alpha, c_over_a=c, l_over_a=l, poisson=0.28, n=16, **effects)
    _check(r, ks)


@SETTINGS
@given(shape=shapes, b=ratios, alpha=alphas, c=offsets, l=offsets, model=st.sampled_from(["rigid", "fastsim"]))
def test_rigid_and_fastsim_stay_finite_and_bounded(shape, b, alpha, c, l, model):
    _check(solve(model, shape=shape, b_over_a=b, alpha=alpha, c_over_a=c, l_over_a=l, poisson=0.28, n=16))


@SETTINGS
@given(shape=shapes, b=ratios, alpha=st.floats(0.05, 2e3), c=st.floats(-3, 3), l=st.floats(-3, 3))
def test_results_are_continuous_in_alpha(shape, b, alpha, c, l):
    common = dict(shape=shape, b_over_a=b, c_over_a=c, l_over_a=l, poisson=0.28, n=16)
    r1 = solve("kinematic", alpha=alpha, **common)
    r2 = solve("kinematic", alpha=alpha * (1 + 1e-6), **common)
    for name in ("nu_T", "nu_v", "nu_0"):
        assert getattr(r2, name) == pytest.approx(getattr(r1, name), abs=1e-4), name


def test_continuity_across_the_onset_of_adhesion():
    """A fine alpha' sweep through the first appearance of a stick zone has no jump: each step
    changes a coefficient by what its neighbours do (second differences below 0.01; measured
    below 1e-3, while nu_v falls by up to 0.021 per step of 5 % in alpha' near half stick)."""
    alphas = np.geomspace(3.0, 60.0, 60)
    rs = [solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=a, c_over_a=0.2, l_over_a=0.4, poisson=0.28, n=16)
          for a in alphas]
    stick = np.array([r.stick_fraction for r in rs])
    assert stick[0] < 0.05 and stick[-1] > 0.5, "the sweep must cross the stick/slip transition"
    for name in ("nu_T", "nu_v", "nu_0"):
        values = np.array([getattr(r, name) for r in rs])
        assert np.max(np.abs(np.diff(values, 2))) < 0.01, name


@pytest.mark.parametrize("model", ["rigid", "fastsim", "kinematic", "linear"])
def test_zero_spin_is_representable_in_creepages(model):
    """Hard case 1: no spin, pure creepage: the rolling point is at infinity, nu_0 is NaN, forces finite."""
    r = solve_creepage(model, shape="ellipse", b_over_a=1.0, xi=0.5, eta=-0.2, phi=0.0, poisson=0.28, n=16)
    assert np.isnan(r.nu_0) and np.isfinite([r.nu_T, r.nu_v, r.nu_Mo]).all()
    assert r.nu_T <= 0.0 and r.nu_v >= 0.0, "traction opposes the creepage"


def test_spin_going_to_zero_approaches_the_pure_creepage_result():
    plain = solve_creepage("kinematic", shape="ellipse", b_over_a=1.0, xi=0.5, eta=0.0, phi=0.0, poisson=0.28, n=16)
    for phi in (1e-3, 1e-6):
        r = solve_creepage("kinematic", shape="ellipse", b_over_a=1.0, xi=0.5, eta=0.0, phi=phi, poisson=0.28, n=16)
        assert r.nu_T == pytest.approx(plain.nu_T, abs=5 * phi + 1e-9)


@pytest.mark.parametrize("model", ["rigid", "fastsim", "kinematic"])
def test_alpha_below_the_float_range_is_rigid_sliding(model):
    """alpha' = 1e-310 makes the spin creepage 20 (1 - nu)/alpha' overflow; it must read as alpha' = 0."""
    common = dict(shape="ellipse", b_over_a=1.0, c_over_a=0.2, l_over_a=0.3, poisson=0.28, n=16)
    tiny = solve(model, alpha=1e-310, **common)
    zero = solve(model, alpha=0.0, **common)
    assert (tiny.nu_T, tiny.nu_v, tiny.nu_0) == (zero.nu_T, zero.nu_v, zero.nu_0)


@pytest.mark.parametrize("model", ["rigid", "linear", "fastsim", "kinematic"])
def test_infinite_alpha_is_no_slip_with_every_coefficient_zero(model):
    """alpha' = inf (documented as allowed) is the no-slip limit: nu_0 -> 0 like 1/alpha' (issue 14.10)."""
    r = solve(model, shape="ellipse", b_over_a=1.0, alpha=np.inf, c_over_a=0.2, l_over_a=0.3, poisson=0.28, n=8)
    assert (r.nu_T, r.nu_v, r.nu_0) == (0.0, 0.0, 0.0)


@pytest.mark.parametrize("model", ["rigid", "fastsim", "kinematic"])
@pytest.mark.parametrize(
    "alpha, c, l, expected",
    [(10.0, 1e156, 0.0, (0.0, 1.0)), (10.0, 0.0, -1e200, (1.0, 0.0)), (1e-156, 0.0, 0.0, None), (1e-300, 0.1, 0.2, None)],
)
def test_extreme_rolling_points_and_tiny_alpha_are_rigid_sliding(model, alpha, c, l, expected):
    """A rolling point 1e156 a away or alpha' = 1e-156 is full sliding (issue 14.10: NaN and a raw
    'Factor is exactly singular' before): finite, |nu| <= 1, equal to the same model at alpha' = 0."""
    common = dict(shape="ellipse", b_over_a=1.0, c_over_a=c, l_over_a=l, poisson=0.28, n=12)
    r = solve(model, alpha=alpha, **common)
    sliding = solve(model, alpha=0.0, **common)
    values = np.array([r.nu_T, r.nu_v, r.nu_0])
    assert np.all(np.isfinite(values)) and abs(r.nu_T) <= 1 + 1e-9 and abs(r.nu_v) <= 1 + 1e-9
    assert (r.nu_T, r.nu_v) == pytest.approx((sliding.nu_T, sliding.nu_v), abs=1e-9)
    if expected is not None:
        assert (r.nu_T, r.nu_v) == pytest.approx(expected, abs=1e-9)


def test_linear_theory_names_a_full_sliding_state_instead_of_overflowing():
    with pytest.raises(ParameterError, match="alpha.*no sliding"):
        solve("linear", shape="ellipse", b_over_a=1.0, alpha=1e-156, c_over_a=0.1, l_over_a=0.0, poisson=0.28)


def test_sliding_threshold_is_continuous():
    """Just below and above RIGID_SLIDING_CREEPAGE the kinematic model gives the same forces."""
    common = dict(shape="ellipse", b_over_a=1.0, alpha=10.0, l_over_a=0.0, poisson=0.28, n=12)
    below, above = (solve("kinematic", c_over_a=c, **common) for c in (6.9e11, 7.0e11))
    assert (below.nu_T, below.nu_v) == pytest.approx((above.nu_T, above.nu_v), abs=1e-12)
