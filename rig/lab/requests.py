"""Reading the lab's JSON requests: every bad field is a ParameterError naming it (the server answers 400).

The page sends JSON objects; a field missing, of the wrong type, NaN or infinite (JSON has neither,
but Python's parser accepts ``NaN``), or out of its range is reported by name, and unknown fields
are errors with a "did you mean" suggestion, as everywhere in rig (rig.validate).

A body is read by :func:`parse_json`, which cannot be made to hurt the server: its size is
bounded by the app (MAX_BODY_BYTES, 413 above it), its nesting depth is measured on the text
before the parser sees it (MAX_DEPTH; Python's parser recurses and would overflow the stack),
and an integer too long for a float is read as infinity, which every number check refuses by
name. Values quoted in an error are cut to SHOWN_CHARS characters.
"""

from __future__ import annotations

import difflib
import json
import re
from collections.abc import Iterable, Mapping

from rig import validate
from rig.errors import ParameterError

MAX_BODY_BYTES = 64 * 1024
"""Largest request body the lab reads [bytes] (a submission of every point is a few kB)."""
MAX_DEPTH = 8
"""Deepest nesting of JSON arrays/objects a request may have (the lab's deepest is 4)."""
MAX_INT_DIGITS = 30
"""An integer with more digits is read as a float (infinity beyond 1e308, refused by name)."""
SHOWN_CHARS = 60
"""Longest quote of a client's value in an error message [characters]."""
_TOKEN = re.compile(rb'\\.|["\[\]{}]', re.DOTALL)


def short(value: object) -> object:
    """``value`` as an error may quote it: long strings and containers cut to SHOWN_CHARS characters."""
    if isinstance(value, (bool, float, type(None))):
        return value
    if isinstance(value, int):
        return value if abs(value) < 10**SHOWN_CHARS else f"<an integer of {len(str(abs(value)))} digits>"
    text = value if isinstance(value, str) else repr(value)
    return text if len(text) <= SHOWN_CHARS else text[:SHOWN_CHARS] + "..."


def depth(raw: bytes) -> int:
    """The deepest nesting of arrays and objects in the JSON text ``raw`` (brackets inside strings
    do not count; an unbalanced text gets the depth it reached)."""
    deepest = level = 0
    inside = False  # inside a string
    for match in _TOKEN.finditer(raw):  # one pass: an escape, a quote or a bracket at a time
        token = match.group()
        if token == b'"':
            inside = not inside
        elif not inside and len(token) == 1:
            level += 1 if token in (b"[", b"{") else -1
            deepest = max(deepest, level)
    return deepest


def parse_json(raw: bytes) -> object:
    """The JSON value of a request body ``raw`` (at most MAX_BODY_BYTES, checked by the caller);
    a ParameterError naming ``body`` if it is not UTF-8 JSON or nests deeper than MAX_DEPTH."""
    nested = depth(raw)
    if nested > MAX_DEPTH:
        raise ParameterError("body", f"JSON nested {nested} deep", f"at most {MAX_DEPTH} levels of arrays/objects")
    try:
        text = raw.decode("utf-8")
        return json.loads(text, parse_int=_integer)
    except (UnicodeDecodeError, ValueError, RecursionError) as error:
        raise ParameterError("body", short(raw.decode("utf-8", "replace")), f"a JSON object ({error})") from None


def _integer(text: str) -> int | float:
    return int(text) if len(text.lstrip("-")) <= MAX_INT_DIGITS else float(text)


def body(data: object, allowed: Iterable[str], where: str = "body") -> Mapping[str, object]:
    """The request's JSON object (or the part ``where`` of it) with only ``allowed`` keys."""
    if not isinstance(data, dict):
        raise ParameterError(where, short(data), "a JSON object")
    _known(data, allowed, "" if where == "body" else f"{where}.")
    return data


def _known(data: Mapping[str, object], allowed: Iterable[str], prefix: str) -> None:
    """An unknown key is an error naming that key (with the closest allowed one)."""
    allowed = tuple(allowed)
    for key in data:
        if key not in allowed:
            close = difflib.get_close_matches(str(key), allowed, n=1, cutoff=0.5)
            hint = f"; did you mean {close[0]!r}?" if close else ""
            raise ParameterError(f"{prefix}{short(key)}", short(data[key]),
                                 f"no such field (fields: {', '.join(allowed)}){hint}")


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
        raise ParameterError(name, short(value), "a JSON object of numbers")
    _known(value, allowed, f"{name}.")
    return {key: validate.number(f"{name}.{key}", v) for key, v in value.items()}
