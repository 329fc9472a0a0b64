"""Hysteresis of a soft disc rolling on a rigid plane: the p-epsilon loop and the shifted resultant.

[Zhao] slides 26-32 (Figs. 5.7-5.9): a point of the soft rim is compressed from P1 to P3 and
released from P3 to P5; an inelastic material follows a different p-epsilon line on the way
back, the loop's area is the energy per unit volume lost per cycle, the front of the contact
carries more pressure than the rear, and the resultant N is shifted forward by u (the
rolling-resistance arm, rig.teaching.rolling_resistance).

Model [our choice; the slides give no constitutive law]: the rim is a layer of thickness h made
of independent Kelvin-Voigt elements (spring E in parallel with a dashpot eta: p = E eps +
eta eps', a Winkler foundation), on a rigid wheel of radius R and width w, rolling at speed v
without slipping. Coordinate xi [m] along the direction of travel, origin under the wheel
centre (front = leading edge at xi > 0; note rig.contact's x points the other way). Small
slopes: the rim's compression at xi is delta = d - xi^2/(2R) (d = penetration), so
eps = delta/h and, because the rim material passes backwards at speed v,
eps' = v xi/(R h). With c^2 = 2 R d and the relaxation length s = v eta/E:

    p(xi) = E/(2 R h) (c^2 - xi^2 + 2 s xi),       rear edge <= xi <= c.

Material enters at the front edge xi = c (delta = 0; the dashpot makes p jump there, a known
artefact of Kelvin-Voigt) and leaves the plane where p = 0, xi_r = s - sqrt(s^2 + c^2) =
-c^2/(s + sqrt(s^2 + c^2)) (earlier than -c: the rim recovers too slowly to follow the plane),
then recovers freely at p = 0. N = w int p dxi, resisting moment M = w int p xi dxi = N u,
f_v = u/R. For s << c, u -> s = v eta/E: the arm is the distance rolled in one relaxation time.

Energy (three independent routes, tested): the work per unit volume per cycle
W = closed integral of p d eps (the loop area), the dashpot's dissipation
eta v (c^3 - xi_r^3)/(3 R^2 h^2) + E eps_r^2/2 (the second term is lost during free recovery),
and the rolling-resistance work per unit travel M/R = W h w (power M v/R = f_v N v).
Validity [our limits]: peak strain d/h <= 0.5, layer h <= R/2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from rig import validate
from rig.errors import ParameterError

MAX_PEAK_STRAIN = 0.5  # d/h, linear viscoelasticity at small strain [1]
MAX_THICKNESS_RATIO = 0.5  # h/R, a thin rim layer (small slopes) [1]


@dataclass(frozen=True)
class KelvinVoigtLayer:
    """Soft rim: modulus_Pa E [Pa] > 0, viscosity_Pa_s eta [Pa s] >= 0, thickness_m h [m] > 0."""

    modulus_Pa: float
    viscosity_Pa_s: float
    thickness_m: float

    def __post_init__(self) -> None:
        validate.number("modulus_Pa", self.modulus_Pa, 0.0, lo_open=True)
        validate.number("viscosity_Pa_s", self.viscosity_Pa_s, 0.0)
        validate.number("thickness_m", self.thickness_m, 0.0, lo_open=True)

    @property
    def relaxation_time_s(self) -> float:
        """tau = eta/E [s] (retardation time of the Kelvin-Voigt element)."""
        return self.viscosity_Pa_s / self.modulus_Pa


@dataclass(frozen=True)
class HysteresisContact:
    """Steady rolling of the disc on the plane (lengths [m], forces [N], moment [N m], power [W]).

    half_width_m: c = sqrt(2 R d); rear_m: xi_r < 0 where the rim leaves the plane;
    relaxation_length_m: s = v eta/E; shift_m: u = M/N; f_v = u/R [1];
    resistance_force_N = M/R (the steady pull at the centre); power_W = M v/R.
    """

    layer: KelvinVoigtLayer
    radius_m: float
    width_m: float
    speed_m_s: float
    normal_force_N: float
    penetration_m: float
    half_width_m: float
    rear_m: float
    relaxation_length_m: float
    resisting_moment_N_m: float

    @property
    def front_m(self) -> float:
        """Leading edge xi = c [m], where the rim first touches the plane."""
        return self.half_width_m

    @property
    def shift_m(self) -> float:
        """Forward shift of the normal resultant u = M/N [m] (slide 32)."""
        return self.resisting_moment_N_m / self.normal_force_N

    @property
    def f_v(self) -> float:
        """Rolling-resistance coefficient f_v = u/R [1] (slide 36)."""
        return self.shift_m / self.radius_m

    @property
    def resistance_force_N(self) -> float:
        """Pull at the centre that keeps the speed, M/R [N]."""
        return self.resisting_moment_N_m / self.radius_m

    @property
    def power_W(self) -> float:
        """Power lost to hysteresis M v/R = f_v N v [W] (slide 35)."""
        return self.resistance_force_N * self.speed_m_s

    def strain(self, xi: np.ndarray) -> np.ndarray:
        """Compression strain eps = (c^2 - xi^2)/(2 R h) [1] of the rim at xi [m] (in contact)."""
        xi = np.asarray(xi, dtype=float)
        return (self.half_width_m**2 - xi**2) / (2.0 * self.radius_m * self.layer.thickness_m)

    def pressure(self, xi: np.ndarray) -> np.ndarray:
        """Contact pressure p(xi) [Pa] at xi [m]; 0 outside [xi_r, c]."""
        xi = np.asarray(xi, dtype=float)
        inside = (xi >= self.rear_m) & (xi <= self.half_width_m)
        scale = self.layer.modulus_Pa / (2.0 * self.radius_m * self.layer.thickness_m)
        p = scale * (self.half_width_m**2 - xi**2 + 2.0 * self.relaxation_length_m * xi)
        return np.where(inside, np.maximum(p, 0.0), 0.0)

    @property
    def exit_strain(self) -> float:
        """Strain eps_r [1] left in the rim where it leaves the plane (recovered freely afterwards)."""
        return float(self.strain(self.rear_m))

    def dissipation_per_cycle(self) -> float:
        """Energy lost per unit volume of rim per pass [J/m^3], from the dashpot (independent of the loop).

        eta v (c^3 - xi_r^3)/(3 R^2 h^2) in contact plus E eps_r^2/2 released during free recovery.
        """
        r, h, layer = self.radius_m, self.layer.thickness_m, self.layer
        in_contact = layer.viscosity_Pa_s * self.speed_m_s * (self.half_width_m**3 - self.rear_m**3) / (3 * r**2 * h**2)
        return in_contact + 0.5 * layer.modulus_Pa * self.exit_strain**2


def _rear_edge(c: float, s: float) -> float:
    """xi_r = s - sqrt(s^2 + c^2), written without cancellation [m]; exactly -c when s = 0."""
    if s == 0.0:
        return -c
    return max(-c, -c * c / (s + math.hypot(s, c))) if c > 0.0 else 0.0  # max: round-off at tiny s


def _load_per_scale(c: float, s: float) -> float:
    """int (c^2 - xi^2 + 2 s xi) dxi over [xi_r, c] [m^3]."""
    x = _rear_edge(c, s)
    return c * c * (c - x) - (c**3 - x**3) / 3.0 + s * (c * c - x * x)


def _moment_per_scale(c: float, s: float) -> float:
    """int (c^2 - xi^2 + 2 s xi) xi dxi over [xi_r, c] [m^4]."""
    x = _rear_edge(c, s)
    return c * c * (c * c - x * x) / 2.0 - (c**4 - x**4) / 4.0 + 2.0 * s * (c**3 - x**3) / 3.0


def roll_on_layer(
    layer: KelvinVoigtLayer, radius: float, width: float, normal_force: float, speed: float
) -> HysteresisContact:
    """Steady rolling of a disc with a Kelvin-Voigt rim on a rigid plane (model: module docstring).

    radius R [m] > 0 with h <= R/2; width w [m] > 0; normal_force N [N] > 0 (peak strain
    d/h <= 0.5); speed v [m/s] >= 0 (v = 0 or eta = 0: elastic, symmetric, u = 0).
    """
    r = validate.number("radius", radius, 0.0, lo_open=True)
    validate.number("layer.thickness_m", layer.thickness_m, 0.0, MAX_THICKNESS_RATIO * r, lo_open=True)
    w = validate.number("width", width, 0.0, lo_open=True)
    n = validate.number("normal_force", normal_force, 0.0, lo_open=True)
    v = validate.number("speed", speed, 0.0)
    s = v * layer.relaxation_time_s
    scale = w * layer.modulus_Pa / (2.0 * r * layer.thickness_m)
    c_elastic = (3.0 * n / (4.0 * scale)) ** (1.0 / 3.0)  # viscosity only stiffens: c <= c_elastic
    if _load_per_scale(c_elastic, s) * scale <= n:
        c = c_elastic
    else:
        c = brentq(lambda x: scale * _load_per_scale(x, s) - n, 0.0, c_elastic, xtol=1e-15 * c_elastic, rtol=1e-15)
    d = c * c / (2.0 * r)
    if d > MAX_PEAK_STRAIN * layer.thickness_m:
        n_max = scale * _load_per_scale(math.sqrt(2.0 * r * MAX_PEAK_STRAIN * layer.thickness_m), s)
        raise ParameterError("normal_force", n, f"(0, {n_max:.6g}] N",
                             hint=f"the peak strain d/h would exceed {MAX_PEAK_STRAIN} (small-strain model)")
    moment = max(scale * _moment_per_scale(c, s), 0.0)  # >= 0 analytically; clamps round-off when s << c
    return HysteresisContact(layer, r, w, v, n, d, c, _rear_edge(c, s), s, moment)


def strain_stress_loop(contact: HysteresisContact, samples: int = 401) -> tuple[np.ndarray, np.ndarray]:
    """Closed p-epsilon path of one rim element over a pass (slides 29-31), arrays [1] and [Pa].

    (0, 0) -> jump to (0, p(c)) at the leading edge -> loading and unloading while xi runs from
    c to xi_r (samples points) -> (eps_r, 0) -> free recovery at p = 0 back to (0, 0).
    """
    samples = validate.integer("samples", samples, 3, 10**6)
    xi = np.linspace(contact.front_m, contact.rear_m, samples)
    strain = np.concatenate([[0.0], contact.strain(xi), [contact.exit_strain, 0.0]])
    stress = np.concatenate([[0.0], contact.pressure(xi), [0.0, 0.0]])
    strain[1] = 0.0  # the leading edge has delta = 0 exactly
    return strain, stress


def cycle_work(strain: np.ndarray, stress: np.ndarray) -> float:
    """Closed integral of stress d(strain) along a sampled path [J/m^3] (trapezoids) = the loop area.

    strain [1] and stress [Pa]: equal-length 1-D arrays of a closed path (first point = last).
    """
    e = np.asarray(strain, dtype=float)
    p = np.asarray(stress, dtype=float)
    if e.shape != p.shape or e.ndim != 1 or e.size < 3:
        raise ParameterError("strain, stress", f"shapes {e.shape}, {p.shape}", "equal 1-D arrays of >= 3 points")
    if not (np.isclose(e[0], e[-1], rtol=0.0, atol=1e-12) and np.isclose(p[0], p[-1], rtol=1e-12, atol=0.0)):
        raise ParameterError("strain, stress", "an open path", "a closed path (first point = last point)")
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(e)))
