"""Cost of a study per operating point: time and log bytes for 100 / 1 600 / 10 000 points, and how a
study scales out on worker processes.

    python benchmarks/bench_scale.py [--points 100 1600 10000] [--repeats 1] [--jobs 1] [--gate-time 4.0]
                                     [--study 100000] [--study-workers 2] [--scaling 10000]
                                     [--scaling-runs j1 j2 cluster [cluster-defaults]] [--scaling-repeats 1]
                                     [--peak-memory]
                                     [--ceiling 256] [--dask-overhead 200 [--dask-overhead-rounds 2]]

The scene is the built-in `default` (stand A, quasi-static drive, 4 s gates, instruments on)
with only the sweep's `num` raised (issue 12). Each run is `python -m rig run SCENE -o DIR` in a
fresh process (imports, the table from a warm cache, the sweep, log, reduction, figure, summary);
the packages are byte-compiled first, as an installed wheel is (ensure_bytecode).
Reported per size: median wall time [s] and its spread over the repeats, the time per point
[ms], the marginal time per point between sizes [ms] (linear growth: the marginal cost does not
rise with the size), log.h5 [bytes], the raw samples the points really record (dynamometer and
balance channels: 8 bytes a sample), the log's overhead beyond them [bytes per point] and the
time to read every group of the log as DataFrames, one call each (rig.logbook's settings,
readings, counters, calibration and the truth) [s].

``--study N`` runs a large study of N points as a user would run it, twice: on a Dask
LocalCluster of ``--study-workers`` single-thread worker processes (`rig run --scheduler`) and
with ``-j`` ``--study-workers`` (a local process pool), and prints points per second, CPU time
(the workers' included) and bytes per point. ``--points`` with no sizes skips the table. On a
shared machine wall times are noisy: the CPU time and the load average before each run are
printed beside them. Never asserts: a benchmark reports.

``--scaling N`` runs a study of N points three times side by side: ``-j 1``, ``-j 2`` and on a Dask
LocalCluster of two single-thread worker processes, each `rig run` (the API's run_scene) in a fresh
process. Per run: wall time, the parent's CPU time (the process that runs the study: it stores the
workers' shards, merges them into log.h5, writes reduced.csv, the figure and the summary) and the
workers' CPU time (the pool's processes, or the cluster's workers measured on the workers), per
point [ms]; the serial fraction s = parent CPU / (parent + workers CPU) - the part of the study no
worker can take over - and Amdahl's projection of the wall time and speed-up on 8, 32 and 128
workers, wall(p) = total CPU (s + (1 - s)/p); the speed-up of ``-j 2`` and of the cluster over
``-j 1`` measured in the same run, and the load average before each run. ``--scaling-repeats R``
runs the three R times in turn and states the median speed-up and serial fraction (the machine's
own speed drifts by some 10 % between minutes; a round's three runs share it). ``--peak-memory`` adds
the parent's peak resident memory [MB] of each run (ru_maxrss). The LocalCluster is made as
docs/scaling.md advises for studies (rig.runner.dask_pool.study_cluster: Dask's profiler off, its
monitors slowed down); ``--scaling-runs ... cluster-defaults`` adds one with Dask's defaults.

``--ceiling N`` measures what two processes can gain on this machine at most: a chunk of N points
simulated, logged and reduced as a worker does it (no pool, no cluster, no parent), repeated, in
one process alone and then in two processes at once; it prints the CPU time per point of each
(equal when two busy cores do not slow each other down) and the speed-up of two processes over
one, the ceiling of the ``-j 2`` and cluster speed-ups (which add the parent's serial part and
the workers' start).

``--dask-overhead N`` measures what Dask's own activity costs a busy worker: the same chunk work
on each worker of a two-worker LocalCluster at once, with the study configuration
(rig.runner.dask_pool.STUDY_CONFIG) and with Dask's defaults, alternating; per worker the share
of its CPU outside the task's thread (Dask's threads) and how long the task's thread waited
(wall time - its CPU time), and the CPU time of the scheduler and the nannies.
"""

from __future__ import annotations

import argparse
import math
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import h5py

