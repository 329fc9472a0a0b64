"""The Dask path (``--scheduler``) and a process pool (``-j 2``) give the log and reduced table of a
one-process run, also after a kill at a random moment and a rerun.

One LocalCluster (rig.runner.dask_pool.study_cluster: 2 worker processes, 1 thread each, the
study configuration) serves the module. The reference is always a
``jobs`` = 1 run of the same seeded scene in another folder: logs are compared by content
(records, truth, metadata but the start time), reduced.csv by text. Scenes: the fake stand of
tests/runner/fake_stand.py (with two points that do not settle) and a short stand-A scene. The
stands are sent to the workers by module path, so the stands defined here are importable too.
"""

from __future__ import annotations

import contextlib
import os
import random
import re
import signal
import subprocess
import sys
import time
from collections import OrderedDict
from pathlib import Path
from concurrent.futures import ThreadPoolExecutor
from unittest import mock

import dask
import h5py
import numpy as np
import pandas as pd
import pytest
from distributed import Client

import rig.runner.chunks
import rig.runner.dask_pool
import rig.runner.reduction
import rig.stands
from rig.errors import ParameterError
from rig.logbook import RunMetadata, utc_timestamp
from rig.logbook.shards import find_shards, shard_folder
from rig.runner import run_scene
from rig.runner.pool import WorkerError
from rig.scenes import load_scene, parse_scene
from tests.runner.fake_stand import NO_FIGURES, FakeStand, register, scene_text
from tests.runner.logs import assert_same_log, log_objects
from tests.runner.study_child import study_text

REPO = Path(__file__).resolve().parents[2]

SWEEP = NO_FIGURES | {"load_N = [5.0, 10.0, 20.0, 25.0]": "load_N = [5.0, 10.0, 50.0, 55.0, 60.0, 8.0]",
                      "mu = 0.3": "mu = 0.3\nsettle_tau_s = 1.0"}  # points 2 (10 -> 50 N) and 5 do not settle
STOP = SWEEP | {"gate_time_s = 1.0": 'gate_time_s = 1.0\non_settle_timeout = "stop"'}

STAND_A_SHORT = {  # the built-in default scene, cheaper: fastsim n = 8, direct calls, 3 points, 1 s gates
    'model = "kinematic"': 'model = "fastsim"',
    "n = 16 ": "n = 8 ",
    "surrogate = true ": "surrogate = false ",
    "{ start = -1.6, stop = 1.6, num = 9 }": "[-1.2, 0.0, 1.2]",
    "gate_time_s = 4.0 ": "gate_time_s = 1.0 ",
}


class BrokenStand(FakeStand):
    """The fake stand whose point 1 raises (a stand's bug, not a settle timeout)."""

    def start_point(self, index, settings, previous, seed):
        if index == 1:
            raise RuntimeError("stand bug at point 1")
        return super().start_point(index, settings, previous, seed)


def _cached_calibrations() -> list[list[int]]:
    """On a worker: per run it keeps (rig.runner.dask_pool), the calibration count of each thread's stand."""
    return [[stand.calibrations for stand in run.values()] for run in rig.runner.dask_pool._stands.values()]


@pytest.fixture(scope="module")
def scheduler(tmp_path_factory):
    cache = tmp_path_factory.mktemp("rig_cache")
    with rig.runner.dask_pool.study_cluster(2, dashboard_address=":0", env={"RIG_CACHE_DIR": str(cache)}) as cluster:
        yield cluster.scheduler_address


@pytest.fixture(autouse=True)
def _stands(monkeypatch, tmp_path):
    register(monkeypatch)
    monkeypatch.setitem(rig.stands.STANDS, "broken", f"{__name__}:BrokenStand")
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path / "cache"))


def _same_outputs(one, other) -> None:
    assert_same_log(one / "log.h5", other / "log.h5")
    assert (one / "reduced.csv").read_text() == (other / "reduced.csv").read_text()


def test_fake_sweep_on_dask_equals_one_job(scheduler, tmp_path):
    scene = parse_scene(scene_text(SWEEP), name="fake")
    one = run_scene(scene, tmp_path / "one", progress=False)
    cluster = run_scene(scene, tmp_path / "dask", scheduler=scheduler, progress=False)
    assert [f.index for f in one.failures] == [f.index for f in cluster.failures] == [2, 5]
    assert one.failures == cluster.failures and cluster.in_log == 4 and not cluster.stopped
    _same_outputs(tmp_path / "one", tmp_path / "dask")
    with Client(scheduler, set_as_default=False) as client:
        runs = [run for worker in client.run(_cached_calibrations).values() for run in worker]
    assert runs and all(run == [1] for run in runs)  # per run, one stand per worker thread, calibrated once


