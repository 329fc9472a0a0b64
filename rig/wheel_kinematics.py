"""Stand-level kinematics of a friction-wheel pair: eqs. (1), (29)-(32) and (36) of [Koziarski].

The one place for these relations: the reduction (rig.reduction) and the stand simulators
(rig.stands.yoke.contact_forces, steady_state) import them from here. Units: angular speeds
[rad/s], angles [rad], lengths [m]. Every function takes scalars or numpy arrays (broadcast);
scalar input gives Python floats (the fast path of the ODE right-hand sides and the reduction),
array input gives arrays.

Geometry and signs (Equations §1.1, 1.2 last paragraph, 2): the contact plane has x along the
rolling direction and y along the contact line, origin at the contact centre O. The axis of
wheel k pierces the contact plane at A_k = (x_k, y_k); its angular velocity has the component
w0k along the contact normal. Both surfaces pass the contact in +x, so for wheel axes on
*opposite* sides of the contact (stand A) the two normal components have opposite signs in a
common frame. We carry them as the *signed speeds* w01 = w1 sin(alpha1) and w02 = -(normal
component of wheel 2 in that frame), so that

    spin          w0 = w01 + w02                              eq. (1), opposite-side axes
    rolling point C  = (w01 A1 + w02 A2) / (w01 + w02)        weighted centroid, Equations §1.2

and the rigid slip of wheel 1 relative to wheel 2 is w0 (-(y - l), x - c), the convention of
rig.contact. With stand A's A1 = (0, l1), A2 = (Delta h, l2) (l2 < 0 signed) and
i_k = w2/w1 this gives eqs. (29)-(31). The numerator w0 C = w01 A1 + w02 A2
(:func:`centroid_moments`) stays finite at any speeds, so a simulator can continue through
w0 -> 0; :func:`rolling_point` divides and raises :class:`SpinTooSmallError` when
|w01 + w02| is below a tolerance (hard case 2: stalled or reversed wheel).
"""

from __future__ import annotations

import math
from enum import Enum

import numpy as np

from rig import validate
from rig.contact.kinematics import spin
from rig.errors import ParameterError

DEFAULT_SPIN_RTOL = 1e-9  # |w01 + w02| <= rtol (|w01| + |w02|) counts as zero spin [1]


class SpinTooSmallError(ParameterError):
    """The spin w01 + w02 of the pair is (numerically) zero: the rolling point is at infinity."""


class AxisSides(Enum):
    """Where the two wheel axes lie relative to the contact (Equations §1.2)."""

    OPPOSITE = "opposite"  # stand A: "axes situated on the opposite sides of the contact area"
    SAME = "same"  # e.g. a disc driving an inner cone: the normal components subtract


def _scalar(*values) -> bool:
    """True when every argument is a 0-d number (the float fast path)."""
    return all(np.ndim(v) == 0 for v in values)


def _out(value):
    """Python float for 0-d results, the array otherwise."""
    return float(value) if np.ndim(value) == 0 else value


def signed_normal_speeds(omega_1, alpha_1, omega_2, alpha_2, sides: AxisSides):
    """Signed normal spin components (w01, w02) [rad/s] with w0 = w01 + w02 (eq. 1).

    omega_k: wheel speed [rad/s], positive when wheel k's surface moves in +x at the contact;
    alpha_k: half contact angle [rad] (angle between the axis and the contact plane).
    """
    if _scalar(omega_1, alpha_1, omega_2, alpha_2):
        w01, w02 = omega_1 * math.sin(alpha_1), omega_2 * math.sin(alpha_2)
    else:
        w01, w02 = np.asarray(omega_1) * np.sin(alpha_1), np.asarray(omega_2) * np.sin(alpha_2)
    return (w01, w02) if sides is AxisSides.OPPOSITE else (w01, -w02)


def pair_spin(omega_1, alpha_1, omega_2, alpha_2, sides: AxisSides):
    """Spin w0 of the wheel pair [rad/s], eq. (1) w0 = w1 sin(alpha1) - w2 sin(alpha2).

    Delegates to rig.contact.kinematics.spin; for axes on opposite sides the second wheel's
    normal component has the opposite sign in the common frame, so its speed enters negated.
    """
    second = -np.asarray(omega_2) if sides is AxisSides.OPPOSITE else np.asarray(omega_2)
    return _out(spin(omega_1, alpha_1, second, alpha_2))


def centroid_moments(w01, w02, pierce_1: tuple[float, float], pierce_2: tuple[float, float]):
    """w0 C = w01 A1 + w02 A2 as (w0 c, w0 l) [m rad/s]: the numerator of the weighted centroid.

    Equations §1.2; eqs. (29) and (31) are its y and x components divided by w0 = w01 + w02.
    Finite for any speeds (also w0 = 0, where C itself is at infinity). w01, w02 [rad/s];
    pierce_k = (x_k, y_k) [m] (or in any length unit, e.g. a).
    """
    return w01 * pierce_1[0] + w02 * pierce_2[0], w01 * pierce_1[1] + w02 * pierce_2[1]


