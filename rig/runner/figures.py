"""The generic figure of a stand run: reduced quantities with error bars next to the truth.

One panel per reduced quantity (l/a, c/a, mu_v, mu_T - those the table has); x is the innermost
swept setting (the point index when nothing is swept); one series per combination of the outer
swept settings and of the settings that tell the procedure's series apart. Points: reduced value +- its standard uncertainty u_<name>; line: true_<name>.
The paper-like campaign figures are drawn elsewhere.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from rig.scenes.procedure import PlannedPoint, Procedure

QUANTITIES = {"l_over_a": "$l/a$", "c_over_a": "$c/a$", "mu_v": r"$\mu_v$", "mu_T": r"$\mu_T$"}


def _series(table: pd.DataFrame, plan: Sequence[PlannedPoint], procedure: Procedure):
    """(label, x values, row positions) per series; x label."""
    by_index = {p.index: p for p in plan}
    if not procedure.sweep:
        return [("", table.index.to_numpy(dtype=float), np.arange(len(table)))], "point index"
    x_name = procedure.sweep[-1][0]
    outer = [name for name, _ in procedure.sweep[:-1]] + procedure.series_settings
    groups: dict[tuple, list[int]] = {}
    for row, index in enumerate(table.index):
        settings = by_index[int(index)].settings
        groups.setdefault(tuple(settings[n] for n in outer), []).append(row)
    series = []
    for key, rows in groups.items():
        label = ", ".join(f"{n} = {v:g}" for n, v in zip(outer, key))
        x = np.array([by_index[int(table.index[r])].settings[x_name] for r in rows])
        order = np.argsort(x, kind="stable")
        series.append((label, x[order], np.asarray(rows)[order]))
    return series, x_name


def reduced_vs_truth_figure(table: pd.DataFrame, plan: Sequence[PlannedPoint], procedure: Procedure, path: Path,
                            title: str) -> Path | None:
    """Draw the figure into ``path`` (PNG); None when the table has none of the quantities."""
    names = [n for n in QUANTITIES if n in table.columns]
    if not names or table.empty:
        return None
    from rig.plotting import colors, new_figure

    series, x_label = _series(table, plan, procedure)
    columns = min(2, len(names))
    rows = math.ceil(len(names) / columns)
    fig = new_figure(figsize=(5.5 * columns, 3.6 * rows))
    axes = fig.subplots(rows, columns, squeeze=False)
    colors = colors()
    for ax, name in zip(axes.flat, names):
        for k, (label, x, positions) in enumerate(series):
            color = colors[k % len(colors)]
            y = table[name].to_numpy(dtype=float)[positions]
            u = table[f"u_{name}"].to_numpy(dtype=float)[positions] if f"u_{name}" in table else None
            ax.errorbar(x, y, yerr=None if u is None else np.nan_to_num(u), fmt="o", ms=4, capsize=3, color=color,
                        label=f"reduced {label}".strip())
            if f"true_{name}" in table:
                ax.plot(x, table[f"true_{name}"].to_numpy(dtype=float)[positions], "-", color=color, alpha=0.7,
                        label=f"truth {label}".strip())
        ax.set_xlabel(x_label)
        ax.set_ylabel(QUANTITIES[name])
        ax.grid(True, alpha=0.3)
    for ax in list(axes.flat)[len(names):]:
        ax.set_visible(False)
    axes.flat[0].legend(fontsize=7)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    return path
