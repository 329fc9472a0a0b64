"""Child process of the scale tests: run a study of the fake stand into a folder on ``-j`` processes or
on a Dask scheduler, to be killed (SIGKILL) at a random moment by the test.

Usage: python -m tests.runner.study_child FOLDER POINTS (JOBS | ADDRESS)
"""

from __future__ import annotations

import sys
from pathlib import Path


def study_text(points: int) -> str:
    """The fake stand's scene with ``points`` loads from 5 to 600 N (steps of ~2 N: every point settles)."""
    from tests.runner.fake_stand import NO_FIGURES, scene_text

    return scene_text(NO_FIGURES | {"load_N = [5.0, 10.0, 20.0, 25.0]":
                                    f"load_N = {{ start = 5.0, stop = 600.0, num = {points} }}"})


def main(folder: str, points: str, where: str) -> None:
    import rig.stands
    from rig.runner import run_scene
    from rig.scenes import parse_scene

    rig.stands.STANDS["fake"] = "tests.runner.fake_stand:FakeStand"
    scene = parse_scene(study_text(int(points)), name="study")
    if where.isdigit():
        run_scene(scene, Path(folder), jobs=int(where), progress=False)
    else:
        run_scene(scene, Path(folder), scheduler=where, progress=False)


if __name__ == "__main__":
    main(*sys.argv[1:])
