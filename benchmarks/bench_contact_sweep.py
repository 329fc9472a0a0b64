"""The kinematic model's accuracy over the stands' whole range: n = 16 / 24 / 32 against converged
values, and the converged values against independent ones.

    python benchmarks/bench_contact_sweep.py [--grids 16 24 32] [--jobs 2] [--markdown FILE]

States: b/a in (0.1, 0.3, 1, 3, 10) x alpha' in (0.1, 0.3, 1, 3, 10, 32.5, 100, 325, 1000) x rolling
point C = (c/a, l/a) in ((0, 0): pure spin; (0.5, 0.5): offset inside the contact; (-1, 1): outside),
nu = 0.28. The converged value of each state is Richardson's extrapolation of n = 32 / 64 / 128 with
the observed order and its own uncertainty (Roache's grid convergence index, factor of safety 1.25;
where the steps change sign or the order is outside 0.5 ... 3, the finest value with three times
the last step: rig.contact.numerical_error.richardson). A state passes when its error plus the
reference's uncertainty is within the goal |d nu_v| <= 0.002, |d nu_0| <= 0.004.

Independent values (second table): Kalker's exact theory as CONTACT computes it, extrapolated to zero
element size (circle, pure spin, alpha' = 3, 10.23, 20.5, 102.3; tests/contact/data/
contact_fortran_pure_spin.toml, with its uncertainty); rigid sliding about the centre of the circle,
nu_0 = 3 pi/16 (alpha' = 1e-3); linear theory with Kalker's C23 (Table E.3, 3 digits) for nu_v of
pure spin at alpha' = 1e4 (the nonlinear part is below 1e-4 relative there). Accuracy only (no
timing): contended machines give the same numbers.
"""

from __future__ import annotations

import argparse
import datetime
import itertools
import json
import os
import platform
import sys
import tomllib
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np

from rig.contact.numerical_error import FULL_SLIDING_SPIN_MOMENT_CIRCLE, REFERENCE_GRIDS, richardson
from rig.contact.solve import DEFAULT_N, solve
from rig.errors import ConvergenceError

SHAPES = (0.1, 0.3, 1.0, 3.0, 10.0)
ALPHAS = (0.1, 0.3, 1.0, 3.0, 10.0, 32.5, 100.0, 325.0, 1000.0)
POINTS = ((0.0, 0.0), (0.5, 0.5), (-1.0, 1.0))
GOAL = (0.002, 0.004)  # |d nu_v|, |d nu_0| at the default grid
POISSON = 0.28
FALLBACK_GRIDS = (16, 32, 64)  # the reference's grids where the solver does not converge on n = 128
# b/a = 10's grid at n = 128 has 768 x 192 cells (rig.contact.grid: rows and columns of a wide contact), and
# a partial-slip solve there takes minutes: its reference is n = 16 / 32 / 64 (up to 384 x 96 cells)
WIDE = 10.0


def reference_grids(b: float) -> tuple[int, int, int]:
    """The three grids of a state's converged reference."""
    return FALLBACK_GRIDS if b >= WIDE else REFERENCE_GRIDS
CONTACT_TOML = Path(__file__).resolve().parents[1] / "tests" / "contact" / "data" / "contact_fortran_pure_spin.toml"


def nu(b: float, alpha: float, c: float, l: float, n: int, model: str = "kinematic") -> np.ndarray:
    """(nu_v, nu_0) [1] of one state; NaN (and a line on stderr) where the solver does not converge."""
    try:
        r = solve(model, shape="ellipse", b_over_a=b, alpha=alpha, c_over_a=c, l_over_a=l, poisson=POISSON, n=n)
    except ConvergenceError as error:
        print(f"b/a {b:g} alpha' {alpha:g} C ({c:g}, {l:g}) n = {n}: {error}", file=sys.stderr, flush=True)
        return np.full(2, np.nan)
    return np.array([r.nu_v, r.nu_0])


def _state(args):
    (b, alpha, c, l), grids = args
    values = {n: nu(b, alpha, c, l, n) for n in sorted(set(grids) | set(reference_grids(b)) | set(FALLBACK_GRIDS))}
    print(f"b/a {b:g} alpha' {alpha:g} C ({c:g}, {l:g}): " + ", ".join(
        f"n {n} {v[0]:.5f} {v[1]:.5f}" for n, v in values.items()), file=sys.stderr, flush=True)
    return values


