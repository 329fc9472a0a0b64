"""The two test stands of [Koziarski] as simulators (contract: rig.stands.base).

``stand_class(name)`` returns the class for a scene's ``stand`` key; the stand modules are
imported only when named.
"""

from __future__ import annotations

import importlib

from rig import validate

__all__ = ["STANDS", "stand_class"]

STANDS = {
    "yoke": "rig.stands.yoke.stand:YokeStand",  # stand A, Figs. 8-9: yoke/spring, high spin
    "disc_roller": "rig.stands.disc_roller.stand:DiscRollerStand",  # stand B, Figs. 12-13
}
"""A scene's ``stand`` key -> ``"module:Class"`` of the stand (its module is imported when named)."""


def stand_class(name: str):
    """The Stand subclass registered under a scene's ``stand`` key.

    Parameters
    ----------
    name : str
        The key, one of :data:`STANDS` (``"yoke"``: stand A, ``"disc_roller"``: stand B).

    Returns
    -------
    type
        The rig.stands.base.Stand subclass (its module is imported now).

    Raises
    ------
    UnknownNameError
        An unknown key, with the closest one.
    """
    validate.choice("stand", name, STANDS)
    module, _, attribute = STANDS[name].partition(":")
    return getattr(importlib.import_module(module), attribute)
