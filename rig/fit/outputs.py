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
        inside = ", the shared calibration and drift errors inside it" if obs.common is not None else ""
        lines.append(f"scatter:     the stated u alone (no extra scatter named; median u per point {u_point:.3g}{inside})")
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
        if full.direct_checked < obs.size:
            how += f" (checked at {full.direct_checked} of the {obs.size} points, spread evenly; no polish)"
    else:
        how += "; no direct-solve check"
    if obs.stand is not None:
        how += " (the stand's own cached tables: the law its simulation uses)"
    lines.append(f"evaluated:   {how}")
    lines.append(f"cost:        {report.seconds:.1f} s")
    return "\n".join(lines) + "\n"


X_LABELS = {"l/a": "rolling point l/a [1] ([Koziarski] eq. (30))", "alpha": "alpha' [1] ([Koziarski] eq. (21))",
            "alpha'": "alpha' [1] ([Koziarski] eq. (21))", "c/a": "c/a [1]"}


def draw(report: FitReport, path: Path) -> None:
    """fit.png: per fitted quantity, the data with 2u error bars (u with the shared errors) and the
    curve of every effect set fitted (the chosen one bold, with its 95 % band); below it the
    residuals over the point-to-point u (without the shared calibration and drift), with the
    shared errors' size as a grey band; on the right the profile chi2 of each parameter with the
    95 % threshold."""
    from rig.plotting import colors, new_figure

    obs, full = report.obs, report.full
    quantities = list(dict.fromkeys(obs.quantity))
    params = [e for e in full.estimates if full.profiles and e.name in full.profiles]
    rows = 2 * len(quantities)
    figure = new_figure(figsize=(11 if params else 8, 3.2 * len(quantities) + 1.5), layout="constrained")
    grid = figure.add_gridspec(rows, 2 if params else 1, height_ratios=[3, 1] * len(quantities),
                               width_ratios=[2.2, 1] if params else [1])
    palette = colors() * 4
    chosen = report.decision
    u_point = full.u_point if full.u_point is not None else full.u_eff
    for q_index, quantity in enumerate(quantities):
        top = figure.add_subplot(grid[2 * q_index, 0])
        bottom = figure.add_subplot(grid[2 * q_index + 1, 0], sharex=top)
        for s_index, (color, series) in enumerate(zip(palette, dict.fromkeys(obs.series[obs.quantity == quantity]))):
            at = np.flatnonzero((obs.series == series) & (obs.quantity == quantity))
            at = at[np.argsort(obs.x[at])]
            top.errorbar(obs.x[at], obs.y[at], yerr=2 * full.u_eff[at], fmt="o", ms=3, color=color,
                         label=f"{series} (2u)" if series != quantity else "data (2u)")
            for style, m in zip(("--", ":", "-.", (0, (1, 3))), [m for m in report.models if m is not chosen]):
                name = f"{m.label} (LR p = {m.lr_p:.2g})" if not np.isnan(m.lr_p) else m.label
                top.plot(obs.x[at], m.result.prediction[at], linestyle=style, lw=1, color=color,
                         label=name if s_index == 0 else None)
            top.plot(obs.x[at], chosen.result.prediction[at], "-", lw=1.8, color=color,
                     label=f"{chosen.label} (chosen)" if s_index == 0 else None)
            if chosen is report.models[-1]:
                top.fill_between(obs.x[at], full.prediction[at] - 1.96 * full.band[at],
                                 full.prediction[at] + 1.96 * full.band[at], color=color, alpha=0.2, lw=0)
            shared = np.sqrt(np.clip(full.u_eff[at] ** 2 - u_point[at] ** 2, 0, None)) / u_point[at]
            bottom.fill_between(obs.x[at], -shared, shared, color="0.85", lw=0)
            bottom.plot(obs.x[at], (obs.y[at] - full.prediction[at]) / u_point[at], "o", ms=3, color=color)
        if np.all(obs.x > 0) and obs.x.max() / obs.x.min() > 100:
            top.set_xscale("log")
        top.set_ylabel(_quantity_label(quantity))
        top.legend(fontsize=6)
        bottom.axhline(0.0, color="k", lw=0.8)
        bottom.set_ylabel("(y - fit)/u_point", fontsize=8)
        bottom.set_xlabel(X_LABELS.get(obs.x_label, obs.x_label))
    fitted = ", ".join(f"{e.name} = {e.value:.4g}" for e in full.estimates)
    g = report.goodness
    figure.suptitle(f"{report.models[-1].label}: {fitted}; chi2/dof = {g.chi2:.3g}/{g.dof}, p = {g.p:.2g}"
                    + ("  - MISFIT: see summary.txt" if g.misfit else "") + "\nresiduals over the point-to-point u; "
                    "grey: size of the shared calibration/drift error", fontsize=9)
    for k, e in enumerate(params):
        ax = figure.add_subplot(grid[k * rows // len(params):(k + 1) * rows // len(params), 1])
        curve = full.profiles[e.name]
        ax.plot(curve[:, 0], curve[:, 1], "o-", ms=3, label=f"profile of {e.name}")
        ax.axhline(3.84, color="r", lw=0.8, label="95 % (Delta chi2 = 3.84)")
        ax.axvspan(e.lo95, e.hi95, color="r", alpha=0.1)
        ax.set_xlabel(f"{e.name} [{e.unit}]")
        ax.set_ylabel("profile Delta chi2")
        width = max(e.hi95 - e.lo95, 1e-12)
        ax.set_xlim(max(e.lo95 - 1.5 * width, float(curve[:, 0].min())), min(e.hi95 + 1.5 * width, float(curve[:, 0].max())))
        ax.set_ylim(0, 12.0)
        ax.legend(fontsize=6)
    figure.savefig(path, format="png", dpi=110)


def _quantity_label(quantity: str) -> str:
    return QUANTITY_LABELS.get(quantity, quantity)


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
