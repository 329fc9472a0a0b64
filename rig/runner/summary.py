"""summary.txt of a stand run: what ran, points, settle times, failures, reduced-vs-truth agreement.

Agreement is stated in units of the stated standard uncertainty: z = |reduced - true| / u per
point, for every quantity whose table has the value, ``u_<name>`` and ``true_<name>``. Points
whose value is NaN (not reducible, with a reason) or whose u is not positive are counted apart.

Off its truth: in a twin run (the log has a truth group) a point whose largest z exceeds the
run's threshold is flagged - a wrong root of eqs. (33)-(35) or a budget that misses an error
cannot pass silently. The threshold is z = 3, raised for many comparisons so that a run whose
every u is right is flagged by chance in at most OFF_TRUTH_FAMILY of runs (Bonferroni over the m
comparisons of the run, normal z: Phi^-1(1 - OFF_TRUTH_FAMILY/(2 m)); 3.9 for m = 100).
:func:`with_off_truth` adds the columns ``z_max`` (the point's largest z [1]) and ``off_truth``
(1 flagged, 0 not, NaN not comparable) to the reduced table; ``rig run`` exits with
OFF_TRUTH_STATUS when a point is flagged (docs/scenes.md, "Exit status and errors").
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy.special import ndtri

from rig.runner.sweep import Failure
from rig.scenes.stand_scene import StandScene

QUANTITIES = ("l_over_a", "c_over_a", "mu_v", "mu_T")
OFF_TRUTH_Z = 3.0  # the smallest threshold of |reduced - true|/u that flags a point [1]
OFF_TRUTH_FAMILY = 0.01  # chance that a run with right u's is flagged at all [1]
OFF_TRUTH_STATUS = 4  # rig run's exit status when a reduced point is off its truth


def z_table(table: pd.DataFrame) -> pd.DataFrame:
    """z = |reduced - true|/u per point (rows) and quantity (columns) [1]; NaN where not comparable
    (NaN value, truth or u, or u <= 0)."""
    out = {}
    for name in QUANTITIES:
        if not {name, f"u_{name}", f"true_{name}"} <= set(table.columns):
            continue
        value, u, true = (table[c].to_numpy(dtype=float) for c in (name, f"u_{name}", f"true_{name}"))
        with np.errstate(invalid="ignore", divide="ignore"):
            z = np.abs(value - true) / u
        out[name] = np.where(np.isfinite(z) & (u > 0), z, np.nan)
    return pd.DataFrame(out, index=table.index)


def off_truth_threshold(comparisons: int) -> float:
    """The z that flags a point [1] for a run with ``comparisons`` finite z (module docstring)."""
    if comparisons <= 0:
        return OFF_TRUTH_Z
    # Phi^-1(1 - q) = -ndtri(q), what scipy.stats.norm.isf(q) computes, without importing scipy.stats
    # (about 0.7 s of CPU: a third of the parent's fixed cost in a run on workers)
    return max(OFF_TRUTH_Z, float(-ndtri(OFF_TRUTH_FAMILY / (2.0 * comparisons))))


def with_off_truth(table: pd.DataFrame) -> pd.DataFrame:
    """``table`` with ``z_max`` and ``off_truth`` when it has truth columns (unchanged otherwise);
    the threshold goes to ``table.attrs["off_truth_z"]``."""
    zs = z_table(table)
    if zs.empty or zs.shape[1] == 0:
        return table
    table = table.copy()
    finite = np.isfinite(zs.to_numpy())
    threshold = off_truth_threshold(int(finite.sum()))
    z_max = zs.max(axis=1, skipna=True).to_numpy(dtype=float)
    table["z_max"] = z_max
    table["off_truth"] = np.where(np.isfinite(z_max), (z_max > threshold).astype(float), np.nan)
    table.attrs["off_truth_z"] = threshold
    if isinstance(table.attrs.get("units"), dict):
        table.attrs["units"] = table.attrs["units"] | {"z_max": "1", "off_truth": "1"}
    return table


def off_truth_points(table: pd.DataFrame | None) -> tuple[int, ...]:
    """Indices of the points flagged off their truth (``off_truth`` = 1)."""
    if table is None or "off_truth" not in table:
        return ()
    return tuple(int(i) for i in table.index[(table["off_truth"] == 1.0).to_numpy()])


def off_truth_lines(table: pd.DataFrame) -> list[str]:
    """The summary's warning on the flagged points (first: it must be read first), [] when none."""
    flagged = off_truth_points(table)
    if not flagged:
        return []
    zs = z_table(table)
    threshold = table.attrs.get("off_truth_z", OFF_TRUTH_Z)
    lines = [f"WARNING: {len(flagged)} reduced point(s) off their truth by more than z = {threshold:.2f} "
             "(|reduced - true|/u; the stated u does not cover the error: a wrong root, or an error the budget "
             "misses) - reduced.csv's off_truth column marks them:"]
    for index in flagged[:20]:
        row = zs.loc[index]
        worst = row.idxmax()
        value, u, true = (table.loc[index, prefix + worst] for prefix in ("", "u_", "true_"))
        lines.append(f"  point {index}: {worst} = {value:.4g} +- {u:.2g} against the truth {true:.4g} "
                     f"(z = {row[worst]:.1f})")
    if len(flagged) > 20:
        lines.append(f"  ... and {len(flagged) - 20} more")
    return lines


