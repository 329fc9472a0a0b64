"""Reduced points off their truth: z = |reduced - true| / u, the run's threshold and the flags.

Agreement is stated in units of the stated standard uncertainty: z = |reduced - true| / u per
point, for every quantity whose table has the value, ``u_<name>`` and ``true_<name>``; NaN where
not comparable (a NaN value, truth or u, or u <= 0).

In a twin run (the log has a truth group) a point whose largest z exceeds the run's threshold is
flagged - a wrong root of eqs. (33)-(35) of [Koziarski] or a budget that misses an error cannot
pass silently. The threshold is z = 3, raised for many comparisons so that a run whose every u
is right is flagged by chance in at most OFF_TRUTH_FAMILY of runs (Bonferroni over the m
comparisons of the run, normal z: Phi^-1(1 - OFF_TRUTH_FAMILY/(2 m)); 3.9 for m = 100).
:func:`with_z_max` adds the column ``z_max`` (the point's largest z [1]; a point's own, so a
chunk of points gets it where it is reduced) and :func:`with_off_truth` ``off_truth`` (1 flagged,
0 not, NaN not comparable; the threshold depends on the whole run); ``rig run`` exits with
OFF_TRUTH_STATUS when a point is flagged (docs/scenes.md, "Exit status and errors").
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from scipy.special import ndtri

QUANTITIES = ("l_over_a", "c_over_a", "mu_v", "mu_T")
OFF_TRUTH_Z = 3.0  # the smallest threshold of |reduced - true|/u that flags a point [1]
OFF_TRUTH_FAMILY = 0.01  # chance that a run with right u's is flagged at all [1]
OFF_TRUTH_STATUS = 4  # rig run's exit status when a reduced point is off its truth


def z_table(table: pd.DataFrame) -> pd.DataFrame:
    """z = |reduced - true|/u per point (rows) and quantity (columns) [1]; NaN where not comparable
    (NaN value, truth or u, or u <= 0)."""
    out = {}
    for name in QUANTITIES:
        if not {name, f"u_{name}", f"true_{name}"} <= set(table.columns):
            continue
        value, u, true = (table[c].to_numpy(dtype=float) for c in (name, f"u_{name}", f"true_{name}"))
        with np.errstate(invalid="ignore", divide="ignore"):
            z = np.abs(value - true) / u
        out[name] = np.where(np.isfinite(z) & (u > 0), z, np.nan)
    return pd.DataFrame(out, index=table.index)


def off_truth_threshold(comparisons: int) -> float:
    """The z that flags a point [1] for a run with ``comparisons`` finite z (module docstring)."""
    if comparisons <= 0:
        return OFF_TRUTH_Z
    # Phi^-1(1 - q) = -ndtri(q), what scipy.stats.norm.isf(q) computes, without importing scipy.stats
    # (about 0.7 s of CPU: a third of the parent's fixed cost in a run on workers)
    return max(OFF_TRUTH_Z, float(-ndtri(OFF_TRUTH_FAMILY / (2.0 * comparisons))))


def with_z_max(table: pd.DataFrame) -> pd.DataFrame:
    """``table`` with ``z_max``, each point's largest z [1], as its last column when it has truth
    columns (unchanged otherwise). A row's z_max depends on that row only."""
    zs = z_table(table)
    return table if zs.empty else _with_z_max(table, zs)  # empty: no truth columns, or no rows


def _with_z_max(table: pd.DataFrame, zs: pd.DataFrame) -> pd.DataFrame:
    """A copy of ``table`` with the z_max of ``zs`` (z_table(table)) as its last column."""
    table = table.drop(columns="z_max") if "z_max" in table else table.copy()
    table["z_max"] = zs.max(axis=1, skipna=True).to_numpy(dtype=float)
    if isinstance(table.attrs.get("units"), dict):
        table.attrs["units"] = table.attrs["units"] | {"z_max": "1"}
    return table


def with_off_truth(table: pd.DataFrame) -> pd.DataFrame:
    """``table`` with ``z_max`` (with_z_max) and then ``off_truth`` as its last two columns when it
    has truth columns (unchanged otherwise); the run's threshold goes to ``table.attrs["off_truth_z"]``."""
    zs = z_table(table)
    if zs.empty:  # no truth columns, or no rows
        return table
    threshold = off_truth_threshold(int(np.isfinite(zs.to_numpy()).sum()))
    table = _with_z_max(table.drop(columns="off_truth") if "off_truth" in table else table, zs)
    z_max = table["z_max"].to_numpy()
    table["off_truth"] = np.where(np.isfinite(z_max), (z_max > threshold).astype(float), np.nan)
    table.attrs["off_truth_z"] = threshold
    if isinstance(table.attrs.get("units"), dict):
        table.attrs["units"] = table.attrs["units"] | {"off_truth": "1"}
    return table


def off_truth_points(table: pd.DataFrame | None) -> tuple[int, ...]:
    """Indices of the points flagged off their truth (``off_truth`` = 1)."""
    if table is None or "off_truth" not in table:
        return ()
    return tuple(int(i) for i in table.index[(table["off_truth"] == 1.0).to_numpy()])


def off_truth_lines(table: pd.DataFrame) -> list[str]:
    """The summary's warning on the flagged points (first: it must be read first), [] when none."""
    flagged = off_truth_points(table)
    if not flagged:
        return []
    zs = z_table(table)
    threshold = table.attrs.get("off_truth_z", OFF_TRUTH_Z)
    lines = [f"WARNING: {len(flagged)} reduced point(s) off their truth by more than z = {threshold:.2f} "
             "(|reduced - true|/u; the stated u does not cover the error: a wrong root, or an error the budget "
             "misses) - reduced.csv's off_truth column marks them:"]
    for index in flagged[:20]:
        row = zs.loc[index]
        worst = row.idxmax()
        value, u, true = (table.loc[index, prefix + worst] for prefix in ("", "u_", "true_"))
        lines.append(f"  point {index}: {worst} = {value:.4g} +- {u:.2g} against the truth {true:.4g} "
                     f"(z = {row[worst]:.1f})")
    if len(flagged) > 20:
        lines.append(f"  ... and {len(flagged) - 20} more")
    return lines
