"""A body on an inclined plane: adhesion (at rest) and sliding with friction.

[Zhao] slides 15-16 (adhesion, Fig. 5.4) and 20-21 (sliding, Fig. 5.5, eqs. 5.6-5.7);
Equations §6. The plane makes the angle alpha [rad] with the horizontal; the body has
mass M [kg]; g [m/s^2] is the acceleration of gravity.

Equilibrium normal and along the plane: N = M g cos(alpha), T = M g sin(alpha). With
ineq. (5.1) the body stays at rest iff M g sin(alpha) <= mu_s M g cos(alpha), i.e.
tan(alpha) <= mu_s: independent of the mass (and of the contact area). Sliding down,
d'Alembert (eqs. 5.6-5.7): M a = M g sin(alpha) - mu_k M g cos(alpha), so
a = g (sin(alpha) - mu_k cos(alpha)), less than the frictionless g sin(alpha) (slide 21).
"""

from __future__ import annotations

import math

from rig import validate
from rig.teaching.coulomb import STANDARD_GRAVITY, friction_coefficient

ANGLE_RANGE = (0.0, math.pi / 2)  # plane inclination [rad]


def _angle(alpha: object) -> float:
    return validate.number("alpha", alpha, *ANGLE_RANGE)


def reaction(mass: float, alpha: float, g: float = STANDARD_GRAVITY) -> tuple[float, float]:
    """Constraint reaction (N, T) [N] that holds a body of mass [kg] at rest on the plane.

    N = M g cos(alpha) normal to the plane, T = M g sin(alpha) along it (slide 16);
    alpha [rad] in [0, pi/2], g [m/s^2] > 0.
    """
    m = validate.number("mass", mass, 0.0, lo_open=True)
    a = _angle(alpha)
    g = validate.number("g", g, 0.0, lo_open=True)
    return m * g * math.cos(a), m * g * math.sin(a)


def at_rest(alpha: float, mu_s: float) -> bool:
    """True when the body stays at rest: tan(alpha) <= mu_s (slides 15-16 with ineq. 5.1).

    alpha [rad] in [0, pi/2], mu_s [1]. Compared as sin(alpha) <= mu_s cos(alpha), which is
    exact at alpha = pi/2 (a vertical wall never holds a body by friction alone).
    """
    a = _angle(alpha)
    return math.sin(a) <= friction_coefficient("mu_s", mu_s) * math.cos(a)


def critical_angle(mu_s: float) -> float:
    """Steepest inclination at which the body still adheres: alpha* = atan(mu_s) [rad]."""
    return math.atan(friction_coefficient("mu_s", mu_s))


def sliding_acceleration(alpha: float, mu_k: float, g: float = STANDARD_GRAVITY) -> float:
    """Acceleration down the plane of a body sliding down: a = g (sin(alpha) - mu_k cos(alpha)) [m/s^2].

    Eqs. (5.6)-(5.7) of [Zhao] (slide 20). alpha [rad] in [0, pi/2], mu_k [1], g [m/s^2] > 0.
    A negative value means the sliding body decelerates (it stops and then obeys at_rest).
    """
    a = _angle(alpha)
    g = validate.number("g", g, 0.0, lo_open=True)
    return g * (math.sin(a) - friction_coefficient("mu_k", mu_k) * math.cos(a))
