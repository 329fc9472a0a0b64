"""Contact characteristics nu_T, nu_v, nu_0 versus alpha' (the kind of seed 000 Figs. 3-7).

``sweep`` evaluates every requested model over a log-spaced alpha' range for each contact
(shape, b/a) and rolling point; ``plot`` draws them with the models overlaid. Dimensionless
throughout (alpha' of eq. 21; nu of eqs. 26-28).
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.contact.solve import solve

COLUMNS = ["model", "shape", "b_over_a", "c_over_a", "l_over_a", "poisson", "n", "alpha",
           "nu_T", "nu_v", "nu_0", "nu_Mo", "stick_fraction"]


@dataclass(frozen=True)
class Case:
    """One contact and rolling point: shape, b/a, c/a, l/a (dimensionless)."""

    shape: str
    b_over_a: float
    c_over_a: float
    l_over_a: float

    @property
    def label(self) -> str:
        return f"{self.shape} b/a={self.b_over_a:g}, C=({self.c_over_a:g}, {self.l_over_a:g})a"


def sweep(
    cases: Iterable[Case],
    models: Sequence[str],
    alphas: Sequence[float],
    *,
    poisson: float,
    n: int,
    effects: dict[str, float] | None = None,
    progress=None,
) -> pd.DataFrame:
    """One row per (case, model, alpha'): the columns of COLUMNS. ``progress(k, total)`` is called per row."""
    effects = effects or {}
    cases = list(cases)
    rows = []
    total = len(cases) * len(models) * len(alphas)
    for case in cases:
        for model in models:
            for alpha in alphas:
                kwargs = effects if model == "kinematic" else {}
                r = solve(model, shape=case.shape, b_over_a=case.b_over_a, alpha=float(alpha),
                          c_over_a=case.c_over_a, l_over_a=case.l_over_a, poisson=poisson, n=n, **kwargs)
                rows.append([model, case.shape, case.b_over_a, case.c_over_a, case.l_over_a, poisson, n,
                             float(alpha), r.nu_T, r.nu_v, r.nu_0, r.nu_Mo, r.stick_fraction])
                if progress is not None:
                    progress(len(rows), total)
    return pd.DataFrame(rows, columns=COLUMNS)


def plot(table: pd.DataFrame, path: Path, title: str) -> Path:
    """Grid of panels: one row per case, columns nu_T, nu_v, nu_0 versus alpha' (log axis)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    keys = ["shape", "b_over_a", "c_over_a", "l_over_a"]
    groups = list(table.groupby(keys, sort=False))
    fig, axes = plt.subplots(len(groups), 3, figsize=(12, 2.8 * len(groups)), squeeze=False, sharex=True)
    styles = {"rigid": ":", "linear": "--", "fastsim": "-.", "kinematic": "-"}
    for row, (key, group) in zip(axes, groups):
        case = Case(*key)
        for model, data in group.groupby("model", sort=False):
            for ax, name in zip(row, ("nu_T", "nu_v", "nu_0")):
                values = data[name].to_numpy()
                if model == "linear":  # linear theory is unbounded; show it where it is meaningful
                    values = np.where(np.abs(values) <= 1.5, values, np.nan)
                ax.plot(data["alpha"], values, styles.get(model, "-"), label=model)
        for ax, name in zip(row, ("nu_T", "nu_v", "nu_0")):
            ax.set_xscale("log")
            ax.set_ylabel({"nu_T": r"$\nu_T$", "nu_v": r"$\nu_v$", "nu_0": r"$\nu_0$"}[name])
            ax.grid(True, which="both", alpha=0.3)
        row[0].set_title(case.label, fontsize=9, loc="left")
    for ax in axes[-1]:
        ax.set_xlabel(r"$\alpha'$ (eq. 21)")
    axes[0][0].legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
