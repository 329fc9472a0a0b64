"""The kinematic model's elastic slip of a known traction against Johnson's closed form.

A Hertz-shaped tangential traction q0 sqrt(1 - r^2) on the circle has a displacement that is a
quadratic inside the contact (rig.contact.hertz.hertz_traction_slip). Through the model's whole slip
operator (FFT influence product, the leading edge's entry profile, the transport weights; [Koziarski],
eqs. 6, 8, 10) its slip converges at order 2.5 or more in the interior, and at order ~0.5 in each row's
first cell, where the traction grows like sqrt(x - x_L) (docs/contact-convergence.md, "Sixth study").
"""

import numpy as np
import pytest

from rig.contact.effects import ContactEffects
from rig.contact.entry import entering
from rig.contact.grid import make_grid
from rig.contact.hertz import hertz_traction_slip
from rig.contact.influence import influence_operator
from rig.contact.models import kinematic

POISSON = 0.28


def slip_error(n, direction):
    """The model's elastic slip (2, N) [q0/G] minus the closed form, for the traction along ``direction``,
    and the cells' centres (x, y) [a]."""
    grid = make_grid("ellipse", 1.0, n)
    disc = kinematic.Discretisation(grid, influence_operator(grid, POISSON), ContactEffects())
    traction = np.zeros((2, grid.index.size))
    traction[direction] = grid.gather(grid.p)
    x, y = grid.centres()
    error = disc.law.apply(traction)[1] - hertz_traction_slip(disc.x_slip, y, POISSON, direction)
    return error, x, y, entering(grid)


@pytest.mark.parametrize("direction", [0, 1])
def test_the_slip_of_a_hertz_shaped_traction_converges_fast_inside_the_contact(direction):
    """r < a/2, both slip components: max error 2.3e-4 / 4.1e-5 / 6.7e-6 at n = 32 / 64 / 128 for a
    traction along x (2.8e-4 / 4.9e-5 / 8.0e-6 along y), against a slip of 0.6 q0/G at r = a/2."""
    worst = []
    for n in (32, 64, 128):
        error, x, y, _ = slip_error(n, direction)
        worst.append(np.abs(error[:, np.hypot(x, y) < 0.5]).max())
    assert worst[0] < 4e-4, worst
    assert np.all(np.log2(np.array(worst[:-1]) / worst[1:]) > 2.3), worst


@pytest.mark.parametrize("direction", [0, 1])
def test_the_first_cell_of_a_row_carries_an_error_of_order_one_half(direction):
    """Rows |y| < 0.7 a, the slip along the traction in their first cell: mean error +7.9e-3 / +5.3e-3 /
    +3.6e-3 at n = 32 / 64 / 128 along x (+7.5e-3 / +4.8e-3 / +3.4e-3 along y): order 0.55-0.6, the
    sqrt(x - x_L) edge's. Taken with an adjoint that grows like 1/sqrt(x - x_L) towards the edge, this is
    the O(h) part of nu_v (docs/contact-convergence.md, "Sixth study")."""
    means = []
    for n in (32, 128):
        error, _, y, first = slip_error(n, direction)
        means.append(error[direction, first & (np.abs(y) < 0.7)].mean())
    order = np.log2(means[0] / means[1]) / 2.0
    assert means[1] > 2e-3 and 0.4 < order < 0.75, (means, order)
