"""The generic figure of a stand run: reduced quantities with error bars next to the truth.

One panel per reduced quantity (l/a, c/a, mu_v, mu_T - those the table has); x is the innermost
swept setting, labelled with its name and unit (setting_label; the point index when nothing is
swept); one series per combination of the outer swept settings and of the settings that tell
the procedure's series apart. Points: reduced value +- its standard uncertainty u_<name> (error
bars; a shaded band for a series of more than MAX_ERROR_BARS points, whose bars would merge into
one another); line: true_<name>.
The paper-like campaign figures are drawn elsewhere.
"""

from __future__ import annotations

import contextlib
import math
import threading
from collections.abc import Sequence
from pathlib import Path

import numpy as np
import pandas as pd

from rig.logbook.atomic import naming
from rig.logbook.units import safe_unit
from rig.scenes.procedure import PlannedPoint, Procedure

SETTING_NAMES = {
    "brake_setpoint": r"brake set-point $T_{set}$", "normal_force": "normal force $F_N$",
    "delta_h": r"yoke shift $\Delta h$", "omega_1_set": r"speed set-point $\omega_1$",
    "l": "rolling-point offset $l$", "sigma": r"twist $\sigma$", "speed_step": "drive speed step",
}
"""Axis names of the settings the built-in stands sweep (others: the key's words)."""
SETTING_UNITS = ("N m", "rad/s", "m/s", "N", "m", "rad", "s", "Hz", "K", "V")
"""Units a setting key may end with (scene keys are ``<name>_<safe unit>``, e.g. ``brake_setpoint_N_m``)."""
QUANTITIES = {"l_over_a": "$l/a$", "c_over_a": "$c/a$", "mu_v": r"$\mu_v$", "mu_T": r"$\mu_T$"}
MAX_ERROR_BARS = 200
"""Most points of a series drawn with error bars; a longer series gets a band of +- u (one polygon,
not thousands of bars: the figure of a 10^5-point study costs no more than that of a short one)."""


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
    return series, setting_label(x_name)


def setting_label(key: str) -> str:
    """Axis label of a setting key with its name and unit: ``brake_setpoint_N_m`` ->
    ``brake set-point $T_{set}$ [N m]``; a key without a unit suffix is dimensionless ([1])."""
    name, unit = key, "1"
    for candidate in SETTING_UNITS:
        suffix = "_" + safe_unit(candidate)
        if key.endswith(suffix) and len(key) > len(suffix):
            name, unit = key[:-len(suffix)], candidate
            break
    return f"{SETTING_NAMES.get(name, name.replace('_', ' '))} [{unit}]"


def import_in_background() -> threading.Thread:
    """Start importing the figure's library (matplotlib's Figure and Agg canvas, about 0.35 s of CPU)
    in a daemon thread and return it: a study's parent that waits for its workers' chunks imports it
    meanwhile, so the figure drawn at the end does not wait for the import (an import under way is
    finished, not repeated, when the figure needs it; an import that fails fails again there)."""
    thread = threading.Thread(target=_import_figure_library, name="rig-figure-import", daemon=True)
    thread.start()
    return thread


def _import_figure_library() -> None:
    with contextlib.suppress(Exception):  # the figure's own import reports it
        import matplotlib.backends.backend_agg  # noqa: F401
        import matplotlib.figure  # noqa: F401


def reduced_vs_truth_figure(table: pd.DataFrame, plan: Sequence[PlannedPoint], procedure: Procedure, path: Path,
                            title: str) -> Path | None:
    """Draw the figure into ``path`` (PNG); None when the table has none of the quantities."""
    fig = draw_reduced_vs_truth(table, plan, procedure, title)
    if fig is None:
        return None
    with naming(path):  # a full disk: the error names the figure (the image library removes it)
        fig.savefig(path, dpi=110)
    return path


def draw_reduced_vs_truth(table: pd.DataFrame, plan: Sequence[PlannedPoint], procedure: Procedure, title: str):
    """The figure as a matplotlib Figure (not saved, no pyplot); None when the table has none of the quantities."""
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
            if x.size <= MAX_ERROR_BARS:
                ax.errorbar(x, y, yerr=None if u is None else np.nan_to_num(u), fmt="o", ms=4, capsize=3, color=color,
                            label=f"reduced {label}".strip())
            else:
                ax.plot(x, y, ".", ms=2, color=color, label=f"reduced {label} (band: +- u)".strip())
                if u is not None:
                    ax.fill_between(x, y - np.nan_to_num(u), y + np.nan_to_num(u), color=color, alpha=0.25, lw=0)
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
    return fig
