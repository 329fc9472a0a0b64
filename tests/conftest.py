"""Suite-wide set-up: the contact-law cache lives in a temporary folder for the whole session.

``RIG_CACHE_DIR`` (rig.contact.surrogate_cache) is set here at import, before any test module
imports rig, so the suite never reads nor writes the user's ``~/.cache/friction-rig`` - neither
in this process nor in the ``rig`` subprocesses the CLI tests start (they inherit the
environment). Tests that need a cache of their own still set the variable with monkeypatch.
"""

from __future__ import annotations

import os
import shutil
import tempfile

from rig.contact.surrogate_cache import ENV_VARIABLE

OWNER = "RIG_TEST_CACHE_OWNER"
"""Set beside the cache variable by the process that made the folder: pytest-xdist's workers inherit
both from the controller and share its folder (a table built by one worker is loaded by the other;
the cache's files are written atomically), and only the controller removes it."""

if os.environ.get(OWNER) and os.environ.get(ENV_VARIABLE):
    SESSION_CACHE = os.environ[ENV_VARIABLE]
    _OWNED = False
else:
    SESSION_CACHE = tempfile.mkdtemp(prefix="friction-rig-test-cache-")
    """The session's cache folder (removed when the session ends)."""
    os.environ[ENV_VARIABLE] = SESSION_CACHE
    os.environ[OWNER] = str(os.getpid())
    _OWNED = True


def pytest_sessionfinish(session, exitstatus):
    if _OWNED:
        shutil.rmtree(SESSION_CACHE, ignore_errors=True)
