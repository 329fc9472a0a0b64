"""Stand A's contact at the instantaneous wheel speeds: forces on wheel 1 and moments on both wheels.

From the wheel speeds (w1, w2) [rad/s] to what the drive train needs (vectorised over samples):

    w01 = w1 sin(alpha1), w02 = w2, w0 = w01 + w02                   eq. (1), opposite-side axes
    w0 C = w01 A1 + w02 A2 = (w02 Delta h, w01 l1 + w02 l2) =: P      eqs. (29)-(31), centroid form
    (rig.wheel_kinematics, the reduction's function centroid_moments: the centroid's numerator,
    finite at w0 = 0)
    alpha' = 10 mu (b/a)(v/w0)/R_x,  v = w1 r1                        eq. (21), line contact
    (nu_T, nu_v, nu_0) = law(l/a, c/a, alpha')                        the scene's contact law
    F_x = mu F_N nu_T, F_y = mu F_N nu_v, M_C = -mu a F_N nu_0        eqs. (26)-(28), w0 > 0
    M_O = M_C + (c + f) F_y - l F_x                                   Equations §1.1 (f: rolling length,
                                                                      0 unless that contact effect is on)
    T1 = sin(alpha1) (M_O + l1 F_x)            moment on wheel 1 in its sense of rotation
    T2 = M_O - Delta h F_y + l2 F_x            moment on wheel 2 in its sense of rotation (= -M_2)

T1 and T2 are the Equations page's T1,contact and -M_2 of eq. (34) written with M_O instead of M_C
(identical algebra), so they stay finite when the rolling point runs off to infinity. The power
balance w1 T1 + w2 T2 = w0 M_C = -P_t <= 0 holds exactly (tests). alpha' uses the reduction's
own function (rig.reduction.equations.alpha_prime_line_contact): the stand and the reduction
agree by construction (eq. 21 with p0 = b E*/(2 R_x) and E = 2E*, so E cancels).

Hard cases (docs: Hard cases), decided here [our choices, docs/stand-a.md]:
* spin w0 < 0 (wheel 2 reversed faster than w01): mirror y (l -> -l; F_y, M_O change sign), as
  rig.contact.physical does;
* rolling point outside the law's domain (start-up: w2 = 0 puts C at A1, l/a ~ 35; hard case 6):
  the law is evaluated on the domain boundary and continued outward to the rigid far field,
  nu = nu_far + lam (nu_b - nu_far_b), nu_Mo = lam nu_Mo_b, lam = |C_b|/|C| -> 0; nu_far is the
  uniform sliding traction -mu p s(O)/|s(O)| (continuous at the boundary, exact at infinity);
* w0 -> 0 (rolling point at infinity, hard case 1): the same continuation with lam = 0;
* alpha' outside the domain (v/w0 -> 0 or inf in transients) is clamped to it;
* standstill (hard case 7): every force and moment is multiplied by tanh(s/eps), s = |w0| sqrt(l^2
  + c^2 + a^2) the slip speed scale [m/s] (= 1 to machine precision at any operating point);
* rolling direction: stand A's wheel 1 never reverses; |v| is used (a negative v only occurs in
  start-up transients near v = 0, where alpha' -> 0 and the rigid law does not depend on v).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from rig import validate
from rig.contact.surrogate import TableDomain
from rig.reduction.equations import alpha_prime_line_contact
from rig.reduction.geometry import StandAGeometry
from rig.wheel_kinematics import centroid_moments

Law = Callable[[np.ndarray, np.ndarray, np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]
"""law(l_over_a, c_over_a, alpha) -> (nu_T, nu_v, nu_0), vectorised (rig.stands.contact_law)."""

TINY = 1e-300


@dataclass(frozen=True, eq=False)
class ContactSample:
    """Contact quantities at given wheel speeds (arrays of one shape).

    w0 [rad/s]; l, c [m] (inf where w0 = 0); alpha [1] (as given to the law); nu_T, nu_v,
    nu_0 [1] (eqs. 26-28, continued outside the domain); F_x, F_y [N] and M_O, M_C [N m] on
    wheel 1; T1, T2 [N m]: contact moments on wheels 1 and 2 in their senses of rotation.
    """

    w0: np.ndarray
    l: np.ndarray
    c: np.ndarray
    alpha: np.ndarray
    nu_T: np.ndarray
    nu_v: np.ndarray
    nu_0: np.ndarray
    F_x: np.ndarray
    F_y: np.ndarray
    M_O: np.ndarray
    M_C: np.ndarray
    T1: np.ndarray
    T2: np.ndarray


class StandAContact:
    """The contact of one operating point: geometry (with its Delta h), F_N, b/a, mu, law, domain.

    geometry: StandAGeometry [m, rad]; normal_force F_N [N]; b_over_a [1]; mu [1]; law: see
    :data:`Law`; domain: TableDomain of the law; slip_speed_eps: regularisation speed [m/s].
    """

    def __init__(self, geometry: StandAGeometry, normal_force: float, b_over_a: float, mu: float, law: Law,
                 domain: TableDomain, slip_speed_eps: float) -> None:
        self.geometry = geometry
        self.normal_force = validate.number("normal_force_N", normal_force, 0.0, lo_open=True)
        self.b_over_a = validate.number("b_over_a", b_over_a, 0.0, lo_open=True)
        self.mu = validate.number("mu", mu, 0.0, lo_open=True)
        self.law = law
        self.domain = domain
        self.slip_speed_eps = validate.number("slip_speed_eps_m_s", slip_speed_eps, 0.0, lo_open=True)
        g = geometry
        self._sin_a1 = math.sin(g.alpha_1)
        self._alpha_per_v_over_w0 = alpha_prime_line_contact(mu, b_over_a, 1.0, g.radius_x)  # [1/m]
        self._shift = float(getattr(law, "rolling_length", 0.0))  # f/a of the rolling-resistance effect [1]

    def moments(self, omega_1, omega_2) -> tuple[np.ndarray, np.ndarray]:
        """(T1, T2) [N m]: contact moments on wheels 1 and 2 in their senses of rotation (arrays)."""
        s = self.evaluate(omega_1, omega_2)
        return s.T1, s.T2

    def moments_scalar(self, omega_1: float, omega_2: float) -> tuple[float, float]:
        """(T1, T2) [N m] for scalar speeds [rad/s]: the very numbers of :meth:`moments` (the same
        operations in the same order, numpy's tanh and hypot), computed on plain floats when w0 > 0
        (the ODE's right-hand side, the steady state's root search); other speeds through moments."""
        g = self.geometry
        a = g.a
        w01 = omega_1 * self._sin_a1
        w0 = w01 + omega_2
        if not w0 > TINY:
            t1, t2 = self.moments(omega_1, omega_2)
            return float(t1), float(t2)
        d = self.domain
        p_c, p_l = centroid_moments(w01, omega_2, (0.0, g.l1), (g.delta_h, g.l2))  # w0 (c, l), eqs. (29)-(31)
        l_c, c_c = (min(max(p / (w0 * a), -1e300), 1e300) for p in (p_l, p_c))  # rolling point [a]
        l_b, c_b = min(max(l_c, d.l_over_a[0]), d.l_over_a[1]), min(max(c_c, d.c_over_a[0]), d.c_over_a[1])
        alpha = min(max(self._alpha_per_v_over_w0 * abs(omega_1) * g.r1 / w0, d.alpha[0]), d.alpha[1])
        nu_t, nu_v, nu_0 = (float(x) for x in self.law(l_b, c_b, alpha))
        nu_mo = -nu_0 + (c_b + self._shift) * nu_v - l_b * nu_t
        slip = math.sqrt(p_l * p_l + p_c * p_c + (w0 * a) ** 2)
        if l_b != l_c or c_b != c_c:  # outside the domain: continued to the far field, as in evaluate
            p_abs, rho_b = max(float(np.hypot(p_l, p_c)), TINY), float(np.hypot(l_b, c_b))
            far_t_b, far_v_b = -l_b / max(rho_b, TINY), c_b / max(rho_b, TINY)
            lam = w0 * a * math.sqrt(rho_b**2 + 1.0) / max(slip, TINY)
            nu_t = -p_l / p_abs + lam * (nu_t - far_t_b)
            nu_v = p_c / p_abs + lam * (nu_v - far_v_b)
            nu_mo = lam * nu_mo
        force = self.mu * self.normal_force * float(np.tanh(slip / self.slip_speed_eps))
        f_x, f_y = force * nu_t, force * nu_v
        m_o = force * a * nu_mo
        return self._sin_a1 * (m_o + g.l1 * f_x), m_o - g.delta_h * f_y + g.l2 * f_x

    def moments_jacobian(self, omega_1: float, omega_2: float) -> np.ndarray:
        """d(T1, T2)/d(w1, w2) [N m s/rad], (2, 2), by forward differences of :meth:`moments_scalar`
        (steps 1e-7 max(|w|, 1 rad/s); the law is C2, so this is accurate to ~1e-7 relative)."""
        base = self.moments_scalar(omega_1, omega_2)
        h1 = 1e-7 * max(abs(omega_1), 1.0)
        h2 = 1e-7 * max(abs(omega_2), 1.0)
        d1 = self.moments_scalar(omega_1 + h1, omega_2)
        d2 = self.moments_scalar(omega_1, omega_2 + h2)
        return np.array([[(d1[0] - base[0]) / h1, (d2[0] - base[0]) / h2],
                         [(d1[1] - base[1]) / h1, (d2[1] - base[1]) / h2]])

    def evaluate(self, omega_1, omega_2) -> ContactSample:
        """Everything at wheel speeds w1, w2 [rad/s] (scalars or arrays of one shape)."""
        g = self.geometry
        a = g.a
        w1 = np.asarray(omega_1, dtype=float)
        w2 = np.asarray(omega_2, dtype=float)
        w01 = w1 * self._sin_a1
        w0 = w01 + w2
        p_c, p_l = centroid_moments(w01, w2, (0.0, g.l1), (g.delta_h, g.l2))  # w0 (c, l) [m rad/s], eqs. (29)-(31)
        sign = np.where(w0 < 0.0, -1.0, 1.0)
        abs_w0 = np.abs(w0)
        safe_w0 = np.maximum(abs_w0, TINY)
        # rolling point of the canonical (w0 > 0) problem in units of a: mirror y when w0 < 0
        lc = np.clip(p_l / (safe_w0 * a), -1e300, 1e300)
        cc = np.clip(sign * p_c / (safe_w0 * a), -1e300, 1e300)
        lb = np.clip(lc, *self.domain.l_over_a)
        cb = np.clip(cc, *self.domain.c_over_a)
        inside = (lb == lc) & (cb == cc) & (abs_w0 > 0.0)
        alpha = np.clip(self._alpha_per_v_over_w0 * np.abs(w1) * g.r1 / safe_w0, *self.domain.alpha)
        nu_t_b, nu_v_b, nu_0_b = (np.asarray(x, dtype=float) for x in self.law(lb, cb, alpha))
        nu_mo_b = -nu_0_b + (cb + self._shift) * nu_v_b - lb * nu_t_b
        slip = np.sqrt(p_l * p_l + p_c * p_c + (w0 * a) ** 2)  # |w0| sqrt(l^2 + c^2 + a^2) [m/s]
        # continuation to the far field (identity inside the domain)
        p_abs = np.maximum(np.hypot(p_l, p_c), TINY)
        rho_b = np.hypot(lb, cb)
        far_t, far_v = -p_l / p_abs, sign * p_c / p_abs
        far_t_b = np.where(inside, 0.0, -lb / np.maximum(rho_b, TINY))
        far_v_b = np.where(inside, 0.0, cb / np.maximum(rho_b, TINY))
        lam = np.where(inside, 1.0, abs_w0 * a * np.sqrt(rho_b**2 + 1.0) / np.maximum(slip, TINY))
        far_t = np.where(inside, 0.0, far_t)
        far_v = np.where(inside, 0.0, far_v)
        nu_t = far_t + lam * (nu_t_b - far_t_b)
        nu_v = sign * (far_v + lam * (nu_v_b - far_v_b))
        nu_mo = sign * lam * nu_mo_b
        scale = np.tanh(slip / self.slip_speed_eps)
        force = self.mu * self.normal_force * scale
        f_x, f_y = force * nu_t, force * nu_v
        m_o = force * a * nu_mo
        spinning = abs_w0 > 0.0  # the rolling point is at infinity at zero spin (reported as inf, not NaN)
        l = np.where(spinning, p_l / np.where(spinning, w0, 1.0), np.inf)
        c = np.where(spinning, p_c / np.where(spinning, w0, 1.0), np.inf)
        finite = np.isfinite(l) & np.isfinite(c)
        c_moment = np.where(finite, c, 0.0) + self._shift * a  # moment about C = (c + f, l), as rig.stands.contact_law
        m_c = np.where(finite, m_o - c_moment * f_y + np.where(finite, l, 0.0) * f_x, -np.inf)
        nu_0 = np.where(finite, np.abs(m_c) / (self.mu * self.normal_force * a), np.inf)
        t1 = self._sin_a1 * (m_o + g.l1 * f_x)
        t2 = m_o - g.delta_h * f_y + g.l2 * f_x
        return ContactSample(w0, l, c, alpha, nu_t, nu_v, nu_0, f_x, f_y, m_o, m_c, t1, t2)
