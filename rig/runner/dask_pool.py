"""Operating points on a Dask distributed cluster (``--scheduler ADDRESS``), results identical to a serial run.

The contract of rig.runner.pool, on a cluster: the same inputs (the scene, the planned points),
the results delivered in point order, so the log, the failures and the STOP policy are those of
a serial run; an error inside a point comes back as rig.runner.pool.WorkerError naming the
point, the error type, its text and the worker's traceback.

The scene goes to the workers once (scattered); one task is a chunk of consecutive points
(rig.runner.chunks: simulated, logged as a shard and reduced on the worker; about 4 chunks per
worker thread, at most 2 048 points each, then shrinking ones), so that a study of 10^5 points is
tens to hundreds of tasks (more workers, more chunks), not 10^5 tasks each carrying the scene (the
scheduler's cost grows with the tasks). A worker thread builds its stand from the scene and
calibrates it once per run (a pure function of the run seed by the contract, so every worker holds
the records the serial run holds), then keeps it for the run's further points. Stands are kept per
(run, worker thread) - a worker with several threads never shares one stand between two points at
once - for the last MAX_CACHED_RUNS runs only.

dask and distributed are the optional extra ``dask``: they are imported when a sweep is sent to
a scheduler (or a cluster is made with :func:`study_cluster`), never on import of rig; without
them, a ParameterError names the extra and the install command. :data:`STUDY_CONFIG` is the Dask
configuration a cluster that runs studies should start with (docs/scaling.md). The workers must
import the same friction-rig version as the client (the log records the client's version; a
worker with another one fails the point) and the stand's module by its path. The logbook's
read-only records (types.MappingProxyType), which pickle refuses, travel by cloudpickle,
distributed's fallback serializer, and arrive as read-only mappings.
"""

from __future__ import annotations

import threading
import uuid
from collections import OrderedDict
from collections.abc import Callable, Sequence

import rig
from rig import validate
from rig.errors import ParameterError
from rig.runner.pool import MAX_WORKERS, WorkerError
from rig.scenes.stand_scene import StandScene
from rig.stands.base import Stand

EXTRA = "dask"
"""The optional extra of friction-rig that brings dask and distributed."""

INSTALL = 'pip install "friction-rig[dask]"'
"""The command that installs the extra."""

CONNECT_TIMEOUT_S = 30.0
"""How long to try to reach the scheduler [s]."""

MAX_CACHED_RUNS = 2
"""A worker keeps the calibrated stands of this many most recent runs."""

STUDY_CONFIG: dict[str, object] = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "5s",
    "distributed.worker.memory.monitor-interval": "1s",
}
"""Dask settings for the scheduler, nannies and workers of a cluster that runs studies: Dask's
statistical profiler off (it samples a running task's stack every 10 ms) and its monitors slowed
down - the event-loop health check from every 20 ms to every 1 s, the system monitor from every
0.5 s to every 5 s, the nanny's and worker's memory check from every 0.1 s to every 1 s. Each wakes
the worker's event loop, which then takes the interpreter from the task's thread. Measured with
``python benchmarks/bench_scale.py --points --dask-overhead 500 --ceiling-repeats 4`` (2 000 points
on each of two workers at once, about 12 s; docs/scaling.md): Dask's own threads 0.25-0.36 % of a
busy worker's CPU instead of 3.9-6.0 % with Dask's defaults, the task's thread kept waiting
0.07-0.19 s instead of 0.67-1.30 s, the scheduler and nannies 0.09-0.19 s of CPU instead of 0.50-0.92 s.
Results do not depend on it; the costs are a coarser dashboard and a memory limit enforced within
1 s instead of 0.1 s."""

_stands: OrderedDict[str, dict[int, Stand]] = OrderedDict()  # run token -> {thread id: stand}
_stands_lock = threading.Lock()


def check_scheduler(address: object, jobs: int) -> str:
    """``address`` if it can name a Dask scheduler (no spaces), ``jobs`` is 1 and the extra is
    installed (imported here, before a run writes anything), else ParameterError.

    A scheduler and ``jobs`` > 1 exclude each other: the cluster's workers set the parallelism.
    """
    if not isinstance(address, str) or not address or any(char.isspace() for char in address):
        raise ParameterError("scheduler", address, "a Dask scheduler address such as tcp://127.0.0.1:8786")
    if jobs != 1:
        raise ParameterError("jobs", jobs, "1 with a Dask scheduler (its workers set the parallelism)",
                             hint=f"scheduler = {address!r}; drop --jobs or the scheduler")
    _distributed("scheduler", address)
    return address


