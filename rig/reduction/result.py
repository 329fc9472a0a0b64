"""The reduced operating point and the step shared by both stands: evaluate, propagate, guard, budget.

A stand's chain is a function ``evaluate(values, start) -> Evaluation`` of the flat input values
(names as in the InputSet). :func:`reduce_point`
1. evaluates it at the readings with ``Start(mu_start, drivers)``: the chain picks, once, the
   first friction estimate in ``drivers`` that gives a fixed point (which mu drives alpha');
2. propagates the uncertainties (rig.reduction.uncertainty.first_order) with every perturbed
   evaluation restarted from the nominal mu *and kept on the nominal driver* - a perturbation
   must not switch the chain to another estimate (hard case 8);
3. applies the significance guard: a ratio mu = numerator/denominator whose denominator (nu_v,
   nu_T, nu_0, D) lies within ``significance`` of its own standard uncertainty of zero is not
   reported (its first-order uncertainty would be meaningless); if it drove alpha', everything
   computed from that mu goes with it;
4. splits the variances into a budget and computes the 95 % half widths U95 (rig.reduction.coverage).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from rig.errors import ParameterError
from rig.reduction.budget import UncertaintyBudget, budget
from rig.reduction.coefficients import with_model_error
from rig.reduction.coverage import expanded_uncertainty
from rig.reduction.drivers import Numerator, significant_drivers
from rig.reduction.iteration import ReductionSettings, solve_with_drivers
from rig.reduction.uncertainty import InputSet, Propagation, first_order


@dataclass(frozen=True)
class Start:
    """Where a chain evaluation starts: mu [1] for the mu <-> alpha' iteration, the friction
    estimates allowed to drive alpha' in order of preference (the first that works is used),
    whether to probe the identifiability at the fixed point (nominal evaluation only), why
    no estimate may drive alpha' when ``drivers`` is empty, and the slope d ln g/d ln mu there
    [1] when known (the nominal fixed point's, for a perturbed evaluation; NaN: not known)."""

    mu: float
    drivers: tuple[str, ...]
    probe: bool = True
    no_driver: str = ""
    slope: float = math.nan


@dataclass(frozen=True)
class Evaluation:
    """One pass of a chain: output values (NaN where undefined), reasons for the NaNs, the mu used
    in alpha' [1], iterations, the estimate that drove alpha' ("" if none) and the slope d ln g/d ln
    mu probed at the fixed point [1] (NaN when not probed)."""

    values: dict[str, float]
    reasons: dict[str, str]
    mu: float
    iterations: int
    driver: str = ""
    slope: float = math.nan


def evaluate_fixed_point(state_at: Callable[[float], tuple[dict, dict]], start: Start, settings: ReductionSettings,
                         out: dict[str, float], driven: tuple[str, ...]) -> Evaluation:
    """The mu <-> alpha' fixed point of a chain (rig.reduction.iteration.solve_with_drivers).

    state_at(mu) -> (driven values, reasons for their NaNs) at alpha'(mu); ``out`` holds the
    chain's values that do not depend on mu and receives the driven ones at the fixed point.
    """
    def make_estimate(driver: str):
        def estimate(mu: float):
            state, reasons = state_at(mu)
            value = state[driver]
            if math.isfinite(value) and value > 0.0:
                return value, (state, reasons), ""
            return math.nan, (state, reasons), reasons.get(driver) or f"{driver} = {value:.6g} is not positive"
        return estimate

    fixed, driver = solve_with_drivers(make_estimate, start.drivers, start.mu, start.probe, settings, start.no_driver,
                                       start.slope)
    if fixed.reason:
        return Evaluation(out, dict.fromkeys(driven, fixed.reason), math.nan, fixed.iterations)
    state, reasons = fixed.state
    out.update(state)
    return Evaluation(out, dict(reasons), fixed.mu, fixed.iterations, driver, fixed.slope)


@dataclass(frozen=True)
class ReducedPoint:
    """A reduced operating point.

    values/uncertainties/expanded: output name -> value / standard uncertainty / half width U95
    of the 95 % interval (units in the names, e.g. ``l_m``; names without a unit are
    dimensionless); reasons: output name -> why it is NaN; iterations of the mu <-> alpha' loop;
    driver: the friction estimate that fed alpha'; propagation: the first-order model, whose
    ``budget`` is split on first use (a reduced table does not need it: rig.reduction.table);
    note: what the reader of a finite value must know (stand B: which root of a non-unique mu was
    chosen and why, rig.reduction.stand_b), a ``note`` column of the row; None: no such column.
    """

    values: Mapping[str, float]
    uncertainties: Mapping[str, float]
    expanded: Mapping[str, float]
    reasons: Mapping[str, str]
    iterations: int
    driver: str
    propagation: Propagation
    note: str | None = None

    @functools.cached_property
    def budget(self) -> UncertaintyBudget:
        """The first-order variance split per input and per source (rig.reduction.budget)."""
        return budget(self.propagation)

    def row(self) -> dict[str, float | str]:
        """Flat row: each output followed by ``u_<output>``, then ``U95_<output>`` for every
        output, and a ``reason`` column."""
        row: dict[str, float | str] = {}
        for name, value in self.values.items():
            row[name] = value
            row[f"u_{name}"] = self.uncertainties[name]
        for name in self.values:
            row[f"U95_{name}"] = self.expanded[name]
        grouped: dict[str, list[str]] = {}
        for name, reason in self.reasons.items():
            grouped.setdefault(reason, []).append(name)
        row["reason"] = "; ".join(f"{', '.join(names)}: {reason}" for reason, names in grouped.items())
        if self.note is not None:
            row["note"] = self.note
        return row


Evaluate = Callable[[Mapping[str, float], Start], Evaluation]


@dataclass(frozen=True)
class Guard:
    """The significance guard of one ratio output (e.g. mu_v) and its denominator output (nu_v)."""

    ratio: str
    denominator: str


def _insignificant(guard: Guard, values: Mapping[str, float], u: Mapping[str, float], significance: float) -> str:
    """Why the guard's ratio is not reported ("" when it is): its denominator lies within
    ``significance`` u of zero, or its u is not finite - then the check cannot be decided, and a
    NaN never passes for "within" (issue 14 item 6)."""
    den, u_den = values[guard.denominator], u[guard.denominator]
    if not math.isfinite(values[guard.ratio]):
        return ""
    if not math.isfinite(u_den):
        return (f"the uncertainty of {guard.denominator} = {den:.3g} is not finite (a perturbed evaluation of the "
                "chain failed), so whether the ratio's denominator is non-zero cannot be checked")
    if abs(den) > significance * u_den:
        return ""
    return (f"|{guard.denominator}| = {abs(den):.3g} is within {significance:g} u = {significance * u_den:.3g} "
            "of 0: the ratio's denominator is not known to be non-zero (hard case 8)")


def reduce_stand_point(evaluate: Callable[..., Evaluation], inputs: InputSet, numerators: Mapping[str, Numerator],
                       guards: tuple[Guard, ...], driven: tuple[str, ...], settings: ReductionSettings,
                       *, driver: str | None = None, **chain: object) -> ReducedPoint:
    """The step both stands' ``reduce`` share: choose the readings that may drive alpha'
    (rig.reduction.drivers), bind the stand's chain ``evaluate(values, start, settings=..., **chain)``
    and reduce the point (:func:`reduce_point`). ``chain`` must hold a callable ``coefficients``
    (l/a, c/a, alpha') -> (nu_T, nu_v, nu_0). driver: the one estimate allowed to drive alpha'
    (a chosen root of a non-unique mu, rig.reduction.roots; the iteration starts at
    settings.mu_start); None: the significant ones in order."""
    if not callable(chain.get("coefficients")):
        raise ParameterError("coefficients", chain.get("coefficients"),
                             "a callable (l_over_a, c_over_a, alpha) -> (nu_T, nu_v, nu_0)")
    drivers, no_driver = significant_drivers(inputs, numerators, settings.significance)
    if driver is not None:
        drivers = (driver,) if driver in drivers else ()
    coefficients = chain["coefficients"]
    chain = dict(chain, coefficients=remembered(coefficients))

    def bound(values: Mapping[str, float], start: Start) -> Evaluation:
        return evaluate(values, start, settings=settings, **chain)

    start = Start(settings.mu_start, drivers, True, no_driver)
    point = reduce_point(bound, inputs, start, settings.relative_step, guards, settings.significance, driven)
    error_at = getattr(coefficients, "numerical_error", None)
    state = [point.values.get(name, math.nan) for name in ("l_over_a", "c_over_a", "alpha_prime")]
    if error_at is None or not all(math.isfinite(x) for x in state):
        return point
    # the model's numerical error at the reduced state, as inputs of its own (rig.reduction.coefficients)
    inputs = with_model_error(inputs, error_at(*state))
    return reduce_point(bound, inputs, start, settings.relative_step, guards, settings.significance, driven)


def remembered(coefficients: Callable[[float, float, float], tuple]) -> Callable[[float, float, float], tuple]:
    """``coefficients`` answering a repeated state from memory (one point's reduction: the Jacobian's
    evaluations restart from the nominal mu, and an input that moves neither the rolling point nor
    the driving estimate - the gate time, the other estimate's reading - asks the contact model the
    nominal questions again). The same answers, also when the model raises (raised again)."""
    memory: dict[tuple[float, float, float], tuple | Exception] = {}

    def answer(l_over_a: float, c_over_a: float, alpha: float) -> tuple:
        key = (l_over_a, c_over_a, alpha)
        if key not in memory:
            try:
                memory[key] = coefficients(l_over_a, c_over_a, alpha)
            except Exception as error:  # noqa: BLE001 - remembered and raised again, as the model raised it
                memory[key] = error
        found = memory[key]
        if isinstance(found, Exception):
            raise found
        return found

    return answer


def reduce_point(evaluate: Evaluate, inputs: InputSet, start: Start, relative_step: float,
                 guards: tuple[Guard, ...], significance: float, driven: tuple[str, ...]) -> ReducedPoint:
    """Evaluate a chain at its inputs, propagate to first order, guard, budget, U95.

    guards: the ratio outputs and their denominators; significance: the guard's factor [1];
    driven: the outputs computed from the driving mu (alpha', nu's, every mu).
    """
    nominal = evaluate(inputs.mapping(inputs.values), start)
    restart = Start(nominal.mu if math.isfinite(nominal.mu) else start.mu,
                    (nominal.driver,) if nominal.driver else start.drivers, False, start.no_driver, nominal.slope)
    names = tuple(nominal.values)
    values, reasons = dict(nominal.values), dict(nominal.reasons)
    propagation = first_order(lambda x: evaluate(x, restart).values, inputs, names, relative_step,
                              np.array([values[n] for n in names]))
    u_all = propagation.uncertainties
    u = {name: float(u_all[i]) if math.isfinite(values[name]) else math.nan for i, name in enumerate(names)}
    for guard in guards:
        why = _insignificant(guard, values, u, significance)
        if why:
            lost = driven if guard.ratio == nominal.driver else (guard.ratio,)
            for name in lost:
                values[name], u[name] = math.nan, math.nan
                reasons.setdefault(name, why if name == guard.ratio else f"{guard.ratio} drives alpha': {why}")
    propagation = Propagation(
        inputs, names, np.array([values[n] for n in names]), propagation.jacobian, propagation.covariance
    )
    expanded = expanded_uncertainty(propagation)
    return ReducedPoint(
        values=values,
        uncertainties=u,
        expanded={name: float(expanded[i]) if math.isfinite(u[name]) else math.nan for i, name in enumerate(names)},
        reasons=reasons,
        iterations=nominal.iterations,
        driver=nominal.driver,
        propagation=propagation,
    )
