"""Elastic materials and the dimensionless material groups of [Koziarski], eqs. (21)-(24).

SI units: moduli [Pa], density [kg/m^3], speeds [m/s], spin [rad/s], lengths [m].
A rigid body is a Material with E = inf (its compliance terms vanish).

Combined constants:
* substitute modulus of eqs. (22)-(23), typos fixed (Equations §1.8 #15):
  E = 2 E1' E2'/(E1' + E2'), E_i' = E_i/(1 - nu_i^2), so E = 2 E* (E* = Hertz contact modulus);
* Kalker's combined shear modulus 2/G = 1/G1 + 1/G2 and combined Poisson ratio
  nu/G = (nu1/G1 + nu2/G2)/2 (Kalker 1990, eq. (1.44); the same definition is coded in
  Vollebregt's CONTACT, src/m_hierarch_data.f90, subroutine combin_mater).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from rig import validate
from rig.errors import ParameterError


@dataclass(frozen=True)
class Material:
    """Isotropic linear-elastic material: E [Pa] (inf = rigid), nu (dimensionless), rho [kg/m^3].

    name and source say where a preset's numbers come from ([T] stated in a seed, [A] assumed).
    """

    E: float
    nu: float
    rho: float
    name: str = ""
    source: str = ""

    def __post_init__(self) -> None:
        validate.number("E", self.E, 0.0, lo_open=True, allow_inf=True)
        validate.number("nu", self.nu, -1.0, 0.5, lo_open=True)
        validate.number("rho", self.rho, 0.0, lo_open=True)

    @property
    def G(self) -> float:
        """Shear modulus G = E/(2(1 + nu)) [Pa]."""
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def plane_strain_modulus(self) -> float:
        """E' = E/(1 - nu^2) [Pa], eq. (23)."""
        return self.E / (1.0 - self.nu**2)

    @property
    def is_rigid(self) -> bool:
        """True for E = inf."""
        return math.isinf(self.E)


STEEL = Material(
    E=210e9,
    nu=0.3,
    rho=7850.0,
    name="steel",
    source="E, nu [T] [Oscillating] Table 1 (and [Koziarski] sec. 2.2, 2.1e5 MPa with the printed 2.1e6 fixed); rho [A]",
)
TEXTILE_LAMINATE = Material(
    E=4.5e9,
    nu=0.3,
    rho=1350.0,
    name="textile laminate (stand A lining)",
    source="E [A] from the stand-A contact size, Equations §3.1; nu, rho [A] Equations §3.1",
)
RUBBER_LINING = Material(
    E=16.8e6,
    nu=0.5,
    rho=1200.0,
    name="rubber lining (stand B roller)",
    source="apparent E [C] from b/a vs load of stand B (E* = 22.4 MPa), Equations §3.2; nu [A]; rho [A] Equations §3.2",
)
PMMA = Material(
    E=3.0e9,
    nu=0.37,
    rho=1190.0,
    name="PMMA (stand B disc)",
    source="E [A] 'E ~ 3 GPa' Equations §3.2; nu, rho [A] typical handbook values",
)
TEXTOLITE = Material(
    E=8000e6,
    nu=0.3,
    rho=1350.0,
    name="textolite ([Koziarski] worked example)",
    source="E, nu [T] [Koziarski] sec. 2.2 (Niemann values); rho [A]",
)
GUM = Material(
    E=40e6,
    nu=0.5,
    rho=1200.0,
    name="gum ([Koziarski] worked example)",
    source="E, nu [T] [Koziarski] sec. 2.2 (Niemann values); rho [A]",
)
RIGID = Material(E=math.inf, nu=0.3, rho=7850.0, name="rigid", source="idealisation: no compliance")

PRESETS = {
    "steel": STEEL,
    "textile_laminate": TEXTILE_LAMINATE,
    "rubber_lining": RUBBER_LINING,
    "pmma": PMMA,
    "textolite": TEXTOLITE,
    "gum": GUM,
    "rigid": RIGID,
}


def _pair(m1: Material, m2: Material) -> None:
    if m1.is_rigid and m2.is_rigid:
        raise ParameterError("materials", (m1.name, m2.name), "at least one deformable body (E < inf)")


def substitute_modulus(m1: Material, m2: Material) -> float:
    """Substitute modulus E = 2 E1' E2'/(E1' + E2') of eqs. (22)-(23) [Pa] (= 2 E*)."""
    _pair(m1, m2)
    return 2.0 / (1.0 / m1.plane_strain_modulus + 1.0 / m2.plane_strain_modulus)


def contact_modulus(m1: Material, m2: Material) -> float:
    """Hertz contact modulus E* = 1/((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa]."""
    _pair(m1, m2)
    return 1.0 / (1.0 / m1.plane_strain_modulus + 1.0 / m2.plane_strain_modulus)


def combined_shear_modulus(m1: Material, m2: Material) -> float:
    """Kalker's combined shear modulus G, 2/G = 1/G1 + 1/G2 [Pa] (rigid counter-body: G = 2 G1)."""
    _pair(m1, m2)
    return 2.0 / (1.0 / m1.G + 1.0 / m2.G)


def combined_poisson(m1: Material, m2: Material) -> float:
    """Kalker's combined Poisson ratio, nu/G = (nu1/G1 + nu2/G2)/2 (dimensionless).

    Kalker (1990) eq. (1.44). Equal materials give nu; against a rigid body G = 2 G_i and
    nu = nu_i (the rigid body's terms vanish).
    """
    g = combined_shear_modulus(m1, m2)
    return 0.5 * g * (m1.nu / m1.G + m2.nu / m2.G)


def track_deformability(mu: float, p0: float, v: float, a: float, E: float, w0: float) -> float:
    """Track deformability alpha' = 40 mu p0 v/(a E |w0|), eq. (21) (dimensionless).

    mu friction coefficient, p0 [Pa] maximum pressure, v [m/s] rolling speed, a [m] half length
    along the contact line, E [Pa] substitute modulus of eq. (22), w0 [rad/s] spin (non-zero;
    the sign is irrelevant). Large alpha' = linear (Kalker) regime, alpha' -> 0 = rigid sliding.
    """
    mu = validate.number("mu", mu, 0.0, lo_open=True)
    p0 = validate.number("p0", p0, 0.0, lo_open=True)
    v = validate.number("v", v, 0.0, lo_open=True)
    a = validate.number("a", a, 0.0, lo_open=True)
    E = validate.number("E", E, 0.0, lo_open=True)
    w0 = validate.number("w0", w0)
    if w0 == 0.0:
        raise ParameterError("w0", w0, "non-zero spin [rad/s]", hint="alpha' is infinite without spin")
    return 40.0 * mu * p0 * v / (a * E * abs(w0))


def density_index(mu: float, rho: float, v: float, G: float) -> float:
    """Density (surface-inertia) index g' = mu rho v^2/(4 pi G), eq. (24) (dimensionless).

    mu friction coefficient, rho [kg/m^3] density, v [m/s] rolling speed, G [Pa] shear modulus.
    The printed "mu g 2^2/(4 pi G)" is read with g = rho and 2^2 = v^2 (Equations §1.7).
    """
    mu = validate.number("mu", mu, 0.0, lo_open=True)
    rho = validate.number("rho", rho, 0.0, lo_open=True)
    v = validate.number("v", v)
    G = validate.number("G", G, 0.0, lo_open=True)
    return mu * rho * v * v / (4.0 * math.pi * G)


def preset(name: str) -> Material:
    """The named preset material (one of PRESETS); an unknown name raises with a suggestion."""
    return PRESETS[validate.choice("material", name, PRESETS)]
