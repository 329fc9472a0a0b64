"""Exceptions raised by friction-rig.

Bad input raises :class:`ParameterError` (a :class:`ValueError`) whose message names the
parameter, the value given and the valid range; an unknown name (model, shape, effect, scene
key) raises :class:`UnknownNameError`, which also suggests the closest valid name.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

from sensors.errors import InstrumentParameterError


class RigError(Exception):
    """Base class of every error friction-rig raises on purpose.

    Picklable whatever a subclass's constructor takes, so that an error raised in a worker
    process (parallel sweeps) reaches the caller with its type, message and attributes.
    """

    def __reduce__(self):
        return (_rebuild, (type(self), str(self), dict(self.__dict__)))


def _rebuild(cls: type, message: str, state: dict) -> RigError:
    error = cls.__new__(cls)
    Exception.__init__(error, message)
    error.__dict__.update(state)
    return error


class ParameterError(RigError, InstrumentParameterError):
    """A parameter is outside its valid range (or not a number where one is needed).

    ``ParameterError(name, value, valid, hint="")`` keeps ``name``, ``value``, ``valid``; the
    message format is the instruments' (sensors.errors), of which this is rig's refinement.
    """


class UnknownNameError(ParameterError):
    """A name (model, shape, effect, scene key, ...) that is not one of the known ones."""

    def __init__(self, kind: str, name: object, choices: Iterable[str]) -> None:
        self.choices = sorted(choices)
        close = difflib.get_close_matches(str(name), self.choices, n=1, cutoff=0.5)
        hint = f"did you mean {close[0]!r}?" if close else ""
        super().__init__(kind, name, "one of " + ", ".join(self.choices), hint=hint)


class ConvergenceError(RigError, RuntimeError):
    """An iteration (contact solve, settling, reduction) did not converge; says what and how far."""


class LogFormatError(RigError, ValueError):
    """A measurement log is damaged or not one of ours: names the file and what is wrong."""
