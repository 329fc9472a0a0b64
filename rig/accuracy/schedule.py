"""Run every setting of a study in two phases, serially or on a local process pool.

Phase 1 (first runs): settings that share a contact law (same ContactSpec, so the same surrogate
tables) run one after another in one task, so a table is built at most once and never by two
processes at the same time; tasks go out longest first (an estimate: table nodes x a model's cost
per solve), which keeps both cores busy. A setting's first run gives its results (reduced table,
lab time) and its cold cost: building or loading its tables. Phase 2 (timed runs): with every
table on disk, the ``repeats`` timed runs of all settings go out one run per task, round-robin
(every setting's 1st, then every setting's 2nd, ...), so a change of the machine's load during
the study falls on all settings alike; then one sampled, untimed run of the scene's own setting
(rig.accuracy.profiler). The cost of a setting is the median of its timed runs. Processes are
started with "spawn", like ``rig run --jobs`` (rig.runner.pool); a run's CPU time is measured in
the process that runs it.
"""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable, Sequence
from concurrent.futures import Executor, ProcessPoolExecutor
from dataclasses import dataclass

import numpy as np
import pandas as pd

from rig.accuracy.design import Setting, StudyDesign
from rig.accuracy.execute import Run, run_once
from rig.accuracy.profiler import Profile
from rig.scenes.stand_scene import StandScene

SOLVE_COST_MS = {"rigid": lambda n: 0.0, "linear": lambda n: 1.0, "fastsim": lambda n: 1.0,
                 "kinematic": lambda n: 0.1 * n * n}
"""Rough cost of one contact solve [ms] by model and grid n (measured order of magnitude, for ordering only)."""

Progress = Callable[[int, int], None]
"""progress(runs done, runs in all)."""


@dataclass(frozen=True)
class Measurement:
    """What the runs of one setting gave.

    reduced: reduced table of the first run (index: point); cpu_first_s: CPU time of the first
    run [s] (includes building or loading the tables); cpu_s: CPU time of each timed run [s];
    lab_time_s: operator time of one run [s]; planned / failures: points planned and not settled;
    identical: every run reduced to the same table; profile: samples of the extra, untimed run
    (None except for the scene's own setting).
    """

    reduced: pd.DataFrame
    cpu_first_s: float
    cpu_s: tuple[float, ...]
    lab_time_s: float
    planned: int
    failures: int
    identical: bool
    profile: Profile | None = None

    @property
    def median_cpu_s(self) -> float:
        """Median CPU time of the timed runs [s]."""
        return float(np.median(self.cpu_s))


@dataclass(frozen=True)
class Job:
    """Runs made one after another in one process: settings, and whether to sample them."""

    scene: StandScene
    design: StudyDesign
    settings: tuple[Setting, ...]
    profile: bool = False

    def estimate_ms(self) -> float:
        """Rough cost of building the first setting's table [ms] (ordering only)."""
        c = self.settings[0].contact
        nodes = int(np.prod(c.table_points)) if c.surrogate else 0
        return nodes * SOLVE_COST_MS[c.model](32 if c.n is None else c.n) + len(self.settings)


def run_job(job: Job) -> list[Run]:
    """The job's runs, in order, in this process."""
    return [run_once(job.scene, job.design.procedure, s, profile=job.profile) for s in job.settings]


def first_run_jobs(scene: StandScene, design: StudyDesign) -> list[Job]:
    """Phase 1: one job per contact law, longest first."""
    groups: dict[tuple, list[Setting]] = {}
    for setting in design.settings():
        groups.setdefault(setting.contact_key(), []).append(setting)
    return sorted((Job(scene, design, tuple(g)) for g in groups.values()), key=lambda j: -j.estimate_ms())


def timed_run_jobs(scene: StandScene, design: StudyDesign, repeats: int) -> list[Job]:
    """Phase 2: ``repeats`` rounds of one run per setting, then the sampled run of the scene's own."""
    settings = design.settings()
    rounds = [Job(scene, design, (s,)) for _ in range(repeats) for s in settings]
    return rounds + [Job(scene, design, (design.scene_setting,), profile=True)]


def _execute(pool: Executor | None, jobs: Sequence[Job], done: Callable[[int], None]) -> list[list[Run]]:
    if pool is None:
        results = []
        for job in jobs:
            results.append(run_job(job))
            done(len(job.settings))
        return results
    futures = [pool.submit(run_job, job) for job in jobs]
    results = []
    for job, future in zip(jobs, futures):
        results.append(future.result())
        done(len(job.settings))
    return results


def measure_all(scene: StandScene, design: StudyDesign, repeats: int, jobs: int,
                progress: Progress | None = None) -> dict[tuple, Measurement]:
    """Every setting's Measurement, by Setting.key(); ``jobs`` processes (1: this one)."""
    first_jobs = first_run_jobs(scene, design)
    timed_jobs = timed_run_jobs(scene, design, repeats)
    total = sum(len(j.settings) for j in first_jobs + timed_jobs)
    count = [0]

    def done(runs: int) -> None:
        count[0] += runs
        if progress is not None:
            progress(count[0], total)

    pool = None
    if jobs > 1:
        pool = ProcessPoolExecutor(max_workers=jobs, mp_context=multiprocessing.get_context("spawn"))
    try:
        first = _execute(pool, first_jobs, done)
        timed = _execute(pool, timed_jobs, done)
    finally:
        if pool is not None:
            pool.shutdown(wait=True, cancel_futures=True)
    firsts = {s.key(): r for job, runs in zip(first_jobs, first) for s, r in zip(job.settings, runs)}
    timings: dict[tuple, list[Run]] = {}
    for job, runs in zip(timed_jobs[:-1], timed[:-1]):
        timings.setdefault(job.settings[0].key(), []).extend(runs)
    profile = timed[-1][0].profile
    own = design.scene_setting.key()
    out = {}
    for key, run in firsts.items():
        runs = timings[key]
        out[key] = Measurement(run.reduced, run.cpu_s, tuple(r.cpu_s for r in runs), run.lab_time_s, run.planned,
                               run.failures, all(r.reduced.equals(run.reduced) for r in runs),
                               profile if key == own else None)
    return out
