"""Hertz normal contact: elliptical point contact and finite line contact (Equations §1.9, 3.1, 3.2, 5.1).

Naming as in [Koziarski] (Equations §1.1): x = rolling direction, y = along the contact line;
**a = half length along y, b = half width along x** (Kalker's tables use the opposite names).
SI units throughout: lengths [m], forces [N], pressures and moduli [Pa].

Point contact (Johnson, Contact Mechanics, ch. 4, as quoted in Equations §5.1): the gap between
two bodies with principal radii aligned with x and y is h = x^2/(2 R_x) + y^2/(2 R_y),
1/R_x = 1/R1x + 1/R2x, 1/R_y = 1/R1y + 1/R2y (negative radius = concave, inf = flat). With the
semi-major axis A_M, semi-minor B_m, ratio lam = B_m/A_M, e^2 = 1 - lam^2 and complete elliptic
integrals K(e), E(e) (scipy parameter m = e^2):
  curvature ratio  C_max/C_min = [(A_M/B_m)^2 E - K]/(K - E),
  A_M^3 = 3 F (K - E)/(2 pi E* e^2 A_gap),  A_gap = C_min/2,
  p0 = 3 F/(2 pi a b),  approach delta = p0 B_m K(e)/E*.
Reconstruction choice [R]: the two differences K - E and (A_M/B_m)^2 E - K cancel badly near the
circle (e -> 0); both are rewritten exactly with Carlson's integral R_D (K - E = (e^2/3) R_D(0, lam^2, 1),
E - lam^2 K = (e^2 lam^2/3) R_D(0, 1, lam^2)), which makes the ellipticity root solve well
conditioned from the circle to lam ~ 1e-9. K and E themselves are reported from scipy's
ellipkm1/ellipe.

Finite line contact of length 2a (Equations §3.1/3.2): b = sqrt(4 F R_x/(pi 2a E*)),
p0 = 2 F/(pi b 2a); pressure semi-elliptic across (x), uniform along (y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipkm1, elliprd

from rig import validate
from rig.errors import ParameterError

# Smallest curvature sum, relative to the curvatures that form it, that still counts as convex.
_CONVEX_TOLERANCE = 1e-12


def ellipse_pressure(x: np.ndarray, y: np.ndarray, *, a: float, b: float, p0: float) -> np.ndarray:
    """Hertz pressure p = p0 sqrt(1 - (x/b)^2 - (y/a)^2) inside the ellipse, 0 outside [Pa].

    x [m] along rolling (half width b [m]), y [m] along the contact line (half length a [m]).
    """
    s = 1.0 - (np.asarray(x, dtype=float) / b) ** 2 - (np.asarray(y, dtype=float) / a) ** 2
    return p0 * np.sqrt(np.clip(s, 0.0, None))


def line_pressure(x: np.ndarray, y: np.ndarray, *, a: float, b: float, p0: float) -> np.ndarray:
    """Finite line contact pressure p = p0 sqrt(1 - (x/b)^2) for |y| <= a, 0 outside [Pa]."""
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    s = np.clip(1.0 - (x / b) ** 2, 0.0, None)
    return np.where(np.abs(y) <= a, p0 * np.sqrt(s), 0.0)


def hertz_traction_slip(x: np.ndarray, y: np.ndarray, poisson: float, direction: int) -> np.ndarray:
    """(du_x/dx, du_y/dx) (2, ...) [q0/G] inside a circle of radius a under the Hertz-shaped tangential
    traction q = q0 sqrt(1 - r^2/a^2) along x (direction 0) or y (1); x, y in units of a.

    Johnson, Contact Mechanics (1985), section 7.2, for one body with c = pi q0/(32 G a):
    traction along x: u_x = c [4 (2 - nu) a^2 - (4 - 3 nu) x^2 - (4 - nu) y^2], u_y = c 2 nu x y.
    Returned for the pair, twice that, with G the pair's combined modulus (2/G = 1/G1 + 1/G2) and nu
    its Poisson's ratio: the relative displacement's rate along x, which is the elastic slip per unit
    rolling speed ([Koziarski], eqs. 8, 10). A closed form the grid models are checked against.
    """
    c = 2.0 * np.pi / 32.0
    along = -2.0 * c * ((4.0 - 3.0 * poisson) if direction == 0 else (4.0 - poisson)) * np.asarray(x, dtype=float)
    cross = 2.0 * c * poisson * np.asarray(y, dtype=float)
    return np.stack([along, cross] if direction == 0 else [cross, along])


@dataclass(frozen=True)
class PointGeometry:
    """Principal radii of curvature [m] of the two bodies, aligned with x (rolling) and y.

    A negative radius is concave (e.g. a raceway groove), ``math.inf`` is flat. The curvature
    sums 1/r1x + 1/r2x and 1/r1y + 1/r2y must both be positive (a convex gap).
    """

    r1x: float
    r1y: float
    r2x: float
    r2y: float

    def __post_init__(self) -> None:
        for name in ("r1x", "r1y", "r2x", "r2y"):
            value = validate.number(name, getattr(self, name), allow_inf=True)
            if value == 0.0:
                raise ParameterError(name, value, "a non-zero radius [m] (negative = concave, inf = flat)")

    def curvature_sums(self) -> tuple[float, float]:
        """(1/R_x, 1/R_y) = (1/r1x + 1/r2x, 1/r1y + 1/r2y) [1/m]; raises unless both are > 0."""
        sums = []
        for axis, r1, r2 in (("x", self.r1x, self.r2x), ("y", self.r1y, self.r2y)):
            total = 1.0 / r1 + 1.0 / r2
            scale = abs(1.0 / r1) + abs(1.0 / r2)
            if scale == 0.0 or total <= _CONVEX_TOLERANCE * scale:
                hint = (
                    "both bodies are flat in this direction: use LineGeometry for a line contact"
                    if scale == 0.0 or total == 0.0
                    else "the concave radius must be larger in magnitude than the convex one it meets"
                )
                raise ParameterError(f"1/r1{axis} + 1/r2{axis}", total, "> 0 [1/m] (a convex gap)", hint=hint)
            sums.append(total)
        return sums[0], sums[1]


@dataclass(frozen=True)
class LineGeometry:
    """Finite line contact: length 2a = ``length`` [m] along y, effective radius R_x [m] across it."""

    length: float
    radius_x: float

    def __post_init__(self) -> None:
        validate.number("length", self.length, 0.0, lo_open=True)
        validate.number("radius_x", self.radius_x, 0.0, lo_open=True)


@dataclass(frozen=True)
class HertzEllipse:
    """Hertz elliptical point contact.

    a [m]: half length along y; b [m]: half width along x (rolling); p0 [Pa]: maximum pressure;
    approach [m]: mutual approach of distant points; e_star [Pa]: contact modulus;
    normal_force [N]; K, E: complete elliptic integrals of the eccentricity (dimensionless).
    """

    shape: ClassVar[str] = "ellipse"

    a: float
    b: float
    p0: float
    approach: float
    e_star: float
    normal_force: float
    K: float
    E: float

    @property
    def b_over_a(self) -> float:
        """Half width over half length b/a (dimensionless)."""
        return self.b / self.a

    @property
    def area(self) -> float:
        """Contact area pi a b [m^2]."""
        return math.pi * self.a * self.b

    def pressure(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Pressure [Pa] at x [m] (rolling), y [m] (contact line)."""
        return ellipse_pressure(x, y, a=self.a, b=self.b, p0=self.p0)


