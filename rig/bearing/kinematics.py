"""Rigid kinematics of a ball between two raceways, eqs. (S4)-(S11) of [Oscillating].

Idealised as in [Oscillating] sec. 3.1: point contacts at the nominal contact angle, no slip, no
elastic deformation. Angular speeds [rad/s] about the bearing axis, speeds [m/s], radii [m].

* (S4), (S5) raceway surface speeds v_OR = w_OR r_o, v_IR = w_IR r_i;
* (S6), (S7) ball-centre speed v_C = (w_OR r_o + w_IR r_i)/2, cage speed w_C = v_C/r_C;
* (S8) r_i,o = r_C -/+ r_RE cos(alpha);
* (S9) relative rolling velocity v_r = (w_OR - w_C) r_o (printed "w_RE" is a typo for w_C,
  Equations §5), equal to (S10) (w_OR - w_IR)(r_C^2 - r_RE^2 cos^2 alpha)/(2 r_C);
* (S11) ball angular speed relative to the cage w = v_r/r_RE.
Spin at the contacts [R]: (S11) holds when the ball's rotation axis (in the cage frame) is
perpendicular to the contact line; the ball then contributes no spin and the spin at a contact
is the normal component of the raceway's angular velocity relative to the cage,
w_s = (w_ring - w_C) sin(alpha) (the bearing analogue of eq. (1) of [Koziarski],
w0 = w1 sin(alpha1) - w2 sin(alpha2)). Other ball-axis assumptions (outer-race control) give
other spin splits; [Oscillating] does not fix one.
"""

from __future__ import annotations

import math

from rig import validate
from rig.bearing.ball_raceway import BearingGeometry, Ring, check_ring


def raceway_speed(bearing: BearingGeometry, ring: Ring, omega_ring: float) -> float:
    """Surface speed of a raceway at its contact point, v = w r, eqs. (S4)/(S5) [m/s]."""
    omega_ring = validate.number("omega_ring", omega_ring)
    return omega_ring * bearing.contact_radius(ring)


def ball_centre_speed(bearing: BearingGeometry, omega_inner: float, omega_outer: float) -> float:
    """v_C = (w_OR r_o + w_IR r_i)/2, eq. (S6) [m/s]."""
    return 0.5 * (raceway_speed(bearing, Ring.OUTER, omega_outer) + raceway_speed(bearing, Ring.INNER, omega_inner))


def cage_speed(bearing: BearingGeometry, omega_inner: float, omega_outer: float) -> float:
    """Angular speed of the ball centres (cage) w_C = v_C/r_C, eq. (S7) [rad/s]."""
    return ball_centre_speed(bearing, omega_inner, omega_outer) / bearing.pitch_radius


def relative_rolling_speed(bearing: BearingGeometry, omega_inner: float, omega_outer: float) -> float:
    """v_r = (w_OR - w_IR)(r_C^2 - r_RE^2 cos^2 alpha)/(2 r_C), eq. (S10) [m/s] (= (S9))."""
    omega_inner = validate.number("omega_inner", omega_inner)
    omega_outer = validate.number("omega_outer", omega_outer)
    r_c = bearing.pitch_radius
    offset = bearing.ball_radius * math.cos(bearing.contact_angle)
    return (omega_outer - omega_inner) * (r_c * r_c - offset * offset) / (2.0 * r_c)


def ball_angular_speed(bearing: BearingGeometry, omega_inner: float, omega_outer: float) -> float:
    """Ball angular speed relative to the cage w = v_r/r_RE, eq. (S11) [rad/s]."""
    return relative_rolling_speed(bearing, omega_inner, omega_outer) / bearing.ball_radius


def contact_spin(bearing: BearingGeometry, ring: Ring, omega_inner: float, omega_outer: float) -> float:
    """Spin at the ball contact with the given raceway, w_s = (w_ring - w_C) sin(alpha) [rad/s].

    Reconstruction [R] (module docstring): ball axis perpendicular to the contact line. Signed
    about the bearing axis direction projected on the contact normal; the two contacts spin in
    opposite senses, |w_s,IR| r_i = |w_s,OR| r_o.
    """
    omega_ring = omega_inner if check_ring(ring) is Ring.INNER else omega_outer
    return (omega_ring - cage_speed(bearing, omega_inner, omega_outer)) * math.sin(bearing.contact_angle)
