"""Kalker's simplified theory (FASTSIM): the half-space replaced by a local flexibility L, u = L q.

Stick: s_g + L dq/dx = 0 along each strip in the rolling direction, integrated from the leading
edge; wherever |q| would exceed the bound p the element slides with q = -p s/|s|. The
flexibilities are chosen so that full stick reproduces linear theory (Kalker's rule
L1 = I_xi/(b C11), L2 = I_xi/(b C22), L3 = I_phi/(b^1.5 C23), weighted by the creepages),
with the C's of rig.contact.kalker. The traction bound is the model's own Hertz pressure (Kalker's
FASTSIM uses a parabolic one) so that large creepage gives exactly the `rigid` model.
Dimensionless units as in rig.contact.models.kinematic.
"""

from __future__ import annotations

import numpy as np

from rig.contact.grid import Grid, leading_edge
from rig.contact.kalker import CreepCoefficients
from rig.contact.kinematics import Creepage


def shape_integrals(shape: str, b_over_a: float) -> tuple[float, float]:
    """(I_xi, I_phi) = integrals over the contact of (x - x_lead) and (x_lead^2 - x^2)/2 [a^3, a^4]."""
    b = b_over_a
    if shape == "ellipse":
        return 8.0 * b**2 / 3.0, np.pi * b**3 / 4.0
    return 4.0 * b**2, 4.0 * b**3 / 3.0


def flexibility(shape: str, b_over_a: float, coeffs: CreepCoefficients, creepage: Creepage) -> float:
    """Kalker's creepage-weighted flexibility L [units a/G]."""
    i_xi, i_phi = shape_integrals(shape, b_over_a)
    root = np.sqrt(b_over_a)
    l1 = i_xi / (b_over_a * coeffs.C11)
    l2 = i_xi / (b_over_a * coeffs.C22)
    l3 = i_phi / (b_over_a * root * coeffs.C23)
    weights = np.array([abs(creepage.xi), abs(creepage.eta), root * abs(creepage.phi)])
    total = np.sqrt(np.sum(weights**2))
    if total == 0.0:
        return l1
    return float((l1 * weights[0] + l2 * weights[1] + l3 * weights[2]) / total)


def slip_increments(grid: Grid, creepage: Creepage) -> tuple[np.ndarray, np.ndarray]:
    """Rigid-slip increments over each active cell's step along x, two ways, (2, nxg, ny) each
    [a mu p0 v/G]: (exact integral, step x slip at the cell centre).

    The step runs from the upstream cell's centre, or from the leading edge for a row's first
    cell. s_g is linear in x, so the midpoint rule gives the exact integral: full-stick
    tractions are then exact at the cell centres. The second form is collocated at the centre:
    an element that slides takes its direction from it, so that in full sliding the traction
    points exactly against the local rigid slip.
    """
    x = grid.x[:, None] * np.ones((1, grid.ny))
    entering = grid.active & ~np.roll(grid.active, 1, axis=0)
    previous = np.where(entering, leading_edge(grid.shape, grid.b_over_a, grid.y)[None, :], x - grid.hx)
    step = np.where(grid.active, x - previous, 0.0)
    exact = step * creepage.field(0.5 * (x + previous), grid.y[None, :])
    collocated = step * creepage.field(x, grid.y[None, :])
    return exact, collocated


def march(grid: Grid, increments: tuple[np.ndarray, np.ndarray], bound_full: np.ndarray, flex: float) -> np.ndarray:
    """FASTSIM traction on the full grid, column by column (2, nxg, ny) [mu p0].

    Stick: q_c = q_up - exact_c/L if that stays within the bound; slip: the implicit FASTSIM
    slip solution |q_c| = bound, q_c parallel to q_up - collocated_c/L (Kalker's projection).
    """
    exact, collocated = increments
    q = np.zeros_like(exact)
    for i in range(1, q.shape[1]):
        stick = q[:, i - 1] - exact[:, i] / flex
        slide = q[:, i - 1] - collocated[:, i] / flex
        r = bound_full[i]
        holds = np.hypot(stick[0], stick[1]) <= r
        norm = np.hypot(slide[0], slide[1])
        q[:, i] = np.where(holds, stick, slide * (r / np.where(norm > 0.0, norm, 1.0)))
    return q
