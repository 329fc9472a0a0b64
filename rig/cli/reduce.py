"""``rig reduce LOG [-o DIR]``: reduce a finished log (eqs. 29-36) from the scene stored in it.

Writes reduced.csv (and the reduced-vs-truth figure) into DIR (default: the log's folder) and
the table into the log's ``/reduced`` group.
"""

from __future__ import annotations

from pathlib import Path

from rig.errors import ParameterError
from rig.runner import reduce_log_file


def add_parser(subparsers) -> None:
    """Register ``rig reduce``."""
    parser = subparsers.add_parser("reduce", help="reduce a log.h5 again (reduced.csv, /reduced in the log)",
                                   description="Reduce a measurement log with its stand's chain, eqs. (29)-(36).")
    parser.add_argument("log", type=Path, metavar="LOG", help="a log.h5 written by 'rig run'")
    parser.add_argument("-o", "--output", type=Path, default=None, metavar="DIR",
                        help="output folder (default: the log's folder)")
    parser.set_defaults(handler=main)


def main(args) -> int:
    try:
        reduction, files = reduce_log_file(args.log, args.output)
    except ParameterError as error:
        if error.name == "output folder" and args.output is None:  # the log's folder is read-only
            raise ParameterError(error.name, error.value, error.valid,
                                 hint=f"{error.hint}; write the outputs elsewhere with -o DIR") from None
        raise
    print(f"reduced {len(reduction.table)} points of {args.log}: wrote {', '.join(str(f) for f in files)}")
    if reduction.problem:
        print(f"note: {reduction.problem}")
    return 0
