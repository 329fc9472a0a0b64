"""Coulomb's experiment "in 5 steps": a slowly increasing force F pulls a body on a plane.

[Zhao] slide 13 (Fig. 5.3) and slide 17; Equations §6. A body of mass M [kg] rests
on a horizontal plane (N = M g). The pull grows linearly, F(t) = k t (k [N/s] small: "slowly").

1. t <= t* = mu_s N / k: the micro-welds hold, the body stays at rest and the tangential
   reaction equals the pull, T = F (ineq. 5.1: adhesion).
2. t > t*: the welds shear, the body slides, and T drops to the kinetic value mu_k N
   (slide 17: "an increase of F is not followed by an increase of T"). Newton:
   M dv/dt = k t - mu_k N, so v(t) = [k (t^2 - t*^2)/2 - mu_k N (t - t*)] / M (closed form).

The model (a rigid block, Coulomb friction with a sharp drop mu_s -> mu_k) is the lecture's;
any re-sticking cannot occur because F keeps increasing.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.errors import ParameterError
from rig.teaching.coulomb import STANDARD_GRAVITY, static_and_kinetic


@dataclass(frozen=True)
class PullTestTrace:
    """Time series of the pull test (arrays of equal length).

    time_s [s], pull_N = F [N], friction_N = T (tangential reaction of the plane, opposing the
    pull) [N], speed_m_s = v [m/s]; breakaway_time_s t* [s], breakaway_force_N = mu_s N [N],
    kinetic_force_N = mu_k N [N], normal_force_N = N [N].
    """

    time_s: np.ndarray
    pull_N: np.ndarray
    friction_N: np.ndarray
    speed_m_s: np.ndarray
    breakaway_time_s: float
    breakaway_force_N: float
    kinetic_force_N: float
    normal_force_N: float


def pull_test(
    mass: float, mu_s: float, mu_k: float, force_rate: float, times: np.ndarray, g: float = STANDARD_GRAVITY
) -> PullTestTrace:
    """Pull F = k t on a block at rest: stick until F = mu_s N, then slide with T = mu_k N.

    mass M [kg] > 0; mu_s, mu_k [1] with 0 <= mu_k <= mu_s; force_rate k [N/s] > 0;
    times [s]: non-negative sample times (any order); g [m/s^2] > 0.
    """
    m = validate.number("mass", mass, 0.0, lo_open=True)
    mu_s, mu_k = static_and_kinetic(mu_s, mu_k)
    k = validate.number("force_rate", force_rate, 0.0, lo_open=True)
    g = validate.number("g", g, 0.0, lo_open=True)
    t = np.asarray(times, dtype=float)
    if t.ndim != 1 or t.size == 0 or not np.all(np.isfinite(t)) or np.any(t < 0.0):
        raise ParameterError("times", f"array of shape {t.shape}", "a non-empty 1-D array of finite times >= 0 s")
    normal = m * g
    t_star = mu_s * normal / k
    sliding = t > t_star
    pull = k * t
    friction = np.where(sliding, mu_k * normal, pull)
    speed = np.where(sliding, (0.5 * k * (t**2 - t_star**2) - mu_k * normal * (t - t_star)) / m, 0.0)
    return PullTestTrace(t, pull, friction, speed, t_star, mu_s * normal, mu_k * normal, normal)
