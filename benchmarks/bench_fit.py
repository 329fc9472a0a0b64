"""Wall time of `rig fit` on the fig10 campaign (48 points, mu and Psi free), warm table cache.

    python benchmarks/bench_fit.py [--repeats 3] [--run-dir DIR]

Runs `python -m rig run fig10` once (or uses --run-dir with its reduced.csv and log.h5), then
`python -m rig fit DIR/reduced.csv --params mu,psi` once to fill the table cache (the five Psi
node tables per b/a; reported as "first"), then --repeats times warm, each a fresh process in a
new output folder. The baseline, measured in the same invocation, is `python -m rig scenes`
(start-up and imports), so the ratio says how the fit compares on whatever the machine is doing.
Reported: median wall and CPU time of the child [s], load average, the budget (issue 10,
acceptance 4: <= 60 s wall warm on 2 cores). Never asserts: a benchmark reports.
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

BUDGET_S = 60.0  # issue 10, acceptance 4


def timed(command: list[str]) -> dict[str, float]:
    """One command in a fresh process: wall [s], CPU of the child [s], load average before [1]."""
    load = os.getloadavg()[0]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        print(f"warning: `{' '.join(command)}` exited with {done.returncode}:\n{done.stderr[-2000:]}", file=sys.stderr)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall": wall, "cpu": cpu, "load": load}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--run-dir", type=Path, default=None, help="an existing `rig run fig10` output folder")
    args = parser.parse_args()
    rig = [sys.executable, "-m", "rig"]
    with tempfile.TemporaryDirectory(prefix="bench_fit_") as tmp:
        run_dir = args.run_dir
        if run_dir is None:
            run_dir = Path(tmp) / "fig10"
            print("simulating fig10 ...", flush=True)
            timed(rig + ["run", "fig10", "-o", str(run_dir)])
        fit = rig + ["fit", str(run_dir / "reduced.csv"), "--params", "mu,psi", "--no-plot"]
        first = timed(fit + ["-o", str(Path(tmp) / "first")])
        warm = [timed(fit + ["-o", str(Path(tmp) / f"warm{k}")]) for k in range(args.repeats)]
        base = [timed(rig + ["scenes"]) for _ in range(args.repeats)]
    med = {key: statistics.median(r[key] for r in warm) for key in ("wall", "cpu", "load")}
    base_wall = statistics.median(r["wall"] for r in base)
    print("rig fit fig10 reduced.csv --params mu,psi (48 points, 2 free, nested sets mu / mu + psi, profiles)")
    print(f"  first run (fills the Psi-node table cache if cold): {first['wall']:.1f} s wall, {first['cpu']:.1f} s CPU")
    print(f"  warm: median {med['wall']:.1f} s wall, {med['cpu']:.1f} s CPU over {args.repeats} runs "
          f"(load average {med['load']:.1f})")
    print(f"  baseline `rig scenes`: median {base_wall:.2f} s wall; ratio fit/baseline {med['wall'] / base_wall:.1f}")
    print(f"  budget (acceptance 4): <= {BUDGET_S:.0f} s wall warm: {'met' if med['wall'] <= BUDGET_S else 'NOT met'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
