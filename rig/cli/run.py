"""``rig run``: run a virtual experiment and write its outputs into a folder.

Until the test stands exist, the default job draws the contact characteristics of seed 000
Figs. 3-7 (nu_T, nu_v, nu_0 versus alpha' for b/a = 0.3, 1, 10, every model overlaid).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
from tqdm import tqdm

from rig.characteristics import Case, plot, sweep

DEFAULT_CASES = [
    Case("ellipse", 1.0, 0.0, 0.0), Case("ellipse", 1.0, 0.4, 0.5),
    Case("ellipse", 0.3, 0.0, 0.0), Case("ellipse", 10.0, 0.0, 0.0), Case("line", 1.0, 0.4, 0.0),
]


def add_parser(subparsers) -> None:
    parser = subparsers.add_parser("run", help="run a virtual experiment (default: contact characteristics)")
    parser.add_argument("-o", "--output", type=Path, default=Path("out"), help="output folder (default: out)")
    parser.add_argument("-n", type=int, default=24, help="cells across 2a for the grid models (default 24)")
    parser.set_defaults(handler=main)


def main(args) -> int:
    out: Path = args.output
    out.mkdir(parents=True, exist_ok=True)
    alphas = np.geomspace(1e-2, 1e4, 25)
    models = ["rigid", "linear", "fastsim", "kinematic"]
    total = len(DEFAULT_CASES) * len(models) * len(alphas)
    with tqdm(total=total, desc="contact characteristics", disable=not sys.stderr.isatty()) as bar:
        table = sweep(DEFAULT_CASES, models, alphas, poisson=0.28, n=args.n,
                      progress=lambda k, _: bar.update(k - bar.n))
    csv_path = out / "characteristics.csv"
    table.to_csv(csv_path, index=False)
    png = plot(table, out / "characteristics.png", "Contact characteristics (seed 000, Figs. 3-7 kind), nu = 0.28")
    print(f"wrote {csv_path} and {png}")
    return 0
