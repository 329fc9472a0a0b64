"""Where the built-in scenes are: ``rig/scenes/builtin/*.toml``, shipped as package data.

An ordinary (non-editable) install carries them, so ``rig run`` works from any folder. The
environment variable ``RIG_SCENES_DIR`` replaces the folder when it is set (a missing folder is
a clear error that names the variable).
"""

from __future__ import annotations

import os
import tomllib
from dataclasses import dataclass
from pathlib import Path

from rig import validate
from rig.errors import ParameterError

ENV_VAR = "RIG_SCENES_DIR"
BUILTIN_DIR = Path(__file__).resolve().parent / "builtin"  # package data (pyproject.toml)
SUFFIX = ".toml"


@dataclass(frozen=True)
class BuiltinScene:
    """A scene file of the built-in folder: name (file stem), path and its one-line description."""

    name: str
    path: Path
    description: str


def scenes_dir() -> Path:
    """The built-in scenes folder (``$RIG_SCENES_DIR`` or the package's ``rig/scenes/builtin``)."""
    override = os.environ.get(ENV_VAR)
    if override:
        folder = Path(override)
        if not folder.is_dir():
            raise ParameterError(ENV_VAR, override, "an existing folder of scene files (*.toml)")
        return folder
    return BUILTIN_DIR


def _description(path: Path) -> str:
    """``[scene] description`` of a scene file, read without validating the rest."""
    try:
        head = tomllib.loads(path.read_text(encoding="utf-8-sig")).get("scene", {})
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        return f"(unreadable scene file: {error})"
    description = head.get("description") if isinstance(head, dict) else None
    return description if isinstance(description, str) else "(no [scene] description)"


def builtin_scenes() -> list[BuiltinScene]:
    """The built-in scenes, sorted by name."""
    return [BuiltinScene(p.stem, p, _description(p)) for p in sorted(scenes_dir().glob("*" + SUFFIX))]


def resolve_scene(name_or_path: str | Path) -> Path:
    """The file of a scene given as a path (anything with a suffix or a folder part) or a built-in name."""
    given = Path(name_or_path)
    if isinstance(name_or_path, Path) or given.suffix or len(given.parts) > 1:
        if not given.is_file():
            raise ParameterError("scene file", str(given), "an existing scene file (*.toml) or a built-in scene name")
        return given
    names = {path.stem: path for path in scenes_dir().glob("*" + SUFFIX)}
    return names[validate.choice("scene", str(name_or_path), names)]
