"""summary.txt of a stand run: what ran, points, settle times, failures, reduced-vs-truth agreement.

Agreement is stated in units of the stated standard uncertainty: z = |reduced - true| / u per
point, for every quantity whose table has the value, ``u_<name>`` and ``true_<name>``. Points
whose value is NaN (not reducible, with a reason) or whose u is not positive are counted apart.

Points off their truth (rig.runner.off_truth) are named first, in a warning, and counted.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pandas as pd

from rig.runner.off_truth import OFF_TRUTH_Z, QUANTITIES, off_truth_lines, off_truth_points
from rig.runner.sweep import Failure
from rig.scenes.stand_scene import StandScene


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
