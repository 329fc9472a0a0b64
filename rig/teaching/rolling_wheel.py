"""A wheel pulled at its centre: rolling without slipping, or rolling with slipping.

[Zhao] slides 22-24 (rolling contact, Fig. 5.6, ineq. 5.10) and 33-40 (Fig. 5.10, power
balance eq. 5.12, vertical equilibrium, "Tangent component T", "Rolling with slipping");
Equations §6. Units: [kg], [kg m^2], [m], [N], [m/s^2], [rad/s^2].

Wheel of mass m, moment of inertia J about its centre, radius r, on a horizontal rigid plane,
moving forward (v > 0). Forces on it: the pull F at the centre (forward), the vertical load Q
(weight included), and at the contact the reaction: normal N = Q (vertical equilibrium, slide
38) shifted forward by u = f_v r (rolling resistance, slide 36), tangential T (positive
backwards). Newton and Euler about the centre:

    m a = F - T,        J omega' = T r - N u.

Rolling without slipping (v = omega r, a = omega' r) gives (Equations §6)

    a = (F - f_v N) / (m + J/r^2),      T = J a / r^2 + f_v N,

which is possible only while |T| <= mu_s N (ineq. 5.10). Otherwise the wheel slips at the
contact and T = mu_k N against the slip (slide 40): a = (F - T)/m, omega' = (T - f_v N) r/J.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rig import validate
from rig.teaching.coulomb import friction_coefficient, static_and_kinetic

F_V_RANGE = (0.0, 1.0)  # dimensionless rolling-resistance coefficient f_v = u/r [1]


@dataclass(frozen=True)
class Wheel:
    """Rigid wheel: mass_kg [kg] > 0, inertia_kg_m2 J about its centre [kg m^2] > 0, radius_m r [m] > 0."""

    mass_kg: float
    inertia_kg_m2: float
    radius_m: float

    def __post_init__(self) -> None:
        validate.number("mass_kg", self.mass_kg, 0.0, lo_open=True)
        validate.number("inertia_kg_m2", self.inertia_kg_m2, 0.0, lo_open=True)
        validate.number("radius_m", self.radius_m, 0.0, lo_open=True)

    @classmethod
    def solid_disc(cls, mass_kg: float, radius_m: float) -> Wheel:
        """Uniform solid disc: J = m r^2 / 2 [kg m^2]."""
        m = validate.number("mass_kg", mass_kg, 0.0, lo_open=True)
        r = validate.number("radius_m", radius_m, 0.0, lo_open=True)
        return cls(m, 0.5 * m * r * r, r)

    @property
    def effective_mass_kg(self) -> float:
        """m + J/r^2 [kg]: the inertia a pull at the centre meets while the wheel rolls."""
        return self.mass_kg + self.inertia_kg_m2 / self.radius_m**2


@dataclass(frozen=True)
class WheelMotion:
    """Instantaneous motion of the pulled wheel.

    acceleration_m_s2: a of the centre [m/s^2]; angular_acceleration_rad_s2: omega' [rad/s^2];
    friction_N: T at the contact, positive backwards [N]; normal_N: N [N];
    rolls: True = rolling without slipping (|T| <= mu_s N), False = rolling with slipping.
    """

    acceleration_m_s2: float
    angular_acceleration_rad_s2: float
    friction_N: float
    normal_N: float
    rolls: bool


def pulled_wheel(wheel: Wheel, pull: float, vertical_load: float, f_v: float, mu_s: float, mu_k: float) -> WheelMotion:
    """Motion of a forward-moving wheel pulled at its centre ([Zhao] slides 33-40).

    pull F [N] (forward positive), vertical_load Q [N] > 0 (weight included; N = Q),
    f_v rolling-resistance coefficient [1] in [0, 1), mu_s >= mu_k >= 0 [1].
    """
    force = validate.number("pull", pull)
    normal = validate.number("vertical_load", vertical_load, 0.0, lo_open=True)
    f_v = validate.number("f_v", f_v, *F_V_RANGE, hi_open=True)
    mu_s, mu_k = static_and_kinetic(mu_s, mu_k)
    m, j, r = wheel.mass_kg, wheel.inertia_kg_m2, wheel.radius_m
    a = (force - f_v * normal) / wheel.effective_mass_kg
    t = j * a / r**2 + f_v * normal
    if abs(t) <= mu_s * normal * (1 + 1e-12):  # at max_rolling_pull t = mu_s N only to rounding: it rolls
        return WheelMotion(a, a / r, t, normal, True)
    t = math.copysign(mu_k * normal, t)  # the contact slips the way the required T pointed
    return WheelMotion((force - t) / m, (t - f_v * normal) * r / j, t, normal, False)


def max_rolling_pull(wheel: Wheel, vertical_load: float, f_v: float, mu_s: float) -> float:
    """Largest forward pull [N] at which the wheel still rolls without slipping.

    From T = J a/r^2 + f_v N = mu_s N with a = (F - f_v N)/(m + J/r^2):
    F_max = f_v N + (mu_s - f_v) N (m r^2 + J)/J; a solid disc without rolling resistance
    gives the textbook 3 mu_s N. vertical_load Q = N [N] > 0, f_v [1] <= mu_s, mu_s [1].
    """
    normal = validate.number("vertical_load", vertical_load, 0.0, lo_open=True)
    mu_s = friction_coefficient("mu_s", mu_s)
    f_v = validate.number("f_v", f_v, *F_V_RANGE, hi_open=True)
    validate.number("f_v", f_v, 0.0, mu_s)  # with f_v > mu_s no pull keeps the wheel rolling
    ratio = wheel.effective_mass_kg * wheel.radius_m**2 / wheel.inertia_kg_m2
    return f_v * normal + (mu_s - f_v) * normal * ratio