BUDGET_S_1600 = 10.0  # issue 12: 1 600 points <= 10 s with -j 1
BUDGET_OVERHEAD_B = 1024.0  # issue 12: <= 1 KB per point beyond the raw samples
BUDGET_FRAMES_S = 0.5  # issue 12: a group of 1 600 points as a DataFrame in one call, <= 0.5 s
BUDGET_PARENT_SHARE = 0.05  # issue 29: the parent's CPU <= 5 % of the study's CPU (10 000 points)
BUDGET_SPEEDUP_2 = 1.6  # issue 29: -j 2 and a two-worker LocalCluster >= 1.6x faster than -j 1 (idle 2 cores)


def scene_file(folder: Path, points: int, gate_time_s: float) -> Path:
    """The default scene with ``points`` brake set-points (and the gate time given)."""
    from rig.scenes import load_scene

    text = load_scene("default").text
    sweep, gate = "num = 9 }", "gate_time_s = 4.0 "
    assert sweep in text and gate in text, "the default scene changed; update bench_scale.py"
    path = folder / f"scale_{points}.toml"
    path.write_text(text.replace(sweep, f"num = {points} }}").replace(gate, f"gate_time_s = {gate_time_s} "))
    return path


def raw_sample_bytes(log: Path) -> int:
    """Bytes of the samples the points record (8 per float64 sample), either log layout."""
    total = 0
    with h5py.File(log, "r") as f:
        if f.attrs["format_version"] >= 2:
            for channel in f["points/channels"].values():
                total += channel["samples"].size * 8
        else:
            for point in f["points"].values():
                total += sum(ds.size * 8 for ds in point["channels"].values())
    return total


def frames_s(log: Path) -> float:
    """Wall time [s] to read the log's groups as DataFrames, one call per group."""
    from rig.logbook import read_calibration, read_counters, read_readings, read_settings
    from rig.logbook.truth import read_truth

    t0 = time.perf_counter()
    for read in (read_settings, read_readings, read_counters, read_calibration, read_truth):
        read(log)
    return time.perf_counter() - t0


def run_once(scene: Path, jobs: int, extra: list[str] | None = None) -> dict[str, float]:
    """One `python -m rig run` in a fresh process: wall, CPU [s], load average, log bytes, and the
    time to read the log's groups as DataFrames [s]."""
    load = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryDirectory(prefix="bench_scale_") as out:
        command = [sys.executable, "-m", "rig", "run", str(scene), "-o", out, "--jobs", str(jobs), *(extra or [])]
        t0 = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True)
        wall = time.perf_counter() - t0
        log = Path(out) / "log.h5"
        size = log.stat().st_size if log.exists() else 0
        raw = raw_sample_bytes(log) if log.exists() else 0
        frames = frames_s(log) if log.exists() else math.nan
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        print(f"warning: `{' '.join(command)}` exited with {done.returncode}:\n{done.stderr[-2000:]}", file=sys.stderr)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall": wall, "cpu": cpu, "load": load, "size": size, "raw": raw, "frames": frames}


def local_cluster(workers: int, study: bool = True):
    """A LocalCluster of ``workers`` one-thread worker processes: with the study configuration
    (rig.runner.dask_pool.study_cluster, as docs/scaling.md advises), or with Dask's defaults."""
    from distributed import LocalCluster

    from rig.runner.dask_pool import study_cluster

    if study:
        return study_cluster(workers)
    return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)


