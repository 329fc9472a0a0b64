"""The reduced operating point and the step shared by both stands: evaluate, propagate, budget.

A stand's chain is a function ``evaluate(values, mu_start) -> Evaluation`` of the flat input
values (names as in the InputSet); :func:`reduce_point` evaluates it at the readings, propagates
the uncertainties (restarting the mu <-> alpha' iteration from the nominal mu, so that the
perturbed evaluations converge in a few steps) and splits the variances into a budget.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from rig.reduction.budget import UncertaintyBudget, budget
from rig.reduction.uncertainty import InputSet, Propagation, first_order


@dataclass(frozen=True)
class Evaluation:
    """One pass of a chain: output values (NaN where undefined), reasons for the NaNs, mu used in alpha'."""

    values: dict[str, float]
    reasons: dict[str, str]
    mu: float
    iterations: int


@dataclass(frozen=True)
class ReducedPoint:
    """A reduced operating point.

    values/uncertainties: output name -> value / standard uncertainty (units in the names, e.g.
    ``l_m``; names without a unit are dimensionless); reasons: output name -> why it is NaN;
    iterations of the mu <-> alpha' loop; propagation and budget of the first-order model.
    """

    values: Mapping[str, float]
    uncertainties: Mapping[str, float]
    reasons: Mapping[str, str]
    iterations: int
    propagation: Propagation
    budget: UncertaintyBudget

    def row(self) -> dict[str, float | str]:
        """Flat row: each output followed by ``u_<output>``, and a ``reason`` column."""
        row: dict[str, float | str] = {}
        for name, value in self.values.items():
            row[name] = value
            row[f"u_{name}"] = self.uncertainties[name]
        grouped: dict[str, list[str]] = {}
        for name, reason in self.reasons.items():
            grouped.setdefault(reason, []).append(name)
        row["reason"] = "; ".join(f"{', '.join(names)}: {reason}" for reason, names in grouped.items())
        return row


Evaluate = Callable[[Mapping[str, float], float], Evaluation]


def reduce_point(evaluate: Evaluate, inputs: InputSet, mu_start: float, relative_step: float) -> ReducedPoint:
    """Evaluate a chain at its inputs, propagate to first order, and build the budget."""
    nominal = evaluate(inputs.mapping(inputs.values), mu_start)
    restart = nominal.mu if math.isfinite(nominal.mu) else mu_start
    names = tuple(nominal.values)
    propagation = first_order(lambda x: evaluate(x, restart).values, inputs, names, relative_step)
    u = propagation.uncertainties
    uncertainties = {
        name: float(u[i]) if math.isfinite(nominal.values[name]) else math.nan for i, name in enumerate(names)
    }
    propagation = Propagation(
        inputs, names, np.array([nominal.values[n] for n in names]), propagation.jacobian, propagation.covariance
    )
    return ReducedPoint(
        values=dict(nominal.values),
        uncertainties=uncertainties,
        reasons=dict(nominal.reasons),
        iterations=nominal.iterations,
        propagation=propagation,
        budget=budget(propagation),
    )
