"""A scene for experiment scripts: load, change with validation, build without a file, write back as TOML.

:class:`Scene` holds a scene document (the tables of a scene file, docs/scenes.md) together with
the validated scene the runner takes. It is immutable: :meth:`Scene.with_` returns a new Scene.
Every change goes through the scene file's own reader (rig.scenes.parse_scene), so a change is
checked exactly like the same key in a TOML file and fails with the same named errors
(:class:`rig.errors.ParameterError` naming the key, the value and the valid range;
:class:`rig.errors.UnknownNameError` with the closest known key).
"""

from __future__ import annotations

import copy
import tomllib
from collections.abc import Mapping
from pathlib import Path

from rig.errors import ParameterError, UnknownNameError
from rig.scenes import load as scene_load
from rig.scenes.locate import builtin_scenes
from rig.scenes.toml_text import dump_toml

REMOVE = None
"""The value that removes a key in :meth:`Scene.with_` (``{"effects.balance_noise": None}``)."""

KEYWORD_DOT = "__"
"""In a keyword of :meth:`Scene.with_`, ``__`` stands for the dot of a dotted key (``contact__n=16``)."""

HEAD_KEYS = ("description", "seed", "drive")
"""Keys of the ``[scene]`` table a bare keyword of :meth:`Scene.with_` may name."""

CHANGED = ", changed in Python"
"""Added to a scene's source (shown in the run summary) once :meth:`Scene.with_` changed it."""

DEFAULT_NAME = "scene"
"""Name of a scene built in Python when none is given (a file's scene is named by its stem)."""


class Scene:
    """A validated scene (stand, contact characteristics or oscillation), immutable.

    Build one with :func:`rig.load_scene` (a built-in name or a ``.toml`` file),
    :meth:`Scene.from_toml` or :meth:`Scene.from_dict`; change it with :meth:`Scene.with_`; write
    it with :meth:`Scene.to_toml`. Values are in the units the scene keys name (SI: ``_N``,
    ``_m``, ``_s``, ``_rad_s``; docs/scenes.md); the scene's own checks apply to every value.

    Attributes
    ----------
    name : str
        The scene's name (a file's stem, or the name given when built in Python).
    kind : str
        ``"stand"``, ``"contact_characteristics"`` or ``"oscillation"`` (``[scene] kind``).
    description : str
        The one-line ``[scene] description``.
    validated : StandScene or CharacteristicsScene or OscillationScene
        What the runner takes (rig.scenes): the stand class, ranges applied, sweeps expanded.
    """

    __slots__ = ("_document", "_validated")

    def __init__(self, validated: scene_load.Scene) -> None:
        object.__setattr__(self, "_validated", validated)
        object.__setattr__(self, "_document", tomllib.loads(validated.text))

    def __setattr__(self, name: str, value: object) -> None:
        raise AttributeError(f"a Scene is immutable: use scene.with_({name}=...) for a changed copy")

    def __delattr__(self, name: str) -> None:
        raise AttributeError("a Scene is immutable")

    # --- building -------------------------------------------------------------------------------------

    @classmethod
    def from_toml(cls, text: str, *, name: str = DEFAULT_NAME, source: str | None = None) -> Scene:
        """A scene from the text of a scene file.

        Parameters
        ----------
        text : str
            TOML text in the scene format (docs/scenes.md).
        name : str, optional
            The scene's name (default ``"scene"``); runs and messages use it.
        source : str, optional
            Where the text came from, for messages and the run summary (default ``"<scene NAME>"``).

        Returns
        -------
        Scene
            The validated scene; its :meth:`to_toml` is ``text`` verbatim (comments kept).

        Raises
        ------
        ParameterError, UnknownNameError
            The first invalid value or unknown key, named by its dotted key.
        """
        source = f"<scene {name}>" if source is None else str(source)
        return cls(scene_load.parse_scene(text, name=str(name), source=source))

    @classmethod
    def from_dict(cls, document: Mapping[str, object], *, name: str = DEFAULT_NAME) -> Scene:
        """A scene from its tables given as nested mappings, without a file.

        Parameters
        ----------
        document : Mapping[str, object]
            The scene's tables as ``tomllib`` reads them from a scene file, e.g.
            ``{"scene": {"stand": "yoke", ...}, "contact": {...}, "procedure": {...}}``.
        name : str, optional
            The scene's name (default ``"scene"``).

        Returns
        -------
        Scene
            The validated scene.

        Raises
        ------
        ParameterError, UnknownNameError
            As for a scene file with the same tables.
        """
        if not isinstance(document, Mapping):
            raise ParameterError("scene document", type(document).__name__, "a mapping of the scene's tables")
        return cls.from_toml(dump_toml(document), name=name)

    # --- reading --------------------------------------------------------------------------------------

    @property
    def name(self) -> str:
        """The scene's name (str)."""
        return self._validated.name

    @property
    def kind(self) -> str:
        """``"stand"``, ``"contact_characteristics"`` or ``"oscillation"`` (str)."""
        return scene_load.scene_kind(self._document).value

    @property
    def description(self) -> str:
        """The one-line description (str)."""
        return self._validated.description

    @property
    def validated(self) -> scene_load.Scene:
        """The validated scene object the runner takes (rig.scenes.StandScene and siblings)."""
        return self._validated

    def to_dict(self) -> dict:
        """The scene's tables as nested dicts (a copy; changing it does not change the scene).

        Returns
        -------
        dict
            What ``tomllib.loads(scene.to_toml())`` returns.
        """
        return copy.deepcopy(self._document)

    def to_toml(self) -> str:
        """The scene as the text of a scene file.

        Returns
        -------
        str
            The file's text verbatim for a scene loaded or built from text and not changed since;
            otherwise the tables written anew (without comments). ``Scene.from_toml(s.to_toml())``
            equals ``s``.
        """
        return self._validated.text

    def __getitem__(self, key: str) -> object:
        """The value at a dotted key, e.g. ``scene["contact.n"]`` (KeyError if the scene does not give it)."""
        value: object = self._document
        for part in _split(key):
            if not isinstance(value, Mapping) or part not in value:
                raise KeyError(key)
            value = value[part]
        return copy.deepcopy(value)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scene) and (self.name, self._document) == (other.name, other._document)

    def __hash__(self) -> int:
        return hash((self.name, self.to_toml()))

    def __repr__(self) -> str:
        return f"<rig.Scene {self.name!r} ({self.kind}): {self.description}>"

    # --- changing -------------------------------------------------------------------------------------

    def with_(self, changes: Mapping[str, object] | None = None, /, **keywords: object) -> Scene:
        """A new scene with some keys changed, validated like a scene file.

        Parameters
        ----------
        changes : Mapping[str, object], optional
            ``{dotted key: value}``, e.g. ``{"contact.n": 16, "procedure.gate_time_s": 2.0,
            "procedure.sweep.brake_setpoint_N_m": {"start": 0.0, "stop": 1.0, "num": 5}}``. A
            value of None removes the key (``{"effects.balance_noise": None}``); a table given for
            a new key adds it (``{"effects.balance_noise": {}}`` builds that effect).
        **keywords
            The same, as keywords: a bare name is a stand parameter (``mu=0.4`` is
            ``parameters.mu``) or a ``[scene]`` key (``seed``, ``description``, ``drive``); ``__``
            stands for a dot (``contact__n=16``). Applied after ``changes``.

        Returns
        -------
        Scene
            A new scene (same name); this one is unchanged.

        Raises
        ------
        ParameterError
            A value outside its valid range, named by its dotted key, with the range (and the unit).
        UnknownNameError
            A key the scene format does not know, with the closest known key.
        """
        if changes is not None and not isinstance(changes, Mapping):
            raise ParameterError("changes", type(changes).__name__, "a mapping {dotted key: value}")
        items = list((changes or {}).items()) + [(self._keyword_key(word), value) for word, value in keywords.items()]
        document = copy.deepcopy(self._document)
        for key, value in items:
            _set(document, _split(key), value, key)
        source = self._validated.source
        if not source.endswith(CHANGED):
            source += CHANGED
        return Scene.from_toml(dump_toml(document), name=self.name, source=source)

    def _keyword_key(self, word: str) -> str:
        """The dotted key a keyword of :meth:`with_` names."""
        if KEYWORD_DOT in word:
            return word.replace(KEYWORD_DOT, ".")
        shorthands = self._shorthands()
        if word not in shorthands:
            raise UnknownNameError("Scene.with_ keyword", word, shorthands)
        return shorthands[word]

    def _shorthands(self) -> dict[str, str]:
        """Bare keyword -> dotted key: the [scene] keys and, for a stand scene, the stand's parameters."""
        known = {key: f"scene.{key}" for key in HEAD_KEYS}
        stand_class = getattr(self._validated, "stand_class", None)
        if stand_class is not None:
            known.update({name: f"parameters.{name}" for name in stand_class.PARAMETERS})
        return known


