"""Contact loads on the disc from the drive-train state of stand B: signed, regularised, vectorised.

Frame (docs/stand-b.md, Equations §1.1 and 3.2): x = the direction in which the disc surface
moves through the contact in FORWARD running, y = along the roller axis pointing towards the
disc axis, z = x cross y = the disc's forward spin axis. Body 1 is the disc. The disc axis
pierces the contact plane at D = (c, l_set + R_c) (O = contact centre): with the roller surface
speed v = w_r R_r (along x) and the disc speed w_d, the rigid slip of the disc relative to the
roller is a rotation w_d about the rolling point C = (c, l) with

    l = l_set + R_c - v/w_d        (steady: w_r = i_g w_d, v/w_d = R_c, l = l_set),

so in forward running (v > 0, w0 = w_d > 0) the contact model's canonical case applies directly.
Reverse running (v < 0, w_d < 0) is the mirror x -> -x of it (Equations §1.1: material flows
in -x, the spin changes sense): the canonical problem at (-c, l), with F_x and the moments
negated and F_y kept. [R] derived here: under x -> -x the rigid slip w0(-(y - l), x - c) with
(v, w0) -> (-v, -w0) maps onto the canonical one at c -> -c.

Loads on the disc: F_x = mu F_N nu_T, F_y = mu F_N nu_v (eqs. 27-28), moment about C
M_C = -mu a F_N nu_0 (w0 > 0, eq. 26), about O: M_O = M_C + c F_y - l F_x. The drive train uses
M_O: the moment about the disc axis is M_D = M_O - c F_y + (l_set + R_c) F_x, which stays exact
when a far rolling point is clipped (hard case 6: forces saturate, M_O stays bounded).

Signs of the state (Equations §1.1; the contact law is stated for v > 0, w0 > 0): with
p = sign(v) and q = sign(v) sign(w_d) the canonical problem is at (c', l') = (p c, q l), and
F_x = p F_x', F_y = q F_y', moments = p q M' (mirror x -> -x flips v and w0: c, F_x, M change
sign; mirror y -> -y flips w0 only: l, F_y, M change sign). [R] derived here and checked in the
tests against the exact steady loads. In canonical form l' = q (l_set + R_c) - |v|/|w_d|, so a
disc at rest under a sliding roller gives l' -> -inf on both sides of w_d = 0: the loads are
continuous there. alpha' = 10 mu (b/a) |v/w_d|/R_r (eq. 21 with Hertz line contact, Equations §1.7): R_c (b/a) 10 mu/R_r in steady running, -> 0 (rigid sliding, hard case 3) when v
reverses at finite spin, which makes the loads continuous across v = 0 as well.

Regularisation (hard cases 6, 7; [assumed] numerical): |l'|/a is clipped to the law's domain
L = rolling_point_limit (forces are saturated there), and beyond it F_y and M_O are continued
with their far-field decay ~ L a/|l'| (full sliding with a nearly uniform slip direction: the
lateral force and the moment about O vanish like 1/|l|) - so they reach 0 when the disc stops
under a sliding roller, from either side; alpha' is clipped to its upper end, and all loads are
scaled by tanh(s/(eps a)), s = |slip at O| + |w_d| a: a regularised Coulomb law that makes the
loads vanish only when all relative motion does (start from rest, reversal).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

Law = Callable[[np.ndarray, np.ndarray, np.ndarray], object]
"""Canonical contact law: (l/a, c/a, alpha') arrays -> (nu_T, nu_v, nu_0) arrays (v > 0, w0 > 0)."""


def evaluate_law(law: Law, l_over_a: np.ndarray, c_over_a: np.ndarray, alpha: float) -> np.ndarray:
    """(3, N) array nu_T, nu_v, nu_0 of a vectorised law at N rolling points [a] and one alpha' [1]."""
    l = np.atleast_1d(np.asarray(l_over_a, dtype=float))
    c = np.broadcast_to(np.asarray(c_over_a, dtype=float), l.shape)
    out = np.asarray(law(l, c, np.full(l.shape, alpha)), dtype=float)
    return out.reshape(3, l.size)


@dataclass(frozen=True)
class SteadyContact:
    """Steady contact of one operating point (exact kinematics, no regularisation).

    nu_T, nu_v, nu_0: model coefficients in the canonical frame of the running direction;
    force_x, force_y [N], moment_c, moment_o [N m]: loads on the disc in the stand frame;
    alpha: alpha' [1]; b_over_a [1].
    """

    nu_T: float
    nu_v: float
    nu_0: float
    force_x: float
    force_y: float
    moment_c: float
    moment_o: float
    alpha: float
    b_over_a: float

    @property
    def resisting_moment(self) -> float:
        """T0 = mu a F_N nu_0 [N m]: the pivoting moment about C resisting the spin (>= 0); the
        stand-B reduction's M_C = T_Mo + R_c F_T equals this (docs/stand-b.md)."""
        return abs(self.moment_c)


@dataclass(frozen=True)
class ContactPoint:
    """The fixed data of one operating point's contact.

    law: canonical law at this point's b/a; normal_force [N]; mu [1]; a, b [m]; alpha: alpha'
    of steady running [1]; alpha_max: upper end of the law's alpha' domain [1]; l_set, c [m]
    (settings); radius_c [m]; spin_eps [rad/s] (regularisation); l_limit: clip of |l'|/a [1].
    """

    law: Law
    normal_force: float
    mu: float
    a: float
    b: float
    alpha: float
    alpha_max: float
    l_set: float
    c: float
    radius_c: float
    spin_eps: float
    l_limit: float
    _scalar_law: Callable = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        one = getattr(self.law, "value_one", None)  # rig.stands.contact_law.ContactLaw's scalar path
        object.__setattr__(self, "_scalar_law", one if one is not None else self.law)

    def steady(self, direction: int) -> SteadyContact:
        """Loads at l = l_set in forward (+1) or reverse (-1) running (the quasi-static contact)."""
        nu_t, nu_v, nu_0 = evaluate_law(self.law, [self.l_set / self.a], direction * self.c / self.a, self.alpha)[:, 0]
        scale = self.mu * self.normal_force
        f_x, f_y, m_c = direction * scale * nu_t, scale * nu_v, -direction * scale * self.a * nu_0
        return SteadyContact(
            float(nu_t), float(nu_v), float(nu_0), float(f_x), float(f_y), float(m_c),
            float(m_c + self.c * f_y - self.l_set * f_x), self.alpha, self.b / self.a,
        )

    def rolling_point(self, roller_surface_speed: np.ndarray, disc_speed: np.ndarray) -> np.ndarray:
        """l = l_set + R_c - v/w_d [m] of the instantaneous rolling point (w_d = 0: +-inf; rest: l_set)."""
        v = np.asarray(roller_surface_speed, dtype=float)
        w = np.asarray(disc_speed, dtype=float)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            ratio = np.where(v == 0.0, 0.0, v / w)
        ratio = np.where((v == 0.0) & (w == 0.0), self.radius_c, ratio)
        return self.l_set + self.radius_c - ratio

    def loads(self, roller_surface_speed: np.ndarray, disc_speed: np.ndarray) -> np.ndarray:
        """(3, N) loads on the disc F_x [N], F_y [N], M_O [N m] at states v [m/s], w_d [rad/s]."""
        v = np.atleast_1d(np.asarray(roller_surface_speed, dtype=float))
        w = np.atleast_1d(np.asarray(disc_speed, dtype=float))
        a = self.a
        p = np.where(v >= 0.0, 1.0, -1.0)
        q = p * np.where(w >= 0.0, 1.0, -1.0)
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):  # a disc at rest: inf, on purpose
            ratio = np.abs(v) / np.abs(w)  # |v/w0| [m]; inf for a disc at rest under a moving roller
            ratio = np.where(np.isnan(ratio), self.radius_c, ratio)  # all at rest: the kinematic ratio
            l_raw = (q * (self.l_set + self.radius_c) - ratio) / a  # canonical l'/a, may be -inf
            far = np.minimum(self.l_limit / np.abs(l_raw), 1.0)  # far field: F_y, M_O ~ a/|l| (0 at inf)
            # clamped to the law's domain after the product: alpha (alpha_max/alpha) may exceed alpha_max by an ulp
            alpha = np.minimum(self.alpha * np.minimum(ratio / self.radius_c, self.alpha_max / self.alpha), self.alpha_max)
        l_hat = np.clip(l_raw, -self.l_limit, self.l_limit)
        c_hat = p * self.c / a
        nu = np.asarray(self.law(l_hat, c_hat, alpha), dtype=float).reshape(3, l_hat.size)
        moment_o = (-nu[2] + c_hat * nu[1] - l_hat * nu[0]) * far
        nu[1] *= far
        slip = np.hypot(w * (self.l_set + self.radius_c) - v, w * self.c) + np.abs(w) * a
        scale = self.mu * self.normal_force * np.tanh(slip / (self.spin_eps * a))
        return np.stack([scale * p * nu[0], scale * q * nu[1], scale * a * p * q * moment_o])

    def loads_one(self, v: float, w: float) -> tuple[float, float, float]:
        """:meth:`loads` for one state in Python floats (the integrator's Newton iterations call
        the right-hand side one state at a time; tested equal to the vectorised form)."""
        a = self.a
        p = 1.0 if v >= 0.0 else -1.0
        q = p if w >= 0.0 else -p
        if w != 0.0:
            ratio = abs(v) / abs(w)
        else:
            ratio = math.inf if v != 0.0 else self.radius_c
        l_raw = (q * (self.l_set + self.radius_c) - ratio) / a
        far = min(self.l_limit / abs(l_raw), 1.0) if l_raw != 0.0 else 1.0
        l_hat = min(max(l_raw, -self.l_limit), self.l_limit)
        c_hat = p * self.c / a
        alpha = min(self.alpha * min(ratio / self.radius_c, self.alpha_max / self.alpha), self.alpha_max)
        nu_t, nu_v, nu_0 = (float(x) for x in self._scalar_law(l_hat, c_hat, alpha))
        moment_o = (-nu_0 + c_hat * nu_v - l_hat * nu_t) * far
        slip = math.hypot(w * (self.l_set + self.radius_c) - v, w * self.c) + abs(w) * a
        scale = self.mu * self.normal_force * math.tanh(slip / (self.spin_eps * a))
        return scale * p * nu_t, scale * q * nu_v * far, scale * a * p * q * moment_o
