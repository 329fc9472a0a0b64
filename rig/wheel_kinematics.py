"""Stand-level kinematics of a friction-wheel pair: eqs. (1), (29)-(32) and (36) of seed 000.

The one place for these relations: the reduction (rig.reduction) and the stand simulators
import them from here. Units: angular speeds [rad/s], angles [rad], lengths [m].

Geometry and signs (seed notes 1.1, 1.2 last paragraph, 2): the contact plane has x along the
rolling direction and y along the contact line, origin at the contact centre O. The axis of
wheel k pierces the contact plane at A_k = (x_k, y_k); its angular velocity has the component
w0k along the contact normal. Both surfaces pass the contact in +x, so for wheel axes on
*opposite* sides of the contact (stand A) the two normal components have opposite signs in a
common frame. We carry them as the *signed speeds* w01 = w1 sin(alpha1) and w02 = -(normal
component of wheel 2 in that frame), so that

    spin          w0 = w01 + w02                              eq. (1), opposite-side axes
    rolling point C  = (w01 A1 + w02 A2) / (w01 + w02)        weighted centroid, seed notes 1.2

and the rigid slip of wheel 1 relative to wheel 2 is w0 (-(y - l), x - c), the convention of
rig.contact. With stand A's A1 = (0, l1), A2 = (Delta h, l2) (l2 < 0 signed) and
i_k = w2/w1 this gives eqs. (29)-(31). Reversed or stalled wheels make w01 + w02 small or
negative; |w01 + w02| below a tolerance raises :class:`SpinTooSmallError` (hard case 2).
"""

from __future__ import annotations

import math
from enum import Enum

from rig import validate
from rig.contact.kinematics import spin
from rig.errors import ParameterError

DEFAULT_SPIN_RTOL = 1e-9  # |w01 + w02| <= rtol (|w01| + |w02|) counts as zero spin [1]


class SpinTooSmallError(ParameterError):
    """The spin w01 + w02 of the pair is (numerically) zero: the rolling point is at infinity."""


class AxisSides(Enum):
    """Where the two wheel axes lie relative to the contact (seed notes 1.2)."""

    OPPOSITE = "opposite"  # stand A: "axes situated on the opposite sides of the contact area"
    SAME = "same"  # e.g. a disc driving an inner cone: the normal components subtract


def signed_normal_speeds(
    omega_1: float, alpha_1: float, omega_2: float, alpha_2: float, sides: AxisSides
) -> tuple[float, float]:
    """Signed normal spin components (w01, w02) [rad/s] with w0 = w01 + w02 (eq. 1).

    omega_k: wheel speed [rad/s], positive when wheel k's surface moves in +x at the contact;
    alpha_k: half contact angle [rad] (angle between the axis and the contact plane).
    """
    w01 = omega_1 * math.sin(alpha_1)
    w02 = omega_2 * math.sin(alpha_2)
    return (w01, w02) if sides is AxisSides.OPPOSITE else (w01, -w02)


def pair_spin(omega_1: float, alpha_1: float, omega_2: float, alpha_2: float, sides: AxisSides) -> float:
    """Spin w0 of the wheel pair [rad/s], eq. (1) w0 = w1 sin(alpha1) - w2 sin(alpha2).

    Delegates to rig.contact.kinematics.spin; for axes on opposite sides the second wheel's
    normal component has the opposite sign in the common frame, so its speed enters negated.
    """
    second = -omega_2 if sides is AxisSides.OPPOSITE else omega_2
    return float(spin(omega_1, alpha_1, second, alpha_2))


def rolling_point(
    w01: float,
    w02: float,
    pierce_1: tuple[float, float],
    pierce_2: tuple[float, float],
    rtol: float = DEFAULT_SPIN_RTOL,
) -> tuple[float, float]:
    """Rolling point C = (c, l) [m] as the weighted centroid of the axis piercing points.

    w01, w02: signed normal speeds [rad/s] (any common scale, e.g. divided by w1);
    pierce_k = (x_k, y_k) [m]. Raises SpinTooSmallError when |w01 + w02| <= rtol (|w01| + |w02|).
    """
    total = w01 + w02
    scale = abs(w01) + abs(w02)
    if not math.isfinite(total) or abs(total) <= rtol * scale or scale == 0.0:
        raise SpinTooSmallError(
            "w01 + w02", total, f"|w01 + w02| > {rtol:g} (|w01| + |w02|) = {rtol * scale:g}",
            hint="stalled or reversed wheel: the rolling point is at infinity (hard case 2)",
        )
    c = (w01 * pierce_1[0] + w02 * pierce_2[0]) / total
    l = (w01 * pierce_1[1] + w02 * pierce_2[1]) / total
    return c, l


def stand_a_rolling_point(
    ratio: float, alpha_1: float, l1: float, l2: float, delta_h: float, rtol: float = DEFAULT_SPIN_RTOL
) -> tuple[float, float]:
    """Stand A rolling point (c, l) [m] from i_k = w2/w1 [1], eqs. (29)-(31).

    l = (l1 sin(alpha1) + l2 i_k)/(sin(alpha1) + i_k), eq. (29)/(30) with signed l2 (< 0);
    c = Delta h i_k/(sin(alpha1) + i_k), eq. (31). alpha_1 [rad], l1, l2, delta_h [m].
    """
    return rolling_point(math.sin(alpha_1), ratio, (0.0, l1), (delta_h, l2), rtol)


def ratio_for_l(l: float, alpha_1: float, l1: float, l2: float) -> float:
    """Inverse of eq. (30): the kinematic ratio i_k = sin(alpha1)(l1 - l)/(l - l2) [1] for l [m].

    Valid for l strictly between l2 and l1 (positive i_k); raises ParameterError otherwise.
    """
    lo, hi = min(l1, l2), max(l1, l2)
    validate.number("l", l, lo, hi, lo_open=True, hi_open=True)
    return math.sin(alpha_1) * (l1 - l) / (l - l2)


def c_for_l(l: float, l1: float, l2: float, delta_h: float) -> float:
    """Eq. (32): c = Delta h (l1 - l)/(l1 - l2) [m] (i_k eliminated with eq. 30)."""
    if l1 == l2:
        raise ParameterError("l1 - l2", 0.0, "non-zero (the axes must pierce at different points)")
    return delta_h * (l1 - l) / (l1 - l2)


def dl_dratio(ratio: float, alpha_1: float, l1: float, l2: float) -> float:
    """Sensitivity dl/di_k = -sin(alpha1)(l1 - l2)/(sin(alpha1) + i_k)^2 [m] (seed notes 2).

    Stand A at l = 0: about -28.5 mm; used for the counting resolution of l.
    """
    s = math.sin(alpha_1)
    return -s * (l1 - l2) / (s + ratio) ** 2


def stand_b_offset(e: float, sigma: float) -> float:
    """Stand B, eq. (36): c = e sin(sigma) [m]; e: pivot distance [m], sigma: twist angle [rad]."""
    return e * math.sin(sigma)


def stand_b_twist(e: float, c: float) -> float:
    """Inverse of eq. (36): the twist sigma = asin(c/e) [rad] giving the offset c [m]."""
    e = validate.number("e", e, 0.0, lo_open=True)
    validate.number("c", c, -e, e)
    return math.asin(c / e)
