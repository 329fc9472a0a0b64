"""Static friction mu0 > mu with stick/slip memory (seed 000 symbol list: mu0 "coefficient of
friction during close-to-zero slip"; seed notes 1.9 step 5, hard case 9).

A material point that arrives at a cell sticking (it entered the contact, or it stuck in the
cell upstream) may hold up to mu0 p; once it slips it holds mu p until it sticks again.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate


@dataclass(frozen=True)
class StaticFriction:
    """Static-to-kinetic friction ratio mu0/mu (dimensionless, >= 1)."""

    ratio: float

    def __post_init__(self) -> None:
        validate.number("static_ratio", self.ratio, 1.0)

    def bound(self, p: np.ndarray, sticking_upstream: np.ndarray) -> np.ndarray:
        """Traction bound per cell [mu p0]: mu0/mu p where the arriving point sticks, else p."""
        return np.where(sticking_upstream, self.ratio * p, p)

    @staticmethod
    def upstream_state(stick: np.ndarray, grid) -> np.ndarray:
        """For each active cell: did the material arriving there stick one cell upstream?

        Material that is not yet in the contact carries no slip, so it arrives sticking.
        """
        full = np.ones(grid.p.size, dtype=bool)
        full[grid.index] = stick
        return full[grid.index - grid.ny]
