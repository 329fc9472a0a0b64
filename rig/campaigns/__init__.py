"""The paper's campaigns: figures laid out like [Koziarski]'s, with the checks each states.

A stand scene names one in ``[outputs] paper_figure``; after the reduction the runner calls the
registered function ``draw(reduced, log_path, out_dir, title) -> CampaignOutcome``: ``reduced``
is the reduced table (reduced.csv, with true_* columns when the log has truth), ``log_path`` the
run's log (settings, readings and - for drawing the simulation's truth beside the reduced points
- rig.logbook.truth), ``out_dir`` the run's folder. The outcome lists the files written and the
lines for summary.txt (each check stated with numbers).
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass

from rig import validate

PAPER_FIGURES = {
    "fig10": "rig.campaigns.yoke_figures:fig10",  # stand A, c = 0: F_y, mu_T, mu_v, T2 vs l/a, b/a = 1 and 2
    "fig11": "rig.campaigns.yoke_figures:fig11",  # stand A, Delta h = 1.06 mm: c/a = 0.4 - l/(87.7 a)
    "fig14": "rig.campaigns.disc_roller_figures:fig14",  # stand B, c = 0: F_T, F_V, T_Mo vs l, four loads
    "fig15": "rig.campaigns.disc_roller_figures:fig15",  # stand B, c/a = -2
}


@dataclass(frozen=True)
class CampaignOutcome:
    """Files a campaign figure wrote (names in the run folder) and its summary lines."""

    files: tuple[str, ...]
    summary: tuple[str, ...]


def paper_figure(name: str):
    """The drawing function registered under ``name`` (UnknownNameError with a suggestion)."""
    validate.choice("outputs.paper_figure", name, PAPER_FIGURES)
    module, _, attribute = PAPER_FIGURES[name].partition(":")
    return getattr(importlib.import_module(module), attribute)
