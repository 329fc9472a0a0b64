"""Forward simulation of stand A and B readings for the reduction tests (independent of the chains).

The forward direction uses the kinematic relations and the contact coefficients to produce what
the instruments would read; the chains must invert it. Coefficient stand-ins:
``rigid_coefficients`` binds the project's rigid (full-sliding) model, which ignores alpha';
``analytic_coefficients`` is a smooth closed form that depends on alpha' (to exercise the
mu <-> alpha' iteration) and is fast enough for Monte Carlo.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

from rig.contact.solve import solve
from rig.reduction import equations as eq
from rig.reduction.geometry import StandAGeometry, StandBGeometry
from rig.reduction.readings import ForceCalibration, Measured
from rig.reduction.stand_a import StandAReadings
from rig.reduction.stand_b import StandBReadings
from rig.wheel_kinematics import stand_a_rolling_point

OMEGA_1 = 2 * math.pi * 240 / 60  # 240 rpm of the driving wheel [rad/s] (Equations §3.1)
SENSITIVITY, OFFSET = 0.01, 0.002  # dynamometer calibration used in the tests [V/N], [V]


def _rigid(l_over_a, c_over_a, alpha, *, b_over_a, shape, n):
    r = solve("rigid", shape=shape, b_over_a=b_over_a, alpha=alpha, c_over_a=c_over_a, l_over_a=l_over_a,
              poisson=0.3, n=n)
    return r.nu_T, r.nu_v, r.nu_0


def rigid_coefficients(b_over_a: float, shape: str = "line", n: int = 16):
    """coefficients(l/a, c/a, alpha') of the rigid model (independent of alpha')."""
    return functools.partial(_rigid, b_over_a=b_over_a, shape=shape, n=n)


def analytic_coefficients(l_over_a: float, c_over_a: float, alpha: float) -> tuple[float, float, float]:
    """A smooth stand-in with |nu| < 1 whose forces grow with alpha' (like the model at small alpha')."""
    r = math.sqrt(l_over_a**2 + c_over_a**2 + 1.0)
    gain = 1.0 - 0.4 / (1.0 + alpha)  # 0.6 at alpha' = 0, -> 1
    return -l_over_a / r * gain, c_over_a / r * gain, math.sqrt(l_over_a**2 + c_over_a**2 + 0.5)


@dataclass(frozen=True)
class TruthA:
    l: float
    c: float
    ratio: float
    alpha: float
    lateral_force: float
    brake_moment: float


def stand_a_truth(mu, normal_force, ratio, coefficients, geometry=StandAGeometry(), b_over_a=1.0) -> TruthA:
    """Exact forces for kinematic ratio i_k (so that counts can be chosen to give it exactly)."""
    g = geometry
    c, l = stand_a_rolling_point(ratio, g.alpha_1, g.l1, g.l2, g.delta_h)
    alpha = eq.alpha_prime_line_contact(mu, b_over_a, g.r1 / (math.sin(g.alpha_1) + ratio), g.radius_x)
    nu_t, nu_v, nu_0 = coefficients(l / g.a, c / g.a, alpha)
    f_y = mu * normal_force * nu_v
    t2 = eq.wheel_2_moment(mu, normal_force, f_y, nu_t, nu_0, l, c, g.l2, g.delta_h, g.a)
    return TruthA(l, c, ratio, alpha, f_y, t2)


def stand_a_readings(counts_1, counts_2, truth: TruthA, normal_force, *, marks=(60, 60), gate_time=20.0,
                     geometry=StandAGeometry(), b_over_a=1.0, u_force=0.5, u_signal=1e-4, u_gate=1e-4,
                     u_weights=None, u_t2=None, signal_noise=0.0, t2_noise=0.0) -> StandAReadings:
    """Instrument readings for known truth; u_* default to the Equations page's resolutions."""
    g = geometry
    force_dyn = truth.lateral_force * g.yoke_lever / g.dynamometer_lever
    u_weights = g.weights_half_width / math.sqrt(3) if u_weights is None else u_weights
    u_t2 = g.balance_moment_half_width / math.sqrt(3) if u_t2 is None else u_t2
    cal = ForceCalibration(SENSITIVITY, OFFSET, 1e-5, 1e-4, -0.5e-9, u_weights)
    return StandAReadings(
        counts_1, counts_2, marks[0], marks[1], Measured(gate_time, u_gate), Measured(normal_force, u_force),
        Measured(SENSITIVITY * force_dyn + OFFSET + signal_noise, u_signal), cal,
        Measured(truth.brake_moment + t2_noise, u_t2), b_over_a,
    )


def stand_b_readings(mu, normal_force, l, sigma, coefficients, geometry=StandBGeometry(), b_over_a=1.0,
                     u=(1e-4, 1e-3, 0.05, 0.05, 0.05, 0.01)) -> tuple[StandBReadings, dict]:
    """Stand B readings for known mu at the settings l [m], sigma [rad] (exact, with given u's)."""
    g = geometry
    c = g.pivot_distance * math.sin(sigma)
    alpha = 10 * mu * b_over_a * g.radius_c / g.roller_radius
    nu_t, nu_v, nu_0 = coefficients(l / g.a, c / g.a, alpha)
    f_t, f_v = mu * normal_force * nu_t, mu * normal_force * nu_v
    moment_c = -mu * g.a * normal_force * nu_0  # spin w0 > 0 (rig.contact convention)
    t_mo = moment_c - g.radius_c * f_t
    readings = StandBReadings(
        Measured(l, u[0]), Measured(sigma, u[1]), Measured(normal_force, u[2]), Measured(f_t, u[3]),
        Measured(f_v, u[4]), Measured(t_mo, u[5]), b_over_a,
    )
    return readings, dict(c=c, alpha=alpha, moment_c=moment_c, f_t=f_t)
