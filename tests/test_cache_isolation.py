"""The suite never touches the user's cache folder: RIG_CACHE_DIR points into a session temp folder,
in this process and in subprocesses (tests/conftest.py)."""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

from rig.contact.surrogate_cache import ENV_VARIABLE, cache_dir
from tests.conftest import SESSION_CACHE

USER_CACHE = Path.home() / ".cache" / "friction-rig"


def test_the_cache_folder_is_a_temp_folder():
    """The session's folder, or a test's own (fixtures may point the variable at theirs): never the user's."""
    folder = cache_dir()
    assert folder != USER_CACHE and USER_CACHE not in folder.parents
    assert Path(tempfile.gettempdir()).resolve() in folder.resolve().parents
    assert Path(SESSION_CACHE).name.startswith("friction-rig-test-cache-") and Path(SESSION_CACHE).is_dir()


def test_a_subprocess_uses_the_same_folder():
    probe = "from rig.contact.surrogate_cache import cache_dir; print(cache_dir())"
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=120)
    assert Path(done.stdout.strip()) == cache_dir() == Path(os.environ[ENV_VARIABLE])
