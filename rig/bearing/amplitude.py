"""Oscillation amplitudes of a ball bearing: Harris (S1)-(S3) and the stroke ratio e = x/2b (S15).

[Oscillating] sec. 2.2.3 and 4. Angles [rad] (use math.degrees for the paper's degrees), lengths [m].
theta is the **double** amplitude (peak to peak) of the oscillating ring relative to the other.
Reconstruction [R]: the inner ring oscillates against a fixed outer ring; then the cage turns
by theta (1 - gamma)/2 (eq. (S7) with w_OR = 0), i.e. by theta (1 - gamma)/2 relative to the
outer ring and theta (1 + gamma)/2 relative to the inner ring. This fixes the "-/+" of Harris:
the upper sign (1 - gamma) belongs to the outer raceway, the lower (1 + gamma) to the inner one.

* (S1) theta_crit = 720 deg/(Z (1 -/+ gamma)) (printed "Z(-/+gamma)" lacks the 1): the stroke
  at which the raceway portions over-rolled by neighbouring balls just touch;
* (S2) wear likely for theta < theta_crit/2 (a comparison, not a function);
* (S3) theta_dith = 720 deg b/(pi d_m (1 -/+ gamma)): the *single* amplitude at which the
  ball-centre travel over a full stroke equals the contact width 2b;
* (S15) e = x/(2b), x = distance rolled over the stroke theta under one of the kinematic
  assumptions K1..K4 of Equations §5.1 (default K3, the rolled track length on the raceway).
"""

from __future__ import annotations

import math
from enum import Enum

from rig import validate
from rig.bearing.ball_raceway import BearingGeometry, Ring, check_ring
from rig.errors import ParameterError

MAX_DOUBLE_AMPLITUDE = 2.0 * math.pi  # a full revolution per stroke [rad]


class KinematicAssumption(Enum):
    """How far the contact travels, x, for a double amplitude theta (Equations §5.1).

    K1: ball-centre travel relative to the outer ring, x = theta d_m (1 - gamma)/4 (= Harris' "-");
    K2: ball-centre travel relative to the inner ring, x = theta d_m (1 + gamma)/4 (= Harris' "+");
    K3: contact-track length rolled on either raceway, x = theta d_m (1 - gamma^2)/4 (rolling
        without slip: the same on both raceways) - the project default;
    K4: pitch-circle arc without the gamma correction, x = theta d_m/4.
    """

    K1 = "ball-centre travel relative to the outer ring"
    K2 = "ball-centre travel relative to the inner ring"
    K3 = "rolled track length on the raceway"
    K4 = "pitch-circle arc, gamma neglected"

    def travel_factor(self, gamma: float) -> float:
        """x/(theta d_m/4) under this assumption (dimensionless)."""
        return {
            KinematicAssumption.K1: 1.0 - gamma,
            KinematicAssumption.K2: 1.0 + gamma,
            KinematicAssumption.K3: 1.0 - gamma * gamma,
            KinematicAssumption.K4: 1.0,
        }[self]


def _assumption(value: object) -> KinematicAssumption:
    if not isinstance(value, KinematicAssumption):
        raise ParameterError("assumption", value, "a KinematicAssumption (K1, K2, K3 or K4)")
    return value


def _harris_factor(gamma: float, raceway: Ring) -> float:
    gamma = validate.number("gamma", gamma, 0.0, 1.0, hi_open=True)
    return 1.0 - gamma if check_ring(raceway) is Ring.OUTER else 1.0 + gamma


def critical_amplitude(balls: int, gamma: float, raceway: Ring) -> float:
    """Harris theta_crit = 4 pi/(Z (1 -/+ gamma)) [rad] (= 720 deg/(Z(1 -/+ gamma)), eq. (S1)).

    balls: number of balls Z; gamma = D_w cos(alpha)/d_m; raceway: OUTER takes (1 - gamma),
    INNER (1 + gamma) (module docstring). Wear is likely below theta_crit/2 (eq. (S2)).
    """
    z = validate.integer("balls", balls, 1)
    return 4.0 * math.pi / (z * _harris_factor(gamma, raceway))


def dither_amplitude(half_width: float, pitch_diameter: float, gamma: float, raceway: Ring) -> float:
    """Harris theta_dith = 4 b/(d_m (1 -/+ gamma)) [rad] (= 720 deg b/(pi d_m (1 -/+ gamma)), eq. (S3)).

    half_width b [m] of the contact in the rolling direction, pitch_diameter d_m [m].
    """
    b = validate.number("half_width", half_width, 0.0, lo_open=True)
    d_m = validate.number("pitch_diameter", pitch_diameter, 0.0, lo_open=True)
    return 4.0 * b / (d_m * _harris_factor(gamma, raceway))


def rolled_distance(
    bearing: BearingGeometry, theta: float, assumption: KinematicAssumption = KinematicAssumption.K3
) -> float:
    """Distance x [m] the contact travels over one stroke of double amplitude theta [rad]."""
    theta = validate.number("theta", theta, 0.0, MAX_DOUBLE_AMPLITUDE)
    return theta * bearing.pitch_diameter * _assumption(assumption).travel_factor(bearing.gamma) / 4.0


def stroke_ratio(
    bearing: BearingGeometry,
    theta: float,
    half_width: float,
    assumption: KinematicAssumption = KinematicAssumption.K3,
) -> float:
    """e = x/(2 b), eq. (S15) (dimensionless): theta [rad] double amplitude, half_width b [m]."""
    b = validate.number("half_width", half_width, 0.0, lo_open=True)
    return rolled_distance(bearing, theta, assumption) / (2.0 * b)


def amplitude_for_stroke_ratio(
    bearing: BearingGeometry,
    e: float,
    half_width: float,
    assumption: KinematicAssumption = KinematicAssumption.K3,
) -> float:
    """Double amplitude theta [rad] at which e = x/(2b) reaches the given value (inverse of (S15))."""
    e = validate.number("e", e, 0.0)
    b = validate.number("half_width", half_width, 0.0, lo_open=True)
    per_radian = bearing.pitch_diameter * _assumption(assumption).travel_factor(bearing.gamma) / (8.0 * b)
    e_max = MAX_DOUBLE_AMPLITUDE * per_radian
    if e > e_max * (1.0 + 1e-12):
        raise ParameterError("e", e, f"[0, {e_max:.6g}] (reached within one revolution, theta <= 2 pi)")
    return min(e / per_radian, MAX_DOUBLE_AMPLITUDE)
