"""The earlier swinging (oscillating) drive of stand B: theta_r(t) = theta_A sin(2 pi f t) on shaft 16.

[Koziarski] section 3.2 mentions that the stand first had a swinging drive, later replaced by the
continuous three-speed drive; its data are not given. Equations §4.2 [assumed]: a crank-rocker
imposes the roller-shaft angle, f ~ 0.2-2 Hz, theta_A ~ 5-30 deg. The rolling speed reverses
twice per cycle, where the steady contact law does not hold: the drive is used together with
the transient (relaxation) contact of rig.stands.disc_roller.components.ContactRelaxation.
[Oscillating] (S15): the stroke ratio e = x/(2b), x = R_r 2 theta_A the rolled distance of a stroke.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SwingingDrive:
    """Imposed roller-shaft motion: amplitude theta_A [rad], frequency f [Hz]."""

    amplitude: float
    frequency: float

    @property
    def period(self) -> float:
        """1/f [s]."""
        return 1.0 / self.frequency

    def angle(self, t: np.ndarray) -> np.ndarray:
        """theta_r(t) [rad] at times t [s]."""
        return self.amplitude * np.sin(2.0 * math.pi * self.frequency * np.asarray(t, dtype=float))

    def speed(self, t: np.ndarray) -> np.ndarray:
        """d theta_r/dt [rad/s]."""
        w = 2.0 * math.pi * self.frequency
        return self.amplitude * w * np.cos(w * np.asarray(t, dtype=float))

    def acceleration(self, t: np.ndarray) -> np.ndarray:
        """d^2 theta_r/dt^2 [rad/s^2]."""
        w = 2.0 * math.pi * self.frequency
        return -self.amplitude * w * w * np.sin(w * np.asarray(t, dtype=float))

    def stroke_ratio(self, roller_radius: float, half_width_b: float) -> float:
        """e = x/(2b) with x = R_r 2 theta_A ([Oscillating] eq. S15) [1]; roller radius, b [m]."""
        return roller_radius * 2.0 * self.amplitude / (2.0 * half_width_b)
