"""Derive linear-theory creepage coefficients C11, C22, C23, C33 with the full-stick grid solver.

``python -m rig.contact.linear_tables`` writes ``data/derived_linear_coefficients.csv``: for each
shape (ellipse, line), each b/a row of Kalker's table and nu = 0, 0.25, 0.5, the full-stick
(unlimited friction) solution of the kinematic model's discretisation at n = 48 and n = 96 cells
across 2a, extrapolated to zero cell size assuming first-order convergence (the upwind scheme's
order; tests/contact/test_convergence.py measures it): C = 2 C(96) - C(48).
For the ellipse the same procedure reproduces Kalker's own C11, C22, C23 (stored table: C11, C22
-0.4 .. +0.9 %, +1.1/+1.3 % at b/a = 10; C23 -0.8 .. +0.6 %), which is how the C33 column and the
line contact's coefficients - not available from Kalker's table - are checked.
tests/contact/test_linear_tables.py re-runs this procedure on cheaper grids (24, 48) for a few
rows against Kalker's numbers; tests/contact/test_kalker_tables.py compares the stored file.

Definitions (Kalker's, in this package's elastic units; F in mu p0 a^2, M in mu p0 a^3):
C11 = -F_x/(beta xi), C22 = -F_y/(beta eta), C23 = F_y/(beta^1.5 phi), C33 = -M_z/(beta^2 phi).
"""

from __future__ import annotations

import csv
import sys
from importlib import resources

import numpy as np

from rig.contact.effects import ContactEffects
from rig.contact.grid import make_grid
from rig.contact.kinematics import Creepage
from rig.contact.models.kinematic import solve_full_stick
from rig.errors import ParameterError

B_OVER_A = (0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0,
            1.11111, 1.25, 1.42857, 1.66667, 2.0, 2.5, 3.33333, 5.0, 10.0)
POISSON = (0.0, 0.25, 0.5)
GRIDS = (48, 96)


def grid_coefficients(shape: str, b_over_a: float, poisson: float, n: int) -> np.ndarray:
    """(C11, C22, C23, C33) of the full-stick solution on the grid with n cells across 2a."""
    grid = make_grid(shape, b_over_a, n)
    x, y = grid.centres()
    area = grid.cell_area
    beta = b_over_a
    unit = {"xi": Creepage(1.0, 0.0, 0.0), "eta": Creepage(0.0, 1.0, 0.0), "phi": Creepage(0.0, 0.0, 1.0)}
    q = {k: solve_full_stick(grid, poisson, c, ContactEffects()) for k, c in unit.items()}
    c11 = -q["xi"][0].sum() * area / beta
    c22 = -q["eta"][1].sum() * area / beta
    c23 = q["phi"][1].sum() * area / beta**1.5
    c33 = -np.sum(x * q["phi"][1] - y * q["phi"][0]) * area / beta**2
    return np.array([c11, c22, c23, c33])


def extrapolated(shape: str, b_over_a: float, poisson: float, grids: tuple[int, int] = GRIDS) -> np.ndarray:
    """Zero-cell-size estimate 2 C(2n) - C(n) (first-order Richardson) from grids (n, 2n);
    the stored table uses (48, 96), tests a cheaper pair."""
    coarse_n, fine_n = grids
    if fine_n != 2 * coarse_n:
        raise ParameterError("grids", grids, "a pair (n, 2n) of cell counts")
    coarse, fine = (grid_coefficients(shape, b_over_a, poisson, n) for n in grids)
    return 2.0 * fine - coarse


def main() -> int:
    target = resources.files("rig.contact.data").joinpath("derived_linear_coefficients.csv")
    header = [
        "# Linear-theory creepage coefficients derived with friction-rig's own full-stick solver",
        "# (python -m rig.contact.linear_tables; method in rig/contact/linear_tables.py and",
        "# docs/contact-model.md). Koziarski's naming: b/a = half width along rolling / half length",
        "# along the contact line (= Kalker's a/b). Kalker's definitions of C11, C22, C23, C33.",
    ]
    rows = []
    for shape in ("ellipse", "line"):
        for beta in B_OVER_A:
            for nu in POISSON:
                values = extrapolated(shape, beta, nu)
                rows.append([shape, f"{beta:g}", f"{nu:g}"] + [f"{v:.5f}" for v in values])
                print(shape, beta, nu, rows[-1][3:], file=sys.stderr, flush=True)
    with open(str(target), "w", newline="") as handle:
        handle.write("\n".join(header) + "\n")
        writer = csv.writer(handle)
        writer.writerow(["shape", "b_over_a", "nu", "C11", "C22", "C23", "C33"])
        writer.writerows(rows)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