def sweep(grids, jobs: int):
    """{(b, alpha, c, l): {n: (nu_v, nu_0)}} over the whole sweep (the widest contacts first: they take longest)."""
    states = list(itertools.product(SHAPES, ALPHAS, POINTS))
    keys = sorted(((b, a, c, l) for b, a, (c, l) in states), key=lambda k: (-k[0], -k[1]))
    work = [(k, tuple(grids)) for k in keys]
    if jobs > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            solved = list(pool.map(_state, work))
    else:
        solved = [_state(w) for w in work]
    found = dict(zip(keys, solved))
    return {(b, a, c, l): found[(b, a, c, l)] for b, a, (c, l) in states}


def contact_limits() -> list[tuple[float, np.ndarray, np.ndarray]]:
    """(alpha', (nu_v, nu_0) limit, uncertainty) of CONTACT's extrapolated pure-spin values (circle)."""
    table = tomllib.loads(CONTACT_TOML.read_text())["extrapolation"]
    alphas = sorted({key.rsplit("_nu_", 1)[0] for key in table if key.startswith("a")},
                    key=lambda k: float(k[1:].replace("_", ".")))
    return [(float(k[1:].replace("_", ".")),
             np.array([table[f"{k}_nu_v"]["limit"], table[f"{k}_nu_0"]["limit"]]),
             np.array([table[f"{k}_nu_v"]["uncertainty"], table[f"{k}_nu_0"]["uncertainty"]])) for k in alphas]


def independent_rows() -> list[tuple]:
    """(what, quantity, independent value, its uncertainty, converged ours, its uncertainty, n = 32 ours)."""
    rows = []
    for alpha, limit, unc in contact_limits():
        solved = [nu(1.0, alpha, 0.0, 0.0, n) for n in (*REFERENCE_GRIDS, DEFAULT_N)]
        ref = richardson(*solved[:3])
        for k, name in enumerate(("nu_v", "nu_0")):
            rows.append((f"circle, pure spin, alpha' {alpha:g}: CONTACT extrapolated", name, limit[k], unc[k],
                         ref.limit[k], ref.uncertainty[k], solved[3][k]))
    solved = [nu(1.0, 1e-3, 0.0, 0.0, n) for n in (*REFERENCE_GRIDS, DEFAULT_N)]
    ref = richardson(*solved[:3])
    # rigid sliding differs from alpha' = 1e-3 by O(alpha'^2) in nu_0 (nu_v moves at O(alpha'))
    rows.append(("circle, pure spin, alpha' 1e-3: rigid sliding 3 pi/16", "nu_0", FULL_SLIDING_SPIN_MOMENT_CIRCLE,
                 0.0, ref.limit[1], ref.uncertainty[1], solved[3][1]))
    for b in SHAPES:
        linear = nu(b, 1e4, 0.0, 0.0, DEFAULT_N, model="linear")[0]
        solved = [nu(b, 1e4, 0.0, 0.0, n) for n in (*reference_grids(b), DEFAULT_N)]
        ref = richardson(*solved[:3])
        # Kalker's table: 3 significant digits, half a unit of the last as the uncertainty
        rows.append((f"b/a {b:g}, pure spin, alpha' 1e4: linear theory, Kalker's C23", "nu_v", linear,
                     5e-3 * abs(linear), ref.limit[0], ref.uncertainty[0], solved[3][0]))
    return rows


