"""Self slip of one element, eqs. (18)-(20) (rig.contact.elastic_slip): the author's three worked
numbers of [Koziarski] sec. 2.2 and a numerical check of the integral (18)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import dblquad

from rig.contact.elastic_slip import (
    AUTHOR_FACTOR,
    CERRUTI_FACTOR,
    element_displacement,
    self_slip_velocity,
    square_shear_integral,
)
from rig.contact.materials import RIGID, Material
from rig.errors import ParameterError

TEXTOLITE = Material(E=8000e6, nu=0.3, rho=1350.0)
GUM = Material(E=40e6, nu=0.5, rho=1200.0)
STEEL = Material(E=2.1e5 * 1e6, nu=0.3, rho=7850.0)  # printed 2.1e6 MPa is a typo (Equations §1.8 #13)


@pytest.mark.parametrize(
    ("mu", "p0", "bodies", "printed"),
    [
        (0.4, 149e6, (TEXTOLITE, RIGID), 0.018476),  # textolite by steel, steel not deformed
        (0.8, 6.38e6, (GUM, RIGID), 0.3222),  # gum by steel, steel not deformed
        (0.2, 3936e6, (STEEL, STEEL), 0.018593),  # steel by steel, both deformed
    ],
)
def test_author_factor_reproduces_the_printed_examples(mu, p0, bodies, printed):
    """ACCEPTANCE (issue 2, item 1): the three v_el,max/v of [Koziarski] sec. 2.2 to 4 significant digits."""
    ratio = self_slip_velocity(mu, p0, 1.0, bodies, compliance_factor=AUTHOR_FACTOR)
    assert f"{ratio:.4g}" == f"{printed:.4g}"


def test_cerruti_factor_is_half_the_author_value():
    bodies = (TEXTOLITE,)
    physical = self_slip_velocity(0.4, 149e6, 2.0, bodies, compliance_factor=CERRUTI_FACTOR)
    author = self_slip_velocity(0.4, 149e6, 2.0, bodies, compliance_factor=AUTHOR_FACTOR)
    assert author == pytest.approx(2.0 * physical, rel=1e-14)
    assert physical / 2.0 == pytest.approx(0.00924, rel=1e-3)  # Equations §1.6 table, last column
    assert self_slip_velocity(0.4, 149e6, 2.0, bodies) == physical  # default is the Cerruti value


def test_printed_eq_20_form_does_not_reproduce_the_examples():
    """The printed 4 p mu (2 - nu) v/(pi G) gives 0.04193 v for textolite, not 0.018476 v."""
    printed_form = 4.0 * 149e6 * 0.4 * (2.0 - 0.3) / (math.pi * TEXTOLITE.G)
    assert printed_form == pytest.approx(0.04193, rel=1e-3)
    assert self_slip_velocity(0.4, 149e6, 1.0, (TEXTOLITE,), AUTHOR_FACTOR) != pytest.approx(printed_form, rel=0.1)


def _integral_18_polar(half_side: float, nu: float) -> float:
    """int int [x^2 + (1 - nu) y^2]/R^3 over the square, with scipy dblquad in polar coordinates
    (removes the 1/R singularity): integrand (cos^2 + (1 - nu) sin^2) dr dtheta, r up to the edge."""
    weight = lambda r, t: math.cos(t) ** 2 + (1.0 - nu) * math.sin(t) ** 2  # noqa: E731
    total = 0.0
    for centre in (0.0, 0.5 * math.pi, math.pi, 1.5 * math.pi):
        edge = lambda t, c=centre: half_side / abs(math.cos(t - c))  # noqa: E731
        value, _ = dblquad(weight, centre - 0.25 * math.pi, centre + 0.25 * math.pi, 0.0, edge, epsabs=0, epsrel=1e-12)
        total += value
    return total


def _integral_18_cartesian(half_side: float, nu: float) -> float:
    """The same integral directly in x, y over the four quadrants (singular corner at the origin)."""
    f = lambda y, x: (x * x + (1.0 - nu) * y * y) / (x * x + y * y) ** 1.5  # noqa: E731
    value, _ = dblquad(f, 0.0, half_side, 0.0, half_side, epsabs=1e-10, epsrel=1e-10)
    return 4.0 * value


@pytest.mark.parametrize(("half_side", "nu"), [(1.0, 0.3), (0.25, 0.5), (2e-3, 0.0)])
def test_integral_18_numerically_equals_closed_form_19(half_side, nu):
    closed = square_shear_integral(half_side, nu)
    assert _integral_18_polar(half_side, nu) == pytest.approx(closed, rel=1e-10)
    assert _integral_18_cartesian(half_side, nu) == pytest.approx(closed, rel=1e-6)


def test_displacement_19_and_velocity_20_are_consistent():
    """v_el = du/dt with dt = 2 dx/v (eq. 17); and eq. (19) as printed for one body, factor 2."""
    dx, v = 0.5e-3, 1.7
    du = element_displacement(0.4, 149e6, dx, (TEXTOLITE,), AUTHOR_FACTOR)
    printed_19 = 4.0 * 149e6 * 0.4 * (2.0 - 0.3) * dx * math.asinh(1.0) / (math.pi * TEXTOLITE.G)
    assert du == pytest.approx(printed_19, rel=1e-14)
    assert du / (2.0 * dx / v) == pytest.approx(self_slip_velocity(0.4, 149e6, v, (TEXTOLITE,), AUTHOR_FACTOR))
    # the Cerruti single-body displacement is (mu p/(2 pi G)) times the integral (18)
    cerruti = element_displacement(0.4, 149e6, dx, (TEXTOLITE,))
    assert cerruti == pytest.approx(0.4 * 149e6 / (2 * math.pi * TEXTOLITE.G) * square_shear_integral(dx, 0.3))


@settings(max_examples=40, deadline=None)
@given(dx=st.floats(1e-6, 1.0))
def test_self_slip_is_independent_of_element_size(dx):
    v = 0.8
    du = element_displacement(0.3, 1e7, dx, (GUM,))
    assert du / (2 * dx / v) == pytest.approx(self_slip_velocity(0.3, 1e7, v, (GUM,)), rel=1e-12)


def test_invalid_input_raises_named_errors():
    with pytest.raises(ParameterError, match="compliance_factor"):
        self_slip_velocity(0.4, 1e6, 1.0, (GUM,), compliance_factor=0.0)
    with pytest.raises(ParameterError, match="bodies"):
        self_slip_velocity(0.4, 1e6, 1.0, ())
    with pytest.raises(ParameterError, match="bodies"):
        self_slip_velocity(0.4, 1e6, 1.0, (RIGID, RIGID))
    with pytest.raises(ParameterError, match="bodies"):
        self_slip_velocity(0.4, 1e6, 1.0, ("steel",))
    with pytest.raises(ParameterError, match="half_side"):
        element_displacement(0.4, 1e6, 0.0, (GUM,))
    with pytest.raises(ParameterError, match="p"):
        self_slip_velocity(0.4, -1.0, 1.0, (GUM,))
