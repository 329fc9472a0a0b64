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

import pytest

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


GROUPS = {
    "lab-server": ("tests/lab/test_lab_api.py", "tests/lab/test_lab_browser.py", "tests/lab/test_lab_browser_class.py",
                   "tests/lab/test_lab_browser_sheet.py", "tests/lab/test_lab_browser_stand_b.py",
                   "tests/lab/test_lab_restart.py"),
    "stand-a-fit": ("tests/fit/test_bad_inputs.py", "tests/fit/test_coverage.py", "tests/fit/test_goodness.py",
                    "tests/fit/test_recovery.py"),
}
"""Modules that share a costly session fixture (tests/lab/conftest.py's warmed-up lab server and headless
Chromium; tests/fit/conftest.py's small stand-A run) or the tables it leaves in the session's cache folder
(the R_x = 20 mm Psi-node tables of the fits): under pytest-xdist each group runs on one worker, so that it is
built once, not by both workers at the same time. Every other module is its own group (as --dist loadfile)."""

LONGEST_GROUPS = ("lab-server", "stand-a-fit", "tests/runner/test_dask.py", "tests/teaching/test_tutorial_scripts.py",
                  "tests/campaigns/test_disc_roller_campaigns.py", "tests/runner/test_outputs_whole.py",
                  "tests/runner/test_damaged_points.py", "tests/fit/test_stand_b_coverage.py",
                  "tests/runner/test_one_writer_per_kind.py", "tests/runner/test_resume_and_pool.py",
                  "tests/runner/test_kill_lock_resume.py", "tests/cli/test_named_failures.py",
                  "tests/fit/test_stand_b.py", "tests/lab/test_lab_cli.py")
"""The groups (a module outside GROUPS is a group of its own) that take longest, longest first (the two
GROUPS about 55-60 s each, then 20 s down to 7 s; measured with --durations=0, load about 2): they run
first, so that the short modules fill in after them instead of one worker finishing a long module alone
at the end while the other waits."""

_GROUP_OF_MODULE = {module: group for group, modules in GROUPS.items() for module in modules}


def group_of(nodeid: str) -> str:
    """The group of a test (by its node id): its module's entry in GROUPS, else its module."""
    module = nodeid.split("::")[0]
    return _GROUP_OF_MODULE.get(module, module)


def pytest_collection_modifyitems(config, items):
    """The LONGEST_GROUPS first (the order within a group is kept); pyproject's --no-loadscope-reorder makes
    pytest-xdist hand the groups out in this order."""
    first = {group: k for k, group in enumerate(LONGEST_GROUPS)}
    items.sort(key=lambda item: first.get(group_of(item.nodeid), len(first)))


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config, log):
    """--dist loadfile with the GROUPS: a group's modules go to one worker. (--dist loadgroup's marks do not
    reach the node ids under pytest 9, so the groups are made here, from the node ids the workers send.)"""
    from xdist.scheduler import LoadScopeScheduling

    class GroupScheduling(LoadScopeScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return group_of(nodeid)

    return GroupScheduling(config, log)
