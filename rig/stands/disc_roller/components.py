"""Lumped components of stand B's drive train (Equations §4.2): motor + worm, loop, bearings, lag.

Each is a frozen dataclass with vectorised methods (numpy arrays of states in, arrays out).
Optional effects are built only when a scene names them; the drive train holds None otherwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

SYNCHRONOUS_SPEED = 2.0 * math.pi * 1500.0 / 60.0  # 4-pole motor at 50 Hz [rad/s] ([assumed], Equations §4.2)
PULL_OUT_RATIO = 2.5  # pull-out over rated torque of an induction motor [1] ([assumed] typical)


@dataclass(frozen=True)
class WormDrive:
    """Motor 23 through the worm gear 22 (self-locking: assumed), seen at the roller shaft 16.

    The induction motor's torque is linear in its slip near synchronism and saturates smoothly
    at the pull-out torque: T_m = T_max tanh(k_m (w_set - w)/T_max) (w at the motor) [assumed].
    The worm is a rigid kinematic link of ratio i_w (self-locking: the roller can never drive
    the motor faster, so the motor inertia is always reflected, J_m i_w^2); its losses are an
    efficiency eta on driving torque and 1/eta on braking torque (the worm's friction adds to the
    motor's braking when the load overruns) [assumed]. Units: inertia [kg m^2], torque [N m],
    speeds [rad/s].
    """

    inertia: float  # roller + reflected motor inertia at shaft 16 [kg m^2]
    ratio: float  # i_w [1]
    efficiency: float  # eta_w [1]
    slope: float  # motor torque per motor slip speed [N m s/rad]
    max_torque: float  # pull-out torque at the motor [N m]

    @classmethod
    def from_rating(cls, roller_inertia: float, motor_inertia: float, ratio: float, efficiency: float,
                    rated_torque: float, rated_slip: float) -> WormDrive:
        """From the motor's rating: slope = T_rated/(s_rated w_sync), T_max = 2.5 T_rated."""
        return cls(
            inertia=roller_inertia + motor_inertia * ratio**2,
            ratio=ratio,
            efficiency=efficiency,
            slope=rated_torque / (rated_slip * SYNCHRONOUS_SPEED),
            max_torque=PULL_OUT_RATIO * rated_torque,
        )

    def torque(self, roller_speed: np.ndarray, set_speed: float) -> np.ndarray:
        """Torque of the worm on the roller shaft [N m] at roller speed [rad/s], no-load speed set_speed [rad/s]."""
        motor = self.max_torque * np.tanh(self.slope * self.ratio * (set_speed - roller_speed) / self.max_torque)
        driving = motor * np.sign(set_speed) >= 0.0
        factor = np.where(driving, self.efficiency, 1.0 / self.efficiency)
        return self.ratio * factor * motor


@dataclass(frozen=True)
class LoopCompliance:
    """Torsion of momentometer 8 closing the gear loop (Equations §4.2): T_Mo = k dz(phi) + d dz'(phi) phi'.

    phi = theta_r/i_g - theta_d: twist at the disc shaft [rad]; stiffness k [N m/rad], damping d
    [N m s/rad]. With backlash 2 delta [rad] the spring acts through the smoothed dead zone
    dz(phi) = phi - delta tanh(phi/delta) (-> phi -+ delta outside, ~phi^3/(3 delta^2) inside;
    [R] our choice of smoothing, C-infinity, no events needed), else dz(phi) = phi.
    """

    stiffness: float
    damping: float
    backlash: float | None = None  # total backlash 2 delta [rad]; None: none

    def deflection(self, twist: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """dz(phi) [rad] and its slope dz'(phi) [1]."""
        if self.backlash is None:
            return twist, np.ones_like(twist)
        half = 0.5 * self.backlash
        th = np.tanh(twist / half)
        return twist - half * th, th * th

    def torque(self, twist: np.ndarray, twist_rate: np.ndarray) -> np.ndarray:
        """Torque transmitted to the disc [N m] at twist [rad] and twist rate [rad/s]."""
        spring, slope = self.deflection(np.asarray(twist, dtype=float))
        return self.stiffness * spring + self.damping * slope * twist_rate

    def twist_for(self, torque: float) -> float:
        """Static twist [rad] that transmits ``torque`` [N m] (inverse of dz, monotone)."""
        target = torque / self.stiffness
        if self.backlash is None or target == 0.0:
            return target
        half = 0.5 * self.backlash
        bound = target + math.copysign(half, target)  # dz(bound) lies beyond the target
        lo, hi = sorted((0.0, bound))
        return brentq(lambda phi: phi - half * math.tanh(phi / half) - target, lo, hi, xtol=1e-18, rtol=1e-14)


@dataclass(frozen=True)
class BearingFriction:
    """Regularised Coulomb friction T = T_c tanh(w/w_s) in the disc and roller bearings.

    disc_torque, roller_torque: T_c [N m]; speed_scale: w_s [rad/s] (hard case 7: no
    discontinuity at zero speed). Equations §4.1: 0.01-0.05 N m [assumed].
    """

    disc_torque: float
    roller_torque: float
    speed_scale: float

    def disc(self, speed: np.ndarray) -> np.ndarray:
        """Friction torque on the disc shaft 3 [N m] at disc speed [rad/s]."""
        return self.disc_torque * np.tanh(speed / self.speed_scale)

    def roller(self, speed: np.ndarray) -> np.ndarray:
        """Friction torque on the roller shaft 16 [N m] at roller speed [rad/s]."""
        return self.roller_torque * np.tanh(speed / self.speed_scale)


@dataclass(frozen=True)
class ContactRelaxation:
    """Transient contact: dF/dt = (max(|v|, v_floor)/L_r)(F_ss - F) for F = (F_x, F_y, M_O).

    L_r = length_over_b * b [m] (Equations §4.2: L_r ~ b...2b), v the rolling speed [m/s],
    v_floor [m/s] keeps the lag finite at reversals (hard case 7). A surrogate of the full
    transient grid model (a separate issue): the loads follow the steady law with the delay of
    the material's travel over about one contact half width.
    """

    length: float
    speed_floor: float

    def rate(self, rolling_speed: np.ndarray) -> np.ndarray:
        """Relaxation rate [1/s] at the rolling speed [m/s]."""
        return np.maximum(np.abs(rolling_speed), self.speed_floor) / self.length
