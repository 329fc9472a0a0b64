"""The paper's element-by-element marching ("no iterative steps") diverges under grid refinement.

[Koziarski] (after eq. 14) advertises computing each element from the forces already known
upstream. Implemented here for full stick - the simplest case, where the answer is Kalker's C11 -
it produces mesh-dependent garbage (Equations §1.9 step 6, hard case 5), while the coupled
solve converges to Kalker's value. This is why rig.contact offers only the coupled solver.
"""

import numpy as np
import pytest

from rig.contact.effects import ContactEffects
from rig.contact.grid import make_grid
from rig.contact.influence import cell_kernels
from rig.contact.kinematics import Creepage
from rig.contact.models.kinematic import solve_full_stick


def apparent_c11_by_marching(n: int, poisson: float = 0.0) -> float:
    """Full stick under unit longitudinal creepage, marched column by column from the leading edge.

    Each element's stick condition s = s_g + (U_c - U_up)/h = 0 is solved for its own traction
    with the displacements of the elements already computed (upstream), as the paper describes.
    """
    grid = make_grid("ellipse", 1.0, n)
    xx, yy = np.meshgrid(grid.x, grid.y, indexing="ij")
    cells = np.flatnonzero(grid.active.ravel())
    x, y = xx.ravel(), yy.ravel()
    kxx = cell_kernels(x[:, None] - x[cells][None, :], y[:, None] - y[cells][None, :], grid.hx, grid.hy, poisson)[0]
    k_self = kxx[cells[0], 0]
    column = cells // grid.ny
    q = np.zeros(cells.size)
    for i in np.unique(column):
        here = np.flatnonzero(column == i)
        known = column < i
        u_here = kxx[cells[here]][:, known] @ q[known]
        u_up = kxx[cells[here] - grid.ny][:, known] @ q[known]
        q[here] = -(grid.hx * 1.0 + u_here - u_up) / k_self
    return -q.sum() * grid.cell_area


def coupled_c11(n: int) -> float:
    grid = make_grid("ellipse", 1.0, n)
    return -solve_full_stick(grid, 0.0, Creepage(1.0, 0.0, 0.0), ContactEffects())[0].sum() * grid.cell_area


def test_explicit_marching_diverges_while_the_coupled_solve_converges():
    marching = [apparent_c11_by_marching(n) for n in (8, 16, 32)]
    coupled = [coupled_c11(n) for n in (8, 16, 32)]
    growth = np.array(marching[1:]) / np.array(marching[:-1])
    assert np.all(growth > 3.0), f"marching gave C11 = {marching} for n = 8, 16, 32 (Kalker: 3.40)"
    assert coupled[-1] == pytest.approx(3.40, rel=0.01), f"coupled solve gave C11 = {coupled}"
    assert abs(coupled[-1] - 3.40) < abs(coupled[0] - 3.40)
