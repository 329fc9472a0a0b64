"""Pure functions of eqs. (21), (29)-(36) against the Equations page's hand numbers (sections 1.7, 2, 3)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from rig.errors import ParameterError
from rig.reduction import equations as eq
from rig.reduction.geometry import StandAGeometry, StandBGeometry

A = StandAGeometry()


def test_counts_give_speeds_and_ratio():
    # 240 rpm with 60 marks over 20 s: 4800 counts; i_k = (N2 z1)/(N1 z2)
    assert eq.angular_speed_from_counts(4800, 60, 20.0) == pytest.approx(2 * math.pi * 4)
    assert eq.ratio_from_counts(4800, 3895, 60, 60) == pytest.approx(3895 / 4800)
    assert eq.ratio_from_counts(4800, 3895, 30, 60) == pytest.approx(3895 / 9600)
    with pytest.raises(ParameterError, match="counts_1 = 0"):
        eq.ratio_from_counts(0, 10, 60, 60)


def test_acceptance_stand_a_at_l_zero():
    c, l = eq.stand_a_rolling_point(0.8115, math.radians(73.4), 42.76e-3, -50.50e-3, 1.06e-3)
    assert abs(l) < 5e-6 and c == pytest.approx(0.486e-3, abs=0.5e-6)
    assert c / A.a == pytest.approx(0.4, abs=1e-3)  # c/a = 0.4 fixes a = 1.215 mm


def test_alpha_prime_stand_a_and_b():
    # Equations §3.1: alpha' = 10 mu (b/a)(v/w0)/R_x = 0.64 (b/a = 1), 1.29 (b/a = 2) at mu = 0.4, v/w0 = 23.15 mm
    assert eq.alpha_prime_line_contact(0.4, 1.0, 23.15e-3, A.radius_x) == pytest.approx(0.644, abs=0.005)
    assert eq.alpha_prime_line_contact(0.4, 2.0, 23.15e-3, A.radius_x) == pytest.approx(1.29, abs=0.005)
    assert A.r1 / (math.sin(A.alpha_1) + 0.8115) == pytest.approx(23.15e-3, abs=0.02e-3)
    b = StandBGeometry()  # Equations §3.2: alpha' = 26.6 mu (b/a)
    assert eq.alpha_prime_line_contact(1.0, 1.0, b.spin_radius, b.radius_x) == pytest.approx(26.6, abs=0.05)


@given(st.floats(0.05, 1.0), st.floats(0.5, 2.0), st.floats(1e-3, 5e-3), st.floats(50e-3, 200e-3))
def test_eq_21_general_form_reduces_to_line_contact(mu, beta, a, radius_x):
    # Hertz line contact: p0 = b E*/(2 R_x), E = 2 E* (eqs. 22-23), b = beta a -> same alpha' for any E*
    e_star, v, w0 = 4.9e9, 1.03, 44.5
    p0 = beta * a * e_star / (2 * radius_x)
    general = eq.alpha_prime(mu, p0, v, a, 2 * e_star, w0)
    assert general == pytest.approx(eq.alpha_prime_line_contact(mu, beta, v / w0, radius_x), rel=1e-12)


def test_dynamometer_lever_turns_0_098_into_0_235_newton():
    f_y = eq.lateral_force_from_dynamometer(0.098, A.dynamometer_lever, A.yoke_lever)
    assert f_y == pytest.approx(0.2352, abs=1e-4)
    assert A.lateral_force_half_width == pytest.approx(0.235, abs=1e-3)
    assert A.balance_moment_half_width == pytest.approx(0.0196, rel=1e-9)
    assert eq.force_from_signal(0.152, 0.01, 0.002) == pytest.approx(15.0)


@given(
    mu=st.floats(0.05, 1.0), l_over_a=st.floats(-0.9, 0.9), c=st.floats(0.0, 1e-3),
    nu_t=st.floats(-0.99, 0.99), nu_v=st.floats(0.01, 0.99), nu_0=st.floats(0.55, 2.0),
)
def test_eq_35_inverts_the_torque_balance_34(mu, l_over_a, c, nu_t, nu_v, nu_0):
    f_n, l = 96.2, l_over_a * A.a
    f_y = mu * f_n * nu_v
    t2 = eq.wheel_2_moment(mu, f_n, f_y, nu_t, nu_0, l, c, A.l2, A.delta_h, A.a)
    d = eq.mu_t_denominator(nu_t, nu_0, l, A.l2, A.a)
    if abs(d) > 1e-3 * A.a:
        assert eq.mu_t(t2, f_n, f_y, nu_t, nu_0, l, c, A.l2, A.delta_h, A.a) == pytest.approx(mu, rel=1e-9)
    assert eq.mu_v(f_y, f_n, nu_v) == pytest.approx(mu, rel=1e-12)


def test_eq_34_magnitude_form_of_the_paper():
    # T2 = |F_x|(|l2| + l) - T0 - F_y (Dh - c) with F_x = mu F_N nu_T (nu_T < 0), T0 = mu a F_N nu_0
    mu, f_n, nu_t, nu_v, nu_0, l, c = 0.4, 96.2, -0.3, 0.4, 0.8, 0.3e-3, 0.48e-3
    f_x, f_y, t0 = mu * f_n * nu_t, mu * f_n * nu_v, mu * A.a * f_n * nu_0
    paper = abs(f_x) * (abs(A.l2) + l) - t0 - f_y * (A.delta_h - c)
    assert eq.wheel_2_moment(mu, f_n, f_y, nu_t, nu_0, l, c, A.l2, A.delta_h, A.a) == pytest.approx(paper, rel=1e-12)


def test_stand_b_moment_transfer_and_mu_from_moment():
    # M_C = T_Mo + R_c F_T: 19 N m of transfer against a 0.4 N m pivoting moment (Equations §3.2)
    r_c, f_t, m_c = 166.3e-3, -0.8 * 144 * 0.8, -0.46
    t_mo = m_c - r_c * f_t
    assert eq.pivoting_moment_stand_b(t_mo, f_t, r_c) == pytest.approx(m_c, rel=1e-12)
    assert eq.mu_from_pivoting_moment(m_c, 144.0, 4e-3, 0.5) == pytest.approx(0.46 / (4e-3 * 144 * 0.5))
    assert eq.mu_from_force(-20.0, 100.0, -0.5) == pytest.approx(0.4)
