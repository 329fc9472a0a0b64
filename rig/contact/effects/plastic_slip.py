"""Plastic ("deformational") self slip: Psi = v0/v_el >= 1, eq. (25) of [Koziarski].

Eq. (20) defines the elastic self slip v_el of an element under full friction: its own
displacement (eq. 19) over the time the material takes to pass it. v_el does not depend on the
element size (Equations §1.6), and eq. (25) states the total self slip as v0 = Psi v_el. The
plastic part (Psi - 1) v_el is therefore a slip *velocity* of the material under its own traction,

    s_plastic = (Psi - 1) v_el q / (mu p) = (Psi - 1) (2 asinh(1) (2 - nu) / pi) q

in the solver's units (slip in mu p0 v/G, traction in mu p0; v_el from eq. (20) as corrected in
Equations §1.6). It is local (not transmitted to other elements) and has no grid length in it, so
the effect converges under grid refinement and Psi keeps its paper meaning at every grid
(docs/contact-model.md, "Plastic slip"). The stick condition becomes |w| <= Psi v_el (eqs. 13-14)
for an element at full traction, as in the paper.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate


def elastic_self_slip_rate(poisson: float) -> float:
    """v_el / (mu p v / G) = 2 asinh(1) (2 - nu)/pi, eq. (20) (Kalker's combined G) [1]."""
    return 2.0 * np.arcsinh(1.0) * (2.0 - poisson) / np.pi


@dataclass(frozen=True)
class PlasticSlip:
    """Total-to-elastic self-slip ratio Psi (dimensionless, >= 1)."""

    psi: float

    def __post_init__(self) -> None:
        validate.number("psi", self.psi, 1.0)

    def rate(self, poisson: float) -> float:
        """(Psi - 1) v_el/(mu p v/G): plastic slip per unit traction [slip units per mu p0]; the
        plastic slip of material under traction q is rate * q (rig.contact.elastic_law)."""
        return (self.psi - 1.0) * elastic_self_slip_rate(poisson)
