"""Argument checks shared by the whole package: each raises a named :class:`ParameterError`.

The implementation is :mod:`paramcheck.validate` (shared with ``sensors``); the name checks
(``choice``, ``known_keys``) suggest the closest valid name.
"""

from __future__ import annotations

from paramcheck.validate import choice, integer, known_keys, number

__all__ = ["choice", "integer", "known_keys", "number"]
