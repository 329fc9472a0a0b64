"""``rig reduce LOG``: reduce a finished log again, from the scene stored in it.

The log holds its scene's text verbatim; it is validated with the current stand code, the stand
is built from it (nothing simulated) and reduces the log, with the folder's lock held (a log
that a run is still writing is refused by name, rig.runner.folder_lock; a folder that takes no
lock file, e.g. a read-only one, is reduced without it): reduced.csv (and the
figure, when the scene asks for figures) go into the output folder, ``/reduced`` into the log.
"""

from __future__ import annotations

import contextlib
from dataclasses import replace
from pathlib import Path

from rig.errors import LogFormatError, ParameterError
from rig.logbook import point_indices, read_metadata
from rig.logbook.schema import check_units
from rig.runner.figures import reduced_vs_truth_figure
from rig.runner.folder_lock import FolderLockedError, folder_lock
from rig.runner.outputs import REDUCED_FIGURE, output_folder, staged_outputs
from rig.runner.reduction import Reduction, reduce_to_files
from rig.scenes.load import parse_scene
from rig.scenes.stand_scene import StandScene


def reduce_log_file(log_path: Path, out_dir: Path | None = None, **parse_options) -> tuple[Reduction, list[Path]]:
    """Reduce ``log_path`` into ``out_dir`` (default: the log's folder); returns the reduction and
    the files written. ``parse_options`` go to rig.scenes.parse_scene (e.g. ``stand_class_of``)."""
    log_path = Path(log_path)
    with contextlib.ExitStack() as stack:
        try:
            stack.enter_context(folder_lock(log_path.parent, f"rig reduce {log_path.name}"))
        except FolderLockedError as error:
            raise FolderLockedError(
                f"{log_path}: the log is being written (or reduced) by another process: {error}") from None
        except ParameterError as error:
            if error.name != "output folder":
                raise
            # the log's folder takes no lock file: no run of this user can be writing there
        return _reduce(log_path, out_dir, **parse_options)


def _reduce(log_path: Path, out_dir: Path | None, **parse_options) -> tuple[Reduction, list[Path]]:
    metadata = read_metadata(log_path)
    if not point_indices(log_path):
        raise LogFormatError(f"{log_path}: the log holds no operating point (every point of its run failed?); "
                             "nothing to reduce")
    scene = parse_scene(metadata.scene_toml, name=log_path.stem, source=f"{log_path} (the scene stored in the log)",
                        **parse_options)
    if not isinstance(scene, StandScene):
        raise ParameterError("log", str(log_path), "the log of a stand run (its scene has no stand)")
    if metadata.stand != scene.stand:
        raise LogFormatError(f"{log_path}: root attribute 'stand' = {metadata.stand!r}, but the scene stored in the "
                             f"log runs stand {scene.stand!r}")
    stand = scene.build_stand()
    check_units(log_path, stand.LOG_SCHEMA)  # a reading in other units than the stand's is refused by name
    out_dir = output_folder(log_path.parent if out_dir is None else out_dir)
    with staged_outputs(out_dir) as staging:
        reduction = reduce_to_files(stand, log_path, scene.contact, staging)
        names = [reduction.csv.name]
        if scene.outputs.figures:
            figure = reduced_vs_truth_figure(reduction.table, scene.procedure.points(), scene.procedure,
                                             staging / REDUCED_FIGURE, f"{scene.name}: {scene.description}")
            names += [] if figure is None else [figure.name]
    return replace(reduction, csv=out_dir / reduction.csv.name), [out_dir / name for name in names]
