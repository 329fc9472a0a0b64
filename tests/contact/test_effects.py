"""Effects change the result in the documented direction, and an effect left off is never called."""

from unittest import mock

import pytest

from rig.contact.effects import plastic_slip, rolling_resistance, static_friction, surface_inertia
from rig.contact.solve import solve

BASE = dict(shape="ellipse", b_over_a=1.0, alpha=20.0, c_over_a=0.0, l_over_a=0.3, poisson=0.28, n=24)


def _solve(**effects):
    return solve("kinematic", **{**BASE, **effects})


def test_plastic_slip_enlarges_the_adhesion_area_and_lowers_the_pivoting_loss():
    plain, plastic = _solve(), _solve(psi=3.0)
    assert plastic.stick_fraction > plain.stick_fraction + 0.05
    assert plastic.nu_0 < plain.nu_0


def test_static_friction_enlarges_the_adhesion_area():
    plain, static = _solve(), _solve(static_ratio=2.0)
    assert static.stick_fraction > plain.stick_fraction + 0.02


def test_surface_inertia_enlarges_adhesion_and_lowers_the_loss_in_partial_slip():
    common = dict(BASE, alpha=30.0, l_over_a=0.0)
    plain = solve("kinematic", **common)
    inert = solve("kinematic", **common, inertia_number=0.2)
    assert inert.stick_fraction > plain.stick_fraction
    assert inert.nu_0 < plain.nu_0


def test_surface_inertia_lowers_the_longitudinal_force_at_large_alpha():
    """The chosen inertia model (docs/contact-model.md) disagrees here with the paper's Fig. 7."""
    common = dict(BASE, alpha=300.0, l_over_a=0.0)
    plain = solve("kinematic", **common)
    inert = solve("kinematic", **common, inertia_number=0.2)
    assert inert.nu_v < 0.8 * plain.nu_v


def test_vanishing_inertia_gives_the_inertia_free_result():
    plain, tiny = _solve(), _solve(inertia_number=1e-9)
    assert (tiny.nu_T, tiny.nu_v, tiny.nu_0) == pytest.approx((plain.nu_T, plain.nu_v, plain.nu_0), abs=1e-7)


def test_neutral_values_reproduce_the_effect_free_result():
    plain = _solve()
    for effects in (dict(psi=1.0), dict(static_ratio=1.0), dict(inertia_number=0.0), dict(rolling_length=0.0)):
        r = _solve(**effects)
        assert (r.nu_T, r.nu_v, r.nu_0) == pytest.approx((plain.nu_T, plain.nu_v, plain.nu_0), abs=1e-9), effects


def test_rolling_resistance_moves_the_rolling_point_across_the_contact_line():
    """Eq. (3): f w0 adds to the lateral slip, i.e. c -> c + f."""
    shifted = _solve(rolling_length=0.2)
    moved = solve("kinematic", **{**BASE, "c_over_a": 0.2})
    assert (shifted.nu_T, shifted.nu_v) == pytest.approx((moved.nu_T, moved.nu_v), abs=1e-9)


@pytest.mark.parametrize(
    "target",
    [
        (plastic_slip.PlasticSlip, "rate"),
        (static_friction.StaticFriction, "bound"),
        (static_friction.StaticFriction, "upstream_state"),
        (surface_inertia.SurfaceInertia, "layer_force"),
        (rolling_resistance.RollingResistance, "shift"),
    ],
)
def test_an_effect_left_off_is_never_called(target):
    cls, method = target
    with mock.patch.object(cls, method, autospec=True) as spy:
        _solve()
        solve("fastsim", **BASE)
    spy.assert_not_called()


def test_an_effect_turned_on_is_called():
    with mock.patch.object(plastic_slip.PlasticSlip, "rate", autospec=True,
                           side_effect=plastic_slip.PlasticSlip.rate) as spy:
        _solve(psi=2.0)
    assert spy.called


def test_plastic_slip_effect_converges_with_the_grid():
    """Issue 15.1: Psi is a slip velocity (eq. 25 with v_el of eq. 20), so its effect does not
    fade under refinement: nu_v and nu_0 change by <= 2 % from n = 32 to 64 (alpha' = 10,
    circle, nu = 0.5, Psi = 5); the former local-compliance model changed nu_v by 12 % there."""
    common = dict(shape="ellipse", b_over_a=1.0, alpha=10.0, c_over_a=0.0, l_over_a=0.0, poisson=0.5, psi=5.0)
    coarse, fine = (solve("kinematic", n=n, **common) for n in (32, 64))
    assert fine.nu_v == pytest.approx(coarse.nu_v, rel=0.02)
    assert fine.nu_0 == pytest.approx(coarse.nu_0, rel=0.02)
    plain = solve("kinematic", n=32, **{**common, "psi": 1.0})
    assert coarse.nu_v < 0.5 * plain.nu_v, "Psi = 5 must matter: the self slip is five times the elastic one"


def test_plastic_self_slip_rate_is_eq_20():
    """v_el/(mu p v/G) = 2 asinh(1)(2 - nu)/pi: 0.56109 (2 - nu), Equations §1.6."""
    assert plastic_slip.elastic_self_slip_rate(0.3) == pytest.approx(0.56109 * 1.7, rel=1e-4)
    assert plastic_slip.PlasticSlip(3.0).rate(0.3) == pytest.approx(2 * 0.56109 * 1.7, rel=1e-4)
