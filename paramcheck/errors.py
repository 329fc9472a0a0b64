"""Error types raised on purpose, shared by ``rig`` and ``sensors``.

Bad input raises :class:`ParameterError` (a :class:`ValueError`) whose message names the
parameter, the value given and the valid range; an unknown name (model, shape, effect, scene
key) raises :class:`UnknownNameError`, which also suggests the closest valid name; an iteration
that does not converge raises :class:`ConvergenceError`. Every one is a :class:`NamedError`.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable


class NamedError(Exception):
    """Base class of every error raised on purpose (the command line prints it as one line).

    Picklable whatever a subclass's constructor takes, so that an error raised in a worker
    process (parallel sweeps) reaches the caller with its type, message and attributes.
    """

    def __reduce__(self):
        return (_rebuild, (type(self), str(self), dict(self.__dict__)))


def _rebuild(cls: type, message: str, state: dict) -> NamedError:
    error = cls.__new__(cls)
    Exception.__init__(error, message)
    error.__dict__.update(state)
    return error


MAX_SHOWN = 200
"""Longest value [characters] an error message quotes; a longer one is cut in the middle."""


def shown(value: object) -> str:
    """``repr(value)`` cut to MAX_SHOWN characters (its start and end kept, the length said), so
    that a 100 000-character value gives a readable one-line error."""
    text = repr(value)
    if len(text) <= MAX_SHOWN:
        return text
    keep = (MAX_SHOWN - 40) // 2
    return f"{text[:keep]} ... {text[-keep:]} ({len(text)} characters)"


class ParameterError(NamedError, ValueError):
    """A parameter or input is outside its valid range (or not a number where one is needed).

    ``ParameterError(name, value, valid, hint="")`` keeps ``name`` (the parameter), ``value``
    (what was given), ``valid`` (the valid range, in words) and ``hint`` for callers that re-raise with
    more context.
    """

    def __init__(self, name: str, value: object, valid: str, *, hint: str = "") -> None:
        self.name = name
        self.value = value
        self.valid = valid
        self.hint = hint
        message = f"{name} = {shown(value)} is not valid; valid: {valid}"
        if hint:
            message += f" ({hint})"
        super().__init__(message)


class UnknownNameError(ParameterError):
    """A name (model, shape, effect, scene key, ...) that is not one of the known ones."""

    def __init__(self, kind: str, name: object, choices: Iterable[str]) -> None:
        self.choices = sorted(choices)
        close = difflib.get_close_matches(str(name), self.choices, n=1, cutoff=0.5)
        hint = f"did you mean {close[0]!r}?" if close else ""
        super().__init__(kind, name, "one of " + ", ".join(self.choices), hint=hint)


class ConvergenceError(NamedError, RuntimeError):
    """An iteration (contact solve, settling, reduction) did not converge; says what and how far."""
