"""Scenes: what a run simulates, as a TOML file (format: docs/scenes.md).

A scene names the stand, its parameter overrides, the contact model and grid, the optional
effects to build (an effect not named is not built), the procedure (fixed and swept settings,
settle timeout, gate time, repeats), the seed and the outputs - or, with ``kind =
"contact_characteristics"``, a sweep of the contact model alone. Scenes are validated on load:
unknown keys and names raise rig.errors.UnknownNameError with a suggestion, out-of-range values
raise rig.errors.ParameterError naming the key and its range, and missing physical input is an
error. Built-in scenes ship with the package, in ``rig/scenes/builtin/`` (rig.scenes.locate).

The names below are imported from their modules on first use (PEP 562), so that listing the
built-in scenes (``rig scenes``) does not import the stands and the contact model.
"""

from __future__ import annotations

import importlib

_HOMES = {
    "BuiltinScene": "locate", "builtin_scenes": "locate", "resolve_scene": "locate", "scenes_dir": "locate",
    "CharacteristicsScene": "characteristics_scene",
    "OscillationScene": "oscillation_scene",
    "PlannedPoint": "procedure", "Procedure": "procedure", "TimeoutPolicy": "procedure",
    "Outputs": "stand_scene", "StandScene": "stand_scene",
    "Scene": "load", "SceneKind": "load", "load_scene": "load", "parse_scene": "load",
}

__all__ = sorted(_HOMES)


def __getattr__(name: str):
    """PEP 562: each exported name is imported from its module when first used."""
    if name not in _HOMES:
        raise AttributeError(f"module 'rig.scenes' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"rig.scenes.{_HOMES[name]}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_HOMES))
