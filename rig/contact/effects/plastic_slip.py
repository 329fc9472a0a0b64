"""Plastic ("deformational") self slip: Psi = v0/v_el >= 1, eq. (25) of seed 000.

Model choice (docs/contact-model.md): the extra self slip (Psi - 1) v_el comes from a local
compliance (Psi - 1) K_self in series with the elastic half-space - a displacement that each
element carries with it but that is not transmitted to other elements. The total self slip of an
element under full traction is then Psi times the elastic one, as eq. (25) states, and the
stick condition becomes |w| <= Psi v_el (eqs. 13-14).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate


@dataclass(frozen=True)
class PlasticSlip:
    """Total-to-elastic self-slip ratio Psi (dimensionless, >= 1)."""

    psi: float

    def __post_init__(self) -> None:
        validate.number("psi", self.psi, 1.0)

    def carried_displacement_step(self, q, k_self, idx, up, grid) -> np.ndarray:
        """Change of the local displacement (Psi - 1) K_self q from the upstream cell to this one."""
        full = grid.scatter(q).reshape(2, -1)
        return (self.psi - 1.0) * k_self * (full[:, idx] - full[:, up])
