"""Static friction mu0 > mu with stick/slip memory ([Koziarski] symbol list: mu0 "coefficient of
friction during close-to-zero slip"; Equations §1.9 step 5, hard case 9).

A material point that arrives at a cell sticking may hold up to mu0 p; once it slips it holds
mu p until it sticks again. Two conventions for the material that *enters* the contact:

* ``StaticFriction`` (keyword ``static_ratio``, the default): it arrives sticking - it carries no
  slip yet - so it may hold mu0 p in its first cell;
* ``StaticFrictionAfterFirstStick`` (keyword ``static_ratio_after_first_stick``): it is kinetic
  until it first sticks (holds mu p in its first cell, mu0 p from the cell after one where it
  stuck) - the reading of the Equations page's memory table.
They differ only in the first cell of each row (tests/contact/test_static_friction_entry.py).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from rig import validate


@dataclass(frozen=True)
class StaticFriction:
    """Static-to-kinetic friction ratio mu0/mu (dimensionless, >= 1); entering material holds mu0 p."""

    ratio: float
    ENTERING_STICKS: ClassVar[bool] = True

    def __post_init__(self) -> None:
        validate.number("static_ratio", self.ratio, 1.0)

    def bound(self, p: np.ndarray, sticking_upstream: np.ndarray) -> np.ndarray:
        """Traction bound per cell [mu p0]: mu0/mu p where the arriving point sticks, else p."""
        return np.where(sticking_upstream, self.ratio * p, p)

    def upstream_state(self, stick: np.ndarray, grid) -> np.ndarray:
        """For each active cell: did the material arriving there stick one cell upstream?

        Material not yet in the contact counts as sticking (ENTERING_STICKS) or as kinetic.
        """
        full = np.full(grid.p.size, self.ENTERING_STICKS, dtype=bool)
        full[grid.index] = stick
        return full[grid.index - grid.ny]


@dataclass(frozen=True)
class StaticFrictionAfterFirstStick(StaticFriction):
    """As StaticFriction, but material entering the contact is kinetic until it first sticks."""

    ENTERING_STICKS: ClassVar[bool] = False
