"""Geometry of an angular-contact ball bearing and the Hertz contact of a ball on a raceway.

[Oscillating] (Schwack et al. 2021), Table 1 and eq. (S8); Hertz point contact from rig.contact.hertz
(Equations §5.1). Lengths [m], angles [rad], forces [N], pressures [Pa].

Choices and readings (Equations §5.1):
* pitch diameter d_m = (D + d)/2 [A] (Table 1 gives only the bore d and outside diameter D);
* osculation = ball radius / groove radius [R] (r_groove = r_RE/osculation); the alternative
  reading 2 - r_groove/r_RE is not used;
* principal curvatures at the contact, x = rolling direction, y = across the groove:
  ball 1/r_RE in both directions; raceway in the rolling direction +cos(alpha)/r_i (inner,
  convex) and -cos(alpha)/r_o (outer, concave), i.e. (2/D_w) gamma/(1 -/+ gamma); across the
  groove -1/r_groove (concave). So the contact ellipse is long across the groove (a, along y)
  and narrow in the rolling direction (b, along x), as in [Oscillating].
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum

from rig import validate
from rig.contact.hertz import HertzEllipse, PointGeometry, point_contact
from rig.contact.materials import Material, contact_modulus
from rig.errors import ParameterError


class Ring(Enum):
    """Which raceway: the inner ring (IR) or the outer ring (OR)."""

    INNER = "inner"
    OUTER = "outer"


@dataclass(frozen=True)
class BearingGeometry:
    """Angular-contact ball bearing: outer_diameter D [m], inner_diameter d [m] (bore),
    ball_radius r_RE [m], contact_angle alpha [rad], osculation_inner/outer = r_RE/r_groove
    (dimensionless, < 1), material of balls and rings."""

    outer_diameter: float
    inner_diameter: float
    ball_radius: float
    contact_angle: float
    osculation_inner: float
    osculation_outer: float
    material: Material

    def __post_init__(self) -> None:
        d_out = validate.number("outer_diameter", self.outer_diameter, 0.0, lo_open=True)
        d_in = validate.number("inner_diameter", self.inner_diameter, 0.0, lo_open=True)
        if d_in >= d_out:
            raise ParameterError("inner_diameter", d_in, f"(0, outer_diameter = {d_out:g}) [m]")
        section = 0.5 * (d_out - d_in)
        validate.number("ball_radius", self.ball_radius, 0.0, 0.5 * section, lo_open=True, hi_open=True)
        validate.number("contact_angle", self.contact_angle, 0.0, 0.5 * math.pi, hi_open=True)
        validate.number("osculation_inner", self.osculation_inner, 0.0, 1.0, lo_open=True, hi_open=True)
        validate.number("osculation_outer", self.osculation_outer, 0.0, 1.0, lo_open=True, hi_open=True)
        if not isinstance(self.material, Material):
            raise ParameterError("material", self.material, "a rig.contact.materials.Material")

    @property
    def pitch_diameter(self) -> float:
        """d_m = (D + d)/2 [m] (assumption, Equations §5.1)."""
        return 0.5 * (self.outer_diameter + self.inner_diameter)

    @property
    def pitch_radius(self) -> float:
        """Radius of the ball centres r_C = d_m/2 [m]."""
        return 0.5 * self.pitch_diameter

    @property
    def ball_diameter(self) -> float:
        """D_w = 2 r_RE [m]."""
        return 2.0 * self.ball_radius

    @property
    def gamma(self) -> float:
        """gamma = D_w cos(alpha)/d_m (dimensionless), [Oscillating] below eq. (S3)."""
        return self.ball_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    def contact_radius(self, ring: Ring) -> float:
        """Distance of the contact point from the bearing axis, r_i,o = r_C -/+ r_RE cos(alpha), eq. (S8) [m]."""
        offset = self.ball_radius * math.cos(self.contact_angle)
        return self.pitch_radius - offset if check_ring(ring) is Ring.INNER else self.pitch_radius + offset

    def groove_radius(self, ring: Ring) -> float:
        """Groove (raceway cross-section) radius r_RE/osculation [m]."""
        osculation = self.osculation_inner if check_ring(ring) is Ring.INNER else self.osculation_outer
        return self.ball_radius / osculation

    def contact_geometry(self, ring: Ring) -> PointGeometry:
        """Principal radii [m] of ball (body 1) and raceway (body 2); x = rolling direction."""
        ring = check_ring(ring)
        rolling = self.contact_radius(ring) / math.cos(self.contact_angle)
        raceway_x = rolling if ring is Ring.INNER else -rolling
        return PointGeometry(self.ball_radius, self.ball_radius, raceway_x, -self.groove_radius(ring))


def check_ring(ring: object) -> Ring:
    """Return ring if it is a Ring, else raise ParameterError."""
    if not isinstance(ring, Ring):
        raise ParameterError("ring", ring, "Ring.INNER or Ring.OUTER")
    return ring


def raceway_contact(bearing: BearingGeometry, ring: Ring, force: float) -> HertzEllipse:
    """Hertz contact of one ball on the given raceway under the contact force [N].

    Returns a [m] across the groove (y), b [m] in the rolling direction (x), p0 [Pa].
    """
    e_star = contact_modulus(bearing.material, bearing.material)
    return point_contact(force, bearing.contact_geometry(ring), e_star)
