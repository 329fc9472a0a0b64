"""The lab's sessions on disk, so that a restarted server gives a student back their session.

One JSON file per session, ``<state folder>/<session id>.json``: the session's
:meth:`rig.lab.session.LabSession.state` (its scene's inputs, the recorded points' settings and
gate times, the checked answers, the exercise and whether it was submitted). Written after
every change, whole: a temporary file in the same folder, flushed and synced, then renamed over
the old one (``os.replace`` is atomic), so a crash leaves the old state or the new one, never
half of either. The folder is ``rig lab --state DIR`` (default ``<output folder>/state``).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import threading
from pathlib import Path

from rig.errors import ParameterError

SESSION_ID = re.compile(r"[0-9a-f]{16}")
"""A session id: 16 hex digits (secrets.token_hex(8)); nothing else names a file."""


class SessionStore:
    """Session states as JSON files in ``folder`` (created on first write)."""

    def __init__(self, folder: Path) -> None:
        self.folder = Path(folder)

    def path(self, ident: str) -> Path | None:
        """The file of session ``ident``, or None for a string that is not a session id."""
        return self.folder / f"{ident}.json" if SESSION_ID.fullmatch(ident) else None

    def write(self, state: dict) -> None:
        """Write ``state`` (with its ``id``) whole: temporary file, fsync, rename."""
        target = self.path(state["id"])
        text = json.dumps(state, allow_nan=False)  # a value JSON cannot hold fails here, before any file
        tmp = target.with_name(f".{target.name}.{os.getpid()}-{threading.get_ident()}.tmp")
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            with open(tmp, "w", encoding="utf-8") as handle:
                handle.write(text)
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(tmp, target)
        except OSError as error:
            raise ParameterError("--state", str(self.folder), f"a folder the lab can write ({error})") from None
        finally:
            with contextlib.suppress(OSError):  # gone after the rename; removed after a failure
                tmp.unlink(missing_ok=True)

    def read(self, ident: str) -> dict | None:
        """The stored state of ``ident``, or None when there is none."""
        path = self.path(ident)
        if path is None or not path.is_file():
            return None
        try:
            return json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError) as error:
            raise ParameterError("session", ident, f"a readable state file {path} ({error})") from None
