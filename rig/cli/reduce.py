"""``rig reduce LOG [-o DIR]``: reduce a finished log (eqs. 29-36) from the scene stored in it.

Writes reduced.csv (and the reduced-vs-truth figure) into DIR (default: the log's folder) and
the table into the log's ``/reduced`` group, and prints the reduced values. In a folder it cannot
write (and without -o), it still prints the values, then a named error suggesting -o (exit 2).
Exit status: 0 every point reduced (or NaN with a reason of the method), 3 some points were
damaged in the log (NaN, reason names the dataset and the bad value; the others reduced as
usual), 2 bad input or another error (printed by rig.cli.main).
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pandas as pd

from rig.errors import ParameterError
from rig.runner import reduce_log_file

DAMAGED_STATUS = 3
"""Exit status of ``rig run`` and ``rig reduce`` when some points of the log were damaged."""


def add_parser(subparsers) -> None:
    """Register ``rig reduce``."""
    parser = subparsers.add_parser("reduce", help="reduce a log.h5 again (reduced.csv, /reduced in the log)",
                                   description="Reduce a measurement log with its stand's chain, eqs. (29)-(36).")
    parser.add_argument("log", type=Path, metavar="LOG", help="a log.h5 written by 'rig run'")
    parser.add_argument("-o", "--output", type=Path, default=None, metavar="DIR",
                        help="output folder (default: the log's folder)")
    parser.set_defaults(handler=main)


SHOWN = ("l_over_a", "c_over_a", "mu_v", "u_mu_v", "mu_T", "u_mu_T")
"""Columns printed (those the table has)."""


def values_text(table: pd.DataFrame) -> str:
    """The main reduced values, one line per point (NaN: see the reason column of reduced.csv)."""
    shown = table[[c for c in SHOWN if c in table.columns]]
    return shown.to_string(float_format=lambda v: f"{v:.4g}", index_names=False)


def main(args) -> int:
    try:
        reduction, files = reduce_log_file(args.log, args.output)
    except ParameterError as error:
        if error.name != "output folder" or args.output is not None:
            raise
        with tempfile.TemporaryDirectory() as scratch:  # the log's folder is read-only: reduce, report, no files
            reduction, _ = reduce_log_file(args.log, Path(scratch))
        print(values_text(reduction.table))
        raise ParameterError(error.name, error.value, error.valid,
                             hint=f"{error.hint}; the reduced values are printed above; write the files elsewhere "
                             "with -o DIR") from None
    print(values_text(reduction.table))
    print(f"reduced {len(reduction.table)} points of {args.log}: wrote {', '.join(str(f) for f in files)}")
    for problem in reduction.problems:
        print(f"note: {problem}")
    return DAMAGED_STATUS if reduction.damaged else 0
