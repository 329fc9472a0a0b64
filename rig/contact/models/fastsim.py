"""Kalker's simplified theory (FASTSIM): the half-space replaced by local flexibilities, u = L q.

Stick: the traction grows along each strip in the rolling direction from the leading edge,
dq/dx = -(xi/L1 - phi y/L4, eta/L2 + phi x/L3): each creepage has its own flexibility
(Kalker, "A fast algorithm for the simplified theory of rolling contact", Vehicle System
Dynamics 11 (1982) 1-13; "Three-dimensional elastic bodies in rolling contact", 1990, ch. 3).
Wherever |q| would exceed the bound p the element slides with q along the trial traction
(Kalker's projection). Kalker's three flexibilities make full stick reproduce linear theory's
forces for each creepage and for any combination of them:

    L1 = 8 a_K/(3 C11 G),  L2 = 8 a_K/(3 C22 G),  L3 = pi a_K sqrt(a_K/b_K)/(4 C23 G)

(Kalker's a_K along rolling, b_K lateral; in this package's units, lengths in a, a_K = b/a = beta,
b_K = 1, tractions in mu p0, creepages in mu p0/G: L1 = 8 beta/(3 C11), L2 = 8 beta/(3 C22),
L3 = pi beta^1.5/(4 C23); the finite line contact uses the same rule with its strip integrals).
With L3 for both components of the spin's slip, full stick gives the spin *moment* 41 % below
linear theory at b/a = 10 (the spin's lateral traction is even in x and carries no moment about
the centre; the moment comes from the longitudinal part -phi y alone). A fourth flexibility for that
part, L4 = I_M/(beta^2 C33) with I_M = integral of y^2 (x_lead - x) over the contact (8 beta^2/15 for
the ellipse), makes the full-stick spin moment linear theory's -G c^4 C33 phi as well, without
changing any force [R, our choice; issue 15 item 2; docs/contact-model.md].

``single_flexibility`` is Kalker's one-parameter variant (one L, the creepage-weighted mean of
L1, L2, L3): exact for a pure creepage, but with combined creepages it misses linear theory's
forces (by 26 % for the spin force at b/a = 10, rolling point l = a); kept for comparison only.
With different flexibilities Kalker's projection makes a sliding element's traction point
against the *scaled* slip (xi/L1 - phi y/L4, eta/L2 + phi x/L3), not the rigid slip: in full
sliding nu_T and nu_v were up to 25 % off the rigid model for combined creepage (line contact,
b/a = 1, C = (0.4, 0.5) a). ``flexibility`` therefore blends the four flexibilities towards their
creepage-weighted mean as the contact saturates (a smooth function of the creepage only): exact
linear theory in full stick, exactly the rigid model in full sliding, continuous in between
[R, our choice; docs/contact-model.md gives the alternatives tried and why they were
rejected]. The traction bound is the model's own Hertz pressure (Kalker's FASTSIM uses a
parabolic one). Dimensionless units as in rig.contact.models.kinematic.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from rig.contact.grid import Grid, leading_edge
from rig.contact.kalker import CreepCoefficients
from rig.contact.kinematics import Creepage


class Flexibilities(NamedTuple):
    """Flexibilities [a/G] for the longitudinal (L1) and lateral (L2) creepage, the spin's lateral
    slip phi x (L3, Kalker's) and the spin's longitudinal slip -phi y (L4, fitted to C33)."""

    L1: float
    L2: float
    L3: float
    L4: float

    @classmethod
    def one(cls, flexibility: float) -> Flexibilities:
        """The same flexibility for every creepage (Kalker's single-flexibility FASTSIM) [a/G]."""
        return cls(flexibility, flexibility, flexibility, flexibility)

    def scaled_slip(self, creepage: Creepage, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Rigid slip with each part divided by its flexibility,
        (xi/L1 - phi y/L4, eta/L2 + phi x/L3) [mu p0/a], shape (2, ...)."""
        c = creepage
        return np.stack(np.broadcast_arrays(c.xi / self.L1 - c.phi * y / self.L4, c.eta / self.L2 + c.phi * x / self.L3))

    def weighted(self, creepage: Creepage, b_over_a: float) -> float:
        """One flexibility: L1, L2, L3 weighted by |xi|, |eta|, sqrt(b/a)|phi| (Kalker) [a/G]."""
        weights = np.array([abs(creepage.xi), abs(creepage.eta), np.sqrt(b_over_a) * abs(creepage.phi)])
        total = np.sqrt(np.sum(weights**2))
        if total == 0.0:
            return self.L1
        return float(np.dot(self[:3], weights) / total)


def shape_integrals(shape: str, b_over_a: float) -> tuple[float, float, float]:
    """(I_xi, I_phi, I_M) = integrals over the contact of (x_lead - x), (x_lead^2 - x^2)/2 and
    y^2 (x_lead - x) [a^3, a^4, a^5]."""
    b = b_over_a
    if shape == "ellipse":
        return 8.0 * b**2 / 3.0, np.pi * b**3 / 4.0, 8.0 * b**2 / 15.0
    return 4.0 * b**2, 4.0 * b**3 / 3.0, 4.0 * b**2 / 3.0


def linear_theory_flexibilities(shape: str, b_over_a: float, coeffs: CreepCoefficients) -> Flexibilities:
    """Kalker's three flexibilities (L1, L2, L3) and the spin-moment flexibility L4 [a/G]: full
    stick reproduces linear theory's forces (C11, C22, C23) and its spin moment (C33)."""
    i_xi, i_phi, i_moment = shape_integrals(shape, b_over_a)
    return Flexibilities(
        L1=float(i_xi / (b_over_a * coeffs.C11)),
        L2=float(i_xi / (b_over_a * coeffs.C22)),
        L3=float(i_phi / (b_over_a**1.5 * coeffs.C23)),
        L4=float(i_moment / (b_over_a**2 * coeffs.C33)),
    )


def flexibility(shape: str, b_over_a: float, coeffs: CreepCoefficients, creepage: Creepage) -> Flexibilities:
    """The flexibilities FASTSIM uses [a/G]: linear theory's four, L_i, blended towards their
    creepage-weighted mean L_w as the contact saturates,

        L_i,eff = L_w + s (L_i - L_w),  s = 1/(1 + eps^2),  eps = 2 (b/a) |w|/L_w,

    |w| = sqrt(xi^2 + eta^2 + (b/a) phi^2) (Kalker's weighting): eps is the full-stick traction
    at the trailing edge over mu p0. Small creepage (s -> 1): the four flexibilities, exact in
    full stick; large creepage (s -> 0): one flexibility, so that full sliding opposes the rigid
    slip (the rigid model). [R] our choice, see the module docstring."""
    linear = linear_theory_flexibilities(shape, b_over_a, coeffs)
    mean = linear.weighted(creepage, b_over_a)
    eps = 2.0 * b_over_a * np.sqrt(creepage.xi**2 + creepage.eta**2 + b_over_a * creepage.phi**2) / mean
    s = 1.0 / (1.0 + eps * eps)
    return Flexibilities(*(float(mean + s * (l - mean)) for l in linear))


def single_flexibility(shape: str, b_over_a: float, coeffs: CreepCoefficients, creepage: Creepage) -> float:
    """Kalker's one-parameter variant: L1, L2, L3 weighted by |xi|, |eta|, sqrt(b/a)|phi| [a/G]."""
    return linear_theory_flexibilities(shape, b_over_a, coeffs).weighted(creepage, b_over_a)


@dataclass(frozen=True, eq=False)
class SlipIncrements:
    """Where each active cell's step along x starts and ends, for a given creepage.

    The step runs from the upstream cell's centre, or from the leading edge for a row's first
    cell: step [a] and its midpoint x_mid [a] per cell (nxg, ny), zero step outside the contact.
    """

    creepage: Creepage
    step: np.ndarray
    x_mid: np.ndarray
    x: np.ndarray
    y: np.ndarray

    def over(self, flex: Flexibilities) -> tuple[np.ndarray, np.ndarray]:
        """Rigid-slip increments over each cell's step divided by the flexibilities
        (Flexibilities.scaled_slip), two ways, (2, nxg, ny) each [mu p0]: (exact integral, step x value at the cell centre).

        s_g is linear in x, so the midpoint rule gives the exact integral: full-stick tractions
        are then exact at the cell centres. The second form is collocated at the centre: an
        element that slides takes its direction from it (Kalker's projection).
        """
        exact = flex.scaled_slip(self.creepage, self.x_mid, self.y)
        return self.step * exact, self.step * flex.scaled_slip(self.creepage, self.x, self.y)


def slip_increments(grid: Grid, creepage: Creepage) -> SlipIncrements:
    """The steps of each active cell along x for the given creepage (see SlipIncrements)."""
    x = grid.x[:, None] * np.ones((1, grid.ny))
    entering = grid.active & ~np.roll(grid.active, 1, axis=0)
    previous = np.where(entering, leading_edge(grid.shape, grid.b_over_a, grid.y)[None, :], x - grid.hx)
    step = np.where(grid.active, x - previous, 0.0)
    return SlipIncrements(creepage, step, 0.5 * (x + previous), x, grid.y[None, :])


def march(grid: Grid, increments: SlipIncrements, bound_full: np.ndarray, flex: Flexibilities | float) -> np.ndarray:
    """FASTSIM traction on the full grid, column by column (2, nxg, ny) [mu p0].

    flex: the four flexibilities, or one number for the single-flexibility variant.
    Stick: q_c = q_up - exact_c if that stays within the bound; slip: the implicit FASTSIM slip
    solution |q_c| = bound, q_c parallel to q_up - collocated_c (Kalker's projection).
    """
    if not isinstance(flex, Flexibilities):
        flex = Flexibilities.one(float(flex))
    exact, collocated = increments.over(flex)
    q = np.zeros_like(exact)
    for i in range(1, q.shape[1]):
        stick = q[:, i - 1] - exact[:, i]
        slide = q[:, i - 1] - collocated[:, i]
        r = bound_full[i]
        holds = np.hypot(stick[0], stick[1]) <= r
        norm = np.hypot(slide[0], slide[1])
        q[:, i] = np.where(holds, stick, slide * (r / np.where(norm > 0.0, norm, 1.0)))
    return q
