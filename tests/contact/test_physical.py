"""Physical-units layer (rig.contact.physical): consistency with solve, the rigid full-sliding
table of Equations §1.10(a) scaled to newtons, negative spin, errors."""

from __future__ import annotations

import math
from unittest import mock

import numpy as np
import pytest

from rig.contact import physical
from rig.contact.hertz import LineGeometry, PointGeometry, curvature_ratio
from rig.contact.materials import (
    PRESETS,
    RIGID,
    STEEL,
    Material,
    combined_poisson,
    contact_modulus,
    substitute_modulus,
)
from rig.contact.physical import rolling_contact
from rig.contact.solve import solve
from rig.errors import ParameterError, UnknownNameError

INF = math.inf
LAMINATE = PRESETS["textile_laminate"]
RUBBER = PRESETS["rubber_lining"]


def ellipse_geometry(b_over_a: float, r_y: float = 0.01) -> PointGeometry:
    """Body radii that give a Hertz ellipse of the requested b/a >= 1 (b along x is the major axis)."""
    return PointGeometry(r_y * curvature_ratio(1.0 / b_over_a), r_y, INF, INF)


def line_force(b_over_a: float, length: float, radius: float, e_star: float) -> float:
    """Load [N] giving a line contact of the requested b/a: F = pi L E* b^2/(4 R)."""
    b = b_over_a * length / 2.0
    return math.pi * length * e_star * b * b / (4.0 * radius)


def test_forces_are_mu_fn_times_the_dimensionless_result():
    geometry = PointGeometry(0.1437, 0.0425, INF, INF)
    r = rolling_contact(
        "kinematic", normal_force=96.2, geometry=geometry, material_1=STEEL, material_2=LAMINATE,
        mu=0.4, speed=1.03, spin=44.5, c=0.3e-3, l=0.5e-3, n=12,
    )
    d = r.dimensionless
    assert r.force_x_N == pytest.approx(0.4 * 96.2 * d.nu_T, rel=1e-12)
    assert r.force_y_N == pytest.approx(0.4 * 96.2 * d.nu_v, rel=1e-12)
    scale = 0.4 * r.contact.a * 96.2
    assert r.moment_O_N_m == pytest.approx(scale * d.nu_Mo, rel=1e-12)
    assert r.moment_C_N_m == pytest.approx(scale * d.nu_MC, rel=1e-12)
    assert r.friction_power_W == pytest.approx(scale * 44.5 * d.nu_0, rel=1e-12)
    # M_C = M_O - c F_y + l F_x (Equations §1.1)
    assert r.moment_C_N_m == pytest.approx(r.moment_O_N_m - 0.3e-3 * r.force_y_N + 0.5e-3 * r.force_x_N, rel=1e-9)
    # P_t = -w0 M_C >= 0 for the rigid-slip power
    assert r.friction_power_W == pytest.approx(-44.5 * r.moment_C_N_m, rel=1e-9)
    # the same call to solve by hand
    direct = solve(
        "kinematic", shape="ellipse", b_over_a=r.contact.b_over_a, alpha=r.alpha_prime,
        c_over_a=0.3e-3 / r.contact.a, l_over_a=0.5e-3 / r.contact.a,
        poisson=combined_poisson(STEEL, LAMINATE), n=12,
    )
    assert d.nu_T == pytest.approx(direct.nu_T, rel=1e-12) and d.nu_v == pytest.approx(direct.nu_v, rel=1e-12)


def test_alpha_prime_uses_eq_21_with_the_substitute_modulus():
    geometry = LineGeometry(2.43e-3, 0.1437)
    r = rolling_contact(
        "rigid", normal_force=385.0, geometry=geometry, material_1=STEEL, material_2=LAMINATE,
        mu=0.4, speed=1.03, spin=44.5, c=0.0, l=0.0,
    )
    c = r.contact
    assert r.substitute_modulus_Pa == pytest.approx(substitute_modulus(STEEL, LAMINATE))
    assert r.alpha_prime == pytest.approx(40 * 0.4 * c.p0 * 1.03 / (c.a * r.substitute_modulus_Pa * 44.5), rel=1e-12)
    # stand A at 385 N: alpha' ~ 1.29 (Equations §3.1; steel here slightly deformable)
    assert r.alpha_prime == pytest.approx(1.29, rel=0.02)


