"""Reading one table of a parsed scene file: required and optional keys, unknown keys, values.

Every error names the dotted path of the offending key in the scene (``procedure.gate_time_s``),
the value found and what is valid (rig.errors.ParameterError); an unknown key raises
rig.errors.UnknownNameError with the closest known key as a suggestion.
"""

from __future__ import annotations

import enum
from collections.abc import Iterable, Mapping
from typing import TypeVar

import numpy as np

from rig import validate
from rig.errors import ParameterError

MISSING = "missing"
"""The value shown in the message of a required key that the scene does not give."""

E = TypeVar("E", bound=enum.Enum)


class Spacing(enum.Enum):
    """How ``{start, stop, num}`` expands into values: evenly (LINEAR) or evenly in log (LOG)."""

    LINEAR = "linear"
    LOG = "log"


def dotted(where: str, key: str) -> str:
    """``dotted("procedure", "gate_time_s") == "procedure.gate_time_s"`` (``where`` may be "")."""
    return f"{where}.{key}" if where else key


def check_keys(table: Mapping[str, object], allowed: Iterable[str], where: str) -> None:
    """UnknownNameError (with a suggestion) for the first key of ``table`` not in ``allowed``."""
    validate.known_keys(f"key in [{where}]" if where else "top-level table", table, allowed)


def sub_table(table: Mapping[str, object], key: str, where: str, *, required: bool) -> dict | None:
    """The sub-table ``key`` of ``table`` (None if absent and not required)."""
    value = table.get(key)
    if value is None:
        if required:
            raise ParameterError(dotted(where, key), MISSING, "a table; required")
        return None
    if not isinstance(value, Mapping):
        raise ParameterError(dotted(where, key), value, "a table")
    return dict(value)


def required(table: Mapping[str, object], key: str, where: str, valid: str) -> object:
    """The value of a required key; ParameterError naming it and ``valid`` when it is absent.

    Physical input never has a silent default: a missing required key is always an error.
    """
    if key not in table:
        raise ParameterError(dotted(where, key), MISSING, f"{valid}; required (no default for physical input)")
    return table[key]


def text(table: Mapping[str, object], key: str, where: str) -> str:
    """A required non-empty single-line string."""
    value = required(table, key, where, "a non-empty one-line string")
    if not isinstance(value, str) or not value.strip() or "\n" in value:
        raise ParameterError(dotted(where, key), value, "a non-empty one-line string")
    return value.strip()


def flag(table: Mapping[str, object], key: str, where: str, default: bool) -> bool:
    """An optional boolean (TOML true/false)."""
    value = table.get(key, default)
    if not isinstance(value, bool):
        raise ParameterError(dotted(where, key), value, "true or false")
    return value


def member(enum_type: type[E], value: object, name: str) -> E:
    """The member of ``enum_type`` whose value is ``value`` (UnknownNameError with a suggestion)."""
    choices = [m.value for m in enum_type]
    return enum_type(validate.choice(name, value, choices))


def number(name: str, value: object, lo: float | None, hi: float | None, unit: str = "", **open_: bool) -> float:
    """``validate.number`` whose message also gives the unit of the valid range."""
    try:
        return validate.number(name, value, lo, hi, **open_)
    except ParameterError as error:
        valid = f"{error.valid} {unit}".rstrip() if unit and unit != "1" else error.valid
        raise ParameterError(name, value, valid) from None


def values(name: str, given: object, lo: float | None, hi: float | None, unit: str = "") -> tuple[float, ...]:
    """A non-empty list of numbers, or ``{start, stop, num, spacing}`` expanded, each inside [lo, hi].

    ``spacing`` is "linear" (default) or "log" (start and stop > 0); ``num`` >= 1.
    """
    if isinstance(given, Mapping):
        check_keys(given, ("start", "stop", "num", "spacing"), name)
        spacing = member(Spacing, given.get("spacing", Spacing.LINEAR.value), dotted(name, "spacing"))
        positive = spacing is Spacing.LOG
        start = number(dotted(name, "start"), required(given, "start", name, "a number"), lo, hi, unit)
        stop = number(dotted(name, "stop"), required(given, "stop", name, "a number"), lo, hi, unit)
        if positive and (start <= 0 or stop <= 0):
            bad, value = ("start", start) if start <= 0 else ("stop", stop)
            raise ParameterError(dotted(name, bad), value, "> 0 for spacing = 'log'")
        num = validate.integer(dotted(name, "num"), required(given, "num", name, "a whole number >= 1"), 1, 10**6)
        grid = np.geomspace(start, stop, num) if positive else np.linspace(start, stop, num)
        return tuple(float(x) for x in grid)
    if isinstance(given, (list, tuple)) and given:
        return tuple(number(f"{name}[{k}]", x, lo, hi, unit) for k, x in enumerate(given))
    raise ParameterError(name, given, "a non-empty list of numbers or a table {start, stop, num, spacing}")
