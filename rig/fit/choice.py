"""Model choice: nested effect sets fitted to the same data, ranked by AIC (BIC and LR test given).

The sets grow one parameter at a time in the order the parameters were named: the parameters
that are not effects (mu) first, then each effect added in turn, the effects not yet added held
at their off value (psi = 1 ...), so each set is the previous one plus one parameter. Ranking:
AIC = chi2 + 2k (lowest first); BIC = chi2 + k ln N is also given. The likelihood-ratio test of
each set against the previous one uses Delta chi2 with the chi-bar-squared null distribution
0.5 chi2(0) + 0.5 chi2(1) when the added parameter's off value is its range's end (psi = 1), so
p = 0.5 P(chi2_1 > Delta chi2) there and P(chi2_1 > Delta chi2) otherwise.

The decision (:func:`decide`) is the LR test's, not AIC's: a set is taken over the previous one
when p < DECISION_ALPHA = 0.01, so that data without the effect call for it in 1 % of repeats
(when the model and the stated u are right). AIC prefers the larger set whenever Delta chi2 > 2,
which null data with a one-sided parameter (psi >= 1) give in 0.5 P(chi2_1 > 2) = 7.9 % of
repeats. Strength (:func:`strength`): "strong" for p < 0.001, "clear" for p < DECISION_ALPHA,
"weak" for p < 0.05 (a p that small turns up in 1-5 % of repeats without the effect: not a
finding on its own), "none" above.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
from scipy.stats import chi2 as chi2_dist

from rig.fit.data import Observations
from rig.fit.engine import FitResult, Objective, fit
from rig.fit.forward import ForwardModel
from rig.fit.parameters import FitParameter


DECISION_ALPHA = 0.01  # LR-test p below which the larger effect set is taken
STRONG_ALPHA = 0.001
WEAK_ALPHA = 0.05


@dataclass(frozen=True)
class RankedModel:
    """One effect set with its fit, rank by AIC (1 = best) and the LR p-value against the previous set."""

    label: str
    result: FitResult
    rank: int
    lr_p: float


def nested_sets(free: Sequence[FitParameter]) -> list[tuple[FitParameter, ...]]:
    """[base, base + e1, base + e1 + e2, ...]: base = the non-effect parameters (may be empty)."""
    base = tuple(p for p in free if not p.is_effect)
    effects = [p for p in free if p.is_effect]
    sets = [base] if base or effects else []
    for k in range(1, len(effects) + 1):
        sets.append(base + tuple(effects[:k]))
    return sets


def set_label(params: Sequence[FitParameter]) -> str:
    return " + ".join(p.name for p in params) if params else "(all fixed: effects off)"


def rank_models(obs: Observations, free: Sequence[FitParameter], fixed: Mapping[str, float],
                start: Mapping[str, float], *, profile: bool = True, polish: str = "auto",
                scatter: float | None = 0.0, widen_misfit: bool = False) -> list[RankedModel]:
    """Fit every nested set (profile intervals for the full set only) and rank them by AIC.

    scatter: extra independent scatter (engine.fit); None estimates it on the full set, and the
    smaller sets are fitted with that same value, so that their chi2 are comparable.
    """
    results = []
    sets = nested_sets(free)
    memo: dict = {}
    if scatter is None:
        full = ForwardModel(obs, sets[-1], fixed, memo)
        scatter = fit(full, [start[p.name] for p in sets[-1]], profile=False, polish="never",
                      label=set_label(sets[-1]), scatter=None).scatter
    for params in sets:
        held = dict(fixed)
        held.update({p.name: p.off for p in free if p not in params})
        model = ForwardModel(obs, params, held, memo)
        if not params:
            results.append((set_label(params), _nothing_free(model, scatter), params))
            continue
        label = set_label(params)
        first = [start[p.name] for p in params]
        if results and results[-1][1].k == len(params) - 1:  # also start from the smaller set's optimum
            nested = [e.value for e in results[-1][1].estimates] + [params[-1].off]
            trials = [fit(model, x, profile=False, polish="never", label=label, scatter=scatter) for x in (first, nested)]
            first = [e.value for e in min(trials, key=lambda r: r.chi2).estimates]
        result = fit(model, first, profile=profile and params == sets[-1], polish=polish, label=label,
                     scatter=scatter, widen_misfit=widen_misfit and params == sets[-1])
        results.append((label, result, params))
    order = np.argsort([r.aic for _, r, _ in results], kind="stable")
    ranks = np.empty(len(results), dtype=int)
    ranks[order] = np.arange(1, len(results) + 1)
    out = []
    for k, (label, result, params) in enumerate(results):
        p = float("nan")
        if k > 0:
            added = params[-1]
            delta = max(0.0, results[k - 1][1].chi2 - result.chi2)
            p = float(chi2_dist.sf(delta, 1))
            if added.off is not None and added.off in (added.lo, added.hi):
                p *= 0.5
        out.append(RankedModel(label, result, int(ranks[k]), p))
    return out


def _nothing_free(model: ForwardModel, scatter: float) -> FitResult:
    obs = model.obs
    theta = np.empty(0)
    prediction = model.predict(theta)
    weights = Objective(model, scatter).weights(theta, prediction)
    chi2 = float(np.sum(weights(obs.y - prediction) ** 2))
    return FitResult(names=(), estimates=(), correlation=np.zeros((0, 0)), chi2=chi2, n_points=obs.size,
                     prediction=prediction, band=np.zeros(obs.size), u_eff=weights.u_total, warnings=(),
                     evaluations=1, message="no free parameter", scatter=scatter)


def strength(p: float) -> str:
    """"strong", "clear", "weak" or "none": the LR evidence for a set over the previous one (module docstring)."""
    if not np.isfinite(p):
        return "none"
    if p < STRONG_ALPHA:
        return "strong"
    if p < DECISION_ALPHA:
        return "clear"
    return "weak" if p < WEAK_ALPHA else "none"


def decide(models: Sequence[RankedModel]) -> RankedModel:
    """The largest set reached from the first by steps each with LR p < DECISION_ALPHA."""
    chosen = models[0]
    for m in models[1:]:
        if not m.lr_p < DECISION_ALPHA:
            break
        chosen = m
    return chosen