# rigid full sliding, Equations §1.10(a): (shape, b/a, c/a, l/a, nu_T, nu_v, nu_0)
FULL_SLIDING = [
    ("ellipse", 1.0, 0.0, 0.5, -0.55223, 0.0, 0.73171),
    ("ellipse", 1.0, 0.4, 0.5, -0.52867, 0.42294, 0.81818),
    ("ellipse", 1.0, 2.0, 2.5, -0.77317, 0.61853, 3.23291),
    ("ellipse", 2.0, 1.0, 0.0, 0.0, 0.62353, 1.23216),
    ("ellipse", 2.0, 0.0, 0.5, -0.44853, 0.0, 1.02345),
    ("line", 0.5, 0.4, 0.0, 0.0, 0.57638, 0.69584),
    ("line", 1.0, 0.4, 0.5, -0.42827, 0.37877, 0.90077),
    ("line", 2.0, 2.0, 0.0, 0.0, 0.91396, 2.10804),
]


@pytest.mark.parametrize(("shape", "b_over_a", "c_a", "l_a", "nu_T", "nu_v", "nu_0"), FULL_SLIDING)
def test_rigid_full_sliding_in_newtons(shape, b_over_a, c_a, l_a, nu_T, nu_v, nu_0):
    mu, spin = 0.3, 12.0
    if shape == "ellipse":
        materials, geometry, force = (STEEL, STEEL), ellipse_geometry(b_over_a), 200.0
    else:
        materials, geometry = (RIGID, RUBBER), LineGeometry(0.008, 0.0625)
        force = line_force(b_over_a, 0.008, 0.0625, contact_modulus(RIGID, RUBBER))
    first = rolling_contact(
        "rigid", normal_force=force, geometry=geometry, material_1=materials[0], material_2=materials[1],
        mu=mu, speed=0.5, spin=spin, c=0.0, l=0.0,
    )
    a = first.contact.a
    assert first.contact.b_over_a == pytest.approx(b_over_a, rel=1e-9)
    r = rolling_contact(
        "rigid", normal_force=force, geometry=geometry, material_1=materials[0], material_2=materials[1],
        mu=mu, speed=0.5, spin=spin, c=c_a * a, l=l_a * a, n=64,
    )
    tol = 4e-4 * mu * force
    assert r.force_x_N == pytest.approx(mu * force * nu_T, abs=tol)
    assert r.force_y_N == pytest.approx(mu * force * nu_v, abs=tol)
    assert r.moment_C_N_m == pytest.approx(-mu * a * force * nu_0, abs=tol * a)
    assert r.friction_power_W == pytest.approx(mu * a * force * spin * nu_0, abs=tol * a * spin)


def test_negative_spin_is_the_mirror_image():
    """Reversing the spin about the same C reverses the rigid slip: F, M change sign, P does not."""
    kwargs = dict(
        normal_force=200.0, geometry=PointGeometry(0.01, 0.01, INF, INF), material_1=STEEL, material_2=STEEL,
        mu=0.3, speed=0.5, n=64,
    )
    a = rolling_contact("rigid", spin=1.0, c=0.0, l=0.0, **kwargs).contact.a
    plus = rolling_contact("rigid", spin=5.0, c=0.4 * a, l=0.5 * a, **kwargs)
    minus = rolling_contact("rigid", spin=-5.0, c=0.4 * a, l=0.5 * a, **kwargs)
    assert minus.force_x_N == pytest.approx(-plus.force_x_N, rel=1e-9)
    assert minus.force_y_N == pytest.approx(-plus.force_y_N, rel=1e-9)
    assert minus.moment_C_N_m == pytest.approx(-plus.moment_C_N_m, rel=1e-9)
    assert minus.moment_O_N_m == pytest.approx(-plus.moment_O_N_m, rel=1e-9)
    assert minus.friction_power_W == pytest.approx(plus.friction_power_W, rel=1e-9)
    assert minus.friction_power_W == pytest.approx(5.0 * minus.moment_C_N_m, rel=1e-9)  # P = -w0 M_C
    assert minus.force_x_N == pytest.approx(0.3 * 200.0 * 0.52867, abs=0.03)  # table 1.10(a), sign flipped


