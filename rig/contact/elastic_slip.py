"""Self slip of one element, eqs. (18)-(20) of [Koziarski] as reconstructed in Equations §1.6.

A square element of side 2 dx carries a uniform shear mu p along x. The displacement of its
centre due to that shear, per deformable body i (Cerruti, prefactor 1/(2 pi G_i)), is

  du_i = (mu p/(2 pi G_i)) * I(nu_i, dx),  I = int int [x^2 + (1 - nu) y^2]/(x^2 + y^2)^(3/2) dx dy
       = 4 dx (2 - nu) asinh(1)                                             (eq. (18) -> (19)),

and the element's own elastic slip velocity is du/dt with dt = 2 dx/v (eq. 17):

  v_el = compliance_factor * asinh(1) * mu p v/pi * sum_i (2 - nu_i)/G_i   (eq. (20) corrected).

``compliance_factor`` (a number, no flag):
* CERRUTI_FACTOR = 1 is the physically correct single-body Cerruti compliance 1/(2 pi G_i)
  (checked in the Equations page against Mindlin's (2 - nu)/(8 G a)); the project default;
* AUTHOR_FACTOR = 2 is the author's per-body 1/(pi G_i), which reproduces his three printed
  numbers (0.018476 v, 0.3222 v, 0.018593 v) to 4 digits. The printed eq. (20)
  "4 p mu (2 - nu) v/(pi G)" contradicts those numbers (Equations §1.8 #12).
v_el does not depend on dx (stated in [Koziarski], confirmed by the closed form).
Rigid bodies (Material.E = inf) contribute nothing.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from rig import validate
from rig.contact.materials import Material
from rig.errors import ParameterError

CERRUTI_FACTOR = 1.0
AUTHOR_FACTOR = 2.0
ASINH_1 = math.asinh(1.0)


def _factor(compliance_factor: float) -> float:
    return validate.number("compliance_factor", compliance_factor, 0.0, lo_open=True)


def _compliance_sum(bodies: Sequence[Material]) -> float:
    """sum_i (2 - nu_i)/G_i over the bodies [1/Pa]; raises if none is deformable."""
    if len(bodies) == 0:
        raise ParameterError("bodies", bodies, "one or two Material objects")
    total = 0.0
    for body in bodies:
        if not isinstance(body, Material):
            raise ParameterError("bodies", body, "Material objects (rig.contact.materials.Material)")
        total += (2.0 - body.nu) / body.G
    if total == 0.0:
        raise ParameterError("bodies", [b.name for b in bodies], "at least one deformable body (E < inf)")
    return total


def square_shear_integral(half_side: float, nu: float) -> float:
    """Closed form of the integral of eq. (18): 4 dx (2 - nu) asinh(1) [m].

    int_{-dx}^{dx} int_{-dx}^{dx} [x^2 + (1 - nu) y^2]/(x^2 + y^2)^(3/2) dx dy, from
    int int 1/R = 8 dx asinh(1) and int int x^2/R^3 = 4 dx asinh(1) (Equations §1.6).
    """
    dx = validate.number("half_side", half_side, 0.0, lo_open=True)
    nu = validate.number("nu", nu, -1.0, 0.5, lo_open=True)
    return 4.0 * dx * (2.0 - nu) * ASINH_1


def element_displacement(
    mu: float, p: float, half_side: float, bodies: Sequence[Material], compliance_factor: float = CERRUTI_FACTOR
) -> float:
    """Displacement of an element's centre under its own shear mu p, eq. (19) [m].

    du = compliance_factor * 2 mu p dx asinh(1)/pi * sum_i (2 - nu_i)/G_i; mu friction
    coefficient, p [Pa] pressure, half_side dx [m], bodies the materials in contact.
    With AUTHOR_FACTOR and one body this is the printed eq. (19), 4 mu p (2 - nu) dx asinh(1)/(pi G).
    """
    factor = _factor(compliance_factor)
    mu = validate.number("mu", mu, 0.0)
    p = validate.number("p", p, 0.0)
    dx = validate.number("half_side", half_side, 0.0, lo_open=True)
    return factor * 2.0 * mu * p * dx * ASINH_1 / math.pi * _compliance_sum(bodies)


def self_slip_velocity(
    mu: float, p: float, v: float, bodies: Sequence[Material], compliance_factor: float = CERRUTI_FACTOR
) -> float:
    """Elastic slip velocity of an element under its own friction force, eq. (20) corrected [m/s].

    v_el = compliance_factor * asinh(1) mu p v/pi * sum_i (2 - nu_i)/G_i = du/(2 dx/v).
    mu friction coefficient, p [Pa] pressure, v [m/s] rolling speed, bodies the materials in
    contact (rigid ones add nothing).
    """
    factor = _factor(compliance_factor)
    mu = validate.number("mu", mu, 0.0)
    p = validate.number("p", p, 0.0)
    v = validate.number("v", v, 0.0)
    return factor * ASINH_1 * mu * p * v / math.pi * _compliance_sum(bodies)
