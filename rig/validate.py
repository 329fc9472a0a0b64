"""Argument checks shared by the whole package: each raises a named :class:`ParameterError`."""

from __future__ import annotations

import math
import operator
from collections.abc import Iterable, Mapping

from rig.errors import ParameterError, UnknownNameError


def _interval(lo: float | None, hi: float | None, lo_open: bool, hi_open: bool) -> str:
    left = "(" if lo_open or lo is None else "["
    right = ")" if hi_open or hi is None else "]"
    lo_s = "-inf" if lo is None else f"{lo:g}"
    hi_s = "inf" if hi is None else f"{hi:g}"
    return f"{left}{lo_s}, {hi_s}{right}"


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
    valid = _interval(lo, hi, lo_open, hi_open)
    if isinstance(value, bool):
        raise ParameterError(name, value, f"a real number in {valid}")
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise ParameterError(name, value, f"a real number in {valid}") from None
    if math.isnan(x) or (math.isinf(x) and not allow_inf):
        raise ParameterError(name, value, f"a finite number in {valid}")
    if lo is not None and (x < lo or (lo_open and x == lo)):
        raise ParameterError(name, value, valid)
    if hi is not None and (x > hi or (hi_open and x == hi)):
        raise ParameterError(name, value, valid)
    return x


def integer(name: str, value: object, lo: int | None = None, hi: int | None = None) -> int:
    """Return ``value`` as an int if it is a whole number (not a bool) inside [lo, hi], else raise."""
    valid = f"a whole number in {_interval(lo, hi, False, False)}"
    if isinstance(value, bool):
        raise ParameterError(name, value, valid)
    try:
        n = operator.index(value)  # type: ignore[arg-type]
    except TypeError:
        raise ParameterError(name, value, valid) from None
    if (lo is not None and n < lo) or (hi is not None and n > hi):
        raise ParameterError(name, value, valid)
    return n


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
