"""The contact solver's per-cell loops, compiled with numba: its inner loops outside the FFTs.

One Krylov product of the kinematic solver (rig.contact.models.kinematic) is two FFT convolutions
and, between them, work that is local to each cell: the preconditioner's upwind solve of the local
law along the rolling direction (a recurrence from the leading edge on, which no array operation
expresses), the moves of the cell list into and out of the FFT grids, the symbol products in
Fourier space and the linearised Coulomb law with its transport. In numpy these were about forty
small array operations and a banded LAPACK solve per product, more time than the FFTs themselves at
the default grid; here each is one loop over the cells (docs/contact-model.md, "Solver cost").

Conventions: cells are the contact's active cells in the grid's flattened C order of [i, j]
(i along the rolling direction x, so every cell comes after the cells upstream of it); (ix, iy)
are a cell's indices on the grid rectangle; fields on a grid are (2, nx, ny) arrays of (x, y)
components; a symmetric 2x2 matrix per cell is stored as its three entries (xx, xy, yy), shape (3, N).
Units are those of the caller (dimensionless; rig.contact.models.kinematic).
"""

from __future__ import annotations

import numba

_compiled = numba.njit(cache=True, nogil=True)


@_compiled
def upwind_solve(v, diagonal_inverse, coupling, upstream, weights, share, ix, iy, w, field):
    """Solve the local law L w = v cell by cell downstream, and place w on the grid ``field``.

    L w at cell c = D_c w_c + E_c sum_k weights[k, c] w_upstream[k, c] (D_c, E_c symmetric 2x2):
    v (2, N) right-hand side; diagonal_inverse (3, N) D_c^-1; coupling (3, N) E_c; upstream (K, N)
    cell-list index of the k-th upstream neighbour or -1 (outside the contact: w = 0 there);
    weights (K, N); w (2, N) the solution (written); field (2, nx, ny): share_c w_c written at
    the cells only (share (3, N) symmetric).
    """
    for c in range(v.shape[1]):
        a0 = 0.0
        a1 = 0.0
        for k in range(upstream.shape[0]):
            u = upstream[k, c]
            if u >= 0:
                a0 += weights[k, c] * w[0, u]
                a1 += weights[k, c] * w[1, u]
        r0 = v[0, c] - (coupling[0, c] * a0 + coupling[1, c] * a1)
        r1 = v[1, c] - (coupling[1, c] * a0 + coupling[2, c] * a1)
        w0 = diagonal_inverse[0, c] * r0 + diagonal_inverse[1, c] * r1
        w1 = diagonal_inverse[1, c] * r0 + diagonal_inverse[2, c] * r1
        w[0, c] = w0
        w[1, c] = w1
        field[0, ix[c], iy[c]] = share[0, c] * w0 + share[1, c] * w1
        field[1, ix[c], iy[c]] = share[1, c] * w0 + share[2, c] * w1


@_compiled
def place(t, ix, iy, field):
    """Write the cells' values t (2, N) into the grid ``field`` (2, nx, ny); other entries untouched."""
    for c in range(t.shape[1]):
        field[0, ix[c], iy[c]] = t[0, c]
        field[1, ix[c], iy[c]] = t[1, c]


@_compiled
def blend(source, ix, iy, share, w, scale, t):
    """t_c = share_c source_c + (I - share_c) w_c scale: source (2, >= nx, >= ny) on the grid,
    share (3, N) symmetric, w and t (2, N)."""
    for c in range(t.shape[1]):
        g0 = source[0, ix[c], iy[c]]
        g1 = source[1, ix[c], iy[c]]
        t[0, c] = share[0, c] * g0 + share[1, c] * g1 + ((1.0 - share[0, c]) * w[0, c] - share[1, c] * w[1, c]) * scale
        t[1, c] = share[1, c] * g0 + share[2, c] * g1 + (-share[1, c] * w[0, c] + (1.0 - share[2, c]) * w[1, c]) * scale


@_compiled
def _transported_at(u, i, j, transport, c):
    """(x, y) of sum_k transport[k, c] u[:, i - k, j]: the displacement carried into cell c's slip."""
    s0 = 0.0
    s1 = 0.0
    for k in range(transport.shape[0]):
        s0 += transport[k, c] * u[0, i - k, j]
        s1 += transport[k, c] * u[1, i - k, j]
    return s0, s1


@_compiled
def transported(u, ix, iy, transport, out):
    """out_c = sum_k transport[k, c] u[:, ix - k, iy]: the displacement carried into each cell's slip
    (u (2, >= nx, >= ny) on the grid, transport (K, N), out (2, N))."""
    for c in range(out.shape[1]):
        out[0, c], out[1, c] = _transported_at(u, ix[c], iy[c], transport, c)


@_compiled
def symbol_product(symbol, spectrum, out):
    """out = S f per frequency: symbol (3, ...) the symmetric 2x2 symbol (xx, xy, yy), spectrum and
    out (2, ...) complex."""
    for i in range(spectrum.shape[1]):
        for j in range(spectrum.shape[2]):
            f0 = spectrum[0, i, j]
            f1 = spectrum[1, i, j]
            out[0, i, j] = symbol[0, i, j] * f0 + symbol[1, i, j] * f1
            out[1, i, j] = symbol[1, i, j] * f0 + symbol[2, i, j] * f1


@_compiled
def linearised_law(u, ix, iy, transport, t, local, slip_gain, out):
    """out_c = A_c t_c + B_c s_c with the elastic slip s_c = sum_k transport[k, c] u[:, ix - k, iy].

    u (2, >= nx, >= ny) displacement on the grid; transport (K, N) weights of the displacement at
    the cell (k = 0) and k cells upstream; t (2, N); local (3, N) A_c; slip_gain (3, N) B_c; out (2, N).
    """
    for c in range(t.shape[1]):
        s0, s1 = _transported_at(u, ix[c], iy[c], transport, c)
        out[0, c] = local[0, c] * t[0, c] + local[1, c] * t[1, c] + slip_gain[0, c] * s0 + slip_gain[1, c] * s1
        out[1, c] = local[1, c] * t[0, c] + local[2, c] * t[1, c] + slip_gain[1, c] * s0 + slip_gain[2, c] * s1


@_compiled
def spread_entry(field, t, cells, full, neighbour, neighbour_active, share):
    """Move share[e] of the traction t (2, N) of each first cell cells[e] from its place full[e] in the
    flat grid field (2, nx ny) to neighbour[e] (added there, or set where the neighbour is outside
    the contact); rig.contact.entry.EntryProfile.spread."""
    for e in range(cells.size):
        for m in range(2):
            moved = share[e] * t[m, cells[e]]
            field[m, full[e]] -= moved
            if neighbour_active[e]:
                field[m, neighbour[e]] += moved
            else:
                field[m, neighbour[e]] = moved


@_compiled
def add_local_slip(indptr, indices, data, t, slip_gain, out):
    """out_c += B_c (C t)_c: C a sparse (2N, 2N) CSR matrix (indptr, indices, data) on t.ravel() of
    t (2, N), B_c the symmetric (3, N) slip_gain; out (2, N)."""
    n = t.shape[1]
    flat = t.ravel()
    for c in range(n):
        c0 = 0.0
        for k in range(indptr[c], indptr[c + 1]):
            c0 += data[k] * flat[indices[k]]
        c1 = 0.0
        for k in range(indptr[n + c], indptr[n + c + 1]):
            c1 += data[k] * flat[indices[k]]
        out[0, c] += slip_gain[0, c] * c0 + slip_gain[1, c] * c1
        out[1, c] += slip_gain[1, c] * c0 + slip_gain[2, c] * c1
