"""Materials and dimensionless groups (rig.contact.materials) against the identities and stand
numbers of Equations §1.7, 3.1 and 3.2."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.contact.hertz import LineGeometry, line_contact
from rig.contact.materials import (
    PRESETS,
    RIGID,
    STEEL,
    Material,
    combined_poisson,
    combined_shear_modulus,
    contact_modulus,
    density_index,
    preset,
    substitute_modulus,
    track_deformability,
)
from rig.errors import ParameterError, UnknownNameError


def test_material_derived_moduli():
    m = Material(E=200e9, nu=0.25, rho=7800.0)
    assert m.G == pytest.approx(80e9)
    assert m.plane_strain_modulus == pytest.approx(200e9 / 0.9375)


def test_substitute_modulus_is_twice_the_contact_modulus():
    soft = Material(E=4.5e9, nu=0.35, rho=1350.0)
    # E1' = 210/0.91 GPa, E2' = 4.5/(1 - 0.1225) GPa
    e1, e2 = 210e9 / 0.91, 4.5e9 / 0.8775
    assert substitute_modulus(STEEL, soft) == pytest.approx(2 * e1 * e2 / (e1 + e2), rel=1e-12)
    assert substitute_modulus(STEEL, soft) == pytest.approx(2 * contact_modulus(STEEL, soft), rel=1e-12)
    # Hertz E* against a rigid body is the plane-strain modulus
    assert contact_modulus(RIGID, soft) == pytest.approx(e2, rel=1e-12)


@settings(max_examples=50, deadline=None)
@given(e1=st.floats(1e6, 1e12), e2=st.floats(1e6, 1e12), nu=st.floats(0.0, 0.5))
def test_equal_poisson_identity(e1, e2, nu):
    """With equal nu and Kalker's G: E = 2G/(1 - nu) and combined nu = nu (Equations §1.7)."""
    m1, m2 = Material(e1, nu, 1000.0), Material(e2, nu, 1000.0)
    g = combined_shear_modulus(m1, m2)
    assert substitute_modulus(m1, m2) == pytest.approx(2.0 * g / (1.0 - nu), rel=1e-12)
    assert combined_poisson(m1, m2) == pytest.approx(nu, abs=1e-12)


def test_kalker_combined_constants():
    """2/G = 1/G1 + 1/G2, nu/G = (nu1/G1 + nu2/G2)/2 (Kalker 1990 eq. 1.44, CONTACT combin_mater)."""
    m1, m2 = Material(210e9, 0.3, 7850.0), Material(16.8e6, 0.5, 1200.0)
    g1, g2 = 210e9 / 2.6, 16.8e6 / 3.0
    g = 2.0 / (1.0 / g1 + 1.0 / g2)
    assert combined_shear_modulus(m1, m2) == pytest.approx(g, rel=1e-12)
    assert combined_poisson(m1, m2) == pytest.approx(g * (0.3 / g1 + 0.5 / g2) / 2.0, rel=1e-12)
    # against a rigid body: G = 2 G_i, nu = nu_i
    assert combined_shear_modulus(RIGID, m2) == pytest.approx(2.0 * g2)
    assert combined_poisson(RIGID, m2) == pytest.approx(0.5)


def test_alpha_prime_identity_with_kappa():
    """alpha' = 20 (1 - nu) kappa, kappa = mu p0 v/(G a w0), for equal nu (Equations §1.7)."""
    nu = 0.3
    m = Material(4.5e9, nu, 1350.0)
    mu, p0, v, a, w0 = 0.4, 40e6, 1.03, 1.2e-3, 44.5
    alpha = track_deformability(mu, p0, v, a, substitute_modulus(m, m), w0)
    kappa = mu * p0 * v / (combined_shear_modulus(m, m) * a * w0)
    assert alpha == pytest.approx(20.0 * (1.0 - nu) * kappa, rel=1e-12)
    assert track_deformability(mu, p0, v, a, 1e9, -w0) == track_deformability(mu, p0, v, a, 1e9, w0)