def test_dask_stops_where_one_job_stops(scheduler, tmp_path):
    scene = parse_scene(scene_text(STOP), name="fake")
    one = run_scene(scene, tmp_path / "one", progress=False)
    cluster = run_scene(scene, tmp_path / "dask", scheduler=scheduler, progress=False)
    assert one.stopped and cluster.stopped and one.in_log == cluster.in_log == 2
    assert [f.index for f in cluster.failures] == [2]
    _same_outputs(tmp_path / "one", tmp_path / "dask")


@pytest.mark.parametrize("changes", [SWEEP, STOP], ids=["skip", "stop"])
def test_batches_of_several_points_equal_one_job(scheduler, tmp_path, monkeypatch, changes):
    """One task per worker thread (batches of 3 points): failures, the STOP and the log as one job."""
    monkeypatch.setattr(rig.runner.chunks, "CHUNKS_PER_WORKER", 1)
    assert rig.runner.chunks.chunk_size(6, 2) == 3
    scene = parse_scene(scene_text(changes), name="fake")
    one = run_scene(scene, tmp_path / "one", progress=False)
    cluster = run_scene(scene, tmp_path / "dask", scheduler=scheduler, progress=False)
    assert one.failures == cluster.failures and one.stopped == cluster.stopped and one.in_log == cluster.in_log
    _same_outputs(tmp_path / "one", tmp_path / "dask")


def test_chunk_size_shares_the_points_between_the_workers():
    assert [rig.runner.chunks.chunk_size(n, 2) for n in (1, 16, 17, 1600, 100_000)] == [1, 2, 3, 200, 2048]
    assert rig.runner.chunks.chunk_size(5, 0) == rig.runner.chunks.chunk_size(5, 1) == 2  # no workers: one


def test_short_stand_a_scene_on_dask_equals_one_job(scheduler, tmp_path):
    text = load_scene("default").text
    for old, new in STAND_A_SHORT.items():
        assert old in text, old
        text = text.replace(old, new)
    scene = parse_scene(text + "\n[outputs]\nfigures = false\n", name="default_short")
    one = run_scene(scene, tmp_path / "one", progress=False)
    formatted, used = rig.runner.reduction._csv_from_rows, []
    with mock.patch.object(rig.runner.reduction, "_csv_from_rows", lambda *a: used.append(formatted(*a)) or used[-1]):
        cluster = run_scene(scene, tmp_path / "dask", scheduler=scheduler, progress=False)
    assert used == [True]  # reduced.csv was made of the lines the workers formatted
    assert one.failures == cluster.failures == () and cluster.in_log == 3
    _same_outputs(tmp_path / "one", tmp_path / "dask")
    table = pd.read_csv(tmp_path / "dask" / "reduced.csv", index_col="point")
    assert np.isfinite(table[["mu_v", "l_over_a"]].to_numpy()).all()  # compared numbers, not NaN == NaN


def test_an_interrupted_run_resumes_on_dask_to_the_same_log(scheduler, tmp_path):
    scene = parse_scene(scene_text(SWEEP), name="fake")
    run_scene(scene, tmp_path / "one", progress=False)
    original = FakeStand.start_point

    def start_point(self, index, *args):
        if index == 3:
            raise KeyboardInterrupt  # the local operator is stopped after points 0 and 1 were written
        return original(self, index, *args)

    with mock.patch.object(FakeStand, "start_point", start_point), pytest.raises(KeyboardInterrupt):
        run_scene(scene, tmp_path / "dask", progress=False)
    report = run_scene(scene, tmp_path / "dask", scheduler=scheduler, progress=False)
    assert report.resumed == 2 and report.in_log == 4 and [f.index for f in report.failures] == [2, 5]
    _same_outputs(tmp_path / "one", tmp_path / "dask")


