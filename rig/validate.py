"""Argument checks shared by the whole package: each raises a named :class:`ParameterError`.

The numeric checks are the instruments' (sensors.validate), raising rig's error type; the name
checks (``choice``, ``known_keys``) suggest the closest valid name.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from rig.errors import ParameterError, UnknownNameError
from sensors import validate as _checks


def number(
    name: str,
    value: object,
    lo: float | None = None,
    hi: float | None = None,
    *,
    lo_open: bool = False,
    hi_open: bool = False,
    allow_inf: bool = False,
) -> float:
    """Return ``value`` as a float if it is a real number inside the interval, else raise.

    ``lo``/``hi`` are the bounds (None: unbounded); ``*_open`` excludes the bound itself.
    NaN is always rejected; infinity only with ``allow_inf``.
    """
    return _checks.number(name, value, lo, hi, lo_open=lo_open, hi_open=hi_open, allow_inf=allow_inf,
                          error=ParameterError)


def integer(name: str, value: object, lo: int | None = None, hi: int | None = None) -> int:
    """Return ``value`` as an int if it is a whole number (not a bool) inside [lo, hi], else raise."""
    return _checks.integer(name, value, lo, hi, error=ParameterError)


def choice(kind: str, value: object, choices: Iterable[str]) -> str:
    """Return ``value`` if it is one of ``choices``; otherwise raise with a suggestion."""
    options = list(choices)
    if not isinstance(value, str) or value not in options:
        raise UnknownNameError(kind, value, options)
    return value


def known_keys(kind: str, given: Mapping[str, object] | Iterable[str], allowed: Iterable[str]) -> None:
    """Raise for the first key of ``given`` that is not in ``allowed`` (with a suggestion)."""
    allowed_set = set(allowed)
    for key in given:
        if key not in allowed_set:
            raise UnknownNameError(kind, key, allowed_set)
