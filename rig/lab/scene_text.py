"""The scene text of a lab session: what ``rig reduce`` rebuilds the stand from.

A saved session's ``log.h5`` stores this text verbatim (rig.logbook.RunMetadata.scene_toml), as
``rig run`` does for its scenes; ``rig reduce`` validates it with the current stand code and
reduces the log. The procedure section is required by the scene format but plays no part in the
reduction (the lab's points are the operator's, not a sweep's); it holds the lab's start settings.
"""

from __future__ import annotations

import json
from collections.abc import Mapping

CONTACT = """[contact]
model = "kinematic"
n = 16
poisson = 0.3
surrogate = true
table_points = [25, 3, 7]
"""
"""The contact law of the lab's stand A: the default scene's (kinematic law, cached surrogate table)."""

GATE_TIME_S = 4.0
"""Default common gate of the lab [s] (the default scene's)."""


def _value(x: float) -> str:
    return repr(float(x))


def stand_a_scene(*, seed: int, mu: float, effects: Mapping[str, Mapping[str, float]],
                  start: Mapping[str, float], description: str) -> str:
    """TOML text of a dynamic stand-A scene with friction coefficient ``mu`` [1], the named
    ``effects`` {name: {parameter: value}} and the start settings ``start`` {setting: SI value}."""
    lines = ["# A rig lab session of stand A (rig.lab): the points are the operator's, recorded in the lab.",
             "[scene]", 'kind = "stand"', f"description = {json.dumps(description)}", 'stand = "yoke"',
             f"seed = {int(seed)}", 'drive = "dynamic"', "", "[parameters]", f"mu = {_value(mu)}", "", CONTACT]
    for name, values in effects.items():
        lines.append(f"[effects.{name}]")
        lines += [f"{key} = {_value(v)}" for key, v in values.items()]
    lines += ["", "[procedure]", "settle_timeout_s = 30.0", f"gate_time_s = {_value(GATE_TIME_S)}",
              'on_settle_timeout = "skip"', "", "[procedure.fixed]"]
    lines += [f"{name} = {_value(v)}" for name, v in start.items()]
    lines += ["", "[outputs]", "figures = false", ""]
    return "\n".join(lines)
