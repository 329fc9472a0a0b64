"""The quasi-static operating point of stand A: wheel 2's speed for a given brake moment, solved directly.

In steady running wheel 1 turns at the set speed w1 (ideal source, or the PI motor without
static error) and wheel 2 is in moment balance (drive train, Equations §4.1, with w2' = 0):

    T2(w1, w2) = T_B tanh(w2/eps) + T_f2(w2)        T2: contact moment on wheel 2, eq. (34)

The unknown is searched as the rolling point l in (l2, l1) (eq. 30 inverted: w2 = w1 i_k(l),
rig.wheel_kinematics.ratio_for_l): the balance is monotone in l (more braking moves C towards
A1, Equations §2) and the bracket is finite. A 1-D root find (scipy brentq) to 1e-12 m in l.
A set-point the contact cannot hold - wheel 2 would stall (T_set above the moment at w2 -> 0)
or would have to overrun without limit - raises ParameterError naming brake_setpoint_N_m and the
attainable range. The steady brake moment is T_set exactly (brake loop at nominal lining
friction, rig.stands.yoke.brake).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from scipy.optimize import brentq

from rig import validate
from rig.errors import ParameterError
from rig.stands.yoke.contact_forces import ContactSample, StandAContact
from rig.stands.yoke.drive_train import BearingFriction
from rig.wheel_kinematics import ratio_for_l

EDGE = 1e-9  # fraction of l1 - l2 kept away from the axes' piercing points [1]
STALL_RATIO = 10.0  # w2 must exceed this many brake eps for the brake to slip (not hold wheel 2) [1]


@dataclass(frozen=True)
class OperatingPoint:
    """Steady state: w1, w2 [rad/s], the contact there, brake moment T_B [N m], bearing moments
    T_f1, T_f2 [N m]; slope = d(T2 - T_f2)/d w2 at constant w1 [N m s/rad] (< 0: the contact
    stiffness that makes w2 follow the brake moment, Equations §4.1 "Stiffness")."""

    omega_1: float
    omega_2: float
    contact: ContactSample
    brake_moment: float
    friction_1: float
    friction_2: float
    slope: float

    @property
    def motor_moment(self) -> float:
        """Moment the drive delivers to wheel 1 [N m] (holds the coupling twist)."""
        return float(-self.contact.T1 + self.friction_1)


def _friction(bearing: BearingFriction | None, w1: float, w2: float) -> tuple[float, float]:
    if bearing is None:
        return 0.0, 0.0
    f1, f2 = bearing.moments(w1, w2)
    return float(f1), float(f2)


def steady_state(contact: StandAContact, omega_1: float, brake_moment: float, *, brake_speed_eps: float,
                 bearing: BearingFriction | None = None) -> OperatingPoint:
    """The operating point at wheel-1 speed w1 [rad/s] > 0 and brake set-point [N m]."""
    w1 = validate.number("omega_1_set_rad_s", omega_1, 0.0, lo_open=True)
    t_set = validate.number("brake_setpoint_N_m", brake_moment)
    g = contact.geometry
    span = g.l1 - g.l2

    def omega_2(l: float) -> float:
        return w1 * ratio_for_l(l, g.alpha_1, g.l1, g.l2)

    def residual(l: float) -> float:
        w2 = omega_2(l)
        t2 = contact.moments_scalar(w1, w2)[1]
        return t2 - t_set * math.tanh(w2 / brake_speed_eps) - _friction(bearing, w1, w2)[1]

    lo, hi = g.l2 + EDGE * span, g.l1 - EDGE * span
    r_lo, r_hi = residual(lo), residual(hi)
    if not (r_lo < 0.0 < r_hi):
        def held(l: float, r: float) -> float:  # the set-point whose residual is 0 at l: (T2 - friction)/tanh
            th = math.tanh(omega_2(l) / brake_speed_eps)
            return t_set + r / th if th != 0.0 else math.copysign(math.inf, r)

        ends = (held(lo, r_lo), held(hi, r_hi))
        bound = f"at least {min(ends):.4g}" if r_lo >= 0.0 else f"at most {max(ends):.4g}"
        raise ParameterError("brake_setpoint_N_m", brake_moment,
                             f"{bound} N m at F_N = {contact.normal_force:g} N, "
                             f"w1 = {w1:g} rad/s: the moments the contact can hold on wheel 2")
    l = brentq(residual, lo, hi, xtol=1e-12, rtol=1e-15, maxiter=200)
    w2 = omega_2(l)
    if w2 < STALL_RATIO * brake_speed_eps:
        stall = contact.moments_scalar(w1, STALL_RATIO * brake_speed_eps)[1]
        raise ParameterError("brake_setpoint_N_m", brake_moment,
                             f"below {stall:.4g} N m: at F_N = {contact.normal_force:g} N the brake would hold "
                             "wheel 2 (stall, hard case 2)")
    f1, f2 = _friction(bearing, w1, w2)
    brake = t_set * math.tanh(w2 / brake_speed_eps)
    h = 1e-6 * w2
    drive = [contact.moments_scalar(w1, x)[1] - _friction(bearing, w1, x)[1] for x in (w2 - h, w2 + h)]
    return OperatingPoint(w1, w2, contact.evaluate(w1, w2), brake, f1, f2, (drive[1] - drive[0]) / (2.0 * h))
