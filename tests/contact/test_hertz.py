"""Hertz point and line contact (rig.contact.hertz) against closed forms, an independent
Boussinesq quadrature, and the stand numbers of Equations §3.1/3.2."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad
from scipy.special import ellipe, ellipk

from rig.contact.hertz import (
    LineGeometry,
    PointGeometry,
    axis_ratio,
    curvature_ratio,
    ellipse_pressure,
    hertz_contact,
    line_contact,
    line_pressure,
    point_contact,
)
from rig.errors import ParameterError

INF = math.inf


def boussinesq_displacement(contact, x0: float, y0: float) -> float:
    """Combined normal displacement at (x0, y0) under the Hertz pressure, by quadrature [m].

    u = 1/(pi E*) int int p/|r - r0| dA in polar coordinates about r0; along each ray the
    pressure is p0 sqrt(g (r+ - r)(r - r-)), integrated in closed form; the angle by quad.
    """
    a, b = contact.a, contact.b
    s0 = 1.0 - (x0 / b) ** 2 - (y0 / a) ** 2

    def along_ray(theta: float) -> float:
        c, s = math.cos(theta), math.sin(theta)
        g = (c / b) ** 2 + (s / a) ** 2
        beta = x0 * c / b**2 + y0 * s / a**2
        root = math.sqrt(beta * beta + g * s0)
        r_plus, r_minus = (-beta + root) / g, (-beta - root) / g
        h, m = 0.5 * (r_plus - r_minus), 0.5 * (r_plus + r_minus)

        def primitive(t: float) -> float:
            return 0.5 * (t * math.sqrt(max(h * h - t * t, 0.0)) + h * h * math.asin(min(1.0, max(-1.0, t / h))))

        return math.sqrt(g) * (primitive(h) - primitive(-m))

    value, _ = quad(along_ray, 0.0, 2.0 * math.pi, limit=200, epsabs=0.0, epsrel=1e-11)
    return contact.p0 * value / (math.pi * contact.e_star)


def test_sphere_on_flat_matches_closed_form():
    force, radius, e_star = 50.0, 0.012, 1.15e11
    c = point_contact(force, PointGeometry(radius, radius, INF, INF), e_star)
    a_ref = (3.0 * force * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    assert c.a == pytest.approx(a_ref, rel=1e-12)
    assert c.b == pytest.approx(a_ref, rel=1e-12)
    assert c.p0 == pytest.approx(3.0 * force / (2.0 * math.pi * a_ref**2), rel=1e-12)
    assert c.approach == pytest.approx(a_ref**2 / radius, rel=1e-12)
    assert c.K == pytest.approx(math.pi / 2) and c.E == pytest.approx(math.pi / 2)


def test_two_spheres_use_the_relative_radius():
    r1, r2, force, e_star = 0.01, 0.03, 20.0, 1e11
    c = point_contact(force, PointGeometry(r1, r1, r2, r2), e_star)
    radius = r1 * r2 / (r1 + r2)
    assert c.a == pytest.approx((3.0 * force * radius / (4.0 * e_star)) ** (1.0 / 3.0), rel=1e-12)


def test_crossed_cylinders_of_equal_radius_equal_a_sphere_on_flat():
    radius, force, e_star = 0.02, 30.0, 2e10
    crossed = point_contact(force, PointGeometry(radius, INF, INF, radius), e_star)
    sphere = point_contact(force, PointGeometry(radius, radius, INF, INF), e_star)
    assert crossed.a == pytest.approx(sphere.a, rel=1e-12)
    assert crossed.b == pytest.approx(sphere.b, rel=1e-12)
    assert crossed.p0 == pytest.approx(sphere.p0, rel=1e-12)


def test_cylinder_on_flat_line_contact_matches_textbook_forms():
    # Johnson: per unit length P' = F/L, b = sqrt(4 P' R/(pi E*)), p0 = sqrt(P' E*/(pi R))
    force, length, radius, e_star = 900.0, 0.02, 0.05, 1.15e11
    c = line_contact(force, LineGeometry(length, radius), e_star)
    load = force / length
    assert c.a == pytest.approx(length / 2)
    assert c.b == pytest.approx(2.0 * math.sqrt(load * radius / (math.pi * e_star)), rel=1e-12)
    assert c.p0 == pytest.approx(math.sqrt(load * e_star / (math.pi * radius)), rel=1e-12)
    # force balance: int p dA = F
    x = np.linspace(-c.b, c.b, 200001)
    assert np.trapezoid(c.pressure(x, 0.0), x) * length == pytest.approx(force, rel=1e-6)


@pytest.mark.parametrize("radii", [(0.01, 1.0, INF, INF), (0.3, 0.02, INF, INF), (0.005, 0.005, INF, -0.006)])
def test_ellipse_displacement_matches_boussinesq_quadrature(radii):
    """u_z = approach - x^2/(2 R_x) - y^2/(2 R_y) inside the contact (independent check of
    the ellipticity root, the semi-axes and the approach)."""
    geometry = PointGeometry(*radii)
    c = point_contact(100.0, geometry, 1.0e11)
    cx, cy = geometry.curvature_sums()
    for fx, fy in [(0.0, 0.0), (0.5, 0.0), (0.0, 0.7), (0.3, -0.4)]:
        x0, y0 = fx * c.b, fy * c.a
        expected = c.approach - 0.5 * cx * x0**2 - 0.5 * cy * y0**2
        assert boussinesq_displacement(c, x0, y0) == pytest.approx(expected, rel=1e-8)


def test_force_balance_of_ellipse():
    c = point_contact(10.0, PointGeometry(0.01, 0.2, INF, INF), 1e11)
    # volume of the semi-ellipsoid 2/3 pi a b p0
    x = np.linspace(-c.b, c.b, 801)
    y = np.linspace(-c.a, c.a, 801)
    p = c.pressure(x[:, None], y[None, :])
    total = np.trapezoid(np.trapezoid(p, y, axis=1), x)
    assert total == pytest.approx(10.0, rel=2e-3)


def test_major_axis_lies_along_the_smaller_curvature():
    rolling_long = point_contact(10.0, PointGeometry(1.0, 0.01, INF, INF), 1e11)
    assert rolling_long.b > rolling_long.a  # R_x large: long in x
    across_long = point_contact(10.0, PointGeometry(0.01, 1.0, INF, INF), 1e11)
    assert across_long.a > across_long.b
    assert across_long.a == pytest.approx(rolling_long.b) and across_long.b == pytest.approx(rolling_long.a)


def test_elliptic_integrals_are_scipys():
    c = point_contact(10.0, PointGeometry(0.01, 0.2, INF, INF), 1e11)
    m = 1.0 - (c.b / c.a) ** 2
    assert c.K == pytest.approx(ellipk(m), rel=1e-12)
    assert c.E == pytest.approx(ellipe(m), rel=1e-12)


# --- stand numbers (Equations §3.1, 3.2) -------------------------------------------------------


@pytest.mark.parametrize(("force", "b_mm"), [(9.0, 2.0), (21.0, 3.0), (36.0, 4.0), (144.0, 8.0)])
def test_stand_b_rubber_line_contact(force, b_mm):
    """E* = 22.4 MPa, roller R = 62.5 mm, track 2a = 8 mm: b = 2/3/4/8 mm (21 N: 3.05 mm, b/a printed 0.75)."""
    c = line_contact(force, LineGeometry(0.008, 0.0625), 22.4e6)
    assert c.b * 1e3 == pytest.approx(b_mm, rel=0.02)
    assert c.b_over_a == pytest.approx(b_mm / 4.0, rel=0.02)


def test_stand_b_pressures():
    """p0 = 2F/(pi b L) = 0.358, 0.716, 1.432 MPa at 9, 36, 144 N (Equations §3.2)."""
    for force, p0 in [(9.0, 0.358e6), (36.0, 0.716e6), (144.0, 1.432e6)]:
        assert line_contact(force, LineGeometry(0.008, 0.0625), 22.38e6).p0 == pytest.approx(p0, rel=2e-3)


def test_stand_a_line_contact_gives_b_over_a_1_and_2():
    """a = 1.215 mm, R_x = 143.7 mm, E* = 4906 MPa: b/a = 1 at 96.2 N and 2 at 385 N; p0 20.7/41.5 MPa."""
    geometry = LineGeometry(2.43e-3, 0.1437)
    low, high = line_contact(96.2, geometry, 4906e6), line_contact(385.0, geometry, 4906e6)
    assert low.b_over_a == pytest.approx(1.0, rel=5e-3)
    assert high.b_over_a == pytest.approx(2.0, rel=5e-3)
    assert low.p0 == pytest.approx(20.7e6, rel=5e-3) and high.p0 == pytest.approx(41.5e6, rel=5e-3)


def test_stand_a_point_contact_numbers():
    """Wheel 1 (R_x = 143.7, R_y = 42.5 mm) on a flat laminate E = 4.47 GPa (nu 0.3, steel rigid):
    b/a = 2.24 at every load, a = 0.69/1.09 mm, b = 1.54/2.44 mm, p0 = 44/69 MPa (Equations §3.1)."""
    geometry = PointGeometry(0.1437, 0.0425, INF, INF)
    e_star = 4.47e9 / (1.0 - 0.3**2)
    for force, a_mm, b_mm, p0 in [(96.2, 0.69, 1.54, 44e6), (385.0, 1.09, 2.44, 69e6)]:
        c = point_contact(force, geometry, e_star)
        assert c.b_over_a == pytest.approx(2.24, abs=0.005)
        assert c.a * 1e3 == pytest.approx(a_mm, abs=0.005)
        assert c.b * 1e3 == pytest.approx(b_mm, abs=0.005)
        assert c.p0 == pytest.approx(p0, abs=0.5e6)


# --- pressure fields ---------------------------------------------------------------------------


def test_pressure_fields():
    assert ellipse_pressure(0.0, 0.0, a=2.0, b=1.0, p0=5.0) == 5.0
    assert ellipse_pressure(0.5, 1.0, a=2.0, b=1.0, p0=5.0) == pytest.approx(5.0 * math.sqrt(0.5))
    assert ellipse_pressure(1.1, 0.0, a=2.0, b=1.0, p0=5.0) == 0.0
    assert line_pressure(0.5, 1.9, a=2.0, b=1.0, p0=4.0) == pytest.approx(4.0 * math.sqrt(0.75))
    assert line_pressure(0.5, 2.1, a=2.0, b=1.0, p0=4.0) == 0.0


# --- errors and hard cases ---------------------------------------------------------------------


def test_invalid_input_raises_named_errors():
    geometry = PointGeometry(0.01, 0.01, INF, INF)
    with pytest.raises(ParameterError, match="normal_force"):
        point_contact(0.0, geometry, 1e11)
    with pytest.raises(ParameterError, match="e_star"):
        point_contact(1.0, geometry, -1.0)
    with pytest.raises(ParameterError, match="r1x"):
        PointGeometry(0.0, 0.01, INF, INF)
    with pytest.raises(ParameterError, match="r2y"):
        PointGeometry(0.01, 0.01, INF, float("nan"))
    with pytest.raises(ParameterError, match="length"):
        LineGeometry(0.0, 0.01)
    with pytest.raises(ParameterError, match="geometry"):
        hertz_contact(1.0, (0.01, 0.01), 1e11)


def test_flat_direction_in_point_contact_points_to_line_geometry():
    with pytest.raises(ParameterError, match="LineGeometry"):
        point_contact(1.0, PointGeometry(0.01, INF, INF, INF), 1e11)


def test_concave_radius_that_encloses_is_rejected():
    # ball of radius 5 mm in a 4.9 mm groove: non-convex gap
    with pytest.raises(ParameterError, match=r"1/r1y \+ 1/r2y"):
        point_contact(1.0, PointGeometry(0.005, 0.005, INF, -0.0049), 1e11)
    with pytest.raises(ParameterError, match="convex"):
        point_contact(1.0, PointGeometry(0.005, 0.005, INF, -0.005), 1e11)


@settings(max_examples=60, deadline=None)
@given(
    force=st.floats(1e-12, 1e6),
    rx=st.floats(1e-4, 10.0),
    ry=st.floats(1e-4, 10.0),
)
def test_point_contact_is_finite_and_consistent(force, rx, ry):
    c = point_contact(force, PointGeometry(rx, ry, INF, INF), 1e11)
    for value in (c.a, c.b, c.p0, c.approach):
        assert math.isfinite(value) and value > 0.0
    assert 2.0 / 3.0 * math.pi * c.a * c.b * c.p0 == pytest.approx(force, rel=1e-9)


@settings(max_examples=60, deadline=None)
@given(ratio=st.floats(1.0, 1e13))
def test_ellipticity_root_is_robust(ratio):
    lam = axis_ratio(ratio)
    assert 0.0 < lam <= 1.0
    assert curvature_ratio(lam) == pytest.approx(ratio, rel=1e-10)


@settings(max_examples=40, deadline=None)
@given(scale=st.floats(1.0, 1.0 + 1e-6))
def test_near_circle_is_continuous(scale):
    """Curvature ratios just above 1 give semi-axes continuous with the circle (no cancellation)."""
    circle = point_contact(10.0, PointGeometry(0.01, 0.01, INF, INF), 1e11)
    c = point_contact(10.0, PointGeometry(0.01, 0.01 * scale, INF, INF), 1e11)
    assert c.a == pytest.approx(circle.a, rel=1e-6)
    assert c.b == pytest.approx(circle.b, rel=1e-6)
    assert c.a >= c.b


def test_force_to_zero_shrinks_the_contact_as_f_to_one_third():
    geometry = PointGeometry(0.01, 0.03, INF, INF)
    small, smaller = point_contact(1e-9, geometry, 1e11), point_contact(1e-12, geometry, 1e11)
    assert small.a / smaller.a == pytest.approx(10.0, rel=1e-9)
    assert small.p0 / smaller.p0 == pytest.approx(10.0, rel=1e-9)
