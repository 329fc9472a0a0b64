"""friction-rig: a virtual test rig of C. Koziarski's friction-wheel experiments.

The API for experiment scripts (rig.api), importable from here::

    import rig
    scene = rig.load_scene("default").with_(mu=0.35)
    result = rig.run(scene, "out/mu035")
    result.reduced          # pandas DataFrame, one row per operating point

Sub-packages: ``rig.contact`` (contact-force model, knows nothing of stands; ``rig.contact.solve``),
``rig.stands`` (the two test stands), ``rig.reduction`` ([Koziarski] eqs. (29)-(36)),
``rig.compare``, ``rig.fit``; instruments live in the separate package ``sensors``. Everything is
imported when first used, so ``import rig`` is cheap.
"""

from __future__ import annotations

import importlib

__version__ = "0.1.0"

_API = ("Run", "Scene", "list_scenes", "load_scene", "open_run", "run")
_SUBPACKAGES = ("api", "compare", "contact", "fit", "reduction", "stands")

__all__ = ["Run", "Scene", "list_scenes", "load_scene", "open_run", "run"]


def __getattr__(name: str):
    """PEP 562: the API names and the sub-packages are imported on first use."""
    if name in _API:
        value = getattr(importlib.import_module("rig.api"), name)
    elif name in _SUBPACKAGES:
        value = importlib.import_module(f"rig.{name}")
    else:
        raise AttributeError(f"module 'rig' has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API) | set(_SUBPACKAGES))
