"""The output files of a run, written so that a kill never leaves a half-written or a stale one.

Every output (reduced.csv, the PNG figures, summary.txt, ...) is first written whole into the
staging folder ``.outputs.tmp/`` inside the output folder; when all are written they are
fsynced and moved into the output folder with ``os.replace`` (atomic), summary.txt last. Before a
run replaces its log, the outputs of the previous run (every name of OUTPUT_NAMES in the folder)
are removed, summary.txt first, so that no output stays beside a log it does not describe.
A write that fails (a full disk) raises an OSError naming the output and the cause; the
staging folder is removed and the previous outputs stay.

A kill at any moment therefore leaves every output file either absent or complete (never
truncated), and a summary.txt only beside the outputs of the log it describes: while the new
outputs are being drawn the folder holds the previous run's complete set (or, once the new log
is in place, none); then the new complete set appears within a few renames. A leftover staging
folder of a killed process is removed by the next run.
"""

from __future__ import annotations

import contextlib
import os
import shutil
from collections.abc import Iterator
from pathlib import Path

from rig.errors import ParameterError, RigError
from rig.logbook.atomic import fsync_dir, fsync_file, write_error
from rig.scenes.stand_scene import PAPER_FIGURE_NAMES

STAGING_NAME = ".outputs.tmp"
REDUCED_ROWS_NAME = ".reduced_rows.part"
"""reduced.csv's lines as a study's workers formatted them, gathered in point order while the study
runs (rig.runner.reduction.csv_rows); removed when reduced.csv is written and by the next run in
the folder (an interrupted run's is of no use)."""
SUMMARY_NAME = "summary.txt"
REDUCED_CSV = "reduced.csv"
REDUCED_FIGURE = "reduced_vs_truth.png"
CHARACTERISTICS_CSV = "characteristics.csv"
CHARACTERISTICS_FIGURE = "characteristics.png"
OSCILLATION_CSV = "oscillation_sweep.csv"
OSCILLATION_FIGURE = "oscillation_sweep.png"
WORK_MAP_FIGURE = "work_map.png"

OUTPUT_NAMES = (SUMMARY_NAME, REDUCED_CSV, REDUCED_FIGURE, CHARACTERISTICS_CSV, CHARACTERISTICS_FIGURE,
                OSCILLATION_CSV, OSCILLATION_FIGURE, WORK_MAP_FIGURE, *(f"{name}.png" for name in PAPER_FIGURE_NAMES))
"""Every file a run may write besides its log (summary.txt first: it is removed first, renamed last)."""


STAND_KIND, CHARACTERISTICS_KIND, OSCILLATION_KIND = "stand", "contact-characteristics", "oscillation"
RUN_MARKS = {
    STAND_KIND: ("log.h5", "log.h5.parts", REDUCED_CSV),
    CHARACTERISTICS_KIND: (CHARACTERISTICS_CSV,),
    OSCILLATION_KIND: (OSCILLATION_CSV,),
}
"""The files that show which kind of run a folder holds."""


class ForeignOutputsError(RigError):
    """The output folder holds another kind of run's outputs (which this run would delete)."""


def claim_folder(out_dir: Path, kind: str) -> None:
    """Refuse, by name, a folder holding the outputs of another kind of run than ``kind`` (one of
    RUN_MARKS): a run replaces the previous outputs of its folder and must not delete another
    kind's. Call it with the folder's lock held (rig.runner.folder_lock)."""
    for other, marks in RUN_MARKS.items():
        found = [name for name in marks if (out_dir / name).exists()]
        if other != kind and found:
            raise ForeignOutputsError(
                f"{out_dir} holds the outputs of a {other} run ({', '.join(found)}); a {kind} run there would "
                "replace them: choose another output folder")


def output_folder(out_dir: object) -> Path:
    """``out_dir`` created if needed; a named error when it cannot be (a file of that name, no permission)."""
    folder = Path(out_dir)
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except FileExistsError:
        raise ParameterError("output folder", str(folder),
                             "a folder or a new name (a file of that name exists)") from None
    except OSError as error:
        raise ParameterError("output folder", str(folder), "a folder this user can create and write",
                             hint=error.strerror or str(error)) from None
    return folder


def remove_stale(out_dir: Path) -> None:
    """Remove the outputs a previous run left in ``out_dir`` (summary.txt first)."""
    for name in OUTPUT_NAMES:
        (out_dir / name).unlink(missing_ok=True)
    fsync_dir(out_dir)


def _being_written(staging: Path) -> str:
    """Name of the file last written in ``staging`` (the one a failed write was writing), else the folder's."""
    files = [(p.stat().st_mtime_ns, p.name) for p in staging.iterdir() if p.is_file()]
    return max(files)[1] if files else staging.name


@contextlib.contextmanager
def staged_outputs(out_dir: Path, *, replace_previous: bool = False) -> Iterator[Path]:
    """Yield the staging folder to write outputs into; when the block ends without an error, move
    every file written there into ``out_dir`` (summary.txt last), after removing the previous run's
    outputs if ``replace_previous``. The staging folder is always removed."""
    staging = out_dir / STAGING_NAME
    shutil.rmtree(staging, ignore_errors=True)
    try:
        staging.mkdir()
    except OSError as error:
        raise ParameterError("output folder", str(out_dir), "a folder this user can write",
                             hint=error.strerror or str(error)) from None
    try:
        try:
            yield staging
        except OSError as error:  # a full disk while an output was written: name that output
            if error.filename is None:
                raise write_error(out_dir / _being_written(staging), error) from None
            if Path(error.filename).parent == staging:  # named where it will be, not where it was staged
                raise write_error(out_dir / Path(error.filename).name, error) from None
            raise
        names = sorted((p.name for p in staging.iterdir() if p.is_file()), key=lambda name: name == SUMMARY_NAME)
        for name in names:
            fsync_file(staging / name)
        if replace_previous:
            remove_stale(out_dir)
        for name in names:
            os.replace(staging / name, out_dir / name)
        fsync_dir(out_dir)
    finally:
        shutil.rmtree(staging, ignore_errors=True)
