"""Child process of tests/runner/test_one_writer_per_kind.py: run a contact-characteristics or
oscillation scene and pause inside its sweep until told to go on.

Usage: python -m tests.runner.kind_child SCENE FOLDER MARKER. The child touches MARKER when its
sweep starts (the folder's lock held) and goes on once ``MARKER.go`` exists.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path


def main(scene: str, folder: str, marker_path: str) -> int:
    import rig.cli
    import rig.runner.characteristics_run as characteristics_run
    import rig.runner.oscillation_run as oscillation_run

    marker = Path(marker_path)
    go = marker.with_name(marker.name + ".go")

    def pausing(original):
        def wrapper(*args, **kwargs):
            marker.touch()
            deadline = time.monotonic() + 120.0
            while not go.exists() and time.monotonic() < deadline:
                time.sleep(0.01)
            return original(*args, **kwargs)
        return wrapper

    characteristics_run.sweep = pausing(characteristics_run.sweep)
    oscillation_run.amplitude_sweep = pausing(oscillation_run.amplitude_sweep)
    return rig.cli.main(["run", scene, "-o", folder])


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:]))