def _distributed(name: str, value: object):
    """The distributed package, imported now; ParameterError naming ``name`` and the extra if it is
    not installed."""
    try:
        import distributed
    except ImportError as error:
        missing = error.name or "distributed"
        raise ParameterError(name, value, f"a value used with the optional {EXTRA!r} extra installed",
                             hint=f"{missing} is not installed; install the extra with: {INSTALL}") from None
    return distributed


def study_cluster(workers: int, **options):
    """A distributed.LocalCluster on this machine made for studies: ``workers`` worker processes of one
    thread each (a point is CPU-bound Python), started with :data:`STUDY_CONFIG`, no dashboard;
    ``options`` go to LocalCluster (e.g. ``env``, ``dashboard_address``). Use it as a context manager
    and pass its ``scheduler_address`` as ``scheduler`` (rig.run, ``rig run --scheduler``)."""
    workers = validate.integer("workers", workers, 1, MAX_WORKERS)
    cluster_class = _distributed("workers", workers).LocalCluster
    import dask  # installed with distributed

    options = {"threads_per_worker": 1, "processes": True, "dashboard_address": None, **options}
    with dask.config.set(STUDY_CONFIG):  # read when the scheduler, nannies and workers start
        return cluster_class(n_workers=workers, **options)


def _stand_for(run: str, scene: StandScene) -> Stand:
    """This thread's calibrated stand of run ``run`` (built and calibrated on first use)."""
    thread = threading.get_ident()
    with _stands_lock:
        stand = _stands.get(run, {}).get(thread)
    if stand is not None:
        return stand
    stand = scene.build_stand()
    stand.calibrate(scene.seed)
    with _stands_lock:
        _stands.setdefault(run, {})[thread] = stand
        _stands.move_to_end(run)
        while len(_stands) > MAX_CACHED_RUNS:
            _stands.popitem(last=False)
    return stand


def _task(run: str, version: str, scene: StandScene, task):
    """A chunk task (rig.runner.chunks) on a worker, with this thread's calibrated stand."""
    from rig.runner.chunks import failed, run_task

    if rig.__version__ != version:
        return failed(task, WorkerError(f"the worker has friction-rig {rig.__version__}, the client {version}"))
    try:
        stand = _stand_for(run, scene)
    except Exception as error:  # noqa: BLE001 - the stand failed to build or calibrate on the worker
        return failed(task, error)
    return run_task(stand, scene, task)


def _what(task) -> str:
    """A chunk task named in an error: its first point (and how many follow it)."""
    points = getattr(task, "points", None)
    if points is None:
        return f"the reduction of the logged points from point {task.first} on"
    point = points[0]
    more = f" (and the {len(points) - 1} after it in its chunk)" if len(points) > 1 else ""
    return f"point {point.index} {dict(point.settings)}{more}"


def run_dask_tasks(scene: StandScene, make_tasks: Callable[[int], Sequence], address: str,
                   deliver: Callable[[object], bool]) -> None:
    """Do the tasks ``make_tasks(worker threads)`` (rig.runner.chunks) on the cluster of the scheduler
    at ``address``; ``deliver`` gets each result in task order and returns True to end the sweep there
    (the tasks not needed are cancelled). The scene goes to the workers once."""
    client = _connect(address)
    run = uuid.uuid4().hex
    futures: list = []
    try:
        tasks = make_tasks(max(1, sum(client.nthreads().values())))
        shared = client.scatter(scene, broadcast=True, hash=False)  # once, not with every task
        futures = [client.submit(_task, run, rig.__version__, shared, task, key=f"rig-chunk-{i}-{run}")
                   for i, task in enumerate(tasks)]
        for i, future in enumerate(futures):
            try:
                result = future.result()
            except Exception as error:  # noqa: BLE001 - a worker died, the task was lost or not (un)picklable
                raise WorkerError(f"{_what(tasks[i])}: the Dask cluster did not run it "
                                  f"({type(error).__name__}: {error})") from error
            future.release()  # the worker may forget a chunk once it is read (a large study's memory)
            futures[i] = None
            if deliver(result):
                break
    finally:
        pending = [future for future in futures if future is not None]
        if pending:
            client.cancel(pending)
        client.close()


def _connect(address: str):
    """A distributed.Client of the scheduler at ``address`` (not made the default client)."""
    client_class = _distributed("scheduler", address).Client
    try:
        return client_class(address, timeout=CONNECT_TIMEOUT_S, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as error:
        reason = str(error)  # raised below, outside this block: the half-made client is not kept alive
    raise ParameterError("scheduler", address, "the address of a running Dask scheduler, e.g. tcp://127.0.0.1:8786",
                         hint=f"could not connect: {reason}")

