"""``rig reduce LOG``: reduce a finished log again, from the scene stored in it.

The log holds its scene's text verbatim; it is validated with the current stand code, the stand
is built from it (nothing simulated) and reduces the log, with the folder's lock held (a log
that a run is still writing is refused by name, rig.runner.folder_lock): reduced.csv (and the
figure, when the scene asks for figures) go into the output folder, ``/reduced`` into the log.
"""

from __future__ import annotations

from pathlib import Path

from rig.errors import ParameterError
from rig.logbook import read_metadata
from rig.runner.folder_lock import FolderLockedError, folder_lock
from rig.runner.figures import FIGURE_NAME, reduced_vs_truth_figure
from rig.runner.reduction import Reduction, reduce_to_files
from rig.scenes.load import parse_scene
from rig.scenes.stand_scene import StandScene


def reduce_log_file(log_path: Path, out_dir: Path | None = None, **parse_options) -> tuple[Reduction, list[Path]]:
    """Reduce ``log_path`` into ``out_dir`` (default: the log's folder); returns the reduction and
    the files written. ``parse_options`` go to rig.scenes.parse_scene (e.g. ``stand_class_of``)."""
    log_path = Path(log_path)
    try:
        with folder_lock(log_path.parent, f"rig reduce {log_path.name}"):
            return _reduce_locked(log_path, out_dir, **parse_options)
    except FolderLockedError as error:
        raise FolderLockedError(f"{log_path}: the log is being written (or reduced) by another process: {error}") from None


def _reduce_locked(log_path: Path, out_dir: Path | None, **parse_options) -> tuple[Reduction, list[Path]]:
    metadata = read_metadata(log_path)
    scene = parse_scene(metadata.scene_toml, name=log_path.stem, source=f"{log_path} (the scene stored in the log)",
                        **parse_options)
    if not isinstance(scene, StandScene):
        raise ParameterError("log", str(log_path), "the log of a stand run (its scene has no stand)")
    out_dir = log_path.parent if out_dir is None else Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    reduction = reduce_to_files(scene.build_stand(), log_path, scene.contact, out_dir)
    files = [reduction.csv]
    if scene.outputs.figures:
        figure = reduced_vs_truth_figure(reduction.table, scene.procedure.points(), scene.procedure,
                                         out_dir / FIGURE_NAME, f"{scene.name}: {scene.description}")
        files += [] if figure is None else [figure]
    return reduction, files
