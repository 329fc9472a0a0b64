"""The two test stands of [Koziarski] as simulators (contract: rig.stands.base).

``stand_class(name)`` returns the class for a scene's ``stand`` key; the stand modules are
imported only when named.
"""

from __future__ import annotations

import importlib

from rig import validate

STANDS = {
    "yoke": "rig.stands.yoke.stand:YokeStand",  # stand A, Figs. 8-9: yoke/spring, high spin
    "disc_roller": "rig.stands.disc_roller.stand:DiscRollerStand",  # stand B, Figs. 12-13
}


def stand_class(name: str):
    """The Stand subclass registered under ``name`` (UnknownNameError with a suggestion otherwise)."""
    validate.choice("stand", name, STANDS)
    module, _, attribute = STANDS[name].partition(":")
    return getattr(importlib.import_module(module), attribute)
