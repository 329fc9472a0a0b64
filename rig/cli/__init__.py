"""The ``rig`` command: one module per subcommand, each with ``add_parser`` and ``main``.

A subcommand module defines ``add_parser(subparsers)`` (which sets ``handler``) and the handler
returns an exit status. Errors friction-rig raises on purpose (bad input, damaged logs,
non-convergence) and operating-system errors (a file that cannot be read or written) are
printed as one line and give exit status 2; Ctrl-C prints one line and gives 130. Library code
never exits. The rules are listed in docs/scenes.md ("Exit status and errors").
"""

from __future__ import annotations

import argparse
import importlib
import sys

from rig import __version__
from rig.errors import RigError

EXIT_INTERRUPTED = 130
"""Exit status after Ctrl-C (128 + SIGINT, as shells report it)."""

SUBCOMMAND_HELP = {
    "run": "run a scene (built-in name or file; default: the stand-A quick scene)",
    "scenes": "list the built-in scenes, one line each",
    "reduce": "reduce a log.h5 again (reduced.csv, /reduced in the log)",
    "compare": "compare a simulated RESULT CSV with a digitised figure (WebPlotDigitizer export)",
    "accuracy": "what accuracy costs for a stand scene: error vs CPU time per setting, Pareto plot",
    "lab": "the virtual lab: operate the stands from a web page",
    "fit": "estimate mu and contact effects from a log, a reduced.csv or a digitised curve",
}
"""The one-line help of each subcommand as ``rig --help`` lists it, without importing the subcommand
modules (their imports - numpy, pandas, the stands - would cost ~2 s of CPU at every start). Each
module's ``add_parser`` passes the same text (tests/cli/test_startup.py checks it)."""

SUBCOMMANDS = tuple(SUBCOMMAND_HELP)


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The parser with ``only`` that subcommand (its module imported), or, for ``only=None``, a parser that
    lists every subcommand by its one-line help and imports none (``rig --help``, ``rig --version``)."""
    parser = argparse.ArgumentParser(prog="rig", description="friction-rig: virtual friction-wheel test rig")
    parser.add_argument("--version", action="version", version=f"friction-rig {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    if only is not None:
        importlib.import_module(f"rig.cli.{only}").add_parser(subparsers)
        return parser
    for name, text in SUBCOMMAND_HELP.items():
        subparsers.add_parser(name, help=text, add_help=False)  # never dispatched: main() imports a named one
    return parser


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    first = next((word for word in argv if not word.startswith("-")), None)
    try:  # imports the subcommands (numpy, scipy, ...): Ctrl-C may come here too
        parser = build_parser(first if first in SUBCOMMANDS else None)
    except KeyboardInterrupt:
        print(f"rig {first}: interrupted" if first in SUBCOMMANDS else "rig: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help()
        return 0
    try:
        return int(args.handler(args))
    except RigError as error:
        print(f"rig {args.command}: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:  # a file or folder that cannot be read or written: named by the OS error
        print(f"rig {args.command}: error: {os_error_text(error)}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print(f"rig {args.command}: interrupted" + (" (run it again to resume)" if args.command == "run" else ""),
              file=sys.stderr)
        return EXIT_INTERRUPTED


def os_error_text(error: OSError) -> str:
    """One line for an OSError: what failed, on which file(s)."""
    reason = error.strerror or str(error) or type(error).__name__
    names = [str(name) for name in (error.filename, error.filename2) if name is not None]
    return f"{reason}: {' -> '.join(names)}" if names else reason
