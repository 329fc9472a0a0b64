"""The instrument package's error type.

``sensors`` does not import ``rig``; both share the error types of :mod:`paramcheck`.
:class:`InstrumentParameterError` is the :class:`~paramcheck.errors.ParameterError` an instrument
raises: a :class:`ValueError` whose message names the parameter, the value given and the valid
range.
"""

from __future__ import annotations

from paramcheck.errors import ParameterError


class InstrumentParameterError(ParameterError):
    """An instrument parameter or input is outside its valid range.

    Attributes ``name`` (the parameter), ``value`` (what was given) and ``valid`` (the valid
    range, in words) are kept for callers that want to re-raise with more context.
    """
