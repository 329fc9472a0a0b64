"""Peak memory and wall time of `rig fit` on a large synthetic reduced table (10^5 rows by default).

    python benchmarks/bench_fit_scaling.py [--rows 100000] [--run-dir DIR] [--baseline-rows 1000]

Runs `python -m rig run fig10` once (or uses --run-dir, a finished stand-A run folder), then writes
a reduced.csv of --rows rows beside a copy of its log.h5: the run's own points repeated in turn,
their F_y jittered by the independent part of their u (seeded), so every row is a point of the log
with its settings, calibration and zero-drift age. Then `python -m rig fit reduced.csv --params mu
--no-plot` in a fresh process for the large table and for --baseline-rows rows, and reports each
child's peak resident memory (resource.getrusage(RUSAGE_CHILDREN).ru_maxrss, one child at a time)
and wall time, with the load average. The fit holds the calibration and drift covariance in O(N)
form (rig.fit.covariance), so memory grows linearly with the rows. Budget: <= 2 GB peak at 10^5
rows. Never asserts: a benchmark reports.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import pandas as pd

BUDGET_BYTES = 2 * 1024**3


def synthetic_table(run_dir: Path, rows: int, folder: Path, seed: int = 1) -> Path:
    """folder/reduced.csv with ``rows`` rows cycling through the run's points (log.h5 copied beside it)."""
    table = pd.read_csv(run_dir / "reduced.csv")
    table = table[np.isfinite(table[["l_over_a", "F_y_N", "i_k"]]).all(axis=1)]
    big = table.iloc[np.arange(rows) % len(table)].reset_index(drop=True)
    rng = np.random.default_rng(seed)
    big["F_y_N"] = big["F_y_N"] + 0.01 * big["u_F_y_N"] * rng.standard_normal(rows)
    folder.mkdir(parents=True, exist_ok=True)
    shutil.copy(run_dir / "log.h5", folder / "log.h5")
    big.to_csv(folder / "reduced.csv", index=False)
    return folder / "reduced.csv"


def measured(command: list[str]) -> dict[str, float]:
    """Run one child; its wall time [s], peak RSS [bytes] and the load average before it."""
    load = os.getloadavg()[0]
    script = ("import resource, subprocess, sys; done = subprocess.run(sys.argv[1:]); "
              "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, done.returncode)")
    t0 = time.perf_counter()
    out = subprocess.run([sys.executable, "-c", script, *command], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    rss_kb, code = out.stdout.split()[-2:]
    if code != "0":
        print(f"warning: exit {code}: {out.stderr[-1500:]}", file=sys.stderr)
    return {"wall": wall, "rss": 1024.0 * float(rss_kb), "load": load, "exit": int(code)}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rows", type=int, default=100_000)
    parser.add_argument("--baseline-rows", type=int, default=1000)
    parser.add_argument("--run-dir", type=Path, default=None, help="a finished stand-A run folder (log.h5, reduced.csv)")
    args = parser.parse_args()
    rig = [sys.executable, "-m", "rig"]
    with tempfile.TemporaryDirectory(prefix="bench_fit_scaling_") as tmp:
        run_dir = args.run_dir
        if run_dir is None:
            run_dir = Path(tmp) / "fig10"
            print("simulating fig10 ...", flush=True)
            subprocess.run(rig + ["run", "fig10", "-o", str(run_dir)], check=True, capture_output=True)
        results = {}
        for rows in (args.baseline_rows, args.rows):
            data = synthetic_table(run_dir, rows, Path(tmp) / f"rows_{rows}")
            results[rows] = measured(rig + ["fit", str(data), "--params", "mu", "--no-plot",
                                            "-o", str(Path(tmp) / f"out_{rows}")])
            r = results[rows]
            print(f"rig fit on {rows} rows: exit {r['exit']}, peak RSS {r['rss'] / 2**20:.0f} MiB, wall "
                  f"{r['wall']:.1f} s (load average {r['load']:.1f})", flush=True)
    small, large = results[args.baseline_rows], results[args.rows]
    extra = (large["rss"] - small["rss"]) / (args.rows - args.baseline_rows)
    print(f"memory per extra row: {extra:.0f} B; an N x N float matrix would take {8 * args.rows**2 / 2**30:.0f} GiB")
    print(f"budget: <= {BUDGET_BYTES / 2**30:.0f} GiB peak at {args.rows} rows: "
          f"{'met' if large['rss'] <= BUDGET_BYTES and large['exit'] == 0 else 'NOT met'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
