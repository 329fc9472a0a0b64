"""Kalker's linear theory, eq. (4) of [Koziarski] (small creepage, full adhesion).

In this package's frame (material flows in +x, the opposite of Kalker's) and the elastic units of
rig.contact.kinematics.Creepage (creepages times G/(mu p0), lengths in a), with
F_N = A_F a b p0 (A_F = 2 pi/3 ellipse, pi line) and beta = b/a:

    nu_T  = -C11 xi / A_F
    nu_v  = -(C22 eta - sqrt(beta) C23 phi) / A_F
    nu_Mo = -(sqrt(beta) C23 eta + beta C33 phi) / A_F

(eq. 4 with creepages and Kalker's combined G, Equations §1.3; the spin terms change sign with
the flow direction - tests/contact/test_linear_limit.py checks them against the grid model).
Linear theory is unbounded: it is valid only while the tractions stay well below mu p.
"""

from __future__ import annotations

import numpy as np

from rig.contact.grid import load_factor
from rig.contact.kalker import CreepCoefficients
from rig.contact.kinematics import Creepage


def force_coefficients(shape: str, b_over_a: float, coeffs: CreepCoefficients, creepage: Creepage) -> dict[str, float]:
    """nu_T, nu_v, nu_Mo of linear theory for the given creepages."""
    area = load_factor(shape)
    root = np.sqrt(b_over_a)
    xi, eta, phi = creepage.xi, creepage.eta, creepage.phi
    return dict(
        nu_T=-coeffs.C11 * xi / area,
        nu_v=-(coeffs.C22 * eta - root * coeffs.C23 * phi) / area,
        nu_Mo=-(root * coeffs.C23 * eta + b_over_a * coeffs.C33 * phi) / area,
    )