def _split(key: object) -> list[str]:
    if not isinstance(key, str) or not key or any(not part for part in key.split(".")):
        raise ParameterError("scene key", key, "a dotted key such as 'contact.n' or 'parameters.mu'")
    return key.split(".")


def _set(document: dict, parts: list[str], value: object, key: str) -> None:
    """Set (or, for None, remove) ``value`` at the dotted ``parts`` of ``document``, making tables on the way."""
    table = document
    for depth, part in enumerate(parts[:-1]):
        below = table.get(part)
        if below is None:
            if value is REMOVE:
                return
            below = table[part] = {}
        if not isinstance(below, dict):
            raise ParameterError(".".join(parts[:depth + 1]), below, f"a table (to set {key!r} inside it)")
        table = below
    if value is REMOVE:
        table.pop(parts[-1], None)
    else:
        table[parts[-1]] = copy.deepcopy(dict(value)) if isinstance(value, Mapping) else value


def load_scene(name_or_path: str | Path) -> Scene:
    """Read and validate a built-in scene by name or a scene file by path.

    Parameters
    ----------
    name_or_path : str or pathlib.Path
        A built-in scene name (:func:`list_scenes`, e.g. ``"fig10"``) or the path of a ``.toml``
        scene file (anything with a suffix or a folder part, or a Path).

    Returns
    -------
    Scene
        The validated scene, named by the file's stem.

    Raises
    ------
    UnknownNameError
        An unknown built-in name, with the closest one.
    ParameterError
        A file that does not exist or cannot be read, or an invalid value in it.
    """
    return Scene(scene_load.load_scene(name_or_path))


def list_scenes() -> list[str]:
    """The names of the built-in scenes, sorted (what ``rig scenes`` lists).

    Returns
    -------
    list of str
        Names :func:`load_scene` accepts.
    """
    return [scene.name for scene in builtin_scenes()]
