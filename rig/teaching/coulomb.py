"""Coulomb's laws of dry friction: static (adhesion) and kinetic (sliding) friction.

[Zhao] (lecture notes "Mutual actions in machinery elements"), section 5.2.1-5.2.3, slides
10-17; Equations §6. Units: forces [N], speeds [m/s], power [W]; friction
coefficients are dimensionless [1].

* Static friction, ineq. (5.1): the contact sticks while |T| <= mu_s N, where T and N are the
  tangential and normal components of the constraint reaction, found from equilibrium.
* Kinetic friction (slide 17): once sliding, |T| = mu_k N, opposite to the sliding velocity,
  with mu_k "usually less" than mu_s (slide 10).
* Kinetic friction is a power loss (slide 21): P = mu_k N |v|.
"""

from __future__ import annotations

import math

from rig import validate
from rig.errors import ParameterError

STANDARD_GRAVITY = 9.80665  # standard acceleration of gravity g [m/s^2] (CGPM 1901)
MU_RANGE = (0.0, 3.0)  # accepted friction coefficients [1]; [Zhao]'s table spans 0.04 ... 1.05


def friction_coefficient(name: str, value: object) -> float:
    """Check a friction coefficient [1]: a finite number in MU_RANGE; returns it as float."""
    return validate.number(name, value, *MU_RANGE)


def static_and_kinetic(mu_s: object, mu_k: object) -> tuple[float, float]:
    """Check a pair (mu_s, mu_k) [1] with 0 <= mu_k <= mu_s (slide 10: kinetic <= static)."""
    mu_s = friction_coefficient("mu_s", mu_s)
    mu_k = validate.number("mu_k", mu_k, 0.0, mu_s)
    return mu_s, mu_k


def static_friction_holds(tangential_force: float, normal_force: float, mu_s: float) -> bool:
    """True when the contact sticks: |T| <= mu_s N, ineq. (5.1) of [Zhao] (slide 14).

    tangential_force T [N] (from the equilibrium equations), normal_force N [N] >= 0, mu_s [1].
    """
    t = validate.number("tangential_force", tangential_force)
    n = validate.number("normal_force", normal_force, 0.0)
    return abs(t) <= friction_coefficient("mu_s", mu_s) * n


def kinetic_friction(normal_force: float, mu_k: float, sliding_velocity: float) -> float:
    """Kinetic friction force T = -mu_k N v/|v| [N] on the sliding body (slide 17).

    normal_force N [N] >= 0; sliding_velocity v [m/s] of the body relative to the support,
    non-zero (at v = 0 the static law (5.1) applies instead: use static_friction_holds).
    """
    n = validate.number("normal_force", normal_force, 0.0)
    mu = friction_coefficient("mu_k", mu_k)
    v = validate.number("sliding_velocity", sliding_velocity)
    if v == 0.0:
        raise ParameterError("sliding_velocity", v, "non-zero (at rest the static law (5.1) applies)")
    return -math.copysign(mu * n, v)


def friction_power(normal_force: float, mu_k: float, sliding_speed: float) -> float:
    """Power dissipated by kinetic friction P = mu_k N |v| [W] (slide 21: a power loss).

    normal_force N [N] >= 0, mu_k [1], sliding_speed v [m/s] (sign ignored).
    """
    n = validate.number("normal_force", normal_force, 0.0)
    v = validate.number("sliding_speed", sliding_speed)
    return friction_coefficient("mu_k", mu_k) * n * abs(v)
