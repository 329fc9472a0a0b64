"""The kinematic model's slip operator against a closed form, and what the leading edge's share of
its error does to nu_v (docs/contact-convergence.md, the operator against Johnson's closed form).

    python studies/edge_consistency.py [--grids 16 32 64 128 256]

The circle (b/a = 1), Poisson 0.28. The traction t = (p, 0) and (0, p) with the Hertz shape
p = p0 sqrt(1 - r^2) has a displacement that is a quadratic in x and y inside the contact (Johnson's
closed form, rig.contact.hertz.hertz_traction_slip). The model's elastic slip dU/dx
(rig.contact.models.kinematic: the FFT influence product, the entry profile and the transport weights
together) is compared with the exact derivative at the points the transport takes it
(Discretisation.x_slip): in the interior (r < 0.5), and cell by cell from each row's leading edge (rows |y| < 0.7).

Two corrections of the first slip cells were tried from these errors (a per-row calibration that makes
the operator exact on the two Hertz-shaped fields, and a per-cell three-cell stencil exact on the
Hertz-weighted linear tractions); they needed changes inside rig.contact and are not kept here:
docs/contact-convergence.md reports what they did.
"""

from __future__ import annotations

import argparse

import numpy as np

import rig.contact.entry as entry
import rig.contact.models.kinematic as kinematic
from rig.contact.effects import ContactEffects
from rig.contact.grid import make_grid
from rig.contact.hertz import hertz_traction_slip
from rig.contact.influence import influence_operator

POISSON = 0.28
ROWS_NEAR_AXIS = 0.7  # |y| [a] of the rows whose leading-edge cells are reported
INTERIOR = 0.5  # r [a] of the cells called interior


def slip_under(grid, law, density, direction):
    """The law's elastic slip (2, N) [p0/G] under the traction p density e_direction (density (N,) [1])."""
    t = np.zeros((2, grid.index.size))
    t[direction] = grid.gather(grid.p) * density
    return law.apply(t)[1]


def operator_errors(grid, disc, poisson, component):
    """The model's elastic slip minus the exact one (2, N) for the Hertz-shaped traction along ``component``."""
    _, y = grid.centres()
    return slip_under(grid, disc.law, 1.0, component) - hertz_traction_slip(disc.x_slip, y, poisson, component)


def cells_from_edge(grid, k):
    """Active-cell indices (E,) of the k-th cell of each row from its leading edge (-1 where the row is shorter)."""
    position = np.full(grid.p.size, -1)
    position[grid.index] = np.arange(grid.index.size)
    return position[grid.index[np.flatnonzero(entry.entering(grid))] + k * grid.ny]


def operator_study(grids) -> None:
    print("Hertz-shaped traction (p, 0) on the circle: the model's dU_x/dx minus the exact one [p0/G]")
    print("n | interior max | mean error of cell k = 0 ... 5 from the leading edge (rows |y| < 0.7) | per-row sum of k = 0 ... 7, x h [p0 a/G]")
    for n in grids:
        grid = make_grid("ellipse", 1.0, n)
        disc = kinematic.Discretisation(grid, influence_operator(grid, POISSON), ContactEffects())
        error = operator_errors(grid, disc, POISSON, 0)[0]
        x, y = grid.centres()
        interior = np.abs(error[np.hypot(x, y) < INTERIOR]).max()
        first = cells_from_edge(grid, 0)
        rows = np.abs(y[first]) < ROWS_NEAR_AXIS
        per_cell = np.array([error[cells_from_edge(grid, k)[rows]] for k in range(8)])
        print(f"{n:4d} | {interior:.2e} | " + " ".join(f"{v:+.1e}" for v in per_cell[:6].mean(axis=1))
              + f" | {per_cell.sum(axis=0).mean() * grid.hx:+.2e}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--grids", type=int, nargs="+", default=[16, 32, 64, 128, 256])
    operator_study(parser.parse_args().grids)


if __name__ == "__main__":
    main()
