"""``rig run [SCENE] [-o DIR] [--jobs N | --scheduler ADDRESS]``: run a scene, write its outputs into DIR.

SCENE is a built-in scene name (``rig scenes`` lists them) or a path to a scene file. Without
SCENE: the stand-A quick scene ``default``. DIR
defaults to ``out/<scene name>``. Running a scene again into the same DIR resumes an
interrupted run. ``--jobs N`` runs a stand scene's points on N local processes, ``--scheduler
ADDRESS`` on the workers of a Dask scheduler (optional extra ``dask``); the two exclude each
other (``--jobs`` must stay 1 with a scheduler: the cluster sets the parallelism), and results
are the same either way. Exit status: 0 every point done, 1 some points did not settle (listed in
summary.txt), 2 bad input or another error (printed by rig.cli.main; among them a folder another
run holds), 3 some points of the log were damaged (reduced to NaN, named in summary.txt), 4 a twin
run's reduced points are off their truth by more than their stated u allows (named first in
summary.txt, ``off_truth`` in reduced.csv; rig.runner.off_truth).
"""

from __future__ import annotations

from pathlib import Path

from rig.cli.reduce import DAMAGED_STATUS
from rig.runner import run_scene
from rig.runner.off_truth import OFF_TRUTH_STATUS
from rig.scenes import load_scene

DEFAULT_SCENE = "default"


def add_parser(subparsers) -> None:
    """Register ``rig run``."""
    parser = subparsers.add_parser(
        "run", help="run a scene (built-in name or file; default: the stand-A quick scene)",
        description="Run a virtual experiment described by a scene and write log.h5, reduced.csv, figures "
        "and summary.txt (or, for a contact-characteristics scene, characteristics.csv/.png) into DIR.",
    )
    parser.add_argument("scene", nargs="?", default=None, metavar="SCENE",
                        help="built-in scene name (see 'rig scenes') or path to a scene .toml file")
    parser.add_argument("-o", "--output", type=Path, default=None, metavar="DIR",
                        help="output folder (default: out/<scene name>)")
    parser.add_argument("-j", "--jobs", type=int, default=1, metavar="N",
                        help="worker processes for the operating points (default 1; results do not depend on N)")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="run the operating points on the workers of this Dask scheduler, e.g. "
                        "tcp://127.0.0.1:8786 (needs the 'dask' extra; not with --jobs > 1; same results)")
    parser.set_defaults(handler=main)


def main(args) -> int:
    scene = load_scene(args.scene if args.scene is not None else DEFAULT_SCENE)
    out_dir = args.output if args.output is not None else Path("out") / scene.name
    report = run_scene(scene, out_dir, jobs=args.jobs, scheduler=args.scheduler)
    print(report.summary, end="")
    print(f"wrote {', '.join(report.files)} in {report.out_dir}")
    if report.failures:
        return 1
    if report.damaged:
        return DAMAGED_STATUS
    return OFF_TRUTH_STATUS if report.off_truth else 0
