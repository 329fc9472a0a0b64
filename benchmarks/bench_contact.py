"""What accuracy costs in the contact model: median time per solve and error, per model and grid.

    python benchmarks/bench_contact.py [--repeats 3] [--markdown docs/accuracy-contact.md]

Part 1 (model ladder): for each model and n in (16, 24, 32, 48), the median wall time of one
solve over six partial-slip states of the circle (alpha' = 3, 10, 30; pure spin and C = (0.4, 0.5) a)
and the largest deviation of nu_T, nu_v, nu_0 from the same model converged (Richardson's
extrapolation of n = 32 / 64 / 128 with the observed order). The baseline of the
time ratios is the rigid model at n = 32, measured in the same run (its row of the table).

Part 2 (kinematic grid study): for the circle and b/a = 0.1 and 10, pure spin at alpha' = 20.5
(about half the area sticking), the error of nu_v and nu_0 for n = 8 ... 128 against the solver's
converged value (Richardson's extrapolation of n = 32 / 64 / 128 with the observed order and its own
uncertainty, rig.contact.numerical_error.richardson, as benchmarks/bench_contact_sweep.py takes it;
stated in the table), and the median time per solve; for the
circle also against Kalker's exact theory converged (CONTACT's limit 0.4518, 0.2623 at alpha' = 20.5;
tests/contact/data/contact_fortran_pure_spin.toml), and the growth of the time from n = 32 (issue 9:
<= 25x from n = 32 to 128, n^2 log n).

Part 3 (solver work): issue 9's time goal (<= 10 ms per partial-slip solve for the circle, <= 30 ms
for b/a = 0.1 and 10 at the default n = 32) on ten partial-slip states: median wall and CPU time, Newton
steps and GMRES products (the counts are load-independent). ``--work-only`` prints this part alone,
e.g. for a baseline from another checkout in the same session: ``PYTHONPATH=OLD python
benchmarks/bench_contact.py --work-only``.

Part 4 (against the established program): CONTACT's pure-spin runs at alpha' = 20.5 from the committed
table (tests/contact/data/contact_fortran_pure_spin.csv: CPU seconds of its own build, measured in the
session that made the table) beside ours at n = 16 ... 64 from part 2, each with its error against
CONTACT's converged limit.
"""

from __future__ import annotations

import argparse
import csv
import datetime
import os
import platform
import statistics
import time
from pathlib import Path

import numpy as np
from rig.contact.numerical_error import richardson
from rig.contact.solve import DEFAULT_N, solve

STATES = [dict(alpha=a, c_over_a=c, l_over_a=l) for a in (3.0, 10.0, 30.0) for c, l in ((0.0, 0.0), (0.4, 0.5))]
GRIDS = (16, 24, 32, 48)
FINE = 128
MODELS = ("rigid", "linear", "fastsim", "kinematic")
STUDY_SHAPES = (1.0, 0.1, 10.0)
STUDY_GRIDS = (8, 16, 24, 32, 48, 64, 128)
EXACT_CIRCLE = (0.4518, 0.2623)  # CONTACT extrapolated to zero element size, pure spin, alpha' = 20.5, nu = 0.28
STUDY_STATE = dict(alpha=20.5, c_over_a=0.0, l_over_a=0.0)
# part 3: (b/a, alpha', c/a, l/a), partial slip
WORK_STATES = [(1.0, 20.5, 0.0, 0.0), (1.0, 3.0, 0.4, 0.5), (1.0, 30.0, 0.4, 0.5), (1.0, 0.3, 0.0, 0.0),
               (1.0, 200.0, 0.0, 0.0), (0.1, 20.5, 0.0, 0.0), (0.1, 1.0, 0.5, 0.5), (10.0, 20.5, 0.0, 0.0),
               (10.0, 100.0, -1.0, 1.0), (10.0, 1.0, 0.5, 0.5)]
CONTACT_TABLE = Path(__file__).resolve().parents[1] / "tests" / "contact" / "data" / "contact_fortran_pure_spin.csv"


def _solve(model: str, n: int, state: dict, b_over_a: float = 1.0):
    return solve(model, shape="ellipse", b_over_a=b_over_a, poisson=0.28, n=n, **state)


def median_time(call, repeats: int, clock=time.perf_counter) -> float:
    """Median time of ``call()`` on ``clock`` over ``repeats`` runs after one warm-up [s]."""
    call()
    samples = []
    for _ in range(repeats):
        start = clock()
        call()
        samples.append(clock() - start)
    return statistics.median(samples)


