"""The files of ``rig fit``: fit.csv, models.csv, fit.png, summary.txt, each written atomically."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from rig.fit.run import FitReport
from rig.logbook import atomic



def _write(path: Path, write) -> None:
    """write(tmp_path) under a temporary name in path's folder, then rename over ``path``."""
    with atomic.replace_atomically(path, atomic.temporary_path(path.parent, path.name)) as tmp:
        write(tmp)


def parameter_table(report: FitReport) -> pd.DataFrame:
    """fit.csv: parameter, value, standard uncertainty u, 95 % profile interval, unit, flags."""
    rows = []
    for e in report.full.estimates:
        rows.append(dict(parameter=e.name, value=e.value, u=e.u, lo95=e.lo95, hi95=e.hi95, unit=e.unit,
                         lo95_at_range_end=e.open_lo, hi95_at_range_end=e.open_hi))
    for name, value in report.fixed.items():
        rows.append(dict(parameter=name, value=value, u=0.0, lo95=value, hi95=value, unit="1",
                         lo95_at_range_end=False, hi95_at_range_end=False))
    return pd.DataFrame(rows)


def model_table(report: FitReport) -> pd.DataFrame:
    """models.csv: effect set, k, chi2, AIC, BIC, rank (by AIC), LR-test p against the previous set,
    its strength and the set the LR decision takes (chosen)."""
    from rig.fit.choice import strength

    return pd.DataFrame([
        dict(effect_set=m.label, k=m.result.k, n_points=m.result.n_points, chi2=m.result.chi2,
             aic=m.result.aic, bic=m.result.bic, rank=m.rank, lr_p_vs_previous=m.lr_p,
             lr_strength=strength(m.lr_p) if k else "", chosen=m is report.decision,
             **{f"{e.name}": e.value for e in m.result.estimates})
        for k, m in enumerate(report.models)
    ])


MEANING = {
    "mu": "coefficient of friction mu ([Koziarski] eqs. (26)-(28))",
    "psi": "plastic slip factor Psi = v0/v_el, the ratio of the slip velocity at which the contact yields "
           "plastically to the elastic one ([Koziarski] eq. (25); 1 = elastic slip only)",
    "static_ratio": "static-to-kinetic friction ratio mu0/mu (1 = none)",
    "inertia_number": "surface-inertia number (0 = none)",
    "rolling_length": "rolling-resistance length f/a (0 = none)",
    "pressure_exponent": "exponent k of mu(p) = mu_ref (p/p_ref)^-k (0 = mu independent of pressure)",
}
QUANTITY_LABELS = {
    "F_y_per_F_N": "F_y/F_N = mu nu_v [1] ([Koziarski] eq. (28))",
    "nu_T": "nu_T [1] ([Koziarski] eq. (26))",
    "nu_v": "nu_v [1] ([Koziarski] eq. (27))",
    "nu_0": "nu_0 [1] ([Koziarski] eq. (28))",
}