@dataclass(frozen=True)
class Agreement:
    """Reduced vs truth for one quantity: n compared points, median and max z [1], how many have
    z <= 2, and how many points were left out (NaN value or no positive uncertainty)."""

    name: str
    n: int
    median_z: float
    max_z: float
    within_2u: int
    left_out: int

    def line(self) -> str:
        if self.n == 0:
            return f"  {self.name}: no comparable points ({self.left_out} NaN or without uncertainty)"
        text = (f"  {self.name}: {self.n} points, median {self.median_z:.2f}, max {self.max_z:.2f}, "
                f"within 2u: {self.within_2u}/{self.n}")
        return text + (f" ({self.left_out} left out: NaN or no uncertainty)" if self.left_out else "")


def agreement(table: pd.DataFrame) -> list[Agreement]:
    """Agreement of every quantity that has value, uncertainty and truth columns."""
    found = []
    for name in QUANTITIES:
        if not {name, f"u_{name}", f"true_{name}"} <= set(table.columns):
            continue
        value, u, true = (table[c].to_numpy(dtype=float) for c in (name, f"u_{name}", f"true_{name}"))
        ok = np.isfinite(value) & np.isfinite(true) & np.isfinite(u) & (u > 0)
        z = np.abs(value[ok] - true[ok]) / u[ok]
        found.append(Agreement(name, int(ok.sum()), float(np.median(z)) if z.size else float("nan"),
                               float(z.max()) if z.size else float("nan"), int((z <= 2.0).sum()),
                               int((~ok).sum())))
    return found


def _settings_text(settings: dict[str, float]) -> str:
    return ", ".join(f"{k} = {v:g}" for k, v in settings.items())


def _procedure_lines(scene: StandScene) -> list[str]:
    p = scene.procedure
    lines = []
    for k, series in enumerate(p.series):
        swept = "; ".join(f"{name}: {len(axis)} values {min(axis):g} .. {max(axis):g}" for name, axis in series.sweep)
        label = "procedure:   " if k == 0 else "             "
        own = {n: v for n, v in series.fixed.items() if n in p.series_settings}
        lines.append(f"{label}{'series ' + _settings_text(own) + ': ' if own else ''}sweep {swept or 'none'}")
    return [
        *lines,
        f"             fixed {_settings_text(dict(p.fixed)) or 'none'}",
        f"             gate {p.gate_time_s:g} s, settle timeout {p.settle_timeout_s:g} s, repeats {p.repeats}, "
        f"on settle timeout: {p.on_settle_timeout.value}",
    ]


@dataclass(frozen=True)
class RunFacts:
    """What the summary reports about one invocation of a stand run."""

    planned: int
    resumed: int
    written_now: int
    failures: Sequence[Failure]
    stopped: bool
    jobs: int
    scheduler: str | None
    settle_times_s: Sequence[float]
    calibration: Sequence[str]
    operator_time_s: float | None


def summary_text(scene: StandScene, facts: RunFacts, table: pd.DataFrame | None, problems: Sequence[str],
                 outputs: Sequence[str], campaign: Sequence[str] = ()) -> str:
    """The text of summary.txt; ``campaign``: the lines of the paper-figure checks, if any."""
    c = scene.contact
    lines = [
        "friction-rig run summary",
        *([] if table is None else off_truth_lines(table)),
        f"scene:       {scene.name} ({scene.source})",
        f"             {scene.description}",
        f"stand:       {scene.stand}, drive {scene.drive.value}, seed {scene.seed}, "
        + (f"Dask scheduler {facts.scheduler}" if facts.scheduler else f"jobs {facts.jobs}"),
        f"contact:     {c.model}, n = {c.n if c.n is not None else 'default'}, poisson {c.poisson:g}, "
        f"{'surrogate table' if c.surrogate else 'direct calls'}",
        f"parameters:  {_settings_text(dict(scene.parameters)) or 'stand defaults'}",
        f"effects:     {', '.join(scene.effects) or 'none'}",
        *_procedure_lines(scene),
        f"points:      planned {facts.planned}, in log {facts.resumed + facts.written_now} "
        f"({facts.resumed} resumed from an interrupted run, {facts.written_now} simulated now), "
        f"failed {len(facts.failures)}" + (" - run stopped at the first failure" if facts.stopped else ""),
    ]
    times = np.asarray(facts.settle_times_s, dtype=float)
    if times.size:
        lines.append(f"settle time: min {times.min():.3g} s, median {np.median(times):.3g} s, max {times.max():.3g} s "
                     f"(simulated, {times.size} points in the log)")
    if facts.operator_time_s is not None:
        lines.append(f"operator:    {facts.operator_time_s:.4g} s of simulated time for the points simulated now")
    lines.append(f"calibration: {', '.join(facts.calibration) or 'none'} (once per run)")
    if facts.failures:
        lines.append("failures (did not settle):")
        lines += [f"  point {f.index} ({_settings_text(f.settings)}): {f.message}" for f in facts.failures]
    if table is not None:
        found = agreement(table)
        lines.append(f"reduced:     {len(table)} points")
        if found:
            lines.append("reduced vs truth, z = |reduced - true| / u (u: stated standard uncertainty):")
            lines += [a.line() for a in found]
            if "off_truth" in table:
                flagged = len(off_truth_points(table))
                lines.append(f"  off truth (z > {table.attrs.get('off_truth_z', OFF_TRUTH_Z):.2f}, 1 % family-wise "
                             f"false-alarm level): {flagged} point(s)")
    if campaign:
        lines.append(f"paper figure ({scene.outputs.paper_figure}):")
        lines += [f"  {line}" for line in campaign]
    if problems:
        lines.append("problems:")
        lines += [f"  {p}" for p in problems]
    lines.append(f"outputs:     {', '.join(outputs)}")
    return "\n".join(lines) + "\n"
