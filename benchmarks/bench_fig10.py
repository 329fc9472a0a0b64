"""Wall time of `rig run fig10`, cold (empty table cache) and warm, against a baseline scene.

    python benchmarks/bench_fig10.py [--scene fig10] [--baseline default] [--repeats 3] [--cold 1]
                                     [--jobs 1] [--markdown FILE]

Each run is the command a user types, `python -m rig run SCENE -o DIR` in a fresh process (imports,
table build or load, the sweep, reduction, figures, summary), into a new temporary folder:
* cold: RIG_CACHE_DIR points at a new empty folder, so the surrogate tables are built;
* warm: RIG_CACHE_DIR is a folder the first cold run filled, so they are loaded.
The baseline (default: the `default` scene, warm) is measured in the same invocation, so the ratio
scene/baseline says how the scene compares on whatever the machine is doing; wall times on a
shared machine are not the machine's speed - the CPU time of the child process (user + sys) and the
load average before each run are reported beside them. Reported: median wall and CPU time per
configuration [s], the ratio of medians to the baseline, the budget (issue 5: <= 60 s wall for
fig10 on 2 cores). Never asserts: a benchmark reports.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BUDGET_S = 60.0  # issue 5, acceptance 5: `rig run fig10` <= 60 s wall on 2 cores


def run_once(scene: str, cache: Path, jobs: int) -> dict[str, float]:
    """One `python -m rig run` in a fresh process: wall [s], CPU of the child [s], load average [1]."""
    load = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with tempfile.TemporaryDirectory(prefix="bench_fig10_out_") as out:
        env = os.environ | {"RIG_CACHE_DIR": str(cache)}
        command = [sys.executable, "-m", "rig", "run", scene, "-o", out, "--jobs", str(jobs)]
        t0 = time.perf_counter()
        done = subprocess.run(command, env=env, capture_output=True, text=True)
        wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        print(f"warning: `{' '.join(command)}` exited with {done.returncode}:\n{done.stderr[-2000:]}", file=sys.stderr)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall": wall, "cpu": cpu, "load": load, "status": float(done.returncode)}


def median_of(runs: list[dict[str, float]], key: str) -> float:
    return statistics.median(r[key] for r in runs)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="fig10", help="scene name or path (default fig10)")
    parser.add_argument("--baseline", default="default", help="baseline scene, run warm (default: default)")
    parser.add_argument("--repeats", type=int, default=3, help="warm runs of the scene and of the baseline")
    parser.add_argument("--cold", type=int, default=1, help="cold runs (each builds every table again)")
    parser.add_argument("--jobs", type=int, default=1, help="--jobs of `rig run` (default 1)")
    parser.add_argument("--markdown", type=Path, help="also write the table to this markdown file")
    args = parser.parse_args()
    rows = {}
    with tempfile.TemporaryDirectory(prefix="bench_fig10_cache_") as shared:
        cold = []
        for k in range(max(args.cold, 1)):
            cache = Path(shared) / ("warm" if k == 0 else f"cold{k}")
            cold.append(run_once(args.scene, cache, args.jobs))  # the first one fills the warm cache
        rows[f"{args.scene}, cold cache"] = cold
        warm_cache = Path(shared) / "warm"
        rows[f"{args.scene}, warm cache"] = [run_once(args.scene, warm_cache, args.jobs) for _ in range(args.repeats)]
        run_once(args.baseline, warm_cache, 1)  # fill the baseline's tables (not timed)
        rows[f"{args.baseline} (baseline), warm"] = [run_once(args.baseline, warm_cache, 1)
                                                     for _ in range(args.repeats)]
    base_wall = median_of(rows[f"{args.baseline} (baseline), warm"], "wall")
    base_cpu = median_of(rows[f"{args.baseline} (baseline), warm"], "cpu")
    lines = [f"`rig run {args.scene}` (--jobs {args.jobs}) on {os.cpu_count()} cores; budget {BUDGET_S:g} s wall",
             "", "| configuration | runs | wall median [s] | CPU median [s] | wall / baseline | CPU / baseline "
             "| load avg before | exit status |", "|---|---|---|---|---|---|---|---|"]
    for name, runs in rows.items():
        wall, cpu = median_of(runs, "wall"), median_of(runs, "cpu")
        loads = ", ".join(f"{r['load']:.1f}" for r in runs)
        status = ", ".join(f"{r['status']:g}" for r in runs)
        lines.append(f"| {name} | {len(runs)} | {wall:.1f} | {cpu:.1f} | {wall / base_wall:.1f} | "
                     f"{cpu / base_cpu:.1f} | {loads} | {status} |")
    cold_wall = median_of(rows[f"{args.scene}, cold cache"], "wall")
    warm_wall = median_of(rows[f"{args.scene}, warm cache"], "wall")
    lines += ["", f"budget: cold {cold_wall:.1f} s, warm {warm_wall:.1f} s of {BUDGET_S:g} s wall "
              f"({'within' if max(cold_wall, warm_wall) <= BUDGET_S else 'OVER'} budget on this machine now)"]
    text = "\n".join(lines)
    print(text)
    if args.markdown:
        args.markdown.write_text(text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