@dataclass(frozen=True)
class HertzLine:
    """Hertz finite line contact: a [m] half length (fixed), b [m] half width, p0 [Pa],
    e_star [Pa] contact modulus, normal_force [N]. The approach of a line contact depends on
    the body dimensions and is not defined here."""

    shape: ClassVar[str] = "line"

    a: float
    b: float
    p0: float
    e_star: float
    normal_force: float

    @property
    def b_over_a(self) -> float:
        """Half width over half length b/a (dimensionless)."""
        return self.b / self.a

    @property
    def area(self) -> float:
        """Contact area 2a 2b [m^2]."""
        return 4.0 * self.a * self.b

    def pressure(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Pressure [Pa] at x [m] (rolling), y [m] (contact line)."""
        return line_pressure(x, y, a=self.a, b=self.b, p0=self.p0)


def curvature_ratio(lam: float) -> float:
    """Ratio of the larger to the smaller gap curvature of a Hertz ellipse with axis ratio lam.

    lam = minor/major semi-axis in (0, 1]. Johnson's [(1/lam^2) E - K]/(K - E), evaluated without
    cancellation as R_D(0, 1, lam^2)/R_D(0, lam^2, 1) (dimensionless, >= 1, = 1 for the circle).
    """
    lam2 = lam * lam
    return float(elliprd(0.0, 1.0, lam2) / elliprd(0.0, lam2, 1.0))


def axis_ratio(ratio: float) -> float:
    """Minor/major semi-axis ratio lam in (0, 1] of the Hertz ellipse for a curvature ratio >= 1.

    Robust root of curvature_ratio(lam) = ratio, solved in log(lam) with a bracket widened
    until it holds (Brent's method).
    """
    ratio = validate.number("curvature ratio", ratio, 1.0)
    if ratio == 1.0:
        return 1.0
    target = math.log(ratio)

    def residual(u: float) -> float:
        return math.log(curvature_ratio(math.exp(u))) - target

    lower = -target - 1.0
    while residual(lower) < 0.0:
        lower *= 2.0
    return math.exp(brentq(residual, lower, 0.0, xtol=1e-15, rtol=4.0 * np.finfo(float).eps))


def point_contact(normal_force: float, geometry: PointGeometry, e_star: float) -> HertzEllipse:
    """Hertz elliptical contact for normal force [N], body radii and contact modulus E* [Pa].

    E* = 1/((1 - nu1^2)/E1 + (1 - nu2^2)/E2) (rig.contact.materials.contact_modulus).
    Returns a along y and b along x (Equations §1.1). Raises ParameterError for a force <= 0
    (no contact: a, b, p0 -> 0) and for a non-convex or flat gap.
    """
    force = validate.number("normal_force", normal_force, 0.0, lo_open=True)
    modulus = validate.number("e_star", e_star, 0.0, lo_open=True)
    cx, cy = geometry.curvature_sums()
    c_min, c_max = min(cx, cy), max(cx, cy)
    lam = axis_ratio(c_max / c_min)
    major = (force * float(elliprd(0.0, lam * lam, 1.0)) / (math.pi * modulus * c_min)) ** (1.0 / 3.0)
    minor = lam * major
    p0 = 3.0 * force / (2.0 * math.pi * major * minor)
    k_int = float(ellipkm1(lam * lam))  # K(m) with m = 1 - lam^2 = e^2
    e_int = float(ellipe(1.0 - lam * lam))
    # the major axis lies along the direction of the smaller curvature
    b, a = (major, minor) if cx <= cy else (minor, major)
    return HertzEllipse(
        a=a,
        b=b,
        p0=p0,
        approach=p0 * minor * k_int / modulus,
        e_star=modulus,
        normal_force=force,
        K=k_int,
        E=e_int,
    )


def line_contact(normal_force: float, geometry: LineGeometry, e_star: float) -> HertzLine:
    """Hertz finite line contact: b = sqrt(4 F R_x/(pi 2a E*)), p0 = 2 F/(pi b 2a).

    normal_force [N], geometry (length 2a [m], R_x [m]), contact modulus e_star [Pa].
    """
    force = validate.number("normal_force", normal_force, 0.0, lo_open=True)
    modulus = validate.number("e_star", e_star, 0.0, lo_open=True)
    length = geometry.length
    b = math.sqrt(4.0 * force * geometry.radius_x / (math.pi * length * modulus))
    p0 = 2.0 * force / (math.pi * b * length)
    return HertzLine(a=0.5 * length, b=b, p0=p0, e_star=modulus, normal_force=force)


def hertz_contact(normal_force: float, geometry: PointGeometry | LineGeometry, e_star: float) -> HertzEllipse | HertzLine:
    """Point or line contact, chosen by the type of ``geometry``."""
    if isinstance(geometry, PointGeometry):
        return point_contact(normal_force, geometry, e_star)
    if isinstance(geometry, LineGeometry):
        return line_contact(normal_force, geometry, e_star)
    raise ParameterError("geometry", geometry, "a PointGeometry or a LineGeometry")