def test_an_error_in_a_point_comes_back_naming_the_point(scheduler, tmp_path):
    scene = parse_scene(scene_text(NO_FIGURES | {'stand = "fake"': 'stand = "broken"'}), name="broken")
    with pytest.raises(WorkerError, match=r"(?s)point 1 \{'load_N': 10\.0.*RuntimeError: stand bug at point 1"):
        run_scene(scene, tmp_path / "run", scheduler=scheduler, progress=False)
    metadata = RunMetadata(scene.text, scene.seed, scene.stand, utc_timestamp())
    shards = find_shards(shard_folder(tmp_path / "run" / "log.h5"), metadata)
    assert [shard.indices for shard in shards] == [(0,)]  # point 0 was logged before the error: running again resumes


class _Done:
    def __init__(self, value):
        self.value = value

    def result(self):
        return self.value

    def release(self):
        self.value = None


class _Lost:
    def result(self):
        raise RuntimeError("worker lost")  # what distributed.KilledWorker or a cancelled task does


class _ClientLosingPoint1:
    """Stand-in for distributed.Client: runs tasks here, loses the one of point 1; records cancel and close."""

    def __init__(self):
        self.cancelled, self.closed = [], False

    def nthreads(self):
        return {"worker": 1}  # one thread: batches of one point for this 4-point scene

    def scatter(self, value, **options):
        return value

    def submit(self, function, *args, key):
        return _Lost() if any(point.index == 1 for point in args[-1].points) else _Done(function(*args))

    def cancel(self, futures):
        self.cancelled = list(futures)

    def close(self):
        self.closed = True


def test_a_lost_task_is_a_worker_error_naming_the_point(monkeypatch, tmp_path):
    client = _ClientLosingPoint1()
    monkeypatch.setattr(rig.runner.dask_pool, "_connect", lambda address: client)
    monkeypatch.setattr(rig.runner.dask_pool, "_stands", OrderedDict())  # the stand-in's tasks run here
    scene = parse_scene(scene_text(NO_FIGURES), name="fake")
    with pytest.raises(WorkerError, match=r"point 1 \{'load_N': 10\.0.*did not run it \(RuntimeError: worker lost\)"):
        run_scene(scene, tmp_path / "run", scheduler="tcp://127.0.0.1:8786", progress=False)
    assert client.closed and len(client.cancelled) == 3  # the lost task and the two after it (the first was read)


def test_each_worker_thread_keeps_its_own_stand_for_the_last_runs(monkeypatch):
    monkeypatch.setattr(rig.runner.dask_pool, "_stands", OrderedDict())
    scene = parse_scene(scene_text(NO_FIGURES), name="fake")
    first = rig.runner.dask_pool._stand_for("run-a", scene)
    assert rig.runner.dask_pool._stand_for("run-a", scene) is first and first.calibrations == 1
    with ThreadPoolExecutor(1) as other:
        second = other.submit(rig.runner.dask_pool._stand_for, "run-a", scene).result()
    assert second is not first and second.calibrations == 1
    for run in ("run-b", "run-c"):
        rig.runner.dask_pool._stand_for(run, scene)
    assert rig.runner.dask_pool.MAX_CACHED_RUNS == 2 and list(rig.runner.dask_pool._stands) == ["run-b", "run-c"]


def test_a_worker_with_another_friction_rig_version_fails_the_point():
    scene = parse_scene(scene_text(NO_FIGURES), name="fake")
    point = scene.procedure.points()[0]
    task = rig.runner.chunks.SimulateTask((point,), RunMetadata(scene.text, scene.seed, scene.stand, utc_timestamp()), True)
    failure = rig.runner.dask_pool._task("run-v", "0.0.0-other", scene, task).error
    assert failure.point == point and failure.kind == "WorkerError"
    assert failure.message == f"the worker has friction-rig {rig.__version__}, the client 0.0.0-other"


def test_the_cli_runs_on_a_scheduler_and_refuses_jobs_with_it(scheduler, tmp_path, capsys):
    import rig.cli

    path = tmp_path / "fake.toml"
    path.write_text(scene_text(SWEEP), encoding="utf-8")
    assert rig.cli.main(["run", str(path), "-o", str(tmp_path / "dask"), "--scheduler", scheduler]) == 1
    assert rig.cli.main(["run", str(path), "-o", str(tmp_path / "one")]) == 1
    _same_outputs(tmp_path / "one", tmp_path / "dask")
    capsys.readouterr()
    assert rig.cli.main(["run", str(path), "-o", str(tmp_path / "x"), "-j", "2", "--scheduler", scheduler]) == 2
    assert "jobs = 2 is not valid; valid: 1 with a Dask scheduler" in capsys.readouterr().err
    assert not (tmp_path / "x").exists()


