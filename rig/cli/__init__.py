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

SUBCOMMANDS = ("run", "scenes", "reduce", "compare", "accuracy", "lab", "fit")


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The parser with every subcommand, or with ``only`` that one (the others' imports - the lab's
    web server, the fit engine - cost ~0.4 s that a ``rig run`` of a large study need not pay)."""
    parser = argparse.ArgumentParser(prog="rig", description="friction-rig: virtual friction-wheel test rig")
    parser.add_argument("--version", action="version", version=f"friction-rig {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in SUBCOMMANDS if only is None else (only,):
        importlib.import_module(f"rig.cli.{name}").add_parser(subparsers)
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
