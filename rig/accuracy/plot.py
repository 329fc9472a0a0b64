"""The Pareto plot: error versus cost, one panel per axis, the front drawn, the scene's choice marked.

On the CPU-time panels a hollow circle, joined by a dotted line, marks the first run of each
setting (it builds or loads the surrogate tables); the front is drawn on the median of the timed
runs. An axis is logarithmic when its values span more than a decade, else linear.
An error of exactly 0 (the reference itself, or a setting whose reduced outputs equal the
reference's to the last count) is drawn with a downward triangle; on a logarithmic error axis it
sits at a floor, half the smallest non-zero error of the panel, and the legend says so.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from rig.accuracy.design import Axis, StudyDesign

COST_LABEL = {True: "lab (operator) time per run [s]",
              False: "CPU time per run [s]: median of the timed runs (filled), first run (hollow)"}
ERROR_LABEL = {True: "stated uncertainty, max of median u(l/a), u(mu_T) [1]",
               False: "error vs reference, max RMS d(l/a, mu_v, mu_T) [1]"}


def _floor(errors: np.ndarray) -> float:
    positive = errors[np.isfinite(errors) & (errors > 0)]
    return 0.5 * positive.min() if positive.size else 1e-4


def _spans_decades(values: np.ndarray) -> bool:
    finite = values[np.isfinite(values) & (values > 0)]
    return bool(finite.size) and finite.max() > 10.0 * finite.min()


def _scale(axis, set_scale, logarithmic: bool) -> None:
    from matplotlib.ticker import NullFormatter, ScalarFormatter

    if logarithmic:
        set_scale("log")
        axis.set_minor_formatter(NullFormatter())
        axis.set_major_formatter(ScalarFormatter())


def _panel(ax, rows: pd.DataFrame, gate: bool, title: str) -> None:
    cost = rows["cost_s"].to_numpy(dtype=float)
    error = rows["error"].to_numpy(dtype=float)
    log_error = _spans_decades(error)
    zero = np.isfinite(error) & (error <= 0)
    shown = np.where(zero, _floor(error), error) if log_error else error
    front = rows["on_front"].to_numpy(dtype=bool)
    ax.scatter(cost[~zero], shown[~zero], color="0.5", label="setting", zorder=2)
    if zero.any():
        ax.scatter(cost[zero], shown[zero], marker="v", color="0.5", zorder=2,
                   label="error 0" + (" (drawn at a floor)" if log_error else ""))
    if not gate:  # the cold cost: first run, which builds or loads the tables (not on the front)
        first = rows["cpu_first_s"].to_numpy(dtype=float)
        ax.scatter(first, shown, facecolors="none", edgecolors="0.6", label="first run (table build/load)",
                   zorder=1)
        for x0, x1, y in zip(cost, first, shown):
            ax.plot([x0, x1], [y, y], ":", color="0.75", linewidth=0.8, zorder=0)
        cost_range = np.concatenate([cost, first])
    else:
        cost_range = cost
    order = np.argsort(cost[front])
    ax.plot(cost[front][order], shown[front][order], "-o", color="tab:blue", label="Pareto front", zorder=3)
    own = rows["scene_choice"].to_numpy(dtype=bool)
    ax.scatter(cost[own], shown[own], marker="*", s=260, color="tab:red", zorder=4,
               label="scene's choice (" + ("on" if front[own].all() else "not on") + " the front)")
    for x, y, text in zip(cost, shown, rows["setting"]):
        if np.isfinite(x) and np.isfinite(y):
            ax.annotate(text, (x, y), fontsize=6, xytext=(3, 3), textcoords="offset points")
    _scale(ax.xaxis, ax.set_xscale, _spans_decades(cost_range))
    _scale(ax.yaxis, ax.set_yscale, log_error)
    ax.set_xlabel(COST_LABEL[gate])
    ax.set_ylabel(ERROR_LABEL[gate])
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, loc="best")


def pareto_figure(design: StudyDesign, table: pd.DataFrame, path: Path, title: str) -> Path:
    """Write the figure (PNG) to ``path`` and return it (matplotlib, Agg backend, imported here)."""
    from rig.plotting import new_figure

    count = len(design.axes)
    columns = 2 if count > 1 else 1
    rows_n = (count + columns - 1) // columns
    fig = new_figure(figsize=(6.0 * columns, 4.6 * rows_n))
    axes = fig.subplots(rows_n, columns, squeeze=False)
    for ax, plan in zip(axes.flat, design.axes):
        _panel(ax, table[table["axis"] == plan.axis.value], plan.axis is Axis.GATE, plan.axis.value)
    for ax in list(axes.flat)[count:]:
        ax.set_visible(False)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    return path
