"""Parse and validate a scene file (TOML, read with tomllib) into a StandScene or CharacteristicsScene.

``[scene] kind`` says which: "stand" (a test stand runs a procedure; the default),
"contact_characteristics" (the contact model alone, no stand) or "oscillation" ([Oscillating]:
frictional work of an oscillating contact). The file's text is kept
verbatim in the scene (it goes into the log).
"""

from __future__ import annotations

import enum
import tomllib
from pathlib import Path
from typing import TYPE_CHECKING

from rig.errors import ParameterError
from rig.scenes import tables as T
from rig.scenes.locate import resolve_scene
from rig.scenes.stand_scene import StandScene, parse_stand_scene

if TYPE_CHECKING:
    from rig.scenes.characteristics_scene import CharacteristicsScene
    from rig.scenes.oscillation_scene import OscillationScene

    Scene = StandScene | CharacteristicsScene | OscillationScene


def __getattr__(name: str):
    """``Scene``, the union of the three kinds, made on first use (PEP 562): the characteristics and
    oscillation kinds' modules (the contact solver, the bearing) are imported only when needed."""
    if name != "Scene":
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from rig.scenes.characteristics_scene import CharacteristicsScene
    from rig.scenes.oscillation_scene import OscillationScene

    globals()["Scene"] = union = StandScene | CharacteristicsScene | OscillationScene
    return union


class SceneKind(enum.Enum):
    """What a scene runs: a stand procedure, the contact characteristics, or an oscillation study."""

    STAND = "stand"
    CHARACTERISTICS = "contact_characteristics"
    OSCILLATION = "oscillation"


def _stand_class(key: object):
    from rig.stands import stand_class  # the stand module is imported only when a scene names it

    return stand_class(key)


def read_document(text: str, source: str) -> dict:
    """The TOML document of a scene; a syntax error is a ParameterError naming the file and the line."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise ParameterError(f"scene file {source}", "not valid TOML", "a TOML document", hint=str(error)) from None


def scene_kind(document: dict) -> SceneKind:
    """``[scene] kind`` of a parsed document (default "stand")."""
    head = T.sub_table(document, "scene", "", required=True)
    return T.member(SceneKind, head.get("kind", SceneKind.STAND.value), "scene.kind")


def parse_scene(text: str, *, name: str, source: str = "<text>", stand_class_of=_stand_class) -> Scene:
    """Validate a scene given as TOML text; ``name`` is its name (a file's stem), ``source`` where
    it came from (for messages); ``stand_class_of`` resolves ``[scene] stand`` (default
    rig.stands.stand_class)."""
    if not isinstance(text, str):
        raise ParameterError("scene text", type(text).__name__, "the scene file's text (str)")
    document = read_document(text, source)
    if not document:
        raise ParameterError(f"scene file {source}", "empty" if not text.strip() else "no table",
                             "a TOML scene document with at least a [scene] table")
    kind = scene_kind(document)
    if kind is SceneKind.CHARACTERISTICS:
        from rig.scenes.characteristics_scene import parse_characteristics_scene

        return parse_characteristics_scene(document, name=name, source=source, text=text)
    if kind is SceneKind.OSCILLATION:
        from rig.scenes.oscillation_scene import parse_oscillation_scene

        return parse_oscillation_scene(document, name=name, source=source, text=text)
    return parse_stand_scene(document, name=name, source=source, text=text, stand_class_of=stand_class_of)


def load_scene(name_or_path: str | Path, *, stand_class_of=_stand_class) -> Scene:
    """Read and validate a built-in scene by name (``"default"``) or a scene file by path."""
    path = resolve_scene(name_or_path)
    try:
        text = path.read_text(encoding="utf-8-sig")  # a byte-order mark (some editors save one) is dropped
    except (OSError, UnicodeDecodeError) as error:
        raise ParameterError("scene file", str(path), "a readable UTF-8 TOML file", hint=str(error)) from None
    return parse_scene(text, name=path.stem, source=str(path), stand_class_of=stand_class_of)
