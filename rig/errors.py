"""Exceptions raised by friction-rig.

The shared types live in :mod:`paramcheck.errors` (the home ``rig`` and ``sensors`` both depend
on): bad input raises :class:`ParameterError` (a :class:`ValueError`) naming the parameter, the
value given and the valid range; an unknown name raises :class:`UnknownNameError` with the
closest valid name; :class:`ConvergenceError` says what did not converge. :class:`RigError` is
the base of every error raised on purpose (instrument errors included); :class:`LogFormatError`
is rig's own.
"""

from __future__ import annotations

from paramcheck.errors import ConvergenceError, NamedError, ParameterError, UnknownNameError

RigError = NamedError

__all__ = ["ConvergenceError", "LogFormatError", "MissingExtraError", "ParameterError", "RigError",
           "UnknownNameError"]


class LogFormatError(RigError, ValueError):
    """A measurement log is damaged or not one of ours: names the file and what is wrong."""


class MissingExtraError(RigError, ImportError):
    """A feature needs an optional dependency that is not installed: names the feature and the pip extra."""

    def __init__(self, feature: str, package: str, extra: str) -> None:
        self.feature = feature
        self.package = package
        self.extra = extra
        super().__init__(f'{feature} needs {package}, which is not installed: pip install "friction-rig[{extra}]"')
