"""The Pareto front of (cost, error): the settings no other setting beats on both at once."""

from __future__ import annotations

import numpy as np

from rig.errors import ParameterError


def pareto_front(costs, errors) -> np.ndarray:
    """Boolean mask: True where no other point has cost <= and error <= with one of them strictly less.

    costs, errors: equal-length sequences (any unit; both minimised). A point with a NaN cost or
    error is not on the front and beats nothing. Equal points are both on the front.
    """
    c = np.asarray(costs, dtype=float)
    e = np.asarray(errors, dtype=float)
    if c.shape != e.shape or c.ndim != 1:
        raise ParameterError("costs, errors", (c.shape, e.shape), "two 1-d sequences of equal length")
    valid = np.isfinite(c) & np.isfinite(e)
    front = valid.copy()
    for i in np.flatnonzero(valid):
        others = valid & (c <= c[i]) & (e <= e[i]) & ((c < c[i]) | (e < e[i]))
        front[i] = not others.any()
    return front
