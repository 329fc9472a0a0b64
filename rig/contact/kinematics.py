"""Contact kinematics of [Koziarski], section 2.1: spin (eq. 1), rolling point (eqs. 2-3), rigid slip.

Pure functions. Units: angular speeds in rad/s, lengths in m, speeds in m/s unless a docstring
says "dimensionless". The contact problem itself is stated in *creepages* (centre slip and spin
divided by the rolling speed), so that zero spin (rolling point at infinity) is representable.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.errors import ParameterError


def spin(omega_1: float, alpha_1: float, omega_2: float, alpha_2: float) -> float:
    """Spin (velocity of pivoting friction) w0 = w1 sin(alpha1) - w2 sin(alpha2), eq. (1) [rad/s].

    alpha_i [rad] is the half contact angle (angle between wheel axis and contact plane); the
    printed "w1 sin a2" is a typo for w2 (Equations §1.8 #1). Signed speeds: for wheel axes
    on opposite sides of the contact the second term enters with the opposite sign of w2.
    """
    return omega_1 * np.sin(alpha_1) - omega_2 * np.sin(alpha_2)


def rolling_point_offset(v_lateral: float, spin_rate: float) -> float:
    """Deviation of the rolling point c = v_y / w0, eq. (2) [m]; raises for zero spin."""
    validate.number("spin_rate", spin_rate)
    if spin_rate == 0.0:
        raise ParameterError(
            "spin_rate", spin_rate, "non-zero", hint="with zero spin the rolling point is at infinity; use creepages"
        )
    return v_lateral / spin_rate


def lateral_slip(v_v: float, f: float, spin_rate: float, v: float, sigma: float) -> float:
    """Lateral slip velocity at the contact centre v_y = v_v + f w0 + v sin(sigma), eq. (3) [m/s].

    v_v: relative velocity along the contact line [m/s]; f: rolling-friction length [m] (the
    forward shift of the normal reaction, not the dimensionless f_v of [Zhao]); v: rolling
    speed [m/s]; sigma: misalignment (twist) angle of the axes [rad].
    """
    return v_v + f * spin_rate + v * np.sin(sigma)


@dataclass(frozen=True)
class Creepage:
    """Rigid slip of body 1 relative to body 2 over the contact, in elastic units (dimensionless).

    s_g(X, Y) = (xi - phi * Y, eta + phi * X), X = x/a, Y = y/a, in units of the elastic slip
    scale mu p0 v / G (G: Kalker's combined shear modulus 2/G = 1/G1 + 1/G2). Hence
    xi = xi_K G/(mu p0), eta = eta_K G/(mu p0) for Kalker's creepages xi_K, eta_K, and
    phi = a G (w0/v)/(mu p0) = 1/kappa, kappa = alpha'/(20 (1 - nu)) (Equations §1.7).
    """

    xi: float
    eta: float
    phi: float

    @classmethod
    def from_rolling_point(cls, alpha: float, c_over_a: float, l_over_a: float, poisson: float) -> Creepage:
        """Creepages of a rotation about C = (c, l) for track deformability alpha' (eq. 21).

        s_g(O) = w0 (l, -c) (Equations §1.1), so xi = phi l/a and eta = -phi c/a.
        alpha' = inf gives zero creepage (full stick, no traction); alpha' = 0 is rigid sliding
        and has no finite elastic scale: callers handle it before calling this.
        """
        phi = 0.0 if np.isinf(alpha) else 20.0 * (1.0 - poisson) / alpha
        return cls(xi=phi * l_over_a, eta=-phi * c_over_a, phi=phi)

    def field(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Rigid slip at points (x, y) [units of a], shape (2, ...)."""
        return np.stack(np.broadcast_arrays(self.xi - self.phi * y, self.eta + self.phi * x))

    def rolling_point(self) -> tuple[float, float]:
        """(c/a, l/a) of the instantaneous centre of the rigid slip; (nan, nan) for zero spin."""
        if self.phi == 0.0:
            return (np.nan, np.nan)
        return (-self.eta / self.phi, self.xi / self.phi)


def rigid_slip_direction(x: np.ndarray, y: np.ndarray, c_over_a: float, l_over_a: float) -> np.ndarray:
    """Unit direction of the rigid slip of a rotation w0 > 0 about C at points (x, y) [a].

    Returns shape (2, ...); zero at C itself, where the direction is undefined (hard case 3).
    """
    sx = -(y - l_over_a)
    sy = x - c_over_a
    norm = np.hypot(sx, sy)
    safe = np.where(norm > 0.0, norm, 1.0)
    return np.stack([np.where(norm > 0.0, sx / safe, 0.0), np.where(norm > 0.0, sy / safe, 0.0)])
