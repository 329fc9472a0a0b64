"""Physical-units layer over :func:`rig.contact.solve.solve` (Equations §1.7 and 1.9 step 9).

    from rig.contact.hertz import PointGeometry
    from rig.contact.materials import STEEL, TEXTILE_LAMINATE
    from rig.contact.physical import rolling_contact
    r = rolling_contact("kinematic", normal_force=96.2, geometry=PointGeometry(0.1437, 0.0425, inf, inf),
                        material_1=STEEL, material_2=TEXTILE_LAMINATE, mu=0.4, speed=1.03, spin=44.5,
                        c=0.0, l=0.0, n=24)
    r.force_x_N, r.force_y_N, r.moment_C_N_m, r.friction_power_W

Steps: Hertz contact (a along y, b along x, p0) from the load, the geometry and E* of the two
materials; alpha' = 40 mu p0 v/(a E |w0|) (eq. 21) with the substitute modulus E of eq. (22);
Kalker's combined Poisson ratio; the dimensionless solve; then
F_x = mu F_N nu_T (eq. 27), F_y = mu F_N nu_v (eq. 28), moments = mu a F_N nu_M,
P_t = mu a F_N |w0| nu_0 (eq. 26).

Sign conventions (Equations §1.1): x = rolling direction (material passes in +x, so the rolling
speed must be > 0; reverse rolling = mirror the x axis), y = contact line; body 1 is the driving
element; the spin w0 [rad/s] is signed. solve() is stated for w0 > 0; a negative spin is
solved as the mirror image y -> -y (rotation w0 about (c, l) = mirror of rotation |w0| about
(c, -l)), which needs only the y-symmetry of the Hertz pressure: F_x is kept, F_y and the
moments change sign, the power is unchanged. Zero spin puts the rolling point at infinity
(hard case 1) and is refused here: use rig.contact.solve.solve_creepage.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from rig import validate
from rig.contact.effects.pressure_friction import friction_at_peak_pressure
from rig.contact.hertz import HertzEllipse, HertzLine, LineGeometry, PointGeometry, hertz_contact
from rig.contact.materials import (
    Material,
    combined_poisson,
    contact_modulus,
    substitute_modulus,
    track_deformability,
)
from rig.contact.result import ContactMaps, ContactResult
from rig.contact.solve import solve
from rig.errors import ParameterError


@dataclass(frozen=True)
class PhysicalContactResult:
    """Forces, moments and power of one steady rolling contact in SI units.

    force_x_N: F_x [N] across the contact line (peripheral force); mu: the coefficient the contact ran at; force_y_N: F_y [N] along it;
    moment_C_N_m: moment about the rolling point C, T0 = M_C [N m] (z component, signed);
    moment_O_N_m: moment about the contact centre O [N m]; friction_power_W: P_t [W] (eq. 26);
    rolling_resistance_moment_N_m: F_N f [N m] of the rolling-friction length f (0 if that
    effect is off); alpha_prime: alpha' of eq. (21); poisson: Kalker's combined nu;
    substitute_modulus_Pa: E of eq. (22); contact: the Hertz contact (a, b, p0);
    dimensionless: the ContactResult of solve (for the actual sign of the spin).
    """

    force_x_N: float
    force_y_N: float
    moment_C_N_m: float
    moment_O_N_m: float
    friction_power_W: float
    rolling_resistance_moment_N_m: float
    alpha_prime: float
    mu: float
    poisson: float
    substitute_modulus_Pa: float
    contact: HertzEllipse | HertzLine
    dimensionless: ContactResult


def _material(name: str, value: object) -> Material:
    if not isinstance(value, Material):
        raise ParameterError(name, value, "a rig.contact.materials.Material")
    return value


def rolling_contact(
    model: str,
    *,
    normal_force: float,
    geometry: PointGeometry | LineGeometry,
    material_1: Material,
    material_2: Material,
    mu: float,
    speed: float,
    spin: float,
    c: float,
    l: float,
    n: int | None = None,
    reference_pressure: float | None = None,
    **effects: float,
) -> PhysicalContactResult:
    """Solve one contact given in physical units.

    model: "rigid", "linear", "fastsim" or "kinematic"; normal_force F_N [N] > 0; geometry:
    PointGeometry (radii [m]) or LineGeometry (length 2a [m], R_x [m]); material_1/2: the
    driving and the driven body; mu: friction coefficient > 0; speed: rolling speed v [m/s] > 0;
    spin: w0 [rad/s], non-zero, signed; c, l: rolling point [m] (c across, l along the contact
    line); n: cells across 2a for grid models; effects: solve()'s dimensionless effect keywords
    (psi, static_ratio, inertia_number, rolling_length = f/a, pressure_exponent), passed through
    unchanged. With pressure_exponent k, mu is the coefficient at reference_pressure p_ref [Pa]
    (required then, an error otherwise): the contact runs at mu(p0) = mu (p0/p_ref)^-k, the
    coefficient at its peak Hertz pressure (rig.contact.effects.pressure_friction).
    """
    m1 = _material("material_1", material_1)
    m2 = _material("material_2", material_2)
    mu = validate.number("mu", mu, 0.0, lo_open=True)
    speed = validate.number("speed", speed, 0.0, lo_open=True)  # +x is the rolling direction by definition
    spin = validate.number("spin", spin)
    if spin == 0.0:
        raise ParameterError(
            "spin", spin, "non-zero [rad/s]", hint="zero spin puts the rolling point at infinity; use solve_creepage"
        )
    c = validate.number("c", c)
    l = validate.number("l", l)

    contact = hertz_contact(normal_force, geometry, contact_modulus(m1, m2))
    if ("pressure_exponent" in effects) != (reference_pressure is not None):
        raise ParameterError("reference_pressure", reference_pressure,
                             "a pressure [Pa] > 0 together with the effect pressure_exponent, None without it")
    if reference_pressure is not None:
        mu = friction_at_peak_pressure(mu, contact.p0, reference_pressure, effects["pressure_exponent"])
    modulus = substitute_modulus(m1, m2)
    alpha = track_deformability(mu, contact.p0, speed, contact.a, modulus, spin)
    poisson = combined_poisson(m1, m2)
    mirrored = spin < 0.0
    result = solve(
        model,
        shape=contact.shape,
        b_over_a=contact.b_over_a,
        alpha=alpha,
        c_over_a=c / contact.a,
        l_over_a=(-l if mirrored else l) / contact.a,
        poisson=poisson,
        n=n,
        **effects,
    )
    if mirrored:
        result = mirror_y(result)

    force = contact.normal_force
    moment_scale = mu * contact.a * force
    return PhysicalContactResult(
        force_x_N=mu * force * result.nu_T,
        force_y_N=mu * force * result.nu_v,
        moment_C_N_m=moment_scale * result.nu_MC,
        moment_O_N_m=moment_scale * result.nu_Mo,
        friction_power_W=moment_scale * abs(spin) * result.nu_0,
        rolling_resistance_moment_N_m=force * contact.a * effects.get("rolling_length", 0.0),
        alpha_prime=alpha,
        mu=mu,
        poisson=poisson,
        substitute_modulus_Pa=modulus,
        contact=contact,
        dimensionless=result,
    )


def mirror_y(result: ContactResult) -> ContactResult:
    """The result of the mirror-image problem y -> -y: nu_T kept, nu_v and moments negated.

    Used for a negative spin (see the module docstring); grid maps are mirrored too. The info
    entries l_over_a and nu_MC are those of the mirrored (actual) problem.
    """
    info = dict(result.info)
    info["nu_MC"] = -result.nu_MC
    if "l_over_a" in info:
        info["l_over_a"] = -info["l_over_a"]
    info["mirrored_y"] = True
    maps = result.maps
    if maps is not None:
        flip = np.array([[1.0], [-1.0]])
        maps = ContactMaps(
            x=maps.x,
            y=-maps.y,
            area=maps.area,
            pressure=maps.pressure,
            traction=maps.traction * flip,
            slip=maps.slip * flip,
            stick=maps.stick,
        )
    return replace(result, nu_v=-result.nu_v, nu_Mo=-result.nu_Mo, maps=maps, info=info)

