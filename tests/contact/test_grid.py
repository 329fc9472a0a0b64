"""The contact grid (rig.contact.grid): the cells carry the whole Hertz load, symmetrically."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.contact.grid import load_factor, make_grid, rows_across

B_OVER_A = st.floats(0.1, 10.0)
N = st.integers(8, 64)
SHIFT = st.floats(-0.5, 0.5)


@settings(max_examples=30, deadline=None)
@given(shape=st.sampled_from(["ellipse", "line"]), b=B_OVER_A, n=N, shift=SHIFT)
def test_the_cells_carry_the_whole_load(shape, b, n, shift):
    """sum p dA = F_N/(a p0) of the exact field (2 pi b/3, pi b). The centre rule alone dropped the
    load of the rim's cut cells whose centre lies outside, 0.1-0.6 % of F_N, of either sign with n
    (b/a = 1: 0.21 / 0.59 / 0.15 / 0.19 / 0.08 % at n = 16 / 24 / 32 / 48 / 64); measured now <= 1e-4."""
    grid = make_grid(shape, b, n, shift)
    load = grid.p.sum() * grid.cell_area
    assert abs(load / (load_factor(shape) * b) - 1.0) < 2e-4


@settings(max_examples=20, deadline=None)
@given(b=B_OVER_A, n=N)
def test_the_loads_are_as_symmetric_as_the_contact(b, n):
    """Mirror images in y (negative spin is solved as one, rig.contact.physical) need mirrored loads:
    nearest-centre ties at the rim go half to each side, corners on the rim count as outside."""
    grid = make_grid("ellipse", b, n)
    np.testing.assert_allclose(grid.p, grid.p[:, ::-1], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(grid.active, grid.active[:, ::-1])


def test_narrow_contacts_get_more_rows_up_to_twice_n():
    """rows_across: n for 0.15 <= b/a <= 20/3, n 0.15/(b/a) below, at most 2n; columns are unaffected."""
    assert [rows_across(32, b) for b in (6.0, 1.0, 0.15, 0.12, 0.1, 0.075, 0.01)] == [32, 32, 32, 40, 48, 64, 64]
    grid = make_grid("ellipse", 0.1, 32)
    assert (grid.n, grid.nx, grid.ny) == (32, 32, 48)
    assert np.isclose(grid.hy, 2.0 / 48) and np.isclose(grid.y[-1], -grid.y[0])


def test_wide_contacts_get_more_rows_and_cells_at_most_two_and_a_half_times_as_long_as_high():
    """rows_across: n (b/a)/(20/3) above b/a = 20/3, at most 1.5 n; cells_along_rolling: 2n from b/a = 2
    until a cell would be longer than 2.5 times its height ((2b/nx)/(2a/ny) <= 2.5)."""
    assert [rows_across(32, b) for b in (5.0, 8.0, 10.0, 20.0)] == [32, 38, 48, 48]
    for b in (2.0, 3.0, 5.0, 8.0, 10.0):
        grid = make_grid("ellipse", b, 32)
        assert grid.hx / grid.hy <= 2.5 + 1e-9, (b, grid.nx, grid.ny)
    assert (make_grid("ellipse", 3.0, 32).nx, make_grid("ellipse", 10.0, 32).nx) == (64, 192)
