"""Argument checks: each raises a named :class:`~paramcheck.errors.ParameterError` (or the subclass a
caller passes as ``error``, e.g. sensors' InstrumentParameterError); ``choice`` and ``known_keys``
suggest the closest valid name."""

from __future__ import annotations

import math
import operator
from collections.abc import Iterable, Mapping

import numpy as np

from paramcheck.errors import ParameterError, UnknownNameError


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
    error: type[ParameterError] = ParameterError,
) -> float:
    """Return ``value`` as a float inside the interval, else raise ``error``.

    ``lo``/``hi``: bounds (None: unbounded); ``*_open`` excludes the bound itself. NaN is always
    rejected, infinity unless ``allow_inf``; booleans and strings are not numbers. The interval's
    text is formatted only for an error (this check runs ~10^5 times in a study's reduction).
    """
    if isinstance(value, (bool, str, bytes)):
        raise error(name, value, f"a real number in {_interval(lo, hi, lo_open, hi_open)}")
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError, OverflowError):  # OverflowError: an int beyond a float's range
        raise error(name, value, f"a real number in {_interval(lo, hi, lo_open, hi_open)}") from None
    if math.isnan(x) or (math.isinf(x) and not allow_inf):
        raise error(name, value, f"a finite number in {_interval(lo, hi, lo_open, hi_open)}")
    if lo is not None and (x < lo or (lo_open and x == lo)):
        raise error(name, value, _interval(lo, hi, lo_open, hi_open))
    if hi is not None and (x > hi or (hi_open and x == hi)):
        raise error(name, value, _interval(lo, hi, lo_open, hi_open))
    return x


def integer(
    name: str,
    value: object,
    lo: int | None = None,
    hi: int | None = None,
    *,
    error: type[ParameterError] = ParameterError,
) -> int:
    """Return ``value`` as an int if it is a whole number (not a bool) inside [lo, hi], else raise ``error``."""
    valid = f"a whole number in {_interval(lo, hi, False, False)}"
    if isinstance(value, bool):
        raise error(name, value, valid)
    try:
        n = operator.index(value)  # type: ignore[arg-type]
    except TypeError:
        raise error(name, value, valid) from None
    if (lo is not None and n < lo) or (hi is not None and n > hi):
        raise error(name, value, valid)
    return n


def finite_array(
    name: str, values: object, *, min_length: int = 1, error: type[ParameterError] = ParameterError
) -> np.ndarray:
    """Return ``values`` as a 1-D float array of finite numbers with at least ``min_length`` entries."""
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise error(name, values, "a 1-D array of real numbers") from None
    if arr.ndim != 1 or arr.size < min_length:
        raise error(
            name, f"array of shape {arr.shape}", f"a 1-D array with at least {min_length} entries"
        )
    if not np.all(np.isfinite(arr)):
        bad = int(np.flatnonzero(~np.isfinite(arr))[0])
        raise error(f"{name}[{bad}]", float(arr[bad]), "a finite number")
    return arr


def time_series(
    t_name: str, t: object, x_name: str, x: object, *, min_length: int = 2,
    error: type[ParameterError] = ParameterError,
) -> tuple[np.ndarray, np.ndarray]:
    """Check a sampled series: times [s] strictly increasing, values finite, same length."""
    ta = finite_array(t_name, t, min_length=min_length, error=error)
    xa = finite_array(x_name, x, min_length=min_length, error=error)
    if xa.size != ta.size:
        raise error(
            x_name, f"{xa.size} samples", f"as many samples as {t_name} ({ta.size})"
        )
    steps = np.diff(ta)
    if np.any(steps <= 0.0):
        bad = int(np.flatnonzero(steps <= 0.0)[0]) + 1
        raise error(
            f"{t_name}[{bad}]", float(ta[bad]), f"strictly increasing times (> {ta[bad - 1]!r} s)"
        )
    return ta, xa


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
