"""Pure functions of the measurement method, eqs. (21), (29)-(36) of [Koziarski] (Equations §2).

The kinematic relations (eqs. 1, 29-32, 36) live in rig.wheel_kinematics and are re-exported
here so that the reduction and the stand simulators share one implementation. Everything else
here is an instrument or balance equation. Units: SI ([m], [rad], [rad/s], [N], [N m], [s]).

Sign convention (Equations §1.1, 2): forces/moments are those the contact exerts on wheel 1
(the driving wheel), F_x along the rolling direction, F_y along the contact line, M_C about the
rolling point C; with spin w0 > 0 the model gives M_C = -mu a F_N nu_0, and nu_T < 0 when the
driven wheel 2 is dragged forward. The braking moment T2 is positive when it resists wheel 2.
These functions divide without guards; the per-stand chains (stand_a, stand_b) check the
denominators first and report NaN with a reason (hard case 8).
"""

from __future__ import annotations

import math

from rig import validate
from rig.wheel_kinematics import (  # re-exported: one source for eqs. 29-32, 36
    c_for_l,
    dl_dratio,
    ratio_for_l,
    stand_a_rolling_point,
    stand_b_offset,
    stand_b_twist,
)

__all__ = [
    "c_for_l", "dl_dratio", "ratio_for_l", "stand_a_rolling_point", "stand_b_offset", "stand_b_twist",
    "angular_speed_from_counts", "ratio_from_counts", "alpha_prime_line_contact", "alpha_prime",
    "force_from_signal", "lateral_force_from_dynamometer", "mu_v", "wheel_2_moment", "mu_t_denominator",
    "mu_t", "pivoting_moment_stand_b", "mu_from_force", "mu_from_pivoting_moment",
]


def angular_speed_from_counts(counts: float, marks: int, gate_time: float) -> float:
    """Wheel speed w = 2 pi N/(z T) [rad/s] from N counts [1] of z marks [1] in a gate T [s]."""
    return 2.0 * math.pi * counts / (marks * gate_time)


def ratio_from_counts(counts_1: float, counts_2: float, marks_1: int, marks_2: int) -> float:
    """Kinematic ratio i_k = w2/w1 = (N2 z1)/(N1 z2) [1] over a common gate (Equations §2).

    Counts are taken as real numbers so that the uncertainty propagation can perturb them;
    counts_1 must be > 0 (a stalled wheel 1 leaves i_k undefined, hard case 2).
    """
    validate.number("counts_1", counts_1, 0.0, lo_open=True)
    validate.number("counts_2", counts_2, 0.0)
    return counts_2 * marks_1 / (counts_1 * marks_2)


def alpha_prime_line_contact(mu: float, b_over_a: float, v_over_spin: float, radius_x: float) -> float:
    """Track deformability alpha' = 10 mu (b/a)(v/w0)/R_x [1] (eq. 21 with Hertz line contact).

    mu: friction coefficient [1]; v_over_spin: rolling speed over spin v/w0 [m]; radius_x:
    effective radius in the rolling direction R_x [m]. With p0 = b E*/(2 R_x) and E = 2 E*
    (eqs. 22-23) eq. (21) reduces to this form, independent of E (Equations §1.7).
    """
    return 10.0 * mu * b_over_a * v_over_spin / radius_x


def alpha_prime(mu: float, p0: float, v: float, a: float, modulus_e: float, spin_rate: float) -> float:
    """Eq. (21): alpha' = 40 mu p0 v/(a E w0) [1]; p0 [Pa], v [m/s], a [m], E of eq. (22) [Pa], w0 [rad/s]."""
    return 40.0 * mu * p0 * v / (a * modulus_e * spin_rate)


def force_from_signal(signal: float, sensitivity: float, offset: float) -> float:
    """Force [N] from a linear calibration signal = sensitivity F + offset (signal in [V], sensitivity [V/N])."""
    return (signal - offset) / sensitivity


def lateral_force_from_dynamometer(force_dyn: float, lever_dyn: float, lever_force: float) -> float:
    """F_y = F_dyn (lever_dyn / R_v) [N]: the yoke moment T_v = F_y R_v (eq. 33) is held by the
    dynamometer at lever_dyn (stand A: 102 mm vs R_v = 42.5 mm). Forces [N], levers [m]."""
    return force_dyn * lever_dyn / lever_force


