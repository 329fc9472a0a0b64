"""The reduced table: one row per operating point, each quantity followed by its uncertainty.

Column order starts with the columns the issue asks for (``l_over_a, u_l_over_a, c_over_a,
u_c_over_a, mu_v, u_mu_v, mu_T, u_mu_T``), then the other outputs of the chain (units in the
names) with their ``u_``, then ``U95_<name>`` for every output (value +- U95 is the reported
95 % interval, rig.reduction.coverage), a ``reason`` column for NaNs, and, when the log has a
truth group, ``true_<name>``.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import pandas as pd

from rig.errors import ParameterError
from rig.reduction.result import ReducedPoint

LEADING = ("l_over_a", "c_over_a", "mu_v", "mu_T")
PREFIXES = ("u_", "U95_")  # standard uncertainty, half width of the 95 % interval (same unit as the output)
TRUTH_COLUMNS = ("l_over_a", "c_over_a", "mu_v", "mu_T")


def reduced_table(
    points: Sequence[ReducedPoint], truth: Sequence[Mapping[str, float]] | None = None
) -> pd.DataFrame:
    """DataFrame of reduced points; truth (one mapping per point, e.g. from the log's truth group)
    adds ``true_l_over_a, true_c_over_a, true_mu_v, true_mu_T`` for the keys it has."""
    rows = [point.row() for point in points]
    frame = pd.DataFrame(rows)
    lead = [col for name in LEADING for col in (name, f"u_{name}")]
    rest = [col for col in frame.columns if col not in lead and col != "reason"]
    frame = frame[lead + rest + ["reason"]] if rows else pd.DataFrame(columns=lead + ["reason"])
    if truth is not None:
        if len(truth) != len(points):
            raise ParameterError("truth", f"{len(truth)} rows", f"one row per point ({len(points)})")
        for name in TRUTH_COLUMNS:
            if any(name in t for t in truth):
                frame[f"true_{name}"] = [t.get(name, float("nan")) for t in truth]
    frame.index.name = "point"
    return frame


def column_output(column: str) -> str:
    """The output a column belongs to: ``u_<name>`` and ``U95_<name>`` -> ``<name>`` (same unit)."""
    for prefix in PREFIXES:
        if column.startswith(prefix):
            return column[len(prefix):]
    return column


DAMAGED = "damaged point"
"""Start of the ``reason`` of a point the log could not give (rig.logbook.read_points)."""


def with_damaged(frame: pd.DataFrame, indices: Sequence[int], damaged: Mapping[int, str]) -> pd.DataFrame:
    """``frame`` (rows: the reduced points) with a row for every point of ``indices``: a damaged
    point (``damaged[index]``: what is wrong, naming the dataset and the bad value) gets NaN in
    every column and ``reason`` = ``"damaged point: <what>"``. Index name ``point``."""
    frame = frame.reindex(pd.Index(list(indices), name="point"))
    if damaged:
        rows = list(damaged)
        frame.loc[rows, "reason"] = [f"{DAMAGED}: {damaged[i]}" for i in rows]
    return frame
