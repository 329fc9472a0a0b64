"""Reading the lab's JSON requests: every bad field is a ParameterError naming it (the server answers 400).

The page sends JSON objects; a field missing, of the wrong type, NaN or infinite (JSON has neither,
but Python's parser accepts ``NaN``), or out of its range is reported by name, and unknown fields
are errors with a "did you mean" suggestion, as everywhere in rig (rig.validate).
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Mapping

from rig import validate
from rig.errors import ParameterError


def body(data: object, allowed: Iterable[str], where: str = "body") -> Mapping[str, object]:
    """The request's JSON object (or the part ``where`` of it) with only ``allowed`` keys."""
    if not isinstance(data, dict):
        raise ParameterError(where, type(data).__name__, "a JSON object")
    _known(data, allowed, "" if where == "body" else f"{where}.")
    return data


def _known(data: Mapping[str, object], allowed: Iterable[str], prefix: str) -> None:
    """An unknown key is an error naming that key (with the closest allowed one)."""
    allowed = tuple(allowed)
    for key in data:
        if key not in allowed:
            close = difflib.get_close_matches(str(key), allowed, n=1, cutoff=0.5)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise ParameterError(f"{prefix}{key}", data[key], f"no such field (fields: {', '.join(allowed)}){hint}")


def required(data: Mapping[str, object], name: str) -> object:
    if name not in data:
        raise ParameterError(name, "missing", "given")
    return data[name]


def number(data: Mapping[str, object], name: str, lo: float | None = None, hi: float | None = None) -> float:
    """A finite number field inside [lo, hi]."""
    return validate.number(name, required(data, name), lo, hi)


def numbers(data: Mapping[str, object], name: str, allowed: Iterable[str]) -> dict[str, float]:
    """A JSON object field {key: finite number} with keys from ``allowed``; errors name ``name.key``."""
    value = required(data, name)
    if not isinstance(value, dict):
        raise ParameterError(name, value, "a JSON object of numbers")
    _known(value, allowed, f"{name}.")
    return {key: validate.number(f"{name}.{key}", v) for key, v in value.items()}
