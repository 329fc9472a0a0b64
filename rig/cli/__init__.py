"""The ``rig`` command: one module per subcommand, each with ``add_parser`` and ``main``.

A subcommand module defines ``add_parser(subparsers)`` (which sets ``handler``) and the handler
returns an exit status. Errors friction-rig raises on purpose (bad input, damaged logs,
non-convergence) are printed as one line and give exit status 2; library code never exits.
"""

from __future__ import annotations

import argparse
import importlib
import sys

from rig import __version__
from rig.errors import RigError

SUBCOMMANDS = ("run", "scenes", "reduce", "compare", "accuracy", "fit")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="rig", description="friction-rig: virtual friction-wheel test rig")
    parser.add_argument("--version", action="version", version=f"friction-rig {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in SUBCOMMANDS:
        importlib.import_module(f"rig.cli.{name}").add_parser(subparsers)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        return int(args.handler(args))
    except RigError as error:
        print(f"rig {args.command}: error: {error}", file=sys.stderr)
        return 2
