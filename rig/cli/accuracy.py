"""``rig accuracy [SCENE] [-o DIR] [-j N] [--repeats R] [--max-values M] [--models ..] [--grids ..]``.

For a stand scene: error versus CPU time of each contact model and grid, surrogate-table
resolution and drive / ODE tolerance, and stated uncertainty versus lab time of the gate time;
writes accuracy.csv, accuracy.md and accuracy_pareto.png into DIR (default
``out/accuracy/<scene name>``) and prints the markdown report. Method: docs/accuracy.md.
"""

from __future__ import annotations

import dataclasses
import shlex
import sys
from pathlib import Path

from rig.accuracy import StudyOptions, run_accuracy
from rig.errors import ParameterError
from rig.scenes import load_scene

DEFAULT_SCENE = "default"
DEFAULTS = StudyOptions()
DEFAULT_JOBS = 2


def parser_default(name: str) -> str:
    """The default text of the list options ``models`` and ``grids``."""
    return ",".join(map(str, getattr(DEFAULTS, name)))


def add_parser(subparsers) -> None:
    """Register ``rig accuracy``."""
    parser = subparsers.add_parser(
        "accuracy", help="what accuracy costs for a stand scene: error vs CPU time per setting, Pareto plot",
        description="Run a stand scene at several contact models and grids, surrogate-table resolutions, "
        "drive modes / ODE tolerances and gate times (each with the rest at the scene's setting), on a shortened "
        "procedure; write the error-versus-cost table (accuracy.csv, accuracy.md), the Pareto plot "
        "(accuracy_pareto.png) and where the time goes.",
    )
    parser.add_argument("scene", nargs="?", default=DEFAULT_SCENE, metavar="SCENE",
                        help="built-in stand scene name (see 'rig scenes') or path to a scene .toml (default: default)")
    parser.add_argument("-o", "--output", type=Path, default=None, metavar="DIR",
                        help="output folder (default: out/accuracy/<scene name>)")
    parser.add_argument("-j", "--jobs", type=int, default=DEFAULT_JOBS, metavar="N",
                        help="worker processes (default 2; CPU times are measured inside each process)")
    parser.add_argument("--repeats", type=int, default=DEFAULTS.repeats, metavar="R",
                        help=f"timed runs per setting, median taken (default {DEFAULTS.repeats})")
    parser.add_argument("--max-values", type=int, default=DEFAULTS.max_values, metavar="M",
                        help="values kept per swept setting of the procedure, evenly spaced, ends kept "
                        f"(default {DEFAULTS.max_values})")
    parser.add_argument("--models", default=parser_default("models"), metavar="M1,M2",
                        help=f"contact models of the model x grid axis (default {','.join(DEFAULTS.models)}; the "
                        "scene's own is always added)")
    parser.add_argument("--grids", default=parser_default("grids"), metavar="N1,N2",
                        help=f"grid sizes n of that axis (default {','.join(map(str, DEFAULTS.grids))}; the scene's "
                        "own is always added)")
    parser.set_defaults(handler=main)


def _list(name: str, text: str, kind: type) -> tuple:
    """A comma-separated option as a tuple of ``kind``; ParameterError naming the option."""
    try:
        return tuple(kind(part) for part in text.split(",") if part.strip())
    except ValueError:
        raise ParameterError(name, text, f"comma-separated {kind.__name__} values, e.g. "
                             + ("8,16" if kind is int else "rigid,kinematic")) from None


def main(args) -> int:
    scene = load_scene(args.scene)
    out_dir = args.output if args.output is not None else Path("out") / "accuracy" / scene.name
    options = dataclasses.replace(DEFAULTS, models=_list("--models", args.models, str),
                                  grids=_list("--grids", args.grids, int), repeats=args.repeats,
                                  max_values=args.max_values)
    given = [f"-j {args.jobs}" if args.jobs != DEFAULT_JOBS else "",
             f"--repeats {args.repeats}" if args.repeats != DEFAULTS.repeats else "",
             f"--max-values {args.max_values}" if args.max_values != DEFAULTS.max_values else "",
             *(f"--{name} {getattr(args, name)}" for name in ("models", "grids")
               if getattr(args, name) != parser_default(name)),
             f"-o {shlex.quote(str(args.output))}" if args.output is not None else ""]
    command = " ".join(["rig accuracy", shlex.quote(str(args.scene)), *(g for g in given if g)])

    def progress(done: int, total: int) -> None:
        print(f"rig accuracy: {done}/{total} runs", file=sys.stderr, flush=True)

    report = run_accuracy(scene, out_dir, options=options, jobs=args.jobs, progress=progress, command=command)
    print(report.markdown, end="")
    print(f"wrote {', '.join(report.files)} in {report.out_dir}")
    return 0
