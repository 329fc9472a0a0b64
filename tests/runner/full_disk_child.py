"""Child process of the full-disk test: run the fake stand's scene onto a nearly full file system.

Usage: python -m tests.runner.full_disk_child SCENE MOUNT RESULTS FREE_KB... For each FREE_KB,
the child fills MOUNT (a small tmpfs the parent mounted) so that about FREE_KB kB stay free, runs
``rig run SCENE -o MOUNT/run`` (status and stderr kept), frees the space and runs the scene again
(the rerun's log.h5 and reduced.csv are copied to RESULTS/<FREE_KB>/). It prints one JSON line
per level. A separate process: a crash (the segmentation fault a full disk used to cause) is
seen by the parent as an exit status, not as the end of the test session.
"""

from __future__ import annotations

import contextlib
import io
import json
import os
import shutil
import sys
from pathlib import Path


def fill(mount: Path, free_kb: int) -> Path:
    """A file that leaves about ``free_kb`` kB of ``mount`` free."""
    stat = os.statvfs(mount)
    size = stat.f_bavail * stat.f_frsize - free_kb * 1024
    filler = mount / "filler"
    fd = os.open(filler, os.O_CREAT | os.O_WRONLY, 0o644)
    try:
        os.posix_fallocate(fd, 0, size)
    finally:
        os.close(fd)
    return filler


def run(scene: str, folder: Path) -> tuple[int, str]:
    import rig.cli

    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        status = rig.cli.main(["run", scene, "-o", str(folder)])
    return status, err.getvalue()


def main(scene: str, mount: str, results: str, *levels: str) -> None:
    from tests.runner.run_child import register_fake_stand

    register_fake_stand()
    mount_path, results_path = Path(mount), Path(results)
    for level in levels:
        folder = mount_path / "run"
        shutil.rmtree(folder, ignore_errors=True)
        filler = fill(mount_path, int(level))
        status, err = run(scene, folder)
        filler.unlink()
        rerun_status, rerun_err = run(scene, folder)
        keep = results_path / level
        keep.mkdir(parents=True)
        for name in ("log.h5", "reduced.csv"):
            if (folder / name).exists():
                shutil.copy(folder / name, keep / name)
        print(json.dumps({"free_kb": int(level), "status": status, "stderr": err,
                          "rerun_status": rerun_status, "rerun_stderr": rerun_err}), flush=True)


if __name__ == "__main__":
    main(*sys.argv[1:])
