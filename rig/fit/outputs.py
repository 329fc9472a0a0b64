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
    """models.csv: effect set, k, chi2, AIC, BIC, rank (by AIC), LR-test p against the previous set."""
    return pd.DataFrame([
        dict(effect_set=m.label, k=m.result.k, n_points=m.result.n_points, chi2=m.result.chi2,
             aic=m.result.aic, bic=m.result.bic, rank=m.rank, lr_p_vs_previous=m.lr_p,
             **{f"{e.name}": e.value for e in m.result.estimates})
        for m in report.models
    ])


def summary_text(report: FitReport) -> str:
    """summary.txt: data, parameters with intervals, correlations, warnings, model ranking, cost."""
    obs, full = report.obs, report.full
    quantities = ", ".join(sorted(set(obs.quantity)))
    lines = ["friction-rig fit", f"data:        {obs.source}", f"points:      {obs.size} ({quantities})",
             f"contact:     {obs.contact.model}, {obs.contact.shape}, n = {obs.contact.n}, poisson "
             f"{obs.contact.poisson:g}, fixed effects {dict(obs.fixed_effects) or 'none'}"]
    lines += [f"note:        {n}" for n in obs.notes]
    how = "direct-solve polish of the estimate (table error not small against u)" if full.polished else (
        "node/table interpolation")
    how += (f"; at the optimum max |table - direct| = {full.table_error:.2g} vs min u = {np.min(obs.u):.2g}"
            if np.isfinite(full.table_error) else "; no direct-solve check")
    if obs.stand is not None:
        how += " (the stand's own cached tables: the law its simulation uses)"
    if full.scatter > 0:
        how += (f"\nscatter:     independent scatter s = {full.scatter:.3g} added to u (the stated u is all "
                "calibration; s makes chi2/dof = 1 for the full set, held for the others)")
    lines.append(f"evaluated:   {how}")
    lines.append(f"chi2:        {full.chi2:.4g} for {full.dof} degrees of freedom (chi2/dof {full.chi2 / max(full.dof, 1):.3g})")
    lines.append("parameters (95 % intervals from the profile likelihood, Delta chi2 = 3.84):")
    for e in full.estimates:
        ends = ("[" if not e.open_lo else "[range end ") + f"{e.lo95:.5g}, {e.hi95:.5g}" + (
            "]" if not e.open_hi else " range end]")
        lines.append(f"  {e.name:14s} {e.value:.5g} +- {e.u:.2g} (u)   95 %: {ends} [{e.unit}]")
    for name, value in report.fixed.items():
        lines.append(f"  {name:14s} {value:.5g} fixed")
    if full.k > 1:
        lines.append("correlation:")
        for name, row in zip(full.names, full.correlation):
            lines.append(f"  {name:14s} " + " ".join(f"{r:+.3f}" for r in row))
    lines += [f"WARNING:     {w}" for w in full.warnings] or ["identifiability: no flat profile, no |r| > 0.95"]
    lines.append("model choice (AIC = chi2 + 2k, lowest first; BIC = chi2 + k ln N):")
    for m in sorted(report.models, key=lambda m: m.rank):
        p = "" if np.isnan(m.lr_p) else f", LR test vs previous set p = {m.lr_p:.3g}"
        lines.append(f"  {m.rank}. {m.label:28s} chi2 {m.result.chi2:9.4g}  AIC {m.result.aic:9.4g}  "
                     f"BIC {m.result.bic:9.4g}{p}")
    lines.append(f"answer:      the data is best described by {report.best.label} (AIC)")
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
