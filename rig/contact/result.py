"""The one result type every contact model returns.

Sign convention (docs/contact-model.md, "Conventions"): x = rolling direction (material passes the contact in +x),
y = along the contact line, z = common normal; body 1 is the driving element. The rigid slip of
body 1 relative to body 2 is a rotation with spin w0 about the rolling point C = (c, l),
s_g(x, y) = w0 * (-(y - l), x - c); the traction on body 1 opposes the slip. With w0 > 0 this gives
nu_T <= 0 for l > 0 and nu_v >= 0 for c > 0 (Equations §1.1).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class ContactMaps:
    """Per-cell fields of a grid model (all dimensionless; lengths in units of a).

    x, y: cell centres [a]; area: cell area [a^2]; pressure: p/p0;
    traction: (q_x, q_y)/(mu p0), shape (2, N); slip: slip velocity (s_x, s_y) in units of
    mu p0 v / G (the elastic slip scale), shape (2, N); stick: True where the cell adheres.
    """

    x: np.ndarray
    y: np.ndarray
    area: np.ndarray
    pressure: np.ndarray
    traction: np.ndarray
    slip: np.ndarray
    stick: np.ndarray


@dataclass(frozen=True)
class ContactResult:
    """Dimensionless force coefficients of one steady rolling contact.

    nu_T = F_x/(mu F_N) (eq. 27), nu_v = F_y/(mu F_N) (eq. 28),
    nu_0 = P_t/(mu a F_N |w0|) = |moment about C|/(mu a F_N) (eq. 26; NaN when the spin is zero,
    where the rolling point is at infinity - use nu_Mo then),
    nu_Mo = moment about the contact centre O/(mu a F_N) (signed, z-component),
    stick_fraction = adhesion area / contact area (0 for full sliding),
    maps = per-cell fields (None for models without a grid), info = solver diagnostics.
    """

    model: str
    shape: str
    b_over_a: float
    nu_T: float
    nu_v: float
    nu_0: float
    nu_Mo: float
    stick_fraction: float
    maps: ContactMaps | None = None
    info: dict = field(default_factory=dict)

    @property
    def nu_MC(self) -> float:
        """Signed moment about the rolling point C/(mu a F_N) (= -sign(w0) nu_0)."""
        return float(self.info.get("nu_MC", np.nan))
