"""The leading edge of the kinematic model's grid: where the material enters each row.

Lengths in a, traction in mu p0, displacement in mu p0 a/G (rig.contact.models.kinematic).
A row's first active cell (centre x_e) is cut by the leading edge x_L, x_e - h < x_L <= x_e. Near
the edge the traction vanishes like sqrt(x - x_L) and the free surface's slip outside grows like
sqrt(x_L - x) (both bounded by mu p ~ sqrt(distance)). The grid's uniform cells do not see where
x_L lies inside that cell: treated like any other cell, the discrete contact starts at the first
cell's upstream face x_e - h/2 instead of x_L, the stick zone of every row starts at the wrong
place, and nu moves at first order with the sub-cell position of the edge (pure spin, line
contact, grid shifted by half a cell: nu_v changes by 0.015 / 0.008 / 0.004 at n = 16 / 32 / 64).
Two parts of the discrete equations take the edge's place into account [R, our construction;
docs/contact-model.md, "The leading edge"]:

* transport (:func:`transport_weights`): the first cell's slip is the mean slip of the material
  inside, the straddling step's outside part removed with the sqrt model (weights on U at the cell
  and two cells upstream); the second cell takes the plain difference over its own step, whose
  two ends are inside (its second-order stencil would reach the sqrt-singular U outside);
* traction (:class:`EntryProfile`): the first cell's force, t_e hx hy, is spread over the part of
  its row inside the contact, [x_L, x_e + h/2], with density ~ sqrt(x - x_L), not uniformly over
  the cell. The displacement of that profile is the FFT product with part of the force moved to
  the next cell upstream or downstream so that the centroid is right (moment matching), plus a
  local correction (profile minus that pair, a quadrupole) at the cells within ``WINDOW`` cell
  lengths hx of the first cell.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import scipy.sparse as sparse

from rig.contact import cellwise
from rig.contact.grid import Grid, leading_edge
from rig.contact.influence import cell_kernels

BACKWARD_2 = (1.5, -2.0, 0.5)  # dU/dx at a cell from it and two cells upstream, times h
PROFILE_STRIPS = 32  # uniform strips that sample the sqrt profile of a first cell
# reach of the local correction in cell lengths hx (the profile's size): beyond it the moment-matched pair
# stands in for the profile (window 2 -> 5 moves nu by < 2e-5 at n = 32)
WINDOW = 2


def entering(grid: Grid) -> np.ndarray:
    """(N,) True for the first active cell of each row (its upstream neighbour is outside)."""
    return ~grid.active.ravel()[grid.index - grid.ny]


def transport_weights(grid: Grid) -> tuple[np.ndarray, np.ndarray]:
    """Weights (3, N) [1/a] of U at each active cell and at the cells one and two steps upstream,
    and the x [a] at which the rigid slip is taken.

    Interior cells: s_c = s_g(x_c) + (3 U_c - 4 U_c-1 + U_c-2)/(2 h). First cell of a row: the
    mean slip S1 over the step [x_c-1, x_c] straddles the edge; its outside part is r S0, S0 the
    mean slip over the step before (wholly outside), r = d^1.5/((d + h)^1.5 - d^1.5),
    d = x_L - x_c-1, so s_c = (S1 - r S0)/(1 - r). Second cell: s_c = s_g(x_c - h/2) + (U_c - U_c-1)/h.
    """
    x, y = grid.centres()
    h = grid.hx
    first = entering(grid)
    second = ~first & ~grid.active.ravel()[grid.index - 2 * grid.ny]
    weights = np.empty((3, x.size))
    weights[:] = np.array(BACKWARD_2)[:, None] / h
    x_slip = x.copy()
    xe = x[first]
    d = np.clip(leading_edge(grid.shape, grid.b_over_a, y[first]) - (xe - h), 0.0, h)
    r = d**1.5 / ((d + h) ** 1.5 - d**1.5)  # outside share of the straddling step's slip over S0
    inside = (1.0 - r) * h
    weights[:, first] = np.stack([1.0 / inside, -(1.0 + r) / inside, r / inside])
    x_slip[first] = ((xe - 0.5 * h) - r * (xe - 1.5 * h)) / (1.0 - r)
    weights[:, second] = np.array([1.0, -1.0, 0.0])[:, None] / h
    x_slip[second] -= 0.5 * h
    return weights, x_slip


@dataclass(frozen=True, eq=False)
class EntryProfile:
    """The first cells' traction spread with the sqrt profile (module docstring).

    cells: (E,) indices of the first cells among the active cells; full, neighbour: (E,) flat
    indices (grid rectangle) of each first cell and of the cell next to it in its row that takes
    the moment-matching share ``share`` (E,) [1] of its force; neighbour_active: (E,) whether that
    cell is in the contact; local: sparse (2N, 2N) [1/a]: the elastic slip of the local correction
    per unit traction of each first cell (the transport applied to its displacement), acting on
    t.ravel() of tractions t (2, N).
    """

    cells: np.ndarray
    full: np.ndarray
    neighbour: np.ndarray
    neighbour_active: np.ndarray
    share: np.ndarray
    local: sparse.csr_matrix

    def spread(self, field: np.ndarray, t: np.ndarray) -> None:
        """Move each first cell's moment-matching share of t (2, N) [mu p0] to its neighbour in the
        traction field (2, nx, ny) on the grid rectangle (in place) that has t at the active cells;
        a neighbour outside the contact gets the share alone (whatever the field held there)."""
        cellwise.spread_entry(field.reshape(2, -1), t, self.cells, self.full, self.neighbour,
                              self.neighbour_active, self.share)

    def clear(self, field: np.ndarray) -> None:
        """Zero the shares :meth:`spread` put outside the contact (for fields reused between products)."""
        field.reshape(2, -1)[:, self.neighbour[~self.neighbour_active]] = 0.0

    def slip(self, t: np.ndarray) -> np.ndarray:
        """(2, N) [mu p0 v/G]: the local correction's elastic slip for tractions t (2, N)."""
        return (self.local @ t.ravel()).reshape(t.shape)