def mu_v(lateral_force: float, normal_force: float, nu_v: float) -> float:
    """Eq. (33): mu_v = T_v/(F_N nu_v R_v) = F_y/(F_N nu_v) [1]; forces [N].

    nu_v is the model's utilisation along the contact line (printed "along the peripheral
    force" is wrong, Equations §2).
    """
    return lateral_force / (normal_force * nu_v)


def wheel_2_moment(
    mu_t: float, normal_force: float, lateral_force: float, nu_t: float, nu_0: float,
    l: float, c: float, l2: float, delta_h: float, a: float,
) -> float:
    """Eq. (34), forward: braking moment T2 [N m] that holds wheel 2 in steady rolling.

    Signed balance of wheel 2 about its axis (Equations §2): the moment of the contact on
    wheel 2 along the normal is M_2 = -M_C + (l - l2) F_x + (Delta h - c) F_y; wheel 2 turns in
    the negative normal sense, so the brake holds T2 = -M_2 with F_x = mu_T F_N nu_T and
    M_C = -mu_T a F_N nu_0 (w0 > 0). In the paper's magnitude form (l2 -> |l2|, |F_x|, T0 = |M_C|):
    T2 = |F_x|(|l2| + l) - T0 - F_y (Delta h - c). Lengths [m], forces [N].
    """
    return mu_t * normal_force * (-(l - l2) * nu_t - a * nu_0) - (delta_h - c) * lateral_force


def mu_t_denominator(nu_t: float, nu_0: float, l: float, l2: float, a: float) -> float:
    """The length in the denominator of eq. (35), D = -(l - l2) nu_T - a nu_0 [m].

    Magnitude form: D = (|l2| + l)|nu_T| - a nu_0; mu_T is undefined where D ~ 0 (hard case 8).
    """
    return -(l - l2) * nu_t - a * nu_0


def mu_t(
    brake_moment: float, normal_force: float, lateral_force: float, nu_t: float, nu_0: float,
    l: float, c: float, l2: float, delta_h: float, a: float,
) -> float:
    """Eq. (35): mu_T = [T2 + F_y (Delta h - c)] / (F_N D), D = -(l - l2) nu_T - a nu_0 [1].

    The inverse of :func:`wheel_2_moment` with the measured F_y (= mu_v F_N nu_v; the printed
    numerator lacks nu_v and the printed denominator mixes units, Equations §2). T2 [N m],
    forces [N], lengths [m]. The paper takes the moment coefficient equal to mu_T.
    """
    denominator = normal_force * mu_t_denominator(nu_t, nu_0, l, l2, a)
    return (brake_moment + lateral_force * (delta_h - c)) / denominator


def pivoting_moment_stand_b(momentometer_torque: float, peripheral_force: float, radius_c: float) -> float:
    """Stand B: moment about the rolling point M_C = T_Mo + R_c F_T [N m] (docs/stand-b.md).

    T_Mo [N m]: the torque the momentometer shaft delivers to the disc; F_T [N]: the peripheral
    force from the bearing dynamometer, R_c [m]: the rolling-point radius on the disc. The disc's
    balance about its axis gives T_Mo + R_c F_T = T0 = mu a F_N nu_0 (the pivoting moment, up to
    the disc bearing's friction); the Equations page's "T_Mo = M_C - R_c F_x" (3.2) fits no sign choice
    of the disc as body 1 (docs/stand-b.md, "Note on the Equations page"). A small difference of large
    numbers (hard case 6): its uncertainty is propagated by the chain.
    """
    return momentometer_torque + radius_c * peripheral_force


def mu_from_force(force: float, normal_force: float, nu: float) -> float:
    """mu = F/(F_N nu) [1] for a force [N] and its model coefficient (eqs. 27, 28, stand B)."""
    return force / (normal_force * nu)


def mu_from_pivoting_moment(moment_c: float, normal_force: float, a: float, nu_0: float) -> float:
    """mu_M = T0/(a F_N nu_0), T0 = |M_C| [1] (eq. 26 in the paper's magnitude form).

    M_C [N m], F_N [N], a [m]. The magnitude is used because the sign convention of stand B's
    momentometer is not given in the seed; M_C itself is reported signed.
    """
    return abs(moment_c) / (a * normal_force * nu_0)
