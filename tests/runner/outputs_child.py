"""Child process of test_outputs_kill: run the fake stand's scene into a folder and SIGKILL itself
at the ``k``-th step of the output phase (a figure being drawn, or the k-th rename).

Usage: python outputs_child.py OUT_DIR SCENE_VARIANT KILL_AT   (KILL_AT: "draw:<k>", "rename:<k>" or "none")
"""

from __future__ import annotations

import os
import signal
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

import rig.stands  # noqa: E402
from rig.runner import outputs, run_scene  # noqa: E402
from rig.scenes import parse_scene  # noqa: E402
from tests.runner.fake_stand import scene_text  # noqa: E402

VARIANTS = {"a": {}, "b": {"mu = 0.3": "mu = 0.25"}}


def _kill_at(kind: str, k: int) -> None:
    count = {"n": 0}

    def step() -> None:
        count["n"] += 1
        if count["n"] == k:
            os.kill(os.getpid(), signal.SIGKILL)

    if kind == "rename":
        real = outputs.os.replace

        def replace(src, dst):
            if sys._getframe(1).f_globals["__name__"] == outputs.__name__:  # the outputs' renames only
                step()
            real(src, dst)

        outputs.os.replace = replace
    elif kind == "draw":
        import matplotlib.figure

        real_save = matplotlib.figure.Figure.savefig

        def savefig(self, path, *args, **kwargs):
            real_save(self, path, *args, **kwargs)
            with open(path, "r+b") as handle:  # a figure half-written when the kill comes
                handle.truncate(100)
            step()

        matplotlib.figure.Figure.savefig = savefig


def main() -> None:
    out_dir, variant, kill = sys.argv[1:]
    rig.stands.STANDS["fake"] = "tests.runner.fake_stand:FakeStand"
    if kill != "none":
        kind, k = kill.split(":")
        _kill_at(kind, int(k))
    run_scene(parse_scene(scene_text(VARIANTS[variant]), name="fake"), Path(out_dir), progress=False)


if __name__ == "__main__":
    main()
