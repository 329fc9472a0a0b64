"""The Pareto plot: error versus cost, one panel per axis, the front drawn, the scene's choice marked.

The front is drawn on the table's cost_s: on the contact and table axes of a scene with surrogate
tables the first run (which builds the setting's tables), with a hollow circle, joined by a dotted
line, at the per-run median beside it; on the drive axis the per-run median, with the first run
hollow. Points carry the row number of the report's table (its '#' column), placed clear of the
labels already drawn, and a setting that cannot give a reduced quantity is drawn as a cross at the
top of the panel ("unavailable"). An axis is logarithmic when its values span more than a decade, else linear.
An error of exactly 0 (the reference itself, or a setting whose reduced outputs equal the
reference's to the last count) is drawn with a downward triangle; on a logarithmic error axis it
sits at a floor, half the smallest non-zero error of the panel, and the legend says so.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pandas as pd

from rig.accuracy.design import Axis, StudyDesign

COST_LABEL = {"gate": "lab (operator) time per run [s]",
              "build": "CPU time [s]: table build + first run (filled), per run (hollow)",
              "run": "CPU time per run [s]: median of the timed runs (filled), first run (hollow)"}
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


def label_offsets(points: np.ndarray, size: tuple[float, float] = (14.0, 9.0)) -> list[tuple[float, float]]:
    """Offsets [display points] for the labels of ``points`` (N, 2) [display points], each the first of
    eight positions round its point whose box (``size``) overlaps no box placed before and no other
    point; the least overlapping one when all do (a greedy placement)."""
    candidates = [(4, 3), (4, -11), (-18, 3), (-18, -11), (4, 12), (-6, 12), (-6, -20), (14, -4)]
    placed: list[tuple[float, float, float, float]] = []
    offsets = []
    w, h = size
    for i, (x, y) in enumerate(points):
        best, best_overlap = candidates[0], math.inf
        for dx, dy in candidates:
            box = (x + dx, y + dy, x + dx + w, y + dy + h)
            overlap = sum(max(0.0, min(box[2], b[2]) - max(box[0], b[0])) * max(0.0, min(box[3], b[3]) - max(box[1], b[1]))
                          for b in placed)
            overlap += sum(w * h for j, (px, py) in enumerate(points)
                           if j != i and box[0] <= px <= box[2] and box[1] <= py <= box[3])
            if overlap < best_overlap:
                best, best_overlap = (dx, dy), overlap
                if overlap == 0.0:
                    break
        placed.append((x + best[0], y + best[1], x + best[0] + w, y + best[1] + h))
        offsets.append(best)
    return offsets


def _panel(ax, rows: pd.DataFrame, kind: str, title: str) -> None:
    gate = kind == "gate"
    cost = rows["cost_s"].to_numpy(dtype=float)
    error = rows["error"].to_numpy(dtype=float)
    unavailable = rows["unavailable"].fillna("").astype(str).str.len().to_numpy() > 0
    log_error = _spans_decades(error)
    zero = np.isfinite(error) & (error <= 0)
    shown = np.where(zero, _floor(error), error) if log_error else error
    finite = shown[np.isfinite(shown)]
    top = (finite.max() * (1.6 if log_error else 1.15)) if finite.size else 1.0
    shown = np.where(unavailable, top, shown)
    front = rows["on_front"].to_numpy(dtype=bool)
    plain = ~zero & ~unavailable
    ax.scatter(cost[plain], shown[plain], color="0.5", label="setting", zorder=2)
    if zero.any():
        ax.scatter(cost[zero], shown[zero], marker="v", color="0.5", zorder=2,
                   label="error 0" + (" (drawn at a floor)" if log_error else ""))
    if unavailable.any():
        ax.scatter(cost[unavailable], shown[unavailable], marker="x", color="tab:orange", zorder=2,
                   label="unavailable: cannot give a reduced quantity (not on the front)")
    if not gate:  # the other cost: per run beside the build, or the first run beside the per-run median
        other = rows["cpu_median_s" if kind == "build" else "cpu_first_s"].to_numpy(dtype=float)
        ax.scatter(other, shown, facecolors="none", edgecolors="0.6",
                   label="per run (median)" if kind == "build" else "first run (table build/load)", zorder=1)
        for x0, x1, y in zip(cost, other, shown):
            ax.plot([x0, x1], [y, y], ":", color="0.75", linewidth=0.8, zorder=0)
        cost_range = np.concatenate([cost, other])
    else:
        cost_range = cost
    order = np.argsort(cost[front])
    ax.plot(cost[front][order], shown[front][order], "-o", color="tab:blue", label="Pareto front", zorder=3)
    own = rows["scene_choice"].to_numpy(dtype=bool)
    ax.scatter(cost[own], shown[own], marker="*", s=260, color="tab:red", zorder=4,
               label="scene's choice (" + ("on" if front[own].all() else "not on") + " the front)")
    _scale(ax.xaxis, ax.set_xscale, _spans_decades(cost_range))
    _scale(ax.yaxis, ax.set_yscale, log_error)
    if unavailable.any() and not log_error:
        ax.set_ylim(top=top * 1.1)
    ax.set_xlabel(COST_LABEL[kind])
    ax.set_ylabel(ERROR_LABEL[gate])
    ax.set_title(title, fontsize=9)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=6, loc="best")
    # numbers, not names, at the points (the report's '#' column), placed clear of each other
    drawn = np.isfinite(cost) & np.isfinite(shown)
    numbers = np.flatnonzero(drawn)
    if numbers.size:
        ax.figure.canvas.draw()  # the transform needs the final limits
        points = ax.transData.transform(np.column_stack([cost[drawn], shown[drawn]])) * 72.0 / ax.figure.dpi
        for k, (dx, dy) in zip(numbers, label_offsets(points)):
            ax.annotate(str(k + 1), (cost[k], shown[k]), fontsize=6, xytext=(dx, dy), textcoords="offset points")
    key = "; ".join(f"{k + 1} {label}" for k, label in enumerate(rows["setting"]))
    ax.text(0.0, -0.16, "\n".join(textwrap.wrap(key, 95)), transform=ax.transAxes, fontsize=6, va="top")


def pareto_figure(design: StudyDesign, table: pd.DataFrame, path: Path, title: str) -> Path:
    """Write the figure (PNG) to ``path`` and return it (matplotlib, Agg backend, imported here)."""
    from rig.plotting import new_figure

    count = len(design.axes)
    columns = 2 if count > 1 else 1
    rows_n = (count + columns - 1) // columns
    fig = new_figure(figsize=(6.5 * columns, 6.0 * rows_n))
    axes = fig.subplots(rows_n, columns, squeeze=False)
    for ax, plan in zip(axes.flat, design.axes):
        rows = table[table["axis"] == plan.axis.value]
        kind = "gate" if plan.axis is Axis.GATE else "run"
        if plan.axis in (Axis.CONTACT, Axis.TABLE) and any(e.setting.contact.surrogate for e in plan.entries):
            kind = "build"
        _panel(ax, rows, kind, plan.axis.value)
    for ax in list(axes.flat)[count:]:
        ax.set_visible(False)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    return path
