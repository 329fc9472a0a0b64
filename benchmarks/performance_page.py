"""Regenerate docs/performance.md: what the tool costs, measured now on this machine.

    python benchmarks/performance_page.py [--repeats 3] [--out docs/performance.md]

Runs quick versions of the benchmarks (a minute or two): the start-up of the `rig` command, one kinematic contact
solve at n = 16/32/64 (the growth with n is a ratio measured in one run), and `rig run default` warm (the contact
table from the cache) with its CPU time. Writes the page with one header line: date, machine, load average. The
full benchmarks (bench_contact.py, bench_fig10.py, bench_scale.py, ...) measure more; their commands are listed on
the page.
"""

from __future__ import annotations

import argparse
import datetime
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
RIG = [sys.executable, "-m", "rig"]


def _child_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed_command(command: list[str], repeats: int, cwd: Path) -> tuple[float, float]:
    """Median wall and CPU time [s] of a command run ``repeats`` times."""
    walls, cpus = [], []
    for _ in range(repeats):
        cpu0, wall0 = _child_cpu(), time.perf_counter()
        subprocess.run(command, cwd=cwd, check=True, capture_output=True)
        walls.append(time.perf_counter() - wall0)
        cpus.append(_child_cpu() - cpu0)
    return statistics.median(walls), statistics.median(cpus)


def contact_solves(repeats: int) -> list[tuple[int, float]]:
    """Median time [s] of one kinematic solve (circle, pure spin, alpha' = 20.5) per n, after a warm-up."""
    from rig.contact import solve

    arguments = dict(shape="ellipse", b_over_a=1.0, alpha=20.5, c_over_a=0.0, l_over_a=0.0, poisson=0.28)
    rows = []
    for n in (16, 32, 64):
        solve("kinematic", n=n, **arguments)
        times = []
        for _ in range(max(repeats, 3)):
            start = time.perf_counter()
            solve("kinematic", n=n, **arguments)
            times.append(time.perf_counter() - start)
        rows.append((n, statistics.median(times)))
    return rows


def header() -> str:
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    machine = f"{platform.machine()}, {os.cpu_count()} CPUs, Python {platform.python_version()}"
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    return f"Measured {date} on {machine}; load average {load} (1, 5, 15 min)."


def page(repeats: int) -> str:
    with tempfile.TemporaryDirectory() as work:
        work = Path(work)
        help_wall, help_cpu = timed_command(RIG + ["--help"], repeats, work)
        scenes_wall, scenes_cpu = timed_command(RIG + ["scenes"], repeats, work)
        timed_command(RIG + ["run", "default", "-o", str(work / "warm")], 1, work)  # fills the table cache
        runs = [timed_command(RIG + ["run", "default", "-o", str(work / f"run{i}")], 1, work) for i in range(repeats)]
        run_wall = statistics.median(w for w, _ in runs)
        run_cpu = statistics.median(c for _, c in runs)
    solves = contact_solves(repeats)
    base = solves[1][1]
    lines = [
        "# Performance",
        "",
        header(),
        "",
        "Written by `python benchmarks/performance_page.py`; do not edit by hand. Medians of "
        f"{repeats} runs. On a shared machine, compare the ratios measured in one run rather than absolute times.",
        "",
        "## Start-up and a default run",
        "",
        "| command | wall [s] | CPU [s] |",
        "|---|---|---|",
        f"| `rig --help` | {help_wall:.3f} | {help_cpu:.3f} |",
        f"| `rig scenes` | {scenes_wall:.3f} | {scenes_cpu:.3f} |",
        f"| `rig run default` (9 points, contact table cached) | {run_wall:.2f} | {run_cpu:.2f} |",
        "",
        "## One contact solve",
        "",
        "Kinematic model, Hertz circle, pure spin at alpha' = 20.5, Poisson's ratio 0.28, after a warm-up solve.",
        "",
        "| n (cells across 2a) | time [ms] | relative to n = 32 |",
        "|---|---|---|",
        *[f"| {n} | {t * 1e3:.1f} | {t / base:.2f} |" for n, t in solves],
        "",
        "## The full benchmarks",
        "",
        "| what | command |",
        "|---|---|",
        "| contact solves over shapes and states, with accuracy | `python benchmarks/bench_contact.py` |",
        "| `rig run fig10`, cold and warm | `python benchmarks/bench_fig10.py` |",
        "| studies of many points, processes, Dask | `python benchmarks/bench_scale.py` |",
        "| stand A / stand B against real time | `python benchmarks/bench_stand_a.py`, `python benchmarks/bench_stand_b.py` |",
        "| `rig fit` | `python benchmarks/bench_fit.py` |",
        "| start-up of the `rig` command | `python benchmarks/bench_startup.py` |",
        "",
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3, help="runs per measurement (default 3)")
    parser.add_argument("--out", type=Path, default=ROOT / "docs" / "performance.md", help="the page to write")
    args = parser.parse_args(argv)
    text = page(args.repeats)
    temporary = args.out.with_suffix(".md.tmp")
    temporary.write_text(text, encoding="utf-8")
    temporary.replace(args.out)
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
