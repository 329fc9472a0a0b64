"""The scene text of a lab session (stand A or B): what ``rig reduce`` rebuilds the stand from.

A saved session's ``log.h5`` stores this text verbatim (rig.logbook.RunMetadata.scene_toml), as
``rig run`` does for its scenes; ``rig reduce`` validates it with the current stand code and
reduces the log. The procedure section is required by the scene format but plays no part in the
reduction (the lab's points are the operator's, not a sweep's); it holds the lab's start settings.
"""

from __future__ import annotations

import json
from collections.abc import Mapping

CONTACT_A = """[contact]
model = "kinematic"
n = 16
poisson = 0.3
surrogate = true
table_points = [25, 3, 7]
"""
"""The contact law of the lab's stand A: the default scene's (kinematic law, cached surrogate table)."""

CONTACT_B = """[contact]
model = "kinematic"
n = 12
poisson = 0.5
surrogate = true
table_points = [25, 9, 7]
"""
"""The contact law of the lab's stand B: fig14's model and grid, with two more alpha' nodes because the
lab's table spans every hidden mu of the effect law_mu_range (one table per dead weight, cached)."""

GATE_TIME_S = {"yoke": 4.0, "disc_roller": 10.0}
"""Default gate of the lab per stand [s] (the default scene's common gate; fig14's recorder gate)."""


def _value(x: float) -> str:
    return repr(float(x))


def stand_scene(stand: str, *, seed: int, mu: float, effects: Mapping[str, Mapping[str, float]],
                start: Mapping[str, float], description: str) -> str:
    """TOML text of a dynamic scene of ``stand`` ("yoke": A, "disc_roller": B) with friction
    coefficient ``mu`` [1], the named ``effects`` {name: {parameter: value}} and the start settings
    ``start`` {setting: SI value}."""
    contact = {"yoke": CONTACT_A, "disc_roller": CONTACT_B}[stand]
    label = {"yoke": "stand A", "disc_roller": "stand B"}[stand]
    lines = [f"# A rig lab session of {label} (rig.lab): the points are the operator's, recorded in the lab.",
             "[scene]", 'kind = "stand"', f"description = {json.dumps(description)}", f'stand = "{stand}"',
             f"seed = {int(seed)}", 'drive = "dynamic"', "", "[parameters]", f"mu = {_value(mu)}", "", contact]
    for name, values in effects.items():
        lines.append(f"[effects.{name}]")
        lines += [f"{key} = {_value(v)}" for key, v in values.items()]
    lines += ["", "[procedure]", "settle_timeout_s = 30.0", f"gate_time_s = {_value(GATE_TIME_S[stand])}",
              'on_settle_timeout = "skip"', "", "[procedure.fixed]"]
    lines += [f"{name} = {_value(v)}" for name, v in start.items()]
    lines += ["", "[outputs]", "figures = false", ""]
    return "\n".join(lines)