def rolling_point(w01, w02, pierce_1: tuple[float, float], pierce_2: tuple[float, float],
                  rtol: float = DEFAULT_SPIN_RTOL):
    """Rolling point C = (c, l) [m] as the weighted centroid of the axis piercing points.

    w01, w02: signed normal speeds [rad/s] (any common scale, e.g. divided by w1; scalars or
    arrays); pierce_k = (x_k, y_k) [m]. Raises SpinTooSmallError when |w01 + w02| <= rtol
    (|w01| + |w02|) anywhere (for arrays the message names the first such element).
    """
    if _scalar(w01, w02):
        total, scale = w01 + w02, abs(w01) + abs(w02)
        if not math.isfinite(total) or abs(total) <= rtol * scale or scale == 0.0:
            raise _spin_error(total, scale, rtol)
        c_moment, l_moment = centroid_moments(w01, w02, pierce_1, pierce_2)
        return c_moment / total, l_moment / total
    w01, w02 = np.broadcast_arrays(np.asarray(w01, dtype=float), np.asarray(w02, dtype=float))
    total, scale = w01 + w02, np.abs(w01) + np.abs(w02)
    bad = ~np.isfinite(total) | (np.abs(total) <= rtol * scale) | (scale == 0.0)
    if np.any(bad):
        k = np.flatnonzero(bad.ravel())[0]
        raise _spin_error(float(total.ravel()[k]), float(scale.ravel()[k]), rtol)
    c_moment, l_moment = centroid_moments(w01, w02, pierce_1, pierce_2)
    return c_moment / total, l_moment / total


def _spin_error(total: float, scale: float, rtol: float) -> SpinTooSmallError:
    return SpinTooSmallError(
        "w01 + w02", total, f"|w01 + w02| > {rtol:g} (|w01| + |w02|) = {rtol * scale:g}",
        hint="stalled or reversed wheel: the rolling point is at infinity (hard case 2)",
    )


def stand_a_rolling_point(ratio, alpha_1: float, l1: float, l2: float, delta_h: float,
                          rtol: float = DEFAULT_SPIN_RTOL):
    """Stand A rolling point (c, l) [m] from i_k = w2/w1 [1] (scalar or array), eqs. (29)-(31).

    l = (l1 sin(alpha1) + l2 i_k)/(sin(alpha1) + i_k), eq. (29)/(30) with signed l2 (< 0);
    c = Delta h i_k/(sin(alpha1) + i_k), eq. (31). alpha_1 [rad], l1, l2, delta_h [m].
    """
    return rolling_point(math.sin(alpha_1), ratio, (0.0, l1), (delta_h, l2), rtol)


def ratio_for_l(l, alpha_1: float, l1: float, l2: float):
    """Inverse of eq. (30): the kinematic ratio i_k = sin(alpha1)(l1 - l)/(l - l2) [1] for l [m].

    Valid for l strictly between l2 and l1 (positive i_k); raises ParameterError otherwise
    (for arrays naming the first value outside).
    """
    lo, hi = min(l1, l2), max(l1, l2)
    if _scalar(l):
        validate.number("l", l, lo, hi, lo_open=True, hi_open=True)
        return math.sin(alpha_1) * (l1 - l) / (l - l2)
    l = np.asarray(l, dtype=float)
    outside = ~((l > lo) & (l < hi))
    if np.any(outside):
        validate.number("l", float(l.ravel()[np.flatnonzero(outside.ravel())[0]]), lo, hi, lo_open=True, hi_open=True)
    return math.sin(alpha_1) * (l1 - l) / (l - l2)


def c_for_l(l, l1: float, l2: float, delta_h: float):
    """Eq. (32): c = Delta h (l1 - l)/(l1 - l2) [m] (i_k eliminated with eq. 30); l scalar or array [m]."""
    if l1 == l2:
        raise ParameterError("l1 - l2", 0.0, "non-zero (the axes must pierce at different points)")
    if _scalar(l):
        return delta_h * (l1 - l) / (l1 - l2)
    return delta_h * (l1 - np.asarray(l, dtype=float)) / (l1 - l2)


def dl_dratio(ratio, alpha_1: float, l1: float, l2: float):
    """Sensitivity dl/di_k = -sin(alpha1)(l1 - l2)/(sin(alpha1) + i_k)^2 [m] (Equations §2).

    Stand A at l = 0: about -28.5 mm; used for the counting resolution of l.
    """
    s = math.sin(alpha_1)
    d = s + (ratio if _scalar(ratio) else np.asarray(ratio, dtype=float))
    return -s * (l1 - l2) / (d * d)  # d * d, not ** 2: Python's pow and numpy's square differ by an ulp


def stand_b_offset(e: float, sigma):
    """Stand B, eq. (36): c = e sin(sigma) [m]; e: pivot distance [m], sigma: twist angle [rad]."""
    return e * math.sin(sigma) if _scalar(sigma) else e * np.sin(np.asarray(sigma, dtype=float))


def stand_b_twist(e: float, c):
    """Inverse of eq. (36): the twist sigma = asin(c/e) [rad] giving the offset c [m]."""
    e = validate.number("e", e, 0.0, lo_open=True)
    if _scalar(c):
        validate.number("c", c, -e, e)
        return math.asin(c / e)
    c = np.asarray(c, dtype=float)
    outside = ~(np.abs(c) <= e)
    if np.any(outside):
        validate.number("c", float(c.ravel()[np.flatnonzero(outside.ravel())[0]]), -e, e)
    return np.arcsin(c / e)
