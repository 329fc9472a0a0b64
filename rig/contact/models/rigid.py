"""Rigid full sliding (alpha' -> 0): every point slides, q = -mu p s_g/|s_g| (Coulomb).

The result is an integral of the pressure times the slip direction over the contact; it is
evaluated by the midpoint rule on a grid ``SUBSAMPLES`` times finer than the model grid, so
it is exact to that quadrature (Equations §1.10(a) gives reference values). The point C itself
(direction undefined, hard case 3) has measure zero and contributes nothing.
"""

from __future__ import annotations

import numpy as np

from rig.contact.grid import make_grid, pressure
from rig.contact.kinematics import Creepage

SUBSAMPLES = 8


def sample_points(shape: str, b_over_a: float, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Quadrature points (x, y) [a] and pressures p/p0 on SUBSAMPLES x finer cells."""
    grid = make_grid(shape, b_over_a, n)
    s = (np.arange(SUBSAMPLES) + 0.5) / SUBSAMPLES - 0.5
    xc, yc = grid.centres()
    ox, oy = np.meshgrid(grid.hx * s, grid.hy * s, indexing="ij")
    x = (xc[:, None] + ox.ravel()[None, :]).ravel()
    y = (yc[:, None] + oy.ravel()[None, :]).ravel()
    p = pressure(shape, b_over_a, x, y)
    keep = p > 0.0
    return x[keep], y[keep], p[keep]


def tractions(x: np.ndarray, y: np.ndarray, bound: np.ndarray, creepage: Creepage) -> np.ndarray:
    """Full-sliding traction (2, N) [mu p0] at points where the rigid slip is s_g (any scale).

    bound: the traction bound at the points [mu p0]: the pressure p/p0, or mu(p) p/(mu0 p0) with a
    pressure-dependent mu (rig.contact.effects.pressure_friction)."""
    s = creepage.field(x, y)
    norm = np.hypot(s[0], s[1])
    return -bound * s / np.where(norm > 0.0, norm, np.inf)
