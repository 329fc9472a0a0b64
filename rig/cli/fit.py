"""``rig fit DATA --params mu,psi``: estimate friction parameters and effects from data (docs/fit.md).

Exit status: 0 the fit converged (files written), 2 bad input or no convergence (one named
line on stderr, printed by rig.cli.main).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rig.errors import ParameterError


def _pairs(text: str | None, what: str) -> dict[str, float | str]:
    if not text:
        return {}
    out = {}
    for item in text.split(","):
        key, sep, value = item.partition("=")
        if not sep or not key.strip():
            raise ParameterError(what, item, "NAME=VALUE pairs separated by commas")
        try:
            out[key.strip()] = float(value)
        except ValueError:
            out[key.strip()] = value.strip()  # rig.fit names it as not a number
    return out


def add_parser(subparsers: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register ``rig fit`` on the ``rig`` command's subparsers."""
    parser = subparsers.add_parser(
        "fit",
        help="estimate mu and contact effects from a log, a reduced.csv or a digitised curve",
        description="Weighted least squares of the contact model to DATA, 95 % profile-likelihood intervals, "
        "correlations, and nested effect sets ranked by AIC/BIC.",
    )
    parser.add_argument("data", type=Path, metavar="DATA", help="log.h5, reduced.csv (log.h5 beside it) or a "
                        "digitised CSV with its TOML sidecar")
    parser.add_argument("--params", required=True, help="free parameters in nesting order, e.g. mu,psi")
    parser.add_argument("--scene", default=None, help="scene of a stand run (default: the one stored in the log)")
    parser.add_argument("--force-scene", action="store_true",
                        help="fit with --scene even where it differs from the log's stored scene (stand, geometry, "
                        "contact law, loads); without it a difference is an error")
    parser.add_argument("--effects", default=None, metavar="NAME=VALUE,...", help="fixed effect values, e.g. psi=1.2")
    parser.add_argument("--start", default=None, metavar="NAME=VALUE,...", help="start values of free parameters")
    parser.add_argument("--sigma", default=None, help="u of a digitised y: VALUE or DATASET=VALUE,...")
    parser.add_argument("--extra-scatter", default=None, metavar="S|fit",
                        help="an independent scatter S added to every point's u (u^2 + S^2) [units of the fitted "
                        "quantity], or 'fit' to estimate it (chi2/dof = 1); default none: the stated u alone")
    parser.add_argument("--sigma-x", default=None, help="u of a digitised x (its axis's units): VALUE or "
                        "DATASET=VALUE,...; carried to y by the effective variance (default: x exact)")
    parser.add_argument("--sidecar", type=Path, default=None, help="TOML sidecar (default: DATA.toml)")
    parser.add_argument("--n", type=int, default=None, help="contact grid cells across 2a (default: scene's, 16)")
    parser.add_argument("--polish", choices=("auto", "check", "never", "always"), default="auto",
                        help="direct solves at the optimum: auto (refit when the table error is not small vs u; "
                        "check only for a stand run), check, never, always")
    parser.add_argument("-o", "--output", type=Path, default=Path("out/fit"), metavar="DIR", help="output folder")
    parser.add_argument("--no-plot", action="store_true", help="do not draw fit.png")
    parser.set_defaults(handler=main)
    return parser


def main(args: argparse.Namespace) -> int:
    """Fit, write the files, print the summary; 0 when the fit converged."""
    from rig.fit.outputs import summary_text, write_outputs
    from rig.fit.run import fit_data

    report = fit_data(
        args.data, [p.strip() for p in args.params.split(",") if p.strip()], sidecar=args.sidecar, sigma=args.sigma,
        sigma_x=args.sigma_x,
        scene=args.scene, effects=_pairs(args.effects, "--effects"), start=_pairs(args.start, "--start"), n=args.n,
        polish=args.polish, force_scene=args.force_scene, extra_scatter=args.extra_scatter,
    )
    write_outputs(report, args.output, plot=not args.no_plot)
    print(summary_text(report), end="")
    print(f"wrote fit.csv, models.csv, summary.txt{'' if args.no_plot else ', fit.png'} in {args.output}")
    return 0