def summary_text(report: FitReport) -> str:
    """summary.txt in the paper's words: warnings first, then goodness of fit, parameters and what
    their intervals mean, correlations, the effect-set decision and what it rests on, data, cost."""
    from rig.fit.choice import DECISION_ALPHA, strength

    obs, full, g = report.obs, report.full, report.goodness
    lines = ["friction-rig fit"]
    lines += [f"WARNING: {w}" for w in report.warnings]
    kind = "the instruments' stated noise, resolution and calibration (each point's u from the reduction)" \
        if obs.stand is not None else "the u given for the digitised points (--sigma)"
    verdict = ("the data scatter MORE than these u explain" if g.misfit else
               "the data scatter as much as these u explain")
    lines.append(f"goodness of fit: chi2 = {g.chi2:.4g} for {g.dof} degrees of freedom (chi2/dof {g.birge**2:.3g}), "
                 f"p = {g.p:.3g} against {kind}: {verdict} (misfit when p < 0.01)")
    u_point = np.median(full.u_eff)
    if report.extra_scatter is None:
        lines.append(f"scatter:     the stated u alone (no extra scatter; median u per point {u_point:.3g}, "
                     "common calibration and drift errors inside it)")
    else:
        how = "estimated so that chi2/dof = 1" if report.extra_scatter == "fit" else "as given"
        lines.append(f"scatter:     extra independent scatter s = {full.scatter:.3g} (--extra-scatter, {how}) beside "
                     f"the instruments' median independent u {np.median(obs.u_independent):.3g}; u_eff^2 = u^2 + s^2")
    lines.append("parameters (95 % intervals: where chi2, minimised over the other parameters, rises 3.84 above its "
                 "minimum - the profile likelihood; they hold the true value in 95 % of repeated measurements when "
                 "the model and the stated u are right):")
    for e in full.estimates:
        ends = ("[" if not e.open_lo else "[range end ") + f"{e.lo95:.5g}, {e.hi95:.5g}" + (
            "]" if not e.open_hi else " range end]")
        lines.append(f"  {e.name:14s} {e.value:.5g} +- {e.u:.2g} (standard u)   95 %: {ends} [{e.unit}]")
        lines.append(f"  {'':14s} {MEANING.get(e.name, '')}")
    for name, value in report.fixed.items():
        lines.append(f"  {name:14s} {value:.5g} held fixed (the scene's)")
    if full.k > 1:
        lines.append("correlation of the estimates:")
        for name, row in zip(full.names, full.correlation):
            lines.append(f"  {name:14s} " + " ".join(f"{r:+.3f}" for r in row))
    if not full.warnings:
        lines.append("identifiability: no flat profile, no |correlation| > 0.95")
    decision = report.decision
    lines.append(f"effect sets (nested; each tested against the previous one by the likelihood ratio, "
                 f"taken when p < {DECISION_ALPHA:g}; AIC = chi2 + 2k and BIC = chi2 + k ln N for reference):")
    for k, m in enumerate(report.models):
        if k == 0:
            test = "the starting set"
        else:
            prev = report.models[k - 1]
            test = (f"vs {prev.label}: Delta chi2 {max(prev.result.chi2 - m.result.chi2, 0):.3g}, LR p = "
                    f"{m.lr_p:.3g} ({strength(m.lr_p)}), AIC margin {prev.result.aic - m.result.aic:+.3g}")
        lines.append(f"  {m.label:28s} chi2 {m.result.chi2:9.4g}  AIC {m.result.aic:9.4g}  BIC {m.result.bic:9.4g}  "
                     f"{test}")
    rest = ("strong: p < 0.001", "clear: p < 0.01", "weak: 0.01 <= p < 0.05 - a p this small turns up in 1-5 % "
            "of measurements without the effect, not a finding on its own", "none: p >= 0.05")
    lines.append(f"answer:      the data call for {decision.label} (LR test at p < {DECISION_ALPHA:g}; strength of "
                 f"each step: {'; '.join(rest)})")
    if g.misfit:
        lines.append("             this decision rests on a model the data contradict (goodness of fit above): "
                     "do not read it as evidence for an effect")
    lines.append(f"data:        {obs.source}")
    lines.append(f"points:      {obs.size}: " + ", ".join(QUANTITY_LABELS.get(q, q) for q in sorted(set(obs.quantity)))
                 + f" versus {obs.x_label}")
    lines.append(f"contact:     {obs.contact.model} law, {obs.contact.shape} contact, n = {obs.contact.n} cells across "
                 f"2a, poisson {obs.contact.poisson:g}, fixed effects {dict(obs.fixed_effects) or 'none'}")
    lines += [f"note:        {n}" for n in obs.notes]
    how = "direct-solve polish of the estimate (table error not small against u)" if full.polished else (
        "node/table interpolation")
    if np.isfinite(full.table_error):
        how += (f"; at the optimum max |table - direct| = {full.table_error:.2g}, "
                f"{full.table_error_ratio:.2g} of a point's u")
    else:
        how += "; no direct-solve check"
    if obs.stand is not None:
        how += " (the stand's own cached tables: the law its simulation uses)"
    lines.append(f"evaluated:   {how}")
    lines.append(f"cost:        {report.seconds:.1f} s")
    return "\n".join(lines) + "\n"


def draw(report: FitReport, path: Path) -> None:
    """fit.png: data with 2u error bars, fitted curve with its 95 % band, weighted residuals."""
    from rig.plotting import colors, new_figure

    obs, full = report.obs, report.full
    figure = new_figure(figsize=(8, 7))
    top, bottom = figure.subplots(2, 1, sharex=True, gridspec_kw=dict(height_ratios=[3, 1]))
    for color, series in zip(colors() * 4, dict.fromkeys(obs.series)):
        for quantity in dict.fromkeys(obs.quantity[obs.series == series]):
            at = np.flatnonzero((obs.series == series) & (obs.quantity == quantity))
            at = at[np.argsort(obs.x[at])]
            label = f"{series}" if series == quantity else f"{series}: {quantity}"
            top.errorbar(obs.x[at], obs.y[at], yerr=2 * full.u_eff[at], fmt="o", ms=3, color=color, label=label)
            top.plot(obs.x[at], full.prediction[at], "-", color=color)
            top.fill_between(obs.x[at], full.prediction[at] - 1.96 * full.band[at],
                             full.prediction[at] + 1.96 * full.band[at], color=color, alpha=0.25, lw=0)
            bottom.plot(obs.x[at], (obs.y[at] - full.prediction[at]) / full.u_eff[at], "o", ms=3, color=color)
    if np.all(obs.x > 0) and obs.x.max() / obs.x.min() > 100:
        top.set_xscale("log")
    fitted = ", ".join(f"{e.name} = {e.value:.4g}" for e in full.estimates)
    top.set_title(f"fit: {fitted}  (error bars 2u, band 95 %)", fontsize=9)
    top.set_ylabel("y")
    top.legend(fontsize=7)
    bottom.axhline(0.0, color="k", lw=0.8)
    bottom.set_ylabel("(y - fit)/u")
    bottom.set_xlabel(obs.x_label)
    figure.savefig(path, format="png", dpi=110)


def write_outputs(report: FitReport, directory: str | Path, *, plot: bool = True) -> list[Path]:
    """Write the files into ``directory`` (created), each atomically; returns their paths."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, write in (
        ("fit.csv", lambda p: parameter_table(report).to_csv(p, index=False)),
        ("models.csv", lambda p: model_table(report).to_csv(p, index=False)),
        ("summary.txt", lambda p: p.write_text(summary_text(report), encoding="utf-8")),
        ("fit.png", (lambda p: draw(report, p)) if plot else None),
    ):
        if write is None:
            continue
        _write(directory / name, write)
        paths.append(directory / name)
    return paths