@lru_cache(maxsize=64)
def entry_profile(grid: Grid, poisson: float) -> EntryProfile:
    """The :class:`EntryProfile` of a grid for Poisson's ratio ``poisson`` (cached, as the grids are)."""
    hx, hy = grid.hx, grid.hy
    x, y = grid.centres()
    cells = np.flatnonzero(entering(grid))
    x_l = leading_edge(grid.shape, grid.b_over_a, y[cells])
    nxg, ny = grid.full_shape
    rows_reached = int(np.ceil(WINDOW * hx / hy))  # the correction is a quadrupole of the profile's size, ~hx
    di, dj = (a.ravel() for a in np.meshgrid(np.arange(-WINDOW, WINDOW + 1), np.arange(-rows_reached, rows_reached + 1),
                                             indexing="ij"))
    column, row = np.divmod(grid.index[cells], ny)
    # strips of the profile's support [x_L, x_e + h/2] relative to the cell centre, their force shares
    lo = (x_l - x[cells])[:, None]
    edges = lo + (0.5 * hx - lo) * np.linspace(0.0, 1.0, PROFILE_STRIPS + 1)[None, :]
    weight = np.diff((edges - lo) ** 1.5, axis=1)
    weight /= weight.sum(axis=1, keepdims=True)
    centroid = lo[:, 0] + 0.6 * (0.5 * hx - lo[:, 0])  # of sqrt(x - x_L) over [x_L, x_e + h/2]
    side = np.where(centroid < 0.0, -1, 1)
    share = np.abs(centroid) / hx
    ti, tj = column[:, None] + di[None, :], row[:, None] + dj[None, :]
    ok = (ti >= 0) & (ti < nxg) & (tj >= 0) & (tj < ny)
    X = np.where(ok, grid.x[np.clip(ti, 0, nxg - 1)] - x[cells][:, None], 0.0)
    Y = dj[None, :] * hy
    profile = np.zeros((3,) + X.shape)
    for k in range(PROFILE_STRIPS):
        width = (edges[:, k + 1] - edges[:, k])[:, None]
        centre = 0.5 * (edges[:, k + 1] + edges[:, k])[:, None]
        traction = weight[:, k, None] * hx / width  # of the strip, per unit traction of the cell
        profile += traction * np.stack(cell_kernels(X - centre, Y, width, hy, poisson))
    own = np.stack(cell_kernels(X, Y, hx, hy, poisson))
    next_to = np.stack(cell_kernels(X - side[:, None] * hx, Y, hx, hy, poisson))
    local = profile - (1.0 - share[:, None]) * own - share[:, None] * next_to
    # displacement correction on the rectangle (full cells, N), then its transport into the slip
    rows = (ti * ny + tj)[ok]
    columns = np.broadcast_to(cells[:, None], ok.shape)[ok]
    shape = (grid.p.size, grid.index.size)
    weights, _ = transport_weights(grid)
    index = grid.index
    transport = sparse.csr_matrix(
        (weights.ravel(), (np.tile(np.arange(index.size), 3), np.concatenate([index - k * ny for k in range(3)]))),
        shape=(index.size, grid.p.size),
    )
    xx, xy, yy = ((transport @ sparse.csr_matrix((part[ok], (rows, columns)), shape=shape)) for part in local)
    slips = sparse.bmat([[xx, xy], [xy, yy]], format="csr")
    full = index[cells]
    neighbour = full + side * ny
    return EntryProfile(cells, full, neighbour, grid.active.ravel()[neighbour], share, slips)
