"""Write a scene document (nested dicts of TOML values) back as TOML text that ``tomllib`` reads unchanged.

The scene format uses a small part of TOML: tables, arrays of tables (``[[characteristics.cases]]``),
inline tables (``{ start = -1.6, stop = 1.6, num = 9 }``), arrays, strings, booleans, whole and real
numbers. :func:`dump_toml` writes exactly that part; comments of a scene file are not kept (a
changed scene is written anew). ``tomllib.loads(dump_toml(d)) == d`` for every document it accepts.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping

from rig.errors import ParameterError

_BARE_KEY = re.compile(r"[A-Za-z0-9_-]+")  # fullmatch: "$" would let a key end in "\n"
_ESCAPES = {'"': '\\"', "\\": "\\\\", "\b": "\\b", "\t": "\\t", "\n": "\\n", "\f": "\\f", "\r": "\\r"}


def _string(text: str) -> str:
    """A TOML basic string: quotes, backslashes and every control character (DEL too) escaped."""
    return '"' + "".join(_ESCAPES.get(c, f"\\u{ord(c):04x}" if ord(c) < 0x20 or ord(c) == 0x7F else c)
                         for c in text) + '"'


def _key(name: object) -> str:
    if not isinstance(name, str) or not name:
        raise ParameterError("scene key", name, "a non-empty string")
    return name if _BARE_KEY.fullmatch(name) else _string(name)


def _value(value: object, where: str) -> str:
    """One TOML value written inline (tables inside arrays or values become inline tables)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, str):
        return _string(value)
    if isinstance(value, Mapping):
        return "{ " + ", ".join(f"{_key(k)} = {_value(v, f'{where}.{k}')}" for k, v in value.items()) + " }"
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_value(v, f"{where}[{k}]") for k, v in enumerate(value)) + "]"
    if hasattr(value, "__float__") and hasattr(value, "dtype"):  # a numpy scalar
        return _value(value.item(), where)
    raise ParameterError(where or "scene value", value,
                         "a TOML value: a string, boolean, number, array or table")


def _is_table_array(value: object) -> bool:
    return isinstance(value, (list, tuple)) and bool(value) and all(isinstance(v, Mapping) for v in value)


def _table(lines: list[str], header: str, table: Mapping[str, object], *, array: bool = False) -> None:
    """Append ``[header]`` (``[[header]]`` for an array entry), its plain keys, then its sub-tables."""
    plain = {k: v for k, v in table.items() if not isinstance(v, Mapping) and not _is_table_array(v)}
    if header:
        if lines:
            lines.append("")
        lines.append(f"[[{header}]]" if array else f"[{header}]")
    for key, value in plain.items():
        lines.append(f"{_key(key)} = {_value(value, f'{header}.{key}' if header else str(key))}")
    for key, value in table.items():
        name = f"{header}.{_key(key)}" if header else _key(key)
        if isinstance(value, Mapping):
            _table(lines, name, value)
        elif _is_table_array(value):
            for entry in value:
                _table(lines, name, entry, array=True)


def dump_toml(document: Mapping[str, object]) -> str:
    """The TOML text of ``document`` (a mapping of tables and values as ``tomllib.loads`` returns them).

    Parameters
    ----------
    document : Mapping[str, object]
        Tables (mappings), arrays of tables (lists of mappings) and values (str, bool, int, float,
        lists, inline mappings).

    Returns
    -------
    str
        TOML text; ``tomllib.loads`` of it equals ``document``.

    Raises
    ------
    ParameterError
        A value TOML cannot hold (None, an object), named by its dotted key.
    """
    lines: list[str] = []
    _table(lines, "", document)
    return "\n".join(lines) + "\n"