def header() -> str:
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    return (f"Generated {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC on {platform.node()} "
            f"({os.cpu_count()} cores, {platform.machine()}), load average {load} at the end (accuracy only: "
            f"the load does not change the numbers).")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--grids", type=int, nargs="+", default=[16, 24, 32])
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--markdown", type=Path)
    parser.add_argument("--save", type=Path, help="also write the solved values (JSON) to this file")
    parser.add_argument("--load", type=Path, help="take the solved values from a --save file instead of solving")
    args = parser.parse_args()
    if args.load:
        stored = json.loads(args.load.read_text())
        solved = {tuple(s["state"]): {int(n): np.array(v, dtype=float) for n, v in s["values"].items()}
                  for s in stored["sweep"]}
        checks = [tuple(row) for row in stored["independent"]]
    else:
        solved = sweep(args.grids, args.jobs)
        checks = independent_rows()
    if args.save:
        args.save.write_text(json.dumps({"sweep": [{"state": list(k), "values": {str(n): [float(x) for x in v]
                                                                                  for n, v in vals.items()}}
                                                   for k, vals in solved.items()],
                                         "independent": [list(row) for row in checks]}))
    worst = {}
    state_lines = []
    fallbacks = []
    unconverged: set[str] = set()
    for (b, alpha, c, l), values in solved.items():
        ref = richardson(*(values[n] for n in reference_grids(b)))
        if not np.all(np.isfinite(ref.limit)) and reference_grids(b) != FALLBACK_GRIDS:
            ref = richardson(*(values[n] for n in FALLBACK_GRIDS))  # the solver did not converge on n = 128
            fallbacks.append(f"b/a {b:g}, alpha' {alpha:g}, C ({c:g}, {l:g})")
        for n in args.grids:
            for k, d in enumerate(np.abs(values[n] - ref.limit)):
                key = (n, b, k)
                if not np.isfinite(d):
                    unconverged.add(f"b/a {b:g}, alpha' {alpha:g}, C ({c:g}, {l:g})")
                    continue
                if d + ref.uncertainty[k] > sum(worst.get(key, (-1.0, 0.0))[:2]):
                    worst[key] = (d, ref.uncertainty[k], alpha, c, l)
        state_lines.append(
            f"b/a {b:g} alpha' {alpha:g} C ({c:g}, {l:g}): converged nu_v {ref.limit[0]:.5f} +- "
            f"{ref.uncertainty[0]:.5f} (order {ref.order[0]:.2f}), nu_0 {ref.limit[1]:.5f} +- {ref.uncertainty[1]:.5f} "
            f"(order {ref.order[1]:.2f}); n = {DEFAULT_N}: {values[DEFAULT_N][0]:.5f}, {values[DEFAULT_N][1]:.5f}")
    print("\n".join(state_lines))
    lines = ["| n | b/a | max abs(d nu_v) + reference's uncertainty (at alpha', c/a, l/a) "
             "| max abs(d nu_0) + reference's uncertainty (at) | within 0.002 / 0.004 |", "|---|---|---|---|---|"]
    for n in args.grids:
        for b in SHAPES:
            dv, d0 = worst[(n, b, 0)], worst[(n, b, 1)]
            ok = "yes" if dv[0] + dv[1] <= GOAL[0] and d0[0] + d0[1] <= GOAL[1] else "no"
            cells = [f"{d[0]:.4f} + {d[1]:.4f} ({d[2]:g}, {d[3]:g}, {d[4]:g})" for d in (dv, d0)]
            lines.append(f"| {n}{' (default)' if n == DEFAULT_N else ''} | {b:g} | {cells[0]} | {cells[1]} | {ok} |")
    lines += ["", "Reference grids: n = 32 / 64 / 128; for b/a = 10 n = 16 / 32 / 64 (its n = 128 grid has 768 x 192 "
              "cells)."]
    if fallbacks:
        lines += ["", f"Reference from n = 16 / 32 / 64 (Newton did not converge on n = 128) at: {'; '.join(fallbacks)}."]
    if not unconverged:
        lines += ["", f"Every one of the {len(solved)} states has a converged value: Newton converged on each grid of "
                  "its reference."]
    if unconverged:
        lines += ["", "No converged value (Newton did not converge within its step limit on a grid of the reference): "
                  + "; ".join(sorted(unconverged)) + "."]
    table = "\n".join(lines)
    independent = ["| independent value | quantity | value +- its uncertainty | converged (ours) +- | "
                   "converged - value | n = 32 - value |", "|---|---|---|---|---|---|"]
    for what, name, value, unc, ref, ref_unc, at32 in checks:
        independent.append(f"| {what} | {name} | {value:.5f} +- {unc:.5f} | {ref:.5f} +- {ref_unc:.5f} | "
                           f"{ref - value:+.5f} | {at32 - value:+.5f} |")
    table2 = "\n".join(independent)
    print(table + "\n\n" + table2)
    if args.markdown:
        args.markdown.write_text(
            f"<!-- generated by: python benchmarks/bench_contact_sweep.py --markdown {args.markdown} -->\n"
            "# The kinematic model against converged and independent values\n\n" + header() + "\n\n"
            "## The default grid against converged values\n\n"
            "Pure spin and offset spin (C = (0.5, 0.5) a inside, (-1, 1) a outside the contact) over b/a 0.1 - 10 and\n"
            "alpha' 0.1 - 1000 (135 states, nu = 0.28): the largest error of nu_v and nu_0 at each grid n against\n"
            "the state's converged value - Richardson's extrapolation of n = 32 / 64 / 128 (b/a = 10: 16 / 32 / 64) with the observed order,\n"
            "whose own uncertainty (Roache's grid convergence index, factor of safety 1.25) is added to the error\n"
            "(rig.contact.numerical_error.richardson). Goal: |d nu_v| <= 0.002, |d nu_0| <= 0.004.\n\n"
            + table + "\n\n"
            "## Converged values against independent ones\n\n"
            "Kalker's exact theory from CONTACT extrapolated to zero element size (uncertainty from its own grid\n"
            "sequence), rigid sliding's closed form 3 pi/16, and linear theory with Kalker's C23 (3 digits).\n\n"
            + table2 + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
