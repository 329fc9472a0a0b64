"""Rigid full sliding (alpha' -> 0) against independent quadrature and exact identities.

Reference: Equations §1.10(a), computed there with a 4000 x 4000 midpoint grid (5 digits).
"""

import numpy as np
import pytest

from rig.contact.solve import solve

# shape, b/a, c/a, l/a, nu_T, nu_v, nu_0
SEED_NOTES_TABLE = [
    ("ellipse", 1, 0, 0, 0, 0, 0.58905),
    ("ellipse", 1, 0, 0.25, -0.28992, 0, 0.62558),
    ("ellipse", 1, 0, 0.5, -0.55223, 0, 0.73171),
    ("ellipse", 1, 0, 1.0, -0.88357, 0, 1.10447),
    ("ellipse", 1, 0, 2.0, -0.97428, 0, 2.05047),
    ("ellipse", 1, 0, 5.0, -0.99598, 0, 5.02003),
    ("ellipse", 1, 0.4, 0, 0, 0.45239, 0.68141),
    ("ellipse", 1, 0.4, 0.5, -0.52867, 0.42294, 0.81818),
    ("ellipse", 1, 2.0, 2.5, -0.77317, 0.61853, 3.23291),
    ("ellipse", 2, 0, 0, 0, 0, 0.90829),
    ("ellipse", 2, 0.4, 0, 0, 0.26567, 0.96174),
    ("ellipse", 2, 1.0, 0, 0, 0.62353, 1.23216),
    ("ellipse", 2, 0, 0.5, -0.44853, 0, 1.02345),
    ("line", 0.5, 0, 0, 0, 0, 0.57327),
    ("line", 0.5, 0.4, 0, 0, 0.57638, 0.69584),
    ("line", 0.5, 2.0, 0, 0, 0.96097, 2.08155),
    ("line", 0.75, 0, 0, 0, 0, 0.63756),
    ("line", 0.75, 0.4, 0, 0, 0.47825, 0.73599),
    ("line", 1, 0, 0, 0, 0, 0.71139),
    ("line", 1, 0, 0.5, -0.44604, 0, 0.82383),
    ("line", 1, 0, 1.0, -0.81814, 0, 1.14653),
    ("line", 1, 0.4, 0, 0, 0.40027, 0.79276),
    ("line", 1, 1.0, 0, 0, 0.81847, 1.17536),
    ("line", 1, 0.4, 0.5, -0.42827, 0.37877, 0.90077),
    ("line", 2, 0, 0, 0, 0, 1.05674),
    ("line", 2, 0, 0.5, -0.37590, 0, 1.15174),
    ("line", 2, 0.4, 0, 0, 0.23321, 1.10357),
    ("line", 2, 1.0, 0, 0, 0.55855, 1.34335),
    ("line", 2, 2.0, 0, 0, 0.91396, 2.10804),
]


def _rigid(shape, b, c, l):
    return solve("rigid", shape=shape, b_over_a=b, alpha=0.0, c_over_a=c, l_over_a=l, poisson=0.3)


def test_pure_spin_of_a_hertz_circle_is_3_pi_over_16():
    r = _rigid("ellipse", 1.0, 0.0, 0.0)
    assert r.nu_0 == pytest.approx(3 * np.pi / 16, rel=5e-3), "pivoting loss of a Hertz circle in full sliding"
    assert abs(r.nu_T) < 1e-12 and abs(r.nu_v) < 1e-12, "pure spin about the centre transmits no force"


@pytest.mark.parametrize("shape, b, c, l, nu_T, nu_v, nu_0", SEED_NOTES_TABLE)
def test_full_sliding_table_within_half_a_percent(shape, b, c, l, nu_T, nu_v, nu_0):
    r = _rigid(shape, b, c, l)
    for name, got, want in (("nu_T", r.nu_T, nu_T), ("nu_v", r.nu_v, nu_v), ("nu_0", r.nu_0, nu_0)):
        assert got == pytest.approx(want, rel=5e-3, abs=5e-4), f"{name} at {shape} b/a={b} C=({c},{l})"


def test_alpha_is_irrelevant_for_rigid_sliding():
    a = solve("rigid", shape="ellipse", b_over_a=1.3, alpha=0.0, c_over_a=0.3, l_over_a=0.7, poisson=0.3)
    b = solve("rigid", shape="ellipse", b_over_a=1.3, alpha=77.0, c_over_a=0.3, l_over_a=0.7, poisson=0.1)
    assert (a.nu_T, a.nu_v, a.nu_0) == pytest.approx((b.nu_T, b.nu_v, b.nu_0), abs=1e-14)


def test_circle_symmetry_swaps_peripheral_and_longitudinal_force():
    """For a circle, moving C along y by d gives the same |force| as moving it along x by d."""
    along_y = _rigid("ellipse", 1.0, 0.0, 0.6)
    along_x = _rigid("ellipse", 1.0, 0.6, 0.0)
    assert abs(along_y.nu_T) == pytest.approx(abs(along_x.nu_v), rel=1e-9)
    assert along_y.nu_0 == pytest.approx(along_x.nu_0, rel=1e-9)


def test_rolling_point_far_away_saturates_the_force_and_the_moment_grows_like_its_distance():
    r = _rigid("ellipse", 1.0, 12.0, 16.0)
    distance = 20.0
    assert np.hypot(r.nu_T, r.nu_v) == pytest.approx(1.0, abs=2e-3), "|F| -> mu F_N for |C| >> a"
    assert r.nu_0 == pytest.approx(distance, rel=2e-3), "nu_0 ~ |C|/a + O(a/|C|)"
    assert r.nu_T == pytest.approx(-16.0 / 20.0, abs=2e-3) and r.nu_v == pytest.approx(12.0 / 20.0, abs=2e-3)


def test_moment_about_c_is_never_smaller_than_about_the_centre():
    centre = _rigid("ellipse", 2.0, 0.0, 0.0)
    for c, l in [(0.2, 0.0), (0.0, 0.3), (0.5, -0.5), (3.0, 1.0)]:
        assert _rigid("ellipse", 2.0, c, l).nu_0 >= centre.nu_0 - 1e-12
