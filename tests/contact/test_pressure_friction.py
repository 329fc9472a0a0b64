"""The pressure-dependent friction coefficient mu(p) = mu_ref (p/p_ref)^-k (contact effect pressure_exponent).

Independent check: in full sliding every element carries its bound mu(p) p along the slip, so the
force is the integral of mu(p) p over the Hertz pressure. In the model's units (tractions in
mu0 p0, mu0 = mu(p0)) the bound is (p/p0)^(1 - k), and with s = (1 - k)/2:

* ellipse, uniform slip direction: int (1 - (x/b)^2 - y^2)^s dA = b pi/(s + 1) (substitute x = b X
  and integrate over the unit disc), over F_N/p0 = 2 pi b/3:  |nu| = 3/(3 - k), for every b/a;
* Hertz circle, pure spin about the centre: int r (1 - r^2)^s dA = pi B(3/2, s + 1), so
  nu_0 = (3/2) Gamma(3/2) Gamma(s + 1)/Gamma(s + 5/2)  (3 pi/16 at k = 0);
* line contact, uniform slip: int_-1^1 (1 - x^2)^s dx = B(1/2, s + 1) over pi/2:
  |nu| = 2 Gamma(s + 1)/(sqrt(pi) Gamma(s + 3/2)).
The grid models carry a first-order edge error (cells cut by the contact's rim), largest at k = 1
where the bound jumps from 1 to 0 at the rim; the tolerances are set from it.
"""

from unittest import mock

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.special import gamma

from rig.contact.effects import pressure_friction
from rig.contact.effects.pressure_friction import PressureDependentFriction, friction_at_peak_pressure
from rig.contact.solve import solve, solve_creepage
from rig.errors import ParameterError, UnknownNameError

BASE = dict(shape="ellipse", b_over_a=1.0, alpha=20.0, c_over_a=0.0, l_over_a=0.3, poisson=0.28, n=24)
EXPONENTS = st.floats(0.0, 1.0, allow_nan=False)


def ellipse_sliding(k):
    return 3.0 / (3.0 - k)


def circle_spin(k):
    s = 0.5 * (1.0 - k)
    return 1.5 * gamma(1.5) * gamma(s + 1.0) / gamma(s + 2.5)


def line_sliding(k):
    s = 0.5 * (1.0 - k)
    return 2.0 * gamma(s + 1.0) / (np.sqrt(np.pi) * gamma(s + 1.5))


def test_closed_forms_reduce_to_the_known_coulomb_values_at_k_0():
    assert ellipse_sliding(0.0) == 1.0 and line_sliding(0.0) == pytest.approx(1.0, abs=1e-15)
    assert circle_spin(0.0) == pytest.approx(3 * np.pi / 16, rel=1e-14)


@pytest.mark.parametrize("model", ["rigid", "fastsim", "kinematic"])
def test_k_0_is_todays_model_bit_for_bit(model):
    common = dict(BASE, alpha=0.0) if model == "rigid" else BASE
    plain = solve(model, **common)
    zero = solve(model, **common, pressure_exponent=0.0)
    assert (zero.nu_T, zero.nu_v, zero.nu_0, zero.stick_fraction) == (plain.nu_T, plain.nu_v, plain.nu_0,
                                                                         plain.stick_fraction)


@pytest.mark.parametrize("model", ["rigid", "fastsim", "kinematic"])
def test_the_effect_left_off_is_never_called(model):
    common = dict(BASE, alpha=0.0) if model == "rigid" else BASE
    with mock.patch.object(PressureDependentFriction, "bound", autospec=True) as spy, \
            mock.patch.object(pressure_friction, "friction_at_peak_pressure") as mu_spy:
        solve(model, **common)
        solve(model, **common, psi=1.5) if model == "kinematic" else None
    spy.assert_not_called()
    mu_spy.assert_not_called()


def test_the_effect_turned_on_is_called_and_changes_the_result():
    with mock.patch.object(PressureDependentFriction, "bound", autospec=True,
                           side_effect=PressureDependentFriction.bound) as spy:
        on = solve("kinematic", **BASE, pressure_exponent=0.3)
    assert spy.called
    assert abs(on.nu_T - solve("kinematic", **BASE).nu_T) > 1e-3


@settings(max_examples=12, deadline=None)
@given(k=EXPONENTS, b_over_a=st.floats(0.3, 3.0))
def test_full_sliding_force_is_the_integral_of_mu_p_times_p_over_the_hertz_ellipse(k, b_over_a):
    """Uniform slip direction (longitudinal creepage 1e6 elastic units: every element slides)."""
    for model in ("rigid", "fastsim", "kinematic"):
        r = solve_creepage(model, shape="ellipse", b_over_a=b_over_a, xi=1e6, eta=0.0, phi=0.0, poisson=0.3, n=32,
                           pressure_exponent=k)
        assert -r.nu_T == pytest.approx(ellipse_sliding(k), rel=1.2e-2), model
        assert abs(r.nu_v) < 1e-8  # the solver converges to 1e-9 of the bound