@pytest.mark.parametrize("address", ["", "tcp://host :8786", 8786])
def test_a_malformed_address_is_refused(address, tmp_path):
    scene = parse_scene(scene_text(NO_FIGURES), name="fake")
    with pytest.raises(ParameterError, match="scheduler = .* a Dask scheduler address"):
        run_scene(scene, tmp_path / "run", scheduler=address, progress=False)


def test_an_unreachable_scheduler_is_a_parameter_error(monkeypatch, tmp_path):
    monkeypatch.setattr(rig.runner.dask_pool, "CONNECT_TIMEOUT_S", 0.5)
    scene = parse_scene(scene_text(NO_FIGURES), name="fake")
    with pytest.raises(ParameterError, match="scheduler = 'tcp://127.0.0.1:1' .* \\(could not connect"):
        run_scene(scene, tmp_path / "run", scheduler="tcp://127.0.0.1:1", progress=False)


def test_without_the_extra_the_error_names_it_and_the_install_command(monkeypatch, tmp_path):
    monkeypatch.setitem(sys.modules, "distributed", None)  # import distributed -> ImportError
    scene = parse_scene(scene_text(NO_FIGURES), name="fake")
    with pytest.raises(ParameterError, match=r"optional 'dask' extra .* pip install \"friction-rig\[dask\]\""):
        run_scene(scene, tmp_path / "run", scheduler="tcp://127.0.0.1:8786", progress=False)
    assert not (tmp_path / "run").exists()  # refused before anything is written


def test_a_scheduler_with_a_characteristics_scene_is_refused(tmp_path):
    scene = load_scene("contact_characteristics")
    with pytest.raises(ParameterError, match="scheduler = 'tcp://127.0.0.1:8786' .* \\(only a stand scene"):
        run_scene(scene, tmp_path / "run", scheduler="tcp://127.0.0.1:8786", progress=False)


def _settings(keys) -> dict:
    """On a worker: those Dask settings as its process holds them."""
    return {key: dask.config.get(key) for key in keys}


def _tick_ms(dask_worker=None, dask_scheduler=None) -> float:
    """On a worker or the scheduler: the interval of its running event-loop check [ms]."""
    return (dask_worker or dask_scheduler).periodic_callbacks["tick"].callback_time


def test_the_study_cluster_starts_every_process_with_the_study_config(scheduler):
    study = rig.runner.dask_pool.STUDY_CONFIG
    with Client(scheduler, set_as_default=False) as client:
        workers = client.run(_settings, list(study))
        ticks = [*client.run(_tick_ms).values(), client.run_on_scheduler(_tick_ms)]
    assert len(workers) == 2 and all(held == study for held in workers.values())
    assert ticks == [1000.0] * 3  # the running processes, not only their configuration (Dask's default: 20 ms)


def test_every_study_setting_is_a_dask_setting_it_changes():
    defaults = dask.config.merge(*dask.config.defaults)  # Dask's own defaults, without this machine's files
    for key, value in rig.runner.dask_pool.STUDY_CONFIG.items():
        assert dask.config.get(key, config=defaults) != value, key  # a renamed key would change nothing


def test_the_docs_start_workers_with_the_study_config():
    """docs/scaling.md's ``DASK_...=...`` variables for ``dask worker`` are STUDY_CONFIG, read as Dask reads them."""
    text = (REPO / "docs" / "scaling.md").read_text(encoding="utf-8")
    variables = dict(re.findall(r"\b(DASK_[A-Z_]+)=(\S+)", text))
    documented = dask.config.collect_env(variables)
    assert {key: dask.config.get(key, config=documented) for key in rig.runner.dask_pool.STUDY_CONFIG} == \
        rig.runner.dask_pool.STUDY_CONFIG
    assert len(variables) == len(rig.runner.dask_pool.STUDY_CONFIG)


@pytest.mark.parametrize("workers", [0, 257, 1.5, "2"])
def test_a_study_cluster_of_a_bad_size_is_refused(workers):
    with pytest.raises(ParameterError, match=r"workers = .* a whole number in \[1, 256\]"):
        rig.runner.dask_pool.study_cluster(workers)


def test_rig_does_not_import_dask_unless_asked():
    code = ("import sys, rig.cli.run, rig.runner, rig.runner.dask_pool; "
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('dask', 'distributed')))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


# ----------------------------------------------------------------------------- a study of a few hundred points

