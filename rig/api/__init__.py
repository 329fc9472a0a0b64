"""The Python API for experiment scripts, in the command line's words (exported from :mod:`rig`).

:func:`load_scene`, :func:`list_scenes` and :class:`Scene` (rig.api.scene): load a built-in or
file scene, change it with the scene file's own checks, build one without a file.
:func:`run`, :func:`open_run` and :class:`Run` (rig.api.run_folder): run a scene into a folder
and read the folder back as pandas objects.
"""

from __future__ import annotations

from rig.api.run_folder import LogGroups, Run, open_run, run
from rig.api.scene import Scene, list_scenes, load_scene

__all__ = ["LogGroups", "Run", "Scene", "list_scenes", "load_scene", "open_run", "run"]
