"""Surface inertia forces of the deformed surface layer, eq. (15) of [Koziarski] (model choice).

The paper writes dF_b = rho d2u/dt2 dx dy dz but gives no model of the layer. Equations §1.9
(step 3) suggests a layer of fixed mass rho h_l per area; that model is ill-posed: its
correction grows like Gamma |k| with the wavenumber, so on a fine grid it resonates at the cell
scale and the result depends on the cell size (docs/contact-model.md shows it). Chosen instead:
a surface wave of wavenumber k moves the material down to a depth ~1/|k|, so the mass per area
that follows the surface is rho/|k|. In steady rolling (d/dt = v d/dx) the half-space then
feels t = q - rho v^2 Lambda^-1 d2u/dx2, Lambda^-1 being the operator with symbol 1/|k|
(convolution with 1/(2 pi R)). Dimensionless:

    q = t + Gamma (1/(2 pi)) int (D2 U)(x') / |x - x'| dA',   Gamma = rho v^2 / G = 4 pi g'/mu

(g' of eq. 24). The correction is of order Gamma = (v/c_s)^2 at every scale, as for the exact
elastodynamic half-space, and the model is well posed for Gamma < 1/2; it is limited to
Gamma <= 0.25 (v <= c_s/2). Only the material inside the contact is given inertia.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from rig import validate

MAX_INERTIA_NUMBER = 0.25


@dataclass(frozen=True)
class SurfaceInertia:
    """Surface-inertia number Gamma = rho v^2/G = (v/c_s)^2 (dimensionless, 0 <= Gamma <= 0.25)."""

    number: float

    def __post_init__(self) -> None:
        validate.number("inertia_number", self.number, 0.0, MAX_INERTIA_NUMBER)

    def layer_force(self, u_full: np.ndarray, grid, op) -> np.ndarray:
        """Gamma Lambda^-1 D2 U at the active cells [mu p0]; u_full is (2, cells) of the rectangle."""
        u = u_full.reshape((2,) + grid.full_shape)
        d2 = np.zeros_like(u)
        d2[:, 2:] = (u[:, 2:] - 2.0 * u[:, 1:-1] + u[:, :-2]) / grid.hx**2
        d2[:, ~grid.active] = 0.0
        return self.number * grid.gather(op.apply_riesz(d2))


def inertia_number_from_index(g_prime: float, mu: float) -> float:
    """Gamma from the paper's density index g' = mu rho v^2/(4 pi G) of eq. (24): Gamma = 4 pi g'/mu."""
    validate.number("g_prime", g_prime, 0.0)
    validate.number("mu", mu, 0.0, lo_open=True)
    return 4.0 * np.pi * g_prime / mu