def dask_run(scene: Path, workers: int) -> dict[str, float]:
    """The scene on a LocalCluster of ``workers`` one-thread worker processes; CPU time includes the
    workers' (counted when the cluster has closed them)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with local_cluster(workers) as cluster:
        run = run_once(scene, 1, ["--scheduler", cluster.scheduler_address])
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    run["cpu"] = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return run


def child_run(scene: str, out: str, where: str) -> int:
    """In a fresh process (``--child``): run the study with ``-j`` ``where`` or on the scheduler at
    address ``where``; print the wall time, this process's CPU time and its children's (the pool's
    workers) [s] and its peak resident memory [MB] as one line of JSON."""
    import json

    from rig.runner import run_scene
    from rig.scenes import load_scene

    t0 = time.perf_counter()
    options = {"jobs": int(where)} if where.isdigit() else {"scheduler": where}
    report = run_scene(load_scene(scene), Path(out), progress=False, **options)
    wall = time.perf_counter() - t0
    me, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    print(json.dumps({"wall": wall, "parent": me.ru_utime + me.ru_stime, "pool": children.ru_utime + children.ru_stime,
                      "maxrss_MB": me.ru_maxrss / 1024.0, "in_log": report.in_log}))
    return 0


def _workers_cpu() -> float:
    """CPU time [s] of this worker process so far (run on every worker of the cluster)."""
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def scaling_run(scene: Path, where: str, client=None) -> dict[str, float]:
    """One study in a fresh process (see child_run); with ``client`` (the LocalCluster's), the
    workers' CPU time is measured on the workers, before and after."""
    import json

    load = os.getloadavg()[0]
    before = sum(client.run(_workers_cpu).values()) if client is not None else 0.0
    with tempfile.TemporaryDirectory(prefix="bench_scale_") as out:
        command = [sys.executable, __file__, "--child", str(scene), out, where]
        done = subprocess.run(command, capture_output=True, text=True)
        log = Path(out) / "log.h5"
        size = log.stat().st_size if log.exists() else 0
    if done.returncode != 0:
        raise SystemExit(f"`{' '.join(command)}` exited with {done.returncode}:\n{done.stderr[-3000:]}")
    run = json.loads(done.stdout.strip().splitlines()[-1])
    run["workers"] = run.pop("pool") if client is None else sum(client.run(_workers_cpu).values()) - before
    run["load"], run["size"] = load, size
    return run


def amdahl_wall(total_cpu: float, serial: float, workers: int) -> float:
    """Amdahl's law: the wall time [s] of work ``total_cpu`` [s] whose fraction ``serial`` runs on one
    process, the rest shared by ``workers`` processes."""
    return total_cpu * (serial + (1.0 - serial) / workers)


SCALING_RUNS = {"j1": "-j 1", "j2": "-j 2", "cluster": "LocalCluster 2 workers",
                "cluster-defaults": "LocalCluster, Dask defaults"}


def scaling(points: int, gate_time_s: float, folder: Path, peak_memory: bool, which: list[str], repeats: int = 1) -> None:
    """-j 1, -j 2 and a two-worker LocalCluster (those of ``which``) side by side on a study of
    ``points`` points, ``repeats`` rounds (each round runs them one after the other, so that a change of
    the machine's speed between rounds falls on all three); the speed-ups are per round, then their median."""
    scene = scene_file(folder, points, gate_time_s)
    rounds: list[dict[str, dict]] = []
    for _ in range(repeats):
        runs = {}
        if "j1" in which:
            runs["-j 1"] = scaling_run(scene, "1")
        if "j2" in which:
            runs["-j 2"] = scaling_run(scene, "2")
        for key in ("cluster", "cluster-defaults"):
            if key in which:
                from distributed import Client

                with local_cluster(2, study=key == "cluster") as cluster, \
                        Client(cluster.scheduler_address, set_as_default=False) as client:
                    runs[SCALING_RUNS[key]] = scaling_run(scene, cluster.scheduler_address, client)
        rounds.append(runs)
    print(f"\nscaling: {points} points, the default scene (gate {gate_time_s:g} s); parent = the process that runs "
          f"the study, workers = the pool's processes or the cluster's workers; {repeats} round(s)")
    print(f"{'round':>5} {'run':>27} {'wall [s]':>9} {'load':>5} {'parent [ms/pt]':>14} {'workers [ms/pt]':>15} "
          f"{'total [ms/pt]':>13} {'serial s':>8} {'speed-up':>8}" + (f" {'peak [MB]':>9}" if peak_memory else ""))
    for k, runs in enumerate(rounds, 1):
        base = runs["-j 1"]["wall"] if "-j 1" in runs else math.nan
        for label, run in runs.items():
            total = run["parent"] + run["workers"]
            ratio = "-" if math.isnan(base) else f"{base / run['wall']:.2f}x"
            print(f"{k:>5} {label:>27} {run['wall']:>9.2f} {run['load']:>5.2f} {1e3 * run['parent'] / points:>14.3f} "
                  f"{1e3 * run['workers'] / points:>15.3f} {1e3 * total / points:>13.3f} {run['parent'] / total:>8.4f} "
                  f"{ratio:>8}" + (f" {run['maxrss_MB']:>9.0f}" if peak_memory else ""))
    for label in [SCALING_RUNS[key] for key in ("j2", "cluster", "cluster-defaults") if SCALING_RUNS[key] in rounds[0]]:
        serials = [runs[label]["parent"] / (runs[label]["parent"] + runs[label]["workers"]) for runs in rounds]
        speedups = [runs["-j 1"]["wall"] / runs[label]["wall"] if "-j 1" in runs else math.nan for runs in rounds]
        serial, speedup = statistics.median(serials), statistics.median(speedups)
        run = rounds[-1][label]
        total = run["parent"] + run["workers"]
        projection = ", ".join(f"{p} workers {amdahl_wall(total, serial, p):.1f} s ({1.0 / (serial + (1 - serial) / p):.1f}x)"
                               for p in (8, 32, 128))
        versus = "" if math.isnan(speedup) else (
            f"speed-up over -j 1 {speedup:.2f}x, median of " + ", ".join(f"{s:.2f}" for s in speedups) +
            f" ({verdict(speedup >= BUDGET_SPEEDUP_2)} the budget {BUDGET_SPEEDUP_2:g}x on an idle 2-core machine); ")
        print(f"{label}: parent CPU {100 * serial:.2f} % of the study's CPU, median of {repeats} "
              f"({verdict(serial <= BUDGET_PARENT_SHARE)} the budget {100 * BUDGET_PARENT_SHARE:g} %); {versus}"
              f"Amdahl: {projection}")


def chunk_work(scene: str, repeats: int) -> dict[str, float]:
    """Simulate, log and reduce the scene's points as one chunk (rig.runner.chunks, as a worker does)
    once to warm up, then ``repeats`` times: the repeats' CPU time of this process and of this thread,
    and their wall time [s]."""
    from rig.logbook import RunMetadata, utc_timestamp
    from rig.runner.chunks import SimulateTask, run_task
    from rig.scenes import load_scene

    loaded = load_scene(scene)
    stand = loaded.build_stand()
    stand.calibrate(loaded.seed)
    task = SimulateTask(tuple(loaded.procedure.points()),
                        RunMetadata(loaded.text, loaded.seed, loaded.stand, utc_timestamp()), True)
    run_task(stand, loaded, task)
    cpu, thread, wall = time.process_time(), time.thread_time(), time.perf_counter()
    for _ in range(repeats):
        run_task(stand, loaded, task)
    return {"cpu": time.process_time() - cpu, "thread": time.thread_time() - thread, "wall": time.perf_counter() - wall}


def ceiling_child(scene: str, repeats: int) -> int:
    """In a fresh process (``--ceiling-child``): chunk_work, printed as one line of JSON."""
    import json

    print(json.dumps(chunk_work(scene, repeats)))
    return 0


def dask_overhead(points: int, repeats: int, rounds: int, gate_time_s: float, folder: Path) -> None:
    """What Dask's own activity costs a study's workers: on a two-worker LocalCluster with the study
    configuration and on one with Dask's defaults (alternating, ``rounds`` times), each worker runs
    chunk_work (a chunk of ``points`` points, ``repeats`` times) at once; per worker, the share of its
    process's CPU spent outside the task's thread (Dask's threads) and the time the task's thread
    waited (wall - its CPU: for the interpreter or a core) [s]; and the CPU of the scheduler and the
    nannies (this process) [s]."""
    from distributed import Client

    scene = str(scene_file(folder, points, gate_time_s))
    print(f"\nDask's own cost: a chunk of {points} points x {repeats} on each of two workers at once, {rounds} round(s)")
    print(f"{'round':>5} {'cluster':>14} {'load':>5} {'Dask threads [% of a worker]':>29} {'task waited [s]':>16} "
          f"{'scheduler + nannies [s]':>23}")
    for k in range(1, rounds + 1):
        for study in (True, False):
            load = os.getloadavg()[0]
            with local_cluster(2, study=study) as cluster, Client(cluster.scheduler_address, set_as_default=False) as client:
                before = resource.getrusage(resource.RUSAGE_SELF)
                futures = [client.submit(chunk_work, scene, repeats, workers=[address], pure=False)
                           for address in client.nthreads()]
                runs = client.gather(futures)
                after = resource.getrusage(resource.RUSAGE_SELF)
            own = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
            threads = ", ".join(f"{100 * (run['cpu'] - run['thread']) / run['cpu']:.2f}" for run in runs)
            waited = ", ".join(f"{run['wall'] - run['thread']:.2f}" for run in runs)
            label = "study" if study else "Dask defaults"
            print(f"{k:>5} {label:>14} {load:>5.2f} {threads:>29} {waited:>16} {own:>23.2f}")


def ceiling(points: int, repeats: int, gate_time_s: float, folder: Path) -> None:
    """The most two processes can gain on this machine: the same chunk work (``points`` points,
    ``repeats`` times, after a warm-up) in one process alone, then in two processes at once; the
    CPU time per point of each and the speed-up of two processes (twice the work) over one."""
    import json

    scene = scene_file(folder, points, gate_time_s)
    command = [sys.executable, __file__, "--ceiling-child", str(scene), str(repeats)]
    print(f"\nceiling: a chunk of {points} points x {repeats} (simulate, log, reduce: a worker's work, no pool, "
          "no cluster) in 1 process, then in 2 processes at once")
    results = {}
    for processes in (1, 2):
        load = os.getloadavg()[0]
        t0 = time.perf_counter()
        children = [subprocess.Popen(command, stdout=subprocess.PIPE, text=True) for _ in range(processes)]
        runs = [json.loads(child.communicate()[0].strip().splitlines()[-1]) for child in children]
        results[processes] = max(run["wall"] for run in runs)
        print(f"{processes} process(es): load {load:.2f}, CPU per point " + ", ".join(
            f"{1e3 * run['cpu'] / (points * repeats):.3f} ms" for run in runs) + f" (wall of the repeats "
              + ", ".join(f"{run['wall']:.2f} s" for run in runs) + f"; whole {time.perf_counter() - t0:.2f} s)")
    print(f"two processes do twice the work in {results[2] / results[1]:.2f} times the wall time of one: the "
          f"ceiling of a speed-up on 2 workers here is {2 * results[1] / results[2]:.2f}x")


PACKAGES = ("rig", "sensors", "paramcheck")
"""friction-rig's installed packages (pyproject.toml)."""


def ensure_bytecode() -> None:
    """Byte-compile friction-rig's packages, as pip does when it installs the wheel, so that every
    measured process imports them as from an installed package: where PYTHONDONTWRITEBYTECODE is set
    (as on the machines this ran on), an editable install's processes would each compile them from
    source again (about 0.2 s of CPU a process: the parent and every worker)."""
    import compileall
    import importlib.util

    for name in PACKAGES:
        compileall.compile_dir(Path(importlib.util.find_spec(name).origin).parent, quiet=1)


def verdict(met: bool) -> str:
    """A budget's verdict as printed."""
    return "met" if met else "NOT met"


def study_line(label: str, points: int, run: dict[str, float]) -> str:
    """One line of a large study's result."""
    return (f"{label}: {points} points in {run['wall']:.1f} s (CPU {run['cpu']:.0f} s, load {run['load']:.1f}) = "
            f"{points / run['wall']:.0f} points/s, log {run['size']} B = {run['size'] / points:.0f} B/point "
            f"({(run['size'] - run['raw']) / points:.0f} B/point beyond the raw samples)")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--points", type=int, nargs="*", default=[100, 1600, 10000], help="study sizes (none: skip)")
    parser.add_argument("--repeats", type=int, default=1, help="runs per size (median reported)")
    parser.add_argument("--jobs", type=int, default=1, help="--jobs of `rig run` (default 1)")
    parser.add_argument("--gate-time", type=float, default=4.0, help="gate time [s] (default 4, the scene's)")
    parser.add_argument("--study", type=int, default=0,
                        help="also run this many points on a Dask LocalCluster and with a process pool")
    parser.add_argument("--study-workers", type=int, default=2,
                        help="workers of the LocalCluster and of the pool (-j) of the study (default 2)")
    parser.add_argument("--scaling", type=int, default=0,
                        help="also run this many points with -j 1, -j 2 and on a two-worker LocalCluster side by side")
    parser.add_argument("--peak-memory", action="store_true", help="print the parent's peak memory of each --scaling run")
    parser.add_argument("--scaling-repeats", type=int, default=1,
                        help="rounds of the --scaling runs (speed-ups per round, then their median; default 1)")
    parser.add_argument("--scaling-runs", nargs="+", choices=sorted(SCALING_RUNS), default=["j1", "j2", "cluster"],
                        help="which --scaling runs (default: -j 1, -j 2 and the LocalCluster with the study "
                             "configuration; cluster-defaults: a LocalCluster with Dask's default configuration)")
    parser.add_argument("--ceiling", type=int, default=0, metavar="POINTS",
                        help="also measure the ceiling of two processes: a chunk of POINTS points in 1 process, "
                             "then in 2 at once")
    parser.add_argument("--ceiling-repeats", type=int, default=10,
                        help="repeats of the --ceiling and --dask-overhead chunk (default 10)")
    parser.add_argument("--dask-overhead", type=int, default=0, metavar="POINTS",
                        help="also measure Dask's own cost on its workers: a chunk of POINTS points on each of two "
                             "workers, with the study configuration and with Dask's defaults")
    parser.add_argument("--dask-overhead-rounds", type=int, default=2,
                        help="alternating rounds of --dask-overhead (default 2)")
    parser.add_argument("--ceiling-child", nargs=2, metavar=("SCENE", "REPEATS"), help=argparse.SUPPRESS)
    parser.add_argument("--child", nargs=3, metavar=("SCENE", "OUT", "WHERE"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        return child_run(*args.child)
    if args.ceiling_child:
        return ceiling_child(args.ceiling_child[0], int(args.ceiling_child[1]))

    ensure_bytecode()
    with tempfile.TemporaryDirectory(prefix="bench_scale_scenes_") as folder:
        warm = scene_file(Path(folder), 3, args.gate_time)
        run_once(warm, 1)  # fills the table cache: every size below runs warm
        print(f"default scene, gate {args.gate_time:g} s, --jobs {args.jobs}, {args.repeats} run(s) per size; "
              "wall times on a shared machine are noisy (CPU time and load average beside them)")
        print(f"{'points':>7} {'wall [s]':>9} {'spread':>7} {'CPU [s]':>8} {'load':>5} {'ms/point':>9} "
              f"{'marginal':>9} {'log [B]':>11} {'raw [B/pt]':>10} {'overhead [B/pt]':>15} {'frames [s]':>10}")
        previous = None
        for n in args.points:
            scene = scene_file(Path(folder), n, args.gate_time)
            runs = [run_once(scene, args.jobs) for _ in range(args.repeats)]
            wall = statistics.median(r["wall"] for r in runs)
            spread = max(r["wall"] for r in runs) - min(r["wall"] for r in runs)
            cpu = statistics.median(r["cpu"] for r in runs)
            size, raw = runs[0]["size"], runs[0]["raw"]
            frames = statistics.median(r["frames"] for r in runs)
            marginal = "" if previous is None else f"{1e3 * (wall - previous[1]) / (n - previous[0]):.2f}"
            print(f"{n:>7} {wall:>9.2f} {spread:>7.2f} {cpu:>8.2f} {runs[0]['load']:>5.2f} {1e3 * wall / n:>9.2f} "
                  f"{marginal:>9} {size:>11} {raw / n:>10.0f} {(size - raw) / n:>15.0f} {frames:>10.3f}")
            previous = (n, wall)
            if n == 1600:
                print(f"        budget: 1 600 points <= {BUDGET_S_1600:g} s ({verdict(wall <= BUDGET_S_1600)}), "
                      f"overhead <= {BUDGET_OVERHEAD_B:g} B/point ({verdict((size - raw) / n <= BUDGET_OVERHEAD_B)}), "
                      f"every group as a DataFrame <= {BUDGET_FRAMES_S:g} s ({verdict(frames <= BUDGET_FRAMES_S)})")
        if args.study:
            scene = scene_file(Path(folder), args.study, args.gate_time)
            print(study_line(f"Dask LocalCluster, {args.study_workers} workers", args.study,
                             dask_run(scene, args.study_workers)))
            print(study_line(f"-j {args.study_workers}", args.study, run_once(scene, args.study_workers)))
        if args.ceiling:
            ceiling(args.ceiling, args.ceiling_repeats, args.gate_time, Path(folder))
        if args.dask_overhead:
            dask_overhead(args.dask_overhead, args.ceiling_repeats, args.dask_overhead_rounds, args.gate_time,
                          Path(folder))
        if args.scaling:
            scaling(args.scaling, args.gate_time, Path(folder), args.peak_memory, args.scaling_runs,
                    args.scaling_repeats)
    return 0


if __name__ == "__main__":
    sys.exit(main())
