"""``rig reduce LOG [-o DIR]``: reduce a finished log (eqs. 29-36) from the scene stored in it.

Writes reduced.csv (and the reduced-vs-truth figure) into DIR (default: the log's folder) and
the table into the log's ``/reduced`` group. Exit status: 0 every point reduced (or NaN with a
reason of the method), 3 some points were damaged in the log (NaN, reason names the dataset and
the bad value; the others reduced as usual), 2 bad input or another error (printed by rig.cli.main).
"""

from __future__ import annotations

from pathlib import Path

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


def main(args) -> int:
    reduction, files = reduce_log_file(args.log, args.output)
    print(f"reduced {len(reduction.table)} points of {args.log}: wrote {', '.join(str(f) for f in files)}")
    for problem in reduction.problems:
        print(f"note: {problem}")
    return DAMAGED_STATUS if reduction.damaged else 0