@pytest.mark.parametrize("modulus", [1e6, 3e9, 2e11])
def test_line_contact_alpha_prime_is_independent_of_E(modulus):
    """Hertz line contact: alpha' = 10 mu (b/a)(v/w0)/R_x, whatever E (Equations §1.7)."""
    mu, v, w0, force = 0.5, 0.3, 2.0, 50.0
    soft = Material(modulus, 0.4, 1000.0)
    geometry = LineGeometry(0.01, 0.05)
    contact = line_contact(force, geometry, contact_modulus(RIGID, soft))
    alpha = track_deformability(mu, contact.p0, v, contact.a, substitute_modulus(RIGID, soft), w0)
    assert alpha == pytest.approx(10.0 * mu * contact.b_over_a * (v / w0) / geometry.radius_x, rel=1e-12)


@pytest.mark.parametrize(("force", "alpha_ref"), [(96.2, 0.64), (385.0, 1.29)])
def test_stand_a_alpha_prime(force, alpha_ref):
    """Stand A, mu = 0.4, v/w0 = 23.15 mm, R_x = 143.7 mm, a = 1.215 mm, laminate E 4.5 GPa:
    alpha' = 0.64 (b/a = 1) and 1.29 (b/a = 2) (Equations §3.1)."""
    laminate = PRESETS["textile_laminate"]
    contact = line_contact(force, LineGeometry(2.43e-3, 0.1437), contact_modulus(RIGID, laminate))
    w0 = 44.5
    v = 0.02315 * w0
    alpha = track_deformability(0.4, contact.p0, v, contact.a, substitute_modulus(RIGID, laminate), w0)
    assert alpha == pytest.approx(alpha_ref, rel=0.01)


@pytest.mark.parametrize("force", [9.0, 21.0, 36.0, 144.0])
def test_stand_b_alpha_prime(force):
    """Stand B: alpha' = 10 mu (b/a) R_c/R_r = 26.6 mu (b/a) (Equations §3.2), R_c = 166.3, R_r = 62.5 mm."""
    rubber = PRESETS["rubber_lining"]
    contact = line_contact(force, LineGeometry(0.008, 0.0625), contact_modulus(RIGID, rubber))
    w0 = 1.889
    v = 0.1663 * w0
    mu = 0.8
    alpha = track_deformability(mu, contact.p0, v, contact.a, substitute_modulus(RIGID, rubber), w0)
    assert alpha / (mu * contact.b_over_a) == pytest.approx(26.6, rel=1e-3)


def test_stand_b_rubber_preset_reproduces_e_star():
    assert contact_modulus(RIGID, PRESETS["rubber_lining"]) == pytest.approx(22.4e6, rel=1e-3)


def test_density_index():
    """g' = mu rho v^2/(4 pi G): stand B rubber, rho 1200, G 5.6 MPa, mu 0.8, v 0.157 m/s -> 3.4e-7."""
    assert density_index(0.8, 1200.0, 0.157, 5.6e6) == pytest.approx(0.8 * 1200 * 0.157**2 / (4 * math.pi * 5.6e6))
    assert density_index(0.8, 1200.0, 0.157, 5.6e6) == pytest.approx(3.4e-7, rel=0.02)


def test_presets_have_sources_and_lookup_suggests():
    for material in PRESETS.values():
        assert material.source
    assert preset("steel") is STEEL
    with pytest.raises(UnknownNameError, match="steel"):
        preset("steal")


def test_invalid_materials_raise_named_errors():
    with pytest.raises(ParameterError, match="nu"):
        Material(1e9, 0.6, 1000.0)
    with pytest.raises(ParameterError, match="E"):
        Material(0.0, 0.3, 1000.0)
    with pytest.raises(ParameterError, match="rho"):
        Material(1e9, 0.3, -1.0)
    with pytest.raises(ParameterError, match="materials"):
        substitute_modulus(RIGID, RIGID)
    with pytest.raises(ParameterError, match="w0"):
        track_deformability(0.4, 1e6, 1.0, 1e-3, 1e9, 0.0)
    with pytest.raises(ParameterError, match="mu"):
        track_deformability(-0.1, 1e6, 1.0, 1e-3, 1e9, 1.0)
