"""Pressure-dependent friction coefficient mu(p) = mu_ref (p/p_ref)^(-k) (model choice, issue 10).

[Koziarski] has one mu for the whole contact. For a rubber lining on PMMA a tribologist expects the
coefficient to fall with the local contact pressure (adhesion friction of elastomers: the real
contact area grows more slowly than the load, k ~ 1/3 for a Hertzian asperity model); the paper's
Figs. 14-15 (forces growing "much more slowly" with F_N) could come from that instead of Psi > 1
(docs/findings-fig14.md). The effect changes only the traction bound of each element,

    |q| <= mu(p) p    instead of    |q| <= mu p    (eqs. 13-14),

and nothing else (the elastic slip, the plastic slip (Psi - 1) v_el q/(mu p) and the inertia
layer are unchanged in form).

Units [R]: the contact model is dimensionless with tractions in mu p0 (rig.contact.models). With
the effect on, the mu of that unit is **mu0 = mu(p0), the coefficient at the peak Hertz
pressure p0** - the reference pressure of the dimensionless model is p0. The bound per cell is then

    mu(p) p / (mu0 p0) = (p/p0)^(1 - k),

which needs k only, so the effect is one keyword (``pressure_exponent``) like the others, and
every coefficient keeps its meaning: nu = F/(mu0 F_N), alpha' = 40 mu0 p0 v/(a E w0) (eq. 21 with
mu0). A physical reference pressure p_ref [Pa] enters only where p0 is known in Pa (a stand, or
rig.contact.physical): mu0 = mu_ref (p0/p_ref)^(-k) (:func:`friction_at_peak_pressure`), so the
coefficient at the peak - and with it every force - falls with the load as p0^(-k).

Range: 0 <= k <= 1. k = 0 is today's Coulomb bound (the effect off); k = 1 is a bound that does
not depend on p (a constant interfacial shear strength mu_ref p_ref); k > 1 would make the
bound grow towards the contact's edge. mu(p) itself is unbounded where p -> 0 for k > 0, but the
traction bound mu(p) p -> 0 there for k < 1 (integrable; tests/contact/test_pressure_friction.py).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate

EXPONENT_RANGE = (0.0, 1.0)


@dataclass(frozen=True)
class PressureDependentFriction:
    """Exponent k of mu(p) = mu_ref (p/p_ref)^(-k) (dimensionless, 0 <= k <= 1)."""

    exponent: float

    def __post_init__(self) -> None:
        validate.number("pressure_exponent", self.exponent, *EXPONENT_RANGE)

    def bound(self, p: np.ndarray) -> np.ndarray:
        """Traction bound mu(p) p/(mu0 p0) = (p/p0)^(1 - k) per point, p in p0 (>= 0) [1]; p itself at k = 0."""
        if self.exponent == 0.0:
            return p
        return np.power(p, 1.0 - self.exponent)


def friction_at_peak_pressure(mu_ref: float, p0_Pa: float, p_ref_Pa: float, exponent: float) -> float:
    """mu0 = mu(p0) = mu_ref (p0/p_ref)^(-k): the mu of the dimensionless model [1].

    mu_ref: coefficient at the reference pressure p_ref [Pa]; p0_Pa: peak Hertz pressure [Pa];
    exponent: k in [0, 1]. k = 0 returns mu_ref itself (no arithmetic on it).
    """
    mu_ref = validate.number("mu", mu_ref, 0.0, lo_open=True)
    p0 = validate.number("p0_Pa", p0_Pa, 0.0, lo_open=True)
    p_ref = validate.number("reference_pressure_Pa", p_ref_Pa, 0.0, lo_open=True)
    k = validate.number("pressure_exponent", exponent, *EXPONENT_RANGE)
    if k == 0.0:
        return mu_ref
    return mu_ref * (p0 / p_ref) ** (-k)
