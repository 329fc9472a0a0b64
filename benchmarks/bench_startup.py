"""CPU time of starting the command: ``rig --help`` and ``rig scenes`` (goal: <= 0.5 s each).

Each command runs in a fresh subprocess (``python -m rig ...``, output discarded), REPEATS times;
the CPU time (user + system) of the child comes from ``resource.getrusage(RUSAGE_CHILDREN)``
before and after. Printed: the median and the range per command, and the machine's load average
(CPU time is less sensitive to load than wall time, but not immune: caches and frequency scaling).

    python benchmarks/bench_startup.py [--repeats N]
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys

COMMANDS = (["--help"], ["scenes"])
GOAL_S = 0.5


def child_cpu_s(argv: list[str]) -> float:
    """CPU seconds (user + system) of one ``python -m rig ARGV`` run."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([sys.executable, "-m", "rig", *argv], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=7, help="runs per command (default 7)")
    repeats = parser.parse_args().repeats
    child_cpu_s(["--help"])  # warm the file cache and the bytecode once
    print(f"load average {' '.join(f'{x:.2f}' for x in os.getloadavg())}, {os.cpu_count()} CPUs, "
          f"Python {sys.version.split()[0]}, {repeats} runs each")
    worst = 0.0
    for argv in COMMANDS:
        times = [child_cpu_s(argv) for _ in range(repeats)]
        median = statistics.median(times)
        worst = max(worst, median)
        print(f"rig {' '.join(argv):<8} CPU median {median:.3f} s (min {min(times):.3f}, max {max(times):.3f})")
    print(f"goal <= {GOAL_S} s: {'met' if worst <= GOAL_S else 'NOT met'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
