"""Figures without a display: a bare matplotlib Figure on the Agg canvas.

No pyplot and no backend switching, so drawing keeps no global state and works in worker
processes and on machines without a screen. matplotlib is imported when a figure is made.
"""

from __future__ import annotations


def new_figure(**kwargs):
    """A matplotlib Figure (keyword arguments as for Figure, e.g. figsize in inches) ready to save."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    figure = Figure(**kwargs)
    FigureCanvasAgg(figure)
    return figure


def colors() -> list[str]:
    """The default colour cycle."""
    import matplotlib

    return matplotlib.rcParams["axes.prop_cycle"].by_key()["color"]
