"""Overlay figure: simulated curves over the digitised points, with a residual panel below.

One column per dataset; top: simulated curve per model (lines; the legend gives a fitted x shift)
and the digitised points as digitised (markers; points skipped, outside the simulated range,
hollow); bottom: simulated - digitised [y units] per model, drawn at the digitised x.
Built on a bare :class:`matplotlib.figure.Figure` with the Agg canvas (no pyplot, no display,
no global state).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from rig.compare.comparison import DatasetComparison
from rig.compare.sidecar import AxisScale, Sidecar

OVERLAY_PNG = "compare_overlay.png"
PANEL_SIZE_IN = (4.2, 4.6)  # width, height of one dataset column [inch]


def overlay_figure(sidecar: Sidecar, items: Sequence[DatasetComparison]) -> Figure:
    """The overlay figure (not saved); datasets in sidecar order, models in RESULT order."""
    names = list(dict.fromkeys(item.spec.name for item in items))
    figure = Figure(figsize=(PANEL_SIZE_IN[0] * len(names), PANEL_SIZE_IN[1]), layout="constrained")
    FigureCanvasAgg(figure)
    axes = figure.subplots(2, len(names), squeeze=False, sharex="col", height_ratios=(3, 1))
    figure.suptitle(sidecar.figure, fontsize="medium")
    for column, name in enumerate(names):
        top, bottom = axes[0, column], axes[1, column]
        group = [item for item in items if item.spec.name == name]
        spec = group[0].spec
        for k, item in enumerate(group):
            colour = f"C{k}"
            comparison = item.comparison
            shift = comparison.metrics.x_shift
            label = (item.model or "simulation") + (f" (x shift {shift:+.3g})" if shift else "")
            top.plot(item.simulated.x, item.simulated.y, "-", color=colour, label=label)
            bottom.plot(comparison.x_ref[comparison.compared], comparison.deviation[comparison.compared], "o-",
                        color=colour, ms=3, lw=0.8)  # fmt: skip
        first = group[0].comparison
        used = np.any([item.comparison.compared for item in group], axis=0)  # compared for some model
        top.plot(first.x_ref[used], first.y_ref[used], "o", color="k", ms=4, label="digitised")
        if (~used).any():
            top.plot(first.x_ref[~used], first.y_ref[~used], "o", mfc="none", color="0.5", ms=4, label="skipped")
        bottom.axhline(0.0, color="0.6", lw=0.8)
        for ax in (top, bottom):
            if sidecar.x.scale is AxisScale.LOG:
                ax.set_xscale("log")
            ax.grid(True, lw=0.3)
        if spec.y.scale is AxisScale.LOG:
            top.set_yscale("log")
        top.set_title(name, fontsize="medium")
        top.set_ylabel(spec.y.label)
        top.legend(fontsize="small")
        bottom.set_ylabel("sim - digitised" + ("" if spec.y.units == "1" else f" [{spec.y.units}]"))
        bottom.set_xlabel(sidecar.x.label)
    return figure


def save_overlay(directory: str | Path, sidecar: Sidecar, items: Sequence[DatasetComparison]) -> Path:
    """Draw the overlay and save it as compare_overlay.png in ``directory``; return the path."""
    path = Path(directory) / OVERLAY_PNG
    path.parent.mkdir(parents=True, exist_ok=True)
    overlay_figure(sidecar, items).savefig(path, dpi=120)
    return path