def test_negative_spin_mirrors_the_maps_of_a_grid_model():
    kwargs = dict(
        normal_force=96.2, geometry=PointGeometry(0.1437, 0.0425, INF, INF), material_1=STEEL, material_2=LAMINATE,
        mu=0.4, speed=1.03, c=0.2e-3, l=0.4e-3, n=10,
    )
    plus = rolling_contact("kinematic", spin=44.5, **kwargs)
    minus = rolling_contact("kinematic", spin=-44.5, **kwargs)
    assert minus.force_x_N == pytest.approx(-plus.force_x_N, rel=1e-6)
    assert minus.dimensionless.nu_MC == pytest.approx(-plus.dimensionless.nu_MC, rel=1e-6)
    # the law is odd in the slip: the traction map at each cell is the negative of the plus one
    mp, mm = plus.dimensionless.maps, minus.dimensionless.maps
    order_p, order_m = np.lexsort((mp.y, mp.x)), np.lexsort((mm.y, mm.x))
    np.testing.assert_allclose(mm.x[order_m], mp.x[order_p], atol=1e-12)
    np.testing.assert_allclose(mm.y[order_m], mp.y[order_p], atol=1e-12)
    np.testing.assert_allclose(mm.traction[:, order_m], -mp.traction[:, order_p], atol=1e-6)
    # and the mirrored map integrates to the reported force
    nu_v = float((mm.traction[1] * mm.area).sum() / (mm.pressure * mm.area).sum())
    assert nu_v == pytest.approx(minus.dimensionless.nu_v, rel=1e-9)


def test_effects_are_passed_through_and_off_effects_are_not_built():
    kwargs = dict(
        normal_force=36.0, geometry=LineGeometry(0.008, 0.0625), material_1=RIGID, material_2=RUBBER,
        mu=0.8, speed=0.314, spin=1.889, c=0.0, l=2e-3,
    )
    with mock.patch.object(physical, "solve", wraps=solve) as spy:
        r = rolling_contact("rigid", rolling_length=0.25, **kwargs)
    assert spy.call_args.kwargs["rolling_length"] == 0.25
    assert r.rolling_resistance_moment_N_m == pytest.approx(36.0 * 0.25 * r.contact.a)
    with mock.patch.object(physical, "solve", wraps=solve) as spy:
        off = rolling_contact("rigid", **kwargs)
    assert "rolling_length" not in spy.call_args.kwargs
    assert off.rolling_resistance_moment_N_m == 0.0
    # rolling length f shifts the rolling point c -> c + f (eq. 3)
    shifted = rolling_contact("rigid", **dict(kwargs, c=0.25 * r.contact.a))
    assert r.force_y_N == pytest.approx(shifted.force_y_N, rel=1e-12)


def test_invalid_input_raises_named_errors():
    base = dict(
        normal_force=36.0, geometry=LineGeometry(0.008, 0.0625), material_1=RIGID, material_2=RUBBER,
        mu=0.8, speed=0.314, spin=1.889, c=0.0, l=0.0,
    )
    for name, value in [("spin", 0.0), ("speed", -0.3), ("mu", 0.0), ("normal_force", 0.0), ("c", math.nan)]:
        with pytest.raises(ParameterError, match=name):
            rolling_contact("rigid", **dict(base, **{name: value}))
    with pytest.raises(ParameterError, match="material_2"):
        rolling_contact("rigid", **dict(base, material_2="rubber"))
    with pytest.raises(ParameterError, match="materials"):
        rolling_contact("rigid", **dict(base, material_2=RIGID))
    with pytest.raises(UnknownNameError, match="kinematic"):
        rolling_contact("kinematik", **base)
    with pytest.raises(UnknownNameError, match="psi"):
        rolling_contact("kinematic", psy=2.0, **base)
    with pytest.raises(ParameterError, match="poisson"):
        rolling_contact("rigid", **dict(base, material_2=Material(1e7, -0.2, 1000.0)))
