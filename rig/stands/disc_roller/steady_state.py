"""Quasi-static operating point of stand B's continuous drive, solved directly (no ODE).

In steady running the gear loop fixes w_r = i_g w_d, so the rolling point sits at l = l_set
exactly (Equations §3.2: the rolling point is kinematic) and the contact loads are the steady
law at (l_set, c) in the running direction. The balances of the drive-train equations with
zero derivatives then give, in order:
    T_Mo = -M_D + T_fd(w_d),  M_D = M_C + R_c F_x    (disc; = -(M_C + R_c F_x) without friction)
    T_w(w_r) = T_Mo/i_g + R_r F_x + T_fr(w_r)        (roller: one monotone root for w_r)
    phi = dz^-1(T_Mo/k)                               (loop twist, with backlash if built)
The same state is the start of the next operating point (rig.stands.base contract).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from rig.errors import ParameterError
from rig.stands.disc_roller.contact import SteadyContact
from rig.stands.disc_roller.drive_train import DriveTrain


@dataclass(frozen=True)
class SteadyState:
    """Steady operating point: state vector y (drive-train layout) and the true quantities.

    contact: steady contact loads; roller_speed, disc_speed [rad/s]; momentometer_torque [N m];
    twist [rad] (0 for a rigid loop).
    """

    y: np.ndarray
    contact: SteadyContact
    roller_speed: float
    disc_speed: float
    momentometer_torque: float
    twist: float


def steady_state(train: DriveTrain, direction: int) -> SteadyState:
    """The quasi-static operating point of a continuous drive running in ``direction`` (+-1)."""
    if train.worm is None:
        raise ParameterError("drive", "swinging", "the continuous drive (a swinging drive has no steady state)")
    i_g = train.gear_ratio
    contact = train.contact.steady(direction)
    m_d = contact.moment_c + train.radius_c * contact.force_x
    friction = train.bearings

    def disc_torque(w_r: float) -> float:
        t_fd = float(friction.disc(w_r / i_g)) if friction is not None else 0.0
        return -m_d + t_fd

    def residual(w_r: float) -> float:
        t_fr = float(friction.roller(w_r)) if friction is not None else 0.0
        load = disc_torque(w_r) / i_g + train.roller_radius * contact.force_x + t_fr
        return float(train.worm.torque(np.asarray(w_r), train.set_speed)) - load

    w_r = _root(residual, train.set_speed, train.worm)
    t_mo = disc_torque(w_r)
    twist = train.loop.twist_for(t_mo) if train.loop is not None else 0.0
    lay = train.layout
    y = np.zeros(lay.size)
    y[lay.roller] = w_r
    if lay.twist is not None:
        y[lay.twist] = twist
        y[lay.disc] = w_r / i_g
    if lay.loads is not None:
        y[lay.loads] = train.contact.loads(w_r * train.roller_radius, w_r / i_g)[:, 0]
    return SteadyState(y, contact, w_r, w_r / i_g, t_mo, twist)


def _root(residual, set_speed: float, worm) -> float:
    """Roller speed where the worm's torque meets the load (worm torque falls with speed)."""
    span = max(abs(set_speed), 1e-3)
    lo, hi = set_speed - span, set_speed + span
    r_lo, r_hi = residual(lo), residual(hi)
    if not (r_lo > 0.0 > r_hi):
        stall = worm.ratio * worm.efficiency * worm.max_torque
        raise ParameterError(
            "load torque on the roller shaft", f"more than the drive delivers near {set_speed:.4g} rad/s",
            f"below the worm drive's pull-out torque ~{stall:.3g} N m", hint="the motor would stall",
        )
    return brentq(residual, lo, hi, xtol=1e-14 * span, rtol=4 * np.finfo(float).eps)


def rest_state(train: DriveTrain) -> np.ndarray:
    """All speeds, the twist and the contact loads zero: the stand at rest [state vector]."""
    return np.zeros(train.layout.size)


def following_state(train: DriveTrain) -> np.ndarray:
    """Swinging drive at t = 0: the disc turns with the roller (w_d = w_r/i_g, loop untwisted) and
    the contact loads are the steady ones of that motion [state vector]."""
    y = np.zeros(train.layout.size)
    w_r = float(train.swinging.speed(0.0))
    lay = train.layout
    if lay.disc is not None:
        y[lay.disc] = w_r / train.gear_ratio
    f_x, f_y, m_o = train.contact.loads(w_r * train.roller_radius, w_r / train.gear_ratio)[:, 0]
    if lay.loads is not None:
        y[lay.loads] = f_x, f_y, m_o
    if lay.twist is not None:  # the loop holds the disc against the contact: T_Mo = -M_D
        c = train.contact
        y[lay.twist] = train.loop.twist_for(-(m_o - c.c * f_y + (c.l_set + train.radius_c) * f_x))
    return y
