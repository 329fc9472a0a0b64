"""``rig compare RESULT DIGITISED``: compare a simulated result with a digitised figure (docs/compare.md).

Exit status: 0 all datasets within the thresholds (or no thresholds), 1 some dataset past a
threshold (one line per failing dataset on stderr), 2 bad input (printed by rig.cli.main).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from rig.compare.comparison import CompareOptions, compare_files, default_sidecar_path
from rig.compare.gate import Thresholds, failures, parse_max_abs
from rig.compare.metrics import Interpolation
from rig.compare.overlay import save_overlay
from rig.compare.report import metrics_table, write_metrics
from rig.runner.outputs import output_folder, staged_outputs


def add_parser(subparsers: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register ``rig compare`` on the ``rig`` command's subparsers."""
    parser = subparsers.add_parser(
        "compare",
        help="compare a simulated RESULT CSV with a digitised figure (WebPlotDigitizer export)",
        description="Interpolate the simulation onto digitised points (no extrapolation) and report "
        "RMSE, max |dev| and max relative dev per dataset; exit 1 past a threshold.",
    )
    parser.add_argument("result", type=Path, metavar="RESULT", help="simulated result CSV (one column per quantity)")
    parser.add_argument("digitised", type=Path, metavar="DIGITISED", help="WebPlotDigitizer CSV export")
    parser.add_argument(
        "--sidecar", type=Path, default=None, help="TOML sidecar describing the figure (default: DIGITISED.toml)"
    )
    parser.add_argument(
        "-o", "--output", type=Path, default=None, metavar="DIR", help="output directory (default: next to RESULT)"
    )
    parser.add_argument("--model", default=None, help="compare only this model of RESULT's 'model' column")
    parser.add_argument(
        "--interpolation",
        choices=[m.value for m in Interpolation],
        default=Interpolation.LINEAR.value,
        help="interpolation of the simulated curve (in log x on a log axis); default linear",
    )
    parser.add_argument(
        "--x-shift-tolerance",
        type=float,
        default=None,
        metavar="TOL",
        help="fit an x shift within +-TOL (x units; relative on a log axis) for digitising error",
    )
    parser.add_argument(
        "--max-abs",
        action="append",
        default=[],
        metavar="QUANTITY=VALUE",
        help="fail if max |dev| of dataset (or y column) QUANTITY exceeds VALUE [its y units]; repeatable",
    )
    parser.add_argument("--max-rmse", type=float, default=None, help="fail if the RMSE of any dataset exceeds this")
    parser.add_argument("--no-plot", action="store_true", help="do not draw compare_overlay.png")
    parser.set_defaults(handler=main)
    return parser


def main(args: argparse.Namespace) -> int:
    """Run the comparison, write the outputs, print a summary; return the exit status (0 or 1)."""
    thresholds = Thresholds(max_abs=parse_max_abs(args.max_abs), max_rmse=args.max_rmse)
    options = CompareOptions(
        interpolation=Interpolation(args.interpolation), x_shift_tolerance=args.x_shift_tolerance, model=args.model
    )
    sidecar_path = args.sidecar if args.sidecar is not None else default_sidecar_path(args.digitised)
    sidecar, items = compare_files(args.result, args.digitised, sidecar_path, options)
    failed = failures(items, thresholds)
    directory = args.output if args.output is not None else args.result.resolve().parent
    meta = {
        "result": str(args.result),
        "digitised": str(args.digitised),
        "sidecar": str(sidecar_path),
        "interpolation": options.interpolation.value,
        "x_shift_tolerance": options.x_shift_tolerance,
        "model": options.model,
        "thresholds": {"max_abs": dict(thresholds.max_abs), "max_rmse": thresholds.max_rmse},
        "passed": not failed,
        "failures": failed,
    }
    directory = output_folder(directory)
    with staged_outputs(directory) as staging:  # written whole, then renamed into place (rig.runner.outputs)
        names = [path.name for path in write_metrics(staging, sidecar, items, meta)]
        if not args.no_plot:
            names.append(save_overlay(staging, sidecar, items).name)
    paths = [directory / name for name in names]
    table = metrics_table(sidecar, items)
    shown = ["dataset", "model", "n_compared", "n_skipped", "rmse", "max_abs_dev", "max_rel_dev", "x_shift"]
    print(f"{sidecar.figure}")
    print(table[shown].to_string(index=False, float_format=lambda v: f"{v:.4g}"))
    for path in paths:
        print(f"wrote {path}")
    for line in failed:
        print(f"rig compare: FAIL {line}", file=sys.stderr)
    return 1 if failed else 0
