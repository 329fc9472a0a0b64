"""Stand A's contact at the instantaneous speeds: signs, identities, far field, standstill (hard cases 1, 6, 7)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.reduction.equations import alpha_prime_line_contact, wheel_2_moment
from rig.reduction.geometry import StandAGeometry
from rig.stands.yoke import laws
from rig.stands.yoke.contact_forces import StandAContact
from rig.wheel_kinematics import ratio_for_l, stand_a_rolling_point
from tests.stands.yoke import standin

G = StandAGeometry()
MU, F_N = 0.4, 96.2


def contact(geometry=G, law=standin.coefficients, force=F_N) -> StandAContact:
    return StandAContact(geometry, force, geometry.b_over_a(force), MU, law, laws.domain(geometry, 1.0, MU), 1e-3)


def speeds_for(l_over_a: float, w1: float = 25.13) -> tuple[float, float]:
    return w1, w1 * ratio_for_l(l_over_a * G.a, G.alpha_1, G.l1, G.l2)


@pytest.mark.parametrize("l_over_a", [-1.0, -0.3, 0.0, 0.4, 1.2])
def test_inside_the_domain_the_law_and_the_reductions_relations_hold(l_over_a):
    c = contact()
    w1, w2 = speeds_for(l_over_a)
    s = c.evaluate(w1, w2)
    c_true, l_true = stand_a_rolling_point(w2 / w1, G.alpha_1, G.l1, G.l2, G.delta_h)  # eqs. (29)-(31)
    assert float(s.l) == pytest.approx(l_true, rel=1e-12, abs=1e-15)
    assert float(s.c) == pytest.approx(c_true, rel=1e-12)
    v_over_w0 = G.r1 / (math.sin(G.alpha_1) + w2 / w1)
    alpha = alpha_prime_line_contact(MU, 1.0, v_over_w0, G.radius_x)  # eq. (21), the reduction's function
    nu = standin.coefficients(l_true / G.a, c_true / G.a, alpha)
    assert float(s.alpha) == pytest.approx(alpha, rel=1e-12)
    assert (float(s.nu_T), float(s.nu_v), float(s.nu_0)) == pytest.approx(tuple(map(float, nu)), rel=1e-12)
    assert float(s.F_x) == pytest.approx(MU * F_N * float(nu[0]), rel=1e-12)  # eq. (27)
    # T2 is eq. (34) forward, the reduction's own function (bearing friction aside)
    t2 = wheel_2_moment(MU, F_N, float(s.F_y), float(nu[0]), float(nu[2]), l_true, c_true, G.l2, G.delta_h, G.a)
    assert float(s.T2) == pytest.approx(t2, rel=1e-12, abs=1e-14)
    assert float(s.M_C) == pytest.approx(-MU * G.a * F_N * float(nu[2]), rel=1e-12)  # w0 > 0


@settings(max_examples=200, deadline=None)
@given(st.floats(-60.0, 60.0), st.floats(-60.0, 60.0))
def test_power_balance_holds_everywhere_and_nothing_is_nan(w1, w2):
    # w1 T1 + w2 T2 = w0 M_C (Equations §1.2: P_t = -w0 M_C >= 0 is the loss) - also in the far field
    c = contact()
    s = c.evaluate(w1, w2)
    for name in ("F_x", "F_y", "M_O", "T1", "T2", "nu_T", "nu_v"):
        assert np.isfinite(getattr(s, name)), name
    if np.isfinite(s.M_C):
        assert w1 * s.T1 + w2 * s.T2 == pytest.approx(float(s.w0 * s.M_C), abs=1e-9 * (1 + abs(w1) + abs(w2)))
        assert float(s.w0 * s.M_C) <= 1e-9
    assert abs(float(s.F_x)) <= MU * F_N * (1 + 1e-9) and abs(float(s.F_y)) <= MU * F_N * 1.5


def test_scalar_path_equals_the_vectorised_path_to_the_last_bit():
    c = contact()
    for w1, w2 in [speeds_for(0.3), speeds_for(-0.9), (25.13, 0.0), (0.0, 0.0), (10.0, -20.0), (25.0, 50.0)]:
        assert c.moments_scalar(w1, w2) == tuple(map(float, c.moments(w1, w2)))


@settings(max_examples=400, deadline=None)
@given(st.floats(-60.0, 60.0), st.floats(1e-6, 1.0 - 1e-6), st.floats(-2.0, 2.0))
def test_scalar_path_is_the_vectorised_path_inside_and_outside_the_domain(w1, where, scale):
    # the steady state's root search and the ODE use the scalar path: the same numbers as moments, bit
    # for bit, inside the domain, in the far field beyond it (C anywhere between A2 and A1) and at w0 <= 0
    c = contact()
    w2 = w1 * ratio_for_l(G.l2 + where * (G.l1 - G.l2), G.alpha_1, G.l1, G.l2)
    for omega_2 in (w2, scale * w2, -w1 * math.sin(G.alpha_1) * (1.0 + 1e-12 * scale)):
        assert c.moments_scalar(w1, omega_2) == tuple(map(float, c.moments(w1, omega_2)))


def test_continuous_across_the_domain_boundary():
    c = contact()
    l_edge = laws.L_MAX * G.a
    w1 = 25.13
    inside = w1 * ratio_for_l(l_edge * (1 - 1e-9), G.alpha_1, G.l1, G.l2)
    outside = w1 * ratio_for_l(l_edge * (1 + 1e-9), G.alpha_1, G.l1, G.l2)
    a, b = c.evaluate(w1, inside), c.evaluate(w1, outside)
    for name in ("F_x", "F_y", "M_O", "T1", "T2"):
        assert float(getattr(b, name)) == pytest.approx(float(getattr(a, name)), rel=1e-6, abs=1e-9), name


def test_far_field_is_uniform_sliding_against_the_slip_at_the_centre():
    # w0 -> 0 (wheel 2 reversed, w02 = -w01): C at infinity, traction -mu p s(O)/|s(O)|, M_O -> 0 (hard case 1)
    c = contact()
    w1 = 25.13
    w2 = -w1 * math.sin(G.alpha_1)
    s = c.evaluate(w1, w2)
    p_l, p_c = w1 * math.sin(G.alpha_1) * G.l1 + w2 * G.l2, w2 * G.delta_h  # w0 (l, c) at w0 -> 0
    slip = np.array([p_l, -p_c]) / math.hypot(p_l, p_c)  # s_g(O) = w0 (l, -c)
    assert (float(s.F_x), float(s.F_y)) == pytest.approx(tuple(-MU * F_N * slip), rel=1e-12)
    assert float(s.M_O) == 0.0


def test_mirror_y_for_negative_spin():
    # w0 < 0 is the canonical problem at (c, -l): F_x kept, F_y and the moments change sign
    # (rig.contact.physical.mirror_y). Short axis offsets put C inside the domain with w0 < 0.
    g = StandAGeometry(l1=1e-3, l2=-1e-3, delta_h=0.3e-3)
    c = contact(g)
    w1, w2 = 1.0 / math.sin(g.alpha_1), -3.0  # w01 = 1, w02 = -3: w0 = -2 rad/s
    s = c.evaluate(w1, w2)
    l, cc = (1.0 * g.l1 + w2 * g.l2) / -2.0, w2 * g.delta_h / -2.0  # eqs. (29), (31): -2 mm, 0.45 mm
    assert (float(s.w0), float(s.l), float(s.c)) == pytest.approx((-2.0, l, cc), rel=1e-12)
    alpha = min(alpha_prime_line_contact(MU, 1.0, w1 * g.r1 / 2.0, g.radius_x), c.domain.alpha[1])  # clamped
    assert float(s.alpha) == pytest.approx(alpha, rel=1e-12)
    nu_t, nu_v, nu_0 = map(float, standin.coefficients(-l / g.a, cc / g.a, alpha))
    force = MU * F_N * math.tanh(2.0 * math.sqrt(l * l + cc * cc + g.a * g.a) / 1e-3)  # slow slip: regularised
    assert float(s.F_x) == pytest.approx(force * nu_t, rel=1e-12)
    assert float(s.F_y) == pytest.approx(-force * nu_v, rel=1e-12)
    assert float(s.M_C) == pytest.approx(+force * g.a * nu_0, rel=1e-12)
    assert float(s.M_O) == pytest.approx(force * g.a * nu_0 + cc * float(s.F_y) - l * float(s.F_x), rel=1e-12)


def test_standstill_gives_zero_forces_not_nan():
    s = contact().evaluate(0.0, 0.0)
    assert (float(s.F_x), float(s.F_y), float(s.M_O), float(s.T1), float(s.T2)) == (0.0, 0.0, 0.0, 0.0, 0.0)


def test_regularisation_is_invisible_at_operating_points():
    # tanh(s/eps) with s = w0 sqrt(l^2 + c^2 + a^2) ~ 0.05 m/s and eps = 1 mm/s is 1 to machine precision
    c = contact()
    w1, w2 = speeds_for(0.0)
    s = c.evaluate(w1, w2)
    assert float(s.F_y) == MU * F_N * float(s.nu_v)
