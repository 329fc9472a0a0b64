"""Rolling resistance: the normal reaction shifted forward by u = f_v r.

[Zhao] slides 25-36 (Figs. 5.9-5.10; power balance eq. 5.12); Equations §6. A wheel
of radius r rolling without slipping at speed v = omega r carries the normal reaction N not
under its centre but a distance u ahead, towards the leading edge of the contact (slide 32),
so N exerts the resisting moment N u about the centre. Slide 36 takes u proportional to the
radius, u = f_v r, with the dimensionless rolling-resistance coefficient f_v (the slides call
it "V mu"; OCR). The power dissipated is N u omega = f_v N v (slide 35), and a wheel pulled
at its centre keeps a constant speed under the pull F = f_v N (a = 0 in rig.teaching.
rolling_wheel), which is how f_v is measured (slide 36: "pulling a wheel on a road").

Koziarski's "coefficient of rolling friction" f in eq. (3) of [Koziarski] is the *length* u,
not f_v (Equations §1.2). Units: [m], [N], [N m], [m/s], [W].
"""

from __future__ import annotations

from dataclasses import dataclass

from rig import validate
from rig.teaching.rolling_wheel import F_V_RANGE

SOURCE = "[Zhao] slide 36 'Characteristic values of the rolling coefficient'"


@dataclass(frozen=True)
class RollingCoefficientRange:
    """Characteristic values of f_v [1] for a contact pair, with the source of the numbers."""

    pair: str
    low: float
    high: float
    source: str


ROLLING_COEFFICIENTS = (
    RollingCoefficientRange("tyre-road", 1e-2, 2e-2, SOURCE),
    RollingCoefficientRange("steel-steel", 1e-3, 5e-3, SOURCE),
)


def _f_v(value: object) -> float:
    return validate.number("f_v", value, *F_V_RANGE, hi_open=True)


def normal_reaction_shift(f_v: float, radius: float) -> float:
    """Forward shift of the normal reaction u = f_v r [m] (slide 36); radius r [m] > 0."""
    return _f_v(f_v) * validate.number("radius", radius, 0.0, lo_open=True)


def resisting_moment(normal_force: float, f_v: float, radius: float) -> float:
    """Rolling-resistance moment about the wheel centre N u = N f_v r [N m] (slide 32); N [N] >= 0."""
    return validate.number("normal_force", normal_force, 0.0) * normal_reaction_shift(f_v, radius)


def dissipated_power(normal_force: float, f_v: float, speed: float) -> float:
    """Power dissipated by rolling friction N u omega = f_v N v [W] (slide 35); speed v [m/s] >= 0."""
    n = validate.number("normal_force", normal_force, 0.0)
    return _f_v(f_v) * n * validate.number("speed", speed, 0.0)


def steady_pull(normal_force: float, f_v: float) -> float:
    """Pull at the centre that keeps the wheel at constant speed: F = f_v N [N] (slide 36)."""
    return _f_v(f_v) * validate.number("normal_force", normal_force, 0.0)


def coefficient_from_pull(pull: float, normal_force: float) -> float:
    """The measurement of slide 36: f_v = F/N [1] from the steady pull F [N] >= 0 and N [N] > 0."""
    f = validate.number("pull", pull, 0.0)
    n = validate.number("normal_force", normal_force, 0.0, lo_open=True)
    return _f_v(f / n)