@settings(max_examples=8, deadline=None)
@given(k=EXPONENTS)
def test_full_sliding_force_of_a_line_contact_is_its_closed_form(k):
    r = solve_creepage("kinematic", shape="line", b_over_a=0.6, xi=0.0, eta=1e6, phi=0.0, poisson=0.3, n=32,
                       pressure_exponent=k)
    assert -r.nu_v == pytest.approx(line_sliding(k), rel=2e-3)


@pytest.mark.parametrize("k", [0.0, 0.3, 0.7, 1.0])
def test_pivoting_loss_of_a_hertz_circle_in_full_sliding(k):
    """alpha' = 0, rolling point at the centre: nu_0 = int r mu(p) p dA/(mu0 a F_N)."""
    for model in ("rigid", "kinematic"):
        r = solve(model, shape="ellipse", b_over_a=1.0, alpha=0.0, c_over_a=0.0, l_over_a=0.0, poisson=0.3, n=64,
                  pressure_exponent=k)
        assert r.nu_0 == pytest.approx(circle_spin(k), rel=1e-2), model


def test_the_edge_error_falls_with_the_grid():
    errors = [abs(-solve_creepage("kinematic", shape="ellipse", b_over_a=1.0, xi=1e6, eta=0.0, phi=0.0, poisson=0.3,
                                  n=n, pressure_exponent=0.7).nu_T / ellipse_sliding(0.7) - 1.0) for n in (16, 64)]
    assert errors[1] < 0.5 * errors[0]


@settings(max_examples=10, deadline=None)
@given(k=EXPONENTS, l_over_a=st.floats(-1.5, 1.5), alpha=st.floats(0.1, 100.0))
def test_partial_slip_results_are_finite_and_within_the_sliding_bound(k, l_over_a, alpha):
    """|F| never exceeds the full-sliding force int mu(p) p dA (3/(3 - k) in these units)."""
    r = solve("kinematic", shape="ellipse", b_over_a=1.0, alpha=alpha, c_over_a=0.2, l_over_a=l_over_a, poisson=0.28,
              n=12, pressure_exponent=k)
    assert np.all(np.isfinite([r.nu_T, r.nu_v, r.nu_0]))
    assert 0.0 <= r.stick_fraction <= 1.0
    assert np.hypot(r.nu_T, r.nu_v) <= ellipse_sliding(k) * (1.0 + 1e-9)
    bound = PressureDependentFriction(k).bound(r.maps.pressure)
    assert np.all(np.hypot(*r.maps.traction) <= bound * (1.0 + 1e-8) + 1e-12)


@settings(max_examples=25, deadline=None)
@given(k=EXPONENTS, p=st.floats(0.0, 1.0))
def test_bound_lies_between_p_and_1_and_falls_to_0_at_the_rim(k, p):
    b = float(PressureDependentFriction(k).bound(np.array([p]))[0])
    assert p - 1e-15 <= b <= 1.0
    if k < 1.0 and p == 0.0:
        assert b == 0.0


def test_coefficient_at_the_peak_pressure_falls_with_the_load():
    assert friction_at_peak_pressure(0.8, 2e6, 1e6, 0.0) == 0.8
    assert friction_at_peak_pressure(0.8, 2e6, 1e6, 0.5) == pytest.approx(0.8 / np.sqrt(2.0), rel=1e-14)
    assert friction_at_peak_pressure(0.8, 1e6, 1e6, 0.9) == pytest.approx(0.8, rel=1e-15)


@pytest.mark.parametrize("k", [-0.1, 1.01, float("nan"), "0.3", True])
def test_an_exponent_outside_its_range_is_a_named_error(k):
    with pytest.raises(ParameterError, match="pressure_exponent"):
        solve("kinematic", **BASE, pressure_exponent=k)


def test_a_misspelt_keyword_is_answered_with_did_you_mean():
    with pytest.raises(UnknownNameError, match="did you mean 'pressure_exponent'"):
        solve("kinematic", **BASE, pressure_exponant=0.2)


def test_linear_theory_refuses_it_by_name():
    with pytest.raises(ParameterError, match="not available for model 'linear'"):
        solve("linear", **BASE, pressure_exponent=0.2)


def test_physical_layer_runs_at_mu_of_the_peak_pressure():
    from rig.contact.hertz import PointGeometry
    from rig.contact.materials import STEEL, TEXTILE_LAMINATE
    from rig.contact.physical import rolling_contact

    common = dict(normal_force=96.2, geometry=PointGeometry(0.1437, 0.0425, np.inf, np.inf), material_1=STEEL,
                  material_2=TEXTILE_LAMINATE, mu=0.4, speed=1.03, spin=44.5, c=0.0, l=0.0, n=12)
    plain = rolling_contact("kinematic", **common)
    at_p0 = rolling_contact("kinematic", **common, reference_pressure=plain.contact.p0, pressure_exponent=0.0)
    assert at_p0.force_x_N == plain.force_x_N
    half = rolling_contact("kinematic", **common, reference_pressure=plain.contact.p0 / 4.0, pressure_exponent=0.5)
    assert half.mu == pytest.approx(0.2, rel=1e-14)
    with pytest.raises(ParameterError, match="reference_pressure"):
        rolling_contact("kinematic", **common, pressure_exponent=0.5)
