"""Uncertainty budget of one operating point: what each input adds to each output's variance.

With the first-order model V_y = J V_x J^T, the variance of output k splits exactly into
    J_ki^2 u_i^2                      (input i alone)
    2 J_ki J_kj cov(x_i, x_j)         (each correlated pair, e.g. calibration sensitivity/offset)
and these terms sum to u(y_k)^2. The budget lists them per input and, summed, per source
(instrument), so a reader sees which instrument limits which result.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pandas as pd

from rig.reduction.uncertainty import Propagation


@dataclass(frozen=True)
class UncertaintyBudget:
    """Variance contributions (rows: inputs and covariance pairs; columns: outputs) [output unit^2]."""

    variance: pd.DataFrame
    sources: dict[str, str]  # row name -> source (instrument)

    def total(self) -> pd.Series:
        """u^2 of each output (sum of the rows)."""
        return self.variance.sum(axis=0, min_count=1)

    def shares(self) -> pd.DataFrame:
        """Each row's fraction of the output variance [1] (columns sum to 1)."""
        return self.variance / self.total()

    def by_source(self) -> pd.DataFrame:
        """Variance contributions summed per source (instrument) [output unit^2]."""
        groups = [self.sources[row] for row in self.variance.index]
        return self.variance.groupby(groups, sort=False).sum(min_count=1)

    def uncertainty_by_source(self) -> pd.DataFrame:
        """sqrt of each source's variance share: the u it alone would cause [output unit]."""
        by = self.by_source()
        return np.sign(by) * np.sqrt(by.abs())


def budget(propagation: Propagation) -> UncertaintyBudget:
    """Split each output variance of a first-order propagation into its terms (exact sum)."""
    inputs = propagation.inputs
    jac = propagation.jacobian
    u = inputs.uncertainties
    rows, sources, terms = [], {}, []
    for i, q in enumerate(inputs.quantities):
        if u[i] == 0.0:
            continue
        rows.append(q.name)
        sources[q.name] = q.source
        terms.append(jac[:, i] ** 2 * u[i] ** 2)
    index = {name: i for i, name in enumerate(inputs.names)}
    source_of = {q.name: q.source for q in inputs.quantities}
    for cov in inputs.covariances:
        i, j = index[cov.first], index[cov.second]
        row = f"cov({cov.first}, {cov.second})"
        rows.append(row)
        same = source_of[cov.first] == source_of[cov.second]
        sources[row] = source_of[cov.first] if same else row
        terms.append(2.0 * jac[:, i] * jac[:, j] * cov.value)
    table = pd.DataFrame(np.array(terms).reshape(len(rows), -1), index=rows, columns=list(propagation.output_names))
    return UncertaintyBudget(table, sources)
