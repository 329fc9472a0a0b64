"""What a surrogate table costs and how accurate it is, against direct calls measured in the same run.

    python benchmarks/bench_surrogate.py [--model kinematic --n 16 --shape line --b-over-a 1]
        [--resolutions 21,5,5 41,9,9 61,13,13] [--samples 200] [--workers 2] [--markdown FILE]

Stand-A-like domain (Equations §3.1): l/a in [-1.5, 1.5], c/a in [0, 0.9], alpha' in [0.3, 3].
For each table resolution (nodes along l/a, c/a, log alpha'): build time (no cache), median
time per evaluation - scalar (law(l, c, alpha) with floats, and with the Jacobian) and vectorised
(per point, over all samples) - and the largest and mean absolute error of nu_T, nu_v, nu_0 against
direct solve() calls at random points (seeded), inside the domain and, separately, on the bridge
0 < alpha' < 0.3; for scale, the model's own grid error (the same states solved with 2n). The
column "PCHIP" is the error of a monotone-cubic (PCHIP) interpolation of the same node values
(scipy RegularGridInterpolator), the alternative the table does not use.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

import numpy as np
from scipy.interpolate import RegularGridInterpolator

from rig.contact.solve import solve
from rig.contact.surrogate import TableDomain, build_table, table_inputs
from rig.stands.contact_law import TableLaw

DOMAIN = TableDomain(l_over_a=(-1.5, 1.5), c_over_a=(0.0, 0.9), alpha=(0.3, 3.0))
SEED = 20240611


def random_states(count: int, rng: np.random.Generator, bridge: bool) -> np.ndarray:
    """(3, count) states (l/a, c/a, alpha'): log-uniform alpha' in the domain, or uniform on the bridge."""
    d = DOMAIN
    l = rng.uniform(*d.l_over_a, count)
    c = rng.uniform(*d.c_over_a, count)
    if bridge:
        alpha = rng.uniform(0.0, d.alpha[0], count)
    else:
        alpha = np.exp(rng.uniform(np.log(d.alpha[0]), np.log(d.alpha[1]), count))
    return np.stack([l, c, alpha])


def median_time(function, repeats: int, inner: int) -> float:
    """Median over repeats of the mean time of ``inner`` calls [s]."""
    function()
    samples = []
    for _ in range(repeats):
        start = time.perf_counter()
        for _ in range(inner):
            function()
        samples.append((time.perf_counter() - start) / inner)
    return statistics.median(samples)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="kinematic")
    parser.add_argument("--n", type=int, default=16)
    parser.add_argument("--shape", default="line")
    parser.add_argument("--b-over-a", type=float, default=1.0)
    parser.add_argument("--poisson", type=float, default=0.3)
    parser.add_argument("--resolutions", nargs="+", default=["21,5,5", "41,9,9", "61,13,13"])
    parser.add_argument("--samples", type=int, default=200)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--grid-check", type=int, default=40, help="states also solved at 2n (grid error)")
    parser.add_argument("--markdown", type=Path, help="also write the tables to this markdown file")
    args = parser.parse_args()
    common = dict(shape=args.shape, b_over_a=args.b_over_a, poisson=args.poisson, n=args.n)

    rng = np.random.default_rng(np.random.SeedSequence(SEED))
    inside = random_states(args.samples, rng, bridge=False)
    bridge = random_states(max(args.samples // 4, 10), rng, bridge=True)

    call_times = []

    def direct(states):
        values = []
        for l, c, a in states.T:
            start = time.perf_counter()
            r = solve(args.model, alpha=a, c_over_a=c, l_over_a=l, **common)
            call_times.append(time.perf_counter() - start)
            values.append((r.nu_T, r.nu_v, r.nu_0))
        return np.array(values).T

    exact_inside = direct(inside)
    direct_time = statistics.median(call_times)
    exact_bridge = direct(bridge)
    # the model's own discretisation error, for scale: the same states on a grid twice as fine
    subset = inside[:, : args.grid_check]
    finer = np.array([[getattr(solve(args.model, alpha=a, c_over_a=c, l_over_a=l, **dict(common, n=2 * args.n)), k)
                       for k in ("nu_T", "nu_v", "nu_0")] for l, c, a in subset.T]).T
    grid_error = np.abs(finer - exact_inside[:, : args.grid_check]).max(axis=1)

    rows = []
    for text in args.resolutions:
        points = tuple(int(p) for p in text.split(","))
        inputs = table_inputs(args.model, effects=None, domain=DOMAIN, points=points, **common)
        start = time.perf_counter()
        table = build_table(inputs, workers=args.workers)
        build = time.perf_counter() - start
        law = TableLaw(table)
        l0, c0, a0 = (float(v) for v in inside[:, 0])
        t_scalar = median_time(lambda: law(l0, c0, a0), args.repeats, 2000)
        t_jac = median_time(lambda: law.evaluate_one(l0, c0, a0), args.repeats, 2000)
        t_vector = median_time(lambda: law(*inside), args.repeats, 20) / inside.shape[1]
        err_in = np.abs(np.array(law(*inside)) - exact_inside)
        err_br = np.abs(np.array(law(*bridge)) - exact_bridge)
        axes = inputs.axes()
        pchip = RegularGridInterpolator(axes, table.values, method="pchip")
        err_pchip = np.abs(pchip(np.stack([inside[0], inside[1], np.log(inside[2])], axis=1)).T - exact_inside)
        rows.append((text, table.values[..., 0].size, build, t_scalar, t_jac, t_vector, err_in, err_br, err_pchip))

    out = [f"model {args.model}, n = {args.n}, {args.shape}, b/a = {args.b_over_a}, poisson = {args.poisson}; "
           f"domain l/a {DOMAIN.l_over_a}, c/a {DOMAIN.c_over_a}, alpha' {DOMAIN.alpha}; {args.samples} random "
           f"states (seed {SEED}); direct solve: median {direct_time * 1e3:.1f} ms per call. The model's own grid "
           f"error, max |n={args.n} - n={2 * args.n}| over {subset.shape[1]} of the states: nu_T, nu_v, nu_0 = "
           + ", ".join(f"{x:.4f}" for x in grid_error) + ".",
           "",
           "| nodes (l, c, alpha) | count | build [s] | scalar [us] | scalar + Jacobian [us] | vectorised [us/point] "
           "| direct / scalar | max error nu_T, nu_v, nu_0 | mean error | max error on the bridge (alpha' < 0.3) "
           "| max error PCHIP |",
           "|---|---|---|---|---|---|---|---|---|---|---|"]
    for text, count, build, ts, tj, tv, e_in, e_br, e_p in rows:
        fmt = lambda e: ", ".join(f"{x:.4f}" for x in e)  # noqa: E731
        out.append(f"| {text} | {count} | {build:.1f} | {ts * 1e6:.1f} | {tj * 1e6:.1f} | {tv * 1e6:.2f} | "
                   f"{direct_time / ts:.0f} | {fmt(e_in.max(axis=1))} | {fmt(e_in.mean(axis=1))} | "
                   f"{fmt(e_br.max(axis=1))} | {fmt(e_p.max(axis=1))} |")
    text = "\n".join(out)
    print(text)
    if args.markdown:
        args.markdown.write_text("<!-- generated by benchmarks/bench_surrogate.py -->\n" + text + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
