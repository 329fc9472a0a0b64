"""``run_accuracy``: the whole study for a stand scene - design, runs, table, report, plot.

Outputs in ``out_dir``: accuracy.csv (rig.accuracy.table.COLUMNS), accuracy.md (the report,
rig.accuracy.markdown) and accuracy_pareto.png (rig.accuracy.plot). Method: docs/accuracy.md.
"""

from __future__ import annotations

import contextlib
import os
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from rig import __version__, validate
from rig.accuracy.design import StudyDesign, StudyOptions, study_design
from rig.accuracy.markdown import report_markdown
from rig.accuracy.plot import pareto_figure
from rig.accuracy.profiler import Profile
from rig.accuracy.schedule import Progress, measure_all
from rig.accuracy.table import result_table, scene_on_front
from rig.contact.surrogate_cache import ENV_VARIABLE
from rig.scenes.procedure import Procedure
from rig.scenes.stand_scene import StandScene

ACCURACY_CSV = "accuracy.csv"
ACCURACY_MD = "accuracy.md"
PARETO_PNG = "accuracy_pareto.png"
MAX_JOBS = 64


@dataclass(frozen=True)
class AccuracyReport:
    """What the study wrote: the folder, the files (names), the table, the markdown, per axis
    whether the scene's choice is on the front, and the profile of the scene's own setting."""

    out_dir: Path
    files: tuple[str, ...]
    table: pd.DataFrame
    markdown: str
    on_front: dict[str, bool]
    profile: Profile | None


def _values(values) -> str:
    return ", ".join(f"{v:g}" for v in values)


def procedure_text(full: Procedure, short: Procedure) -> str:
    """The shortened procedure in words: per series, the values kept of each swept setting."""
    labels = full.series_settings
    parts = []
    for k, (a, b) in enumerate(zip(full.series, short.series)):
        head = ", ".join(f"{name} = {a.fixed[name]:g}" for name in labels)
        sweeps = "; ".join(f"{name} {len(kept)} of {len(dict(a.sweep)[name])} values ({_values(kept)})"
                           for name, kept in b.sweep) or "no swept setting"
        parts.append((f"series {k + 1} ({head}): " if len(full.series) > 1 else "") + sweeps)
    return " / ".join(parts)


def header_lines(scene: StandScene, design: StudyDesign, options: StudyOptions, jobs: int,
                 command: str | None) -> list[str]:
    """How the study was run, for the report."""
    p = design.procedure
    lines = [f"Produced by `{command}` (friction-rig {__version__})." if command else
             f"friction-rig {__version__}.", "",
             f"* Scene `{scene.name}`: {scene.description}. Stand `{scene.stand}`, seed {scene.seed}, "
             f"drive {scene.drive.value}, contact {scene.contact.model} n={scene.contact.n or 'default'}"
             + (f", table {'x'.join(map(str, scene.contact.table_points))}" if scene.contact.surrogate else
                ", direct calls") + f", gate {scene.procedure.gate_time_s:g} s.",
             f"* Study procedure (shortened, the same for every setting): {p.n_points} of "
             f"{scene.procedure.n_points} points - {procedure_text(scene.procedure, p)}; one repeat per point; "
             f"settle timeout {p.settle_timeout_s:g} s.",
             f"* Cost: CPU time of the process that runs the setting (not wall), median of {options.repeats} "
             f"timed runs, made round-robin over the settings after a first, untimed run of each that builds or "
             f"loads its surrogate tables ('first run'); a run = simulate + write log.h5 + reduce (no figures); "
             f"{jobs} process(es) in parallel. The study keeps its surrogate tables in a cache of its own, "
             "emptied when it ends, so every first run builds its tables: on the contact and table axes the "
             "front is drawn on that cost (the table build plus one run), the per-run median beside it.",
             "* Error: RMS over the points of (reduced - reference's reduced), same seed; truth error: "
             "inverse-variance weighted RMS of (reduced - truth). Gate axis: median stated standard "
             "uncertainty against lab time.",
             ]
    lines.append("* ODE tolerance: the stand's relative integrator tolerances times the factor (the stand "
                 "parameter ode_tolerance_factor).")
    return lines


@contextlib.contextmanager
def own_table_cache():
    """A fresh, empty surrogate-table cache (rig.contact.surrogate_cache) for the study's runs, so
    that each first run pays its table build; the worker processes inherit it (spawned within the
    block); the previous setting is restored and the folder removed afterwards."""
    previous = os.environ.get(ENV_VARIABLE)
    with tempfile.TemporaryDirectory(prefix="rig-accuracy-tables-") as folder:
        os.environ[ENV_VARIABLE] = folder
        try:
            yield Path(folder)
        finally:
            if previous is None:
                os.environ.pop(ENV_VARIABLE, None)
            else:
                os.environ[ENV_VARIABLE] = previous


def run_accuracy(scene: StandScene, out_dir: Path, *, options: StudyOptions | None = None, jobs: int = 1,
                 progress: Progress | None = None, command: str | None = None) -> AccuracyReport:
    """Run the study for a stand scene into ``out_dir`` (created if needed); ``jobs`` processes."""
    options = StudyOptions() if options is None else options
    jobs = validate.integer("jobs", jobs, 1, MAX_JOBS)
    design = study_design(scene, options)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    with own_table_cache():
        measurements = measure_all(scene, design, options.repeats, jobs, progress)
    table = result_table(design, measurements)
    own = measurements[design.scene_setting.key()]
    header = header_lines(scene, design, options, jobs, command)
    own_row = table[table["scene_choice"]].iloc[0]
    header.append(f"* Instrument floor: the scene's own setting states a median u(l/a) = {own_row['u_l_over_a']:.4f} "
                  f"and u(mu_T) = {own_row['u_mu_T']:.4f}; differences of reduced outputs below these are counting "
                  "and noise jitter, not accuracy. 'RMS d true l/a' is the simulation's own difference, without "
                  "instruments.")
    unequal = [k for k, m in measurements.items() if not m.identical]
    if unequal:
        header.append(f"* WARNING: {len(unequal)} setting(s) reduced differently from run to run (not deterministic).")
    markdown = report_markdown(f"rig accuracy: {scene.name}", header, design, table, own.profile, own.median_cpu_s)
    table.to_csv(out_dir / ACCURACY_CSV, index=False)
    (out_dir / ACCURACY_MD).write_text(markdown, encoding="utf-8")
    pareto_figure(design, table, out_dir / PARETO_PNG,
                  f"rig accuracy {scene.name}: error vs cost, each axis with the rest at the scene's setting")
    return AccuracyReport(out_dir, (ACCURACY_CSV, ACCURACY_MD, PARETO_PNG), table, markdown, scene_on_front(table),
                          own.profile)
