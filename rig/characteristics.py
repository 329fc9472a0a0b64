"""Contact characteristics nu_T, nu_v, nu_0 versus alpha' (the kind of [Koziarski] Figs. 3-7).

``sweep`` evaluates every requested model over a log-spaced alpha' range for each contact
(shape, b/a) and rolling point; ``plot`` draws them with the models overlaid. Dimensionless
throughout (alpha' of eq. 21; nu of eqs. 26-28).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pandas as pd

from rig.contact.solve import solve

MIN_SPAN = 0.1  # smallest y range of a panel [1]
COLUMNS = ["model", "variant", "shape", "b_over_a", "c_over_a", "l_over_a", "poisson", "n", "alpha",
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
    variants: Mapping[str, Mapping[str, float]] | None = None,
    progress=None,
) -> pd.DataFrame:
    """One row per (case, model or variant, alpha'): the columns of COLUMNS.

    ``effects`` apply to the kinematic model in ``models``; ``variants`` {label: effects} add
    kinematic-model runs with other effects ([Koziarski] Figs. 4-7 switch Psi, mu0/mu and surface
    inertia on one at a time); ``progress(k, total)`` is called per row.
    """
    runs = [(model, "", dict(effects or {}) if model == "kinematic" else {}) for model in models]
    runs += [("kinematic", label, dict(extra)) for label, extra in (variants or {}).items()]
    cases = list(cases)
    rows = []
    total = len(cases) * len(runs) * len(alphas)
    for case in cases:
        for model, label, kwargs in runs:
            for alpha in alphas:
                r = solve(model, shape=case.shape, b_over_a=case.b_over_a, alpha=float(alpha),
                          c_over_a=case.c_over_a, l_over_a=case.l_over_a, poisson=poisson, n=n, **kwargs)
                rows.append([model, label, case.shape, case.b_over_a, case.c_over_a, case.l_over_a, poisson, n,
                             float(alpha), r.nu_T, r.nu_v, r.nu_0, r.nu_Mo, r.stick_fraction])
                if progress is not None:
                    progress(len(rows), total)
    return pd.DataFrame(rows, columns=COLUMNS)


def plot(table: pd.DataFrame, path: Path, title: str) -> Path:
    """Grid of panels: one row per case, columns nu_T, nu_v, nu_0 versus alpha' (log axis)."""
    from rig.plotting import new_figure

    keys = ["shape", "b_over_a", "c_over_a", "l_over_a"]
    groups = list(table.groupby(keys, sort=False))
    fig = new_figure(figsize=(12, 2.8 * len(groups)))
    axes = fig.subplots(len(groups), 3, squeeze=False, sharex=True)
    styles = {"rigid": ":", "linear": "--", "fastsim": "-.", "kinematic": "-"}
    for row, (key, group) in zip(axes, groups):
        case = Case(*key)
        for (model, variant), data in group.groupby(["model", "variant"], sort=False):
            label = f"kinematic, {variant}" if variant else model
            for ax, name in zip(row, ("nu_T", "nu_v", "nu_0")):
                values = data[name].to_numpy()
                if model == "linear":  # linear theory is unbounded; show it where it is meaningful
                    values = np.where(np.abs(values) <= 1.5, values, np.nan)
                ax.plot(data["alpha"], values, styles["kinematic"] if variant else styles.get(model, "-"),
                        label=label, linewidth=1.0 if variant else 1.4)
        for ax, name in zip(row, ("nu_T", "nu_v", "nu_0")):
            low, high = ax.get_ylim()
            if high - low < MIN_SPAN:  # rounding noise of a zero coefficient: do not magnify it
                middle = 0.5 * (low + high)
                ax.set_ylim(middle - MIN_SPAN / 2, middle + MIN_SPAN / 2)
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
    return path
