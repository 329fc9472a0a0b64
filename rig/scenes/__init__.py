"""Scenes: what a run simulates, as a TOML file (format: docs/scenes.md).

A scene names the stand, its parameter overrides, the contact model and grid, the optional
effects to build (an effect not named is not built), the procedure (fixed and swept settings,
settle timeout, gate time, repeats), the seed and the outputs - or, with ``kind =
"contact_characteristics"``, a sweep of the contact model alone. Scenes are validated on load:
unknown keys and names raise rig.errors.UnknownNameError with a suggestion, out-of-range values
raise rig.errors.ParameterError naming the key and its range, and missing physical input is an
error. Built-in scenes ship with the package, in ``rig/scenes/builtin/`` (rig.scenes.locate).
"""

from __future__ import annotations

from rig.scenes.characteristics_scene import CharacteristicsScene
from rig.scenes.load import Scene, SceneKind, load_scene, parse_scene
from rig.scenes.locate import BuiltinScene, builtin_scenes, resolve_scene, scenes_dir
from rig.scenes.oscillation_scene import OscillationScene
from rig.scenes.procedure import PlannedPoint, Procedure, TimeoutPolicy
from rig.scenes.stand_scene import Outputs, StandScene

__all__ = [
    "BuiltinScene",
    "CharacteristicsScene",
    "OscillationScene",
    "Outputs",
    "PlannedPoint",
    "Procedure",
    "Scene",
    "SceneKind",
    "StandScene",
    "TimeoutPolicy",
    "builtin_scenes",
    "load_scene",
    "parse_scene",
    "resolve_scene",
    "scenes_dir",
]