STUDY_POINTS = 300
KILL_WITHIN_S = 1.5  # the kill comes at a random moment this long [s] at most after the first chunk was logged
GIVE_UP_S = 120.0  # a safety net against a hung child, not a timing assertion


@pytest.fixture(scope="module")
def study_reference(tmp_path_factory):
    """The study on one process (the log written point by point, reduced whole): the reference."""
    import rig.stands

    rig.stands.STANDS["fake"] = "tests.runner.fake_stand:FakeStand"
    try:
        folder = tmp_path_factory.mktemp("study_one")
        run_scene(parse_scene(study_text(STUDY_POINTS), name="study"), folder, progress=False)
    finally:
        del rig.stands.STANDS["fake"]
    return folder


def _same_study(folder, reference) -> None:
    assert log_objects(folder / "log.h5") == log_objects(reference / "log.h5")  # every dataset, /reduced too
    assert (folder / "reduced.csv").read_text() == (reference / "reduced.csv").read_text()
    assert sorted(p.name for p in folder.iterdir()) == sorted(p.name for p in reference.iterdir())  # no staging


def test_a_study_on_two_jobs_and_on_dask_equals_one_job(study_reference, scheduler, tmp_path):
    scene = parse_scene(study_text(STUDY_POINTS), name="study")
    pool = run_scene(scene, tmp_path / "pool", jobs=2, progress=False)
    cluster = run_scene(scene, tmp_path / "dask", scheduler=scheduler, progress=False)
    assert pool.in_log == cluster.in_log == STUDY_POINTS and pool.failures == cluster.failures == ()
    _same_study(tmp_path / "pool", study_reference)
    _same_study(tmp_path / "dask", study_reference)


@pytest.mark.parametrize("where", ["jobs", "dask"])
def test_a_study_killed_at_a_random_moment_resumes_to_the_same_outputs(study_reference, scheduler, tmp_path, where):
    folder = tmp_path / "run"
    given = "2" if where == "jobs" else scheduler
    child = subprocess.Popen([sys.executable, "-m", "tests.runner.study_child", str(folder), str(STUDY_POINTS), given],
                             cwd=REPO, start_new_session=True)  # its own group: the kill takes the pool's workers too
    delay = random.uniform(0.0, KILL_WITHIN_S)
    try:
        waited = 0.0
        while not any(shard_folder(folder / "log.h5").glob("points_*.h5")) and child.poll() is None:
            assert waited < GIVE_UP_S, "the child never logged a chunk"
            time.sleep(0.01)
            waited += 0.01
        time.sleep(delay)
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(child.pid, signal.SIGKILL)
        child.wait()
    logged = STUDY_POINTS if (folder / "log.h5").exists() else _points_in_shards(folder / "log.h5")
    scene = parse_scene(study_text(STUDY_POINTS), name="study")
    report = run_scene(scene, folder, progress=False, **({"jobs": 2} if where == "jobs" else {"scheduler": scheduler}))
    killed = f"killed {delay:.2f} s after the first chunk was logged, {logged} points logged then"
    assert report.in_log == STUDY_POINTS and report.resumed == logged, killed
    _same_study(folder, study_reference)


def _points_in_shards(log) -> int:
    """Points in the complete shards a killed run left (read only: nothing is removed)."""
    total = 0
    for path in shard_folder(log).glob("points_*.h5"):
        with h5py.File(path, "r") as handle:
            total += handle["points/index"].shape[0]
    return total


@pytest.mark.parametrize("points, workers", [(1, 1), (6, 2), (300, 2), (10_000, 2), (100_000, 3)])
def test_chunks_shrink_at_the_end_so_that_the_workers_finish_together(points, workers):
    sizes = rig.runner.chunks.chunk_sizes(points, workers)
    first = rig.runner.chunks.chunk_size(points, workers)
    assert sum(sizes) == points and all(size >= 1 for size in sizes)
    assert sizes[0] == first and all(a >= b for a, b in zip(sizes, sizes[1:]))  # never growing
    smallest = min(first, rig.runner.chunks.MIN_TAIL_CHUNK)
    assert all(size >= smallest for size in sizes[:-1])  # no tiny chunks but the remainder
    # what is left when a chunk starts is at least twice the workers' chunks (then each worker's
    # last chunk is at most half of what the others still have to do), or the chunk is of the minimum
    left = points
    for size in sizes:
        assert size == left or size * 2 * workers <= left + 2 * workers - 1 or size == smallest
        left -= size