def _nu3(r) -> np.ndarray:
    return np.array([r.nu_T, r.nu_v, r.nu_0])


def ladder(repeats: int) -> list[tuple]:
    """(model, n, median ms per solve, ratio to rigid n=32, max error vs the model converged) rows; the
    converged value of each state is Richardson's extrapolation of n = 32 / 64 / FINE (observed order)."""
    measured = []
    for model in MODELS:
        reference = [richardson(*(_nu3(_solve(model, m, s)) for m in (FINE // 4, FINE // 2, FINE))).limit
                     for s in STATES]
        for n in GRIDS:
            t = median_time(lambda: [_solve(model, n, s) for s in STATES], repeats) / len(STATES)
            error = max(float(np.max(np.abs(_nu3(_solve(model, n, s)) - f))) for s, f in zip(STATES, reference))
            measured.append((model, n, t, error))
    baseline = next(t for model, n, t, _ in measured if (model, n) == ("rigid", 32))
    return [(model, n, t * 1e3, t / baseline, error) for model, n, t, error in measured]


def grid_study(repeats: int) -> list[tuple]:
    """(b/a, n, |d nu_v|, |d nu_0| vs the extrapolated value, median ms, extrapolated nu_v, nu_0, their
    uncertainties, d nu_v and d nu_0 vs exact theory or None) rows."""
    rows = []
    for b in STUDY_SHAPES:
        solved = {n: _solve("kinematic", n, STUDY_STATE, b) for n in STUDY_GRIDS}
        ref = richardson(*(np.array([solved[n].nu_v, solved[n].nu_0]) for n in (32, 64, 128)))
        (ref_v, ref_0), (unc_v, unc_0) = ref.limit, ref.uncertainty
        for n, r in solved.items():
            t = median_time(lambda: _solve("kinematic", n, STUDY_STATE, b), repeats)
            exact = (r.nu_v - EXACT_CIRCLE[0], r.nu_0 - EXACT_CIRCLE[1]) if b == 1.0 else (None, None)
            rows.append((b, n, abs(r.nu_v - ref_v), abs(r.nu_0 - ref_0), t * 1e3, ref_v, ref_0, unc_v, unc_0, *exact))
    return rows


def solver_work(repeats: int) -> list[tuple]:
    """(b/a, alpha', c/a, l/a, median wall ms, median CPU ms, Newton steps, GMRES products) at n = DEFAULT_N."""
    rows = []
    for b, alpha, c, l in WORK_STATES:
        state = dict(alpha=alpha, c_over_a=c, l_over_a=l)
        r = _solve("kinematic", DEFAULT_N, state, b)
        wall = median_time(lambda: _solve("kinematic", DEFAULT_N, state, b), repeats)
        cpu = median_time(lambda: _solve("kinematic", DEFAULT_N, state, b), repeats, time.process_time)
        rows.append((b, alpha, c, l, wall * 1e3, cpu * 1e3, r.info["newton_iterations"], r.info["krylov_iterations"]))
    return rows


def against_contact(study: list[tuple]) -> list[tuple]:
    """(program, cells across 2a, d nu_v, d nu_0 vs CONTACT's limit, ms per solve) at alpha' = 20.5, circle."""
    with CONTACT_TABLE.open() as f:
        theirs = [("CONTACT", int(row["elements_across"]), float(row["nu_v"]) - EXACT_CIRCLE[0],
                   float(row["nu_0"]) - EXACT_CIRCLE[1], float(row["cpu_s"]) * 1e3)
                  for row in csv.DictReader(f) if float(row["alpha_prime"]) == STUDY_STATE["alpha"]]
    ours = [("friction-rig kinematic", n, ev, e0, t) for b, n, _, _, t, _, _, _, _, ev, e0 in study
            if b == 1.0 and 16 <= n <= 64]
    return theirs + ours


def header() -> str:
    """Date, machine and load of the run (the times depend on them; ratios within one run less)."""
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    return (f"Generated {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC on {platform.node()} "
            f"({os.cpu_count()} cores, {platform.machine()}), load average {load} at the end.")


def _signed(value) -> str:
    return "" if value is None else f"{value:+.4f}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--markdown", type=Path, help="also write the tables to this markdown file")
    parser.add_argument("--work-only", action="store_true",
                        help="part 3 alone (e.g. for another checkout: PYTHONPATH=OTHER python benchmarks/bench_contact.py --work-only)")
    args = parser.parse_args()
    table3 = "\n".join(
        ["| b/a | alpha' | c/a, l/a | median wall ms | median CPU ms | Newton steps | GMRES products |",
         "|---|---|---|---|---|---|---|"]
        + [f"| {b:g} | {a:g} | {c:g}, {l:g} | {w:.1f} | {cpu:.1f} | {newton} | {krylov} |"
           for b, a, c, l, w, cpu, newton, krylov in solver_work(args.repeats)]
    )
    if args.work_only:
        print(table3)
        return 0
    rows = ladder(args.repeats)
    table1 = "\n".join(
        ["| model | n | median time per solve [ms] | ratio to rigid n=32 | max error vs the model converged |", "|---|---|---|---|---|"]
        + [f"| {m} | {n} | {t:.1f} | {r:.1f} | {e:.4f} |" for m, n, t, r, e in rows]
    )
    study = grid_study(args.repeats)
    at_default = {b: t for b, n, _, _, t, *_ in study if n == DEFAULT_N}
    table2 = "\n".join(
        ["| b/a | n | abs(d nu_v) | abs(d nu_0) | median ms per solve | time / time at n = 32 "
         "| converged nu_v, nu_0 (32/64/128 extrapolated) +- own uncertainty | d nu_v, d nu_0 vs exact theory |",
         "|---|---|---|---|---|---|---|---|"]
        + [f"| {b:g} | {n}{' (default)' if n == DEFAULT_N else ''} | {dv:.4f} | {d0:.4f} | {t:.1f} | {t / at_default[b]:.2f} "
           f"| {rv:.4f} +- {uv:.4f}, {r0:.4f} +- {u0:.4f} | {_signed(ev)} {_signed(e0)} |"
           for b, n, dv, d0, t, rv, r0, uv, u0, ev, e0 in study]
    )
    table4 = "\n".join(
        ["| program | cells across 2a | d nu_v | d nu_0 | ms per solve |", "|---|---|---|---|---|"]
        + [f"| {name} | {n} | {ev:+.4f} | {e0:+.4f} | {t:.1f} |" for name, n, ev, e0, t in against_contact(study)]
    )
    print("\n\n".join([table1, table2, table3, table4]))
    if args.markdown:
        args.markdown.write_text(
            "<!-- generated by: python benchmarks/bench_contact.py --markdown docs/accuracy-contact.md -->\n"
            "# What accuracy costs in the contact model\n\n" + header() + "\n\n"
            "## The model ladder\n\n"
            "Median wall time of one solve over six partial-slip states (Hertz circle, alpha' = 3, 10, 30;\n"
            "pure spin and C = (0.4, 0.5) a), against the largest deviation of nu_T, nu_v, nu_0 from the\n"
            "same model converged (Richardson's extrapolation of n = 32 / 64 / 128 with the observed order) -\n"
            "the discretisation error bought with the grid, not the model's distance from exact theory. 2-core machine,\n"
            f"median of {args.repeats} repeats; ratios against the rigid model at n = 32 in the same run.\n"
            "rigid and fastsim errors are those of their own quadrature/march; linear has no grid.\n\n"
            + table1 + "\n\n"
            "## The kinematic model's grid study\n\n"
            "Pure spin at alpha' = 20.5 (about half the area sticking), nu = 0.28, for the circle and the\n"
            "ellipses b/a = 0.1 and 10; errors against the solver's converged value (Richardson's\n"
            "extrapolation of n = 32 / 64 / 128 with the observed order, its own uncertainty in the table), and for the circle also\n"
            "against Kalker's exact theory converged (CONTACT's limit 0.4518 +- 0.0004, 0.2623 +- 0.001;\n"
            "docs/contact-convergence.md). The time column's ratio shows the growth with the grid (the solver's\n"
            "goal: <= 25x from n = 32 to 128, n^2 log n; a wide contact's grid has 4.5 times the cells of the circle's).\n\n"
            + table2 + "\n\n"
            "## Solver work at the default grid\n\n"
            f"Ten partial-slip states at n = {DEFAULT_N}; the solver's goal is <= 10 ms for the circle and <= 30 ms for\n"
            f"b/a = 0.1 and 10 on a quiet machine. Median of {args.repeats} (wall and CPU); counts are load-independent.\n\n"
            + table3 + "\n\n"
            "## Against the established program\n\n"
            "Kalker's exact theory as CONTACT computes it (pure spin, circle, alpha' = 20.5; its CPU time from\n"
            "tests/contact/data/contact_fortran_pure_spin.csv, a gfortran build without MKL measured on this\n"
            "machine type in another session) and ours from the grid study above; errors against CONTACT's\n"
            "own converged limit (0.4518 +- 0.0004, 0.2623 +- 0.001).\n\n"
            + table4 + "\n"
        )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
