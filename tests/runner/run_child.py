"""Child process of the kill, lock and resume tests: run the fake stand's scene into a folder and
stop at a chosen moment (the parent then kills it with SIGKILL, or lets it go on).

Usage: python -m tests.runner.run_child MODE FOLDER MARKER. The child touches MARKER when it
reaches the moment; in mode ``pause`` it then waits until ``MARKER.go`` exists and finishes.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

from tests.runner.fake_stand import NO_FIGURES, scene_text

MOMENTS = ("before_point_2", "torn_frame", "finalize", "outputs", "reduced", "pause")
"""Where the child stops: before point 2 is written, half-way through point 2's journal frame,
half-way through laying out the log, with the log complete but no output written, half-way
through writing /reduced; ``pause``: before point 2, then goes on when told."""

SCENE_REPLACE = NO_FIGURES


def scene():
    from rig.scenes import parse_scene

    return parse_scene(scene_text(SCENE_REPLACE), name="fake")


def register_fake_stand() -> None:
    import rig.stands

    rig.stands.STANDS["fake"] = "tests.runner.fake_stand:FakeStand"


def _stop(marker: Path, pause: bool = False) -> None:
    marker.touch()
    go = marker.with_name(marker.name + ".go")
    while not (pause and go.exists()):
        time.sleep(0.01)


def main(moment: str, folder: str, marker_path: str) -> None:
    import rig.logbook.journal as journal
    import rig.logbook.reduced as reduced
    import rig.logbook.writer as writer
    import rig.runner.stand_run as stand_run
    from rig.runner import run_scene

    register_fake_stand()
    marker = Path(marker_path)
    if moment in ("before_point_2", "pause"):
        original_write = writer.LogWriter.write_point

        def write_point(self, point, truth):
            if point.index == 2:
                _stop(marker, pause=moment == "pause")
            original_write(self, point, truth)
        writer.LogWriter.write_point = write_point
    elif moment == "torn_frame":
        original_encode = journal.encode

        def encode(entry):
            frame = original_encode(entry)
            if entry.index == 2:
                with open(Path(folder) / "log.h5.parts" / writer.JOURNAL, "ab") as handle:
                    handle.write(frame[: len(frame) // 2])
                _stop(marker)
            return frame
        journal.encode = encode
    elif moment == "finalize":
        original_columnar = writer.write_columnar

        def write_columnar(root, entries):
            root.create_group("partial")
            root.file.flush()
            _stop(marker)
            original_columnar(root, entries)
        writer.write_columnar = write_columnar
    elif moment == "outputs":
        def reduce_to_files(*args):
            _stop(marker)
        stand_run.reduce_to_files = reduce_to_files
    elif moment == "reduced":
        def write_table(group, table, units):
            group.create_dataset("partial", data=[0.0])
            group.file.flush()
            _stop(marker)
        reduced._write_table = write_table
    else:
        raise SystemExit(f"unknown moment {moment!r}; one of {MOMENTS}")
    run_scene(scene(), Path(folder), progress=False)


if __name__ == "__main__":
    main(*sys.argv[1:])
