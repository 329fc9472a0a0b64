"""Shared fixtures of the rig compare tests."""

from __future__ import annotations

import pytest

import rig.cli


@pytest.fixture
def rig_main(monkeypatch):
    """rig.cli.main with only the compare subcommand registered (isolates these tests from the
    import state of the other subcommand modules, which other parts of the project own)."""
    monkeypatch.setattr(rig.cli, "SUBCOMMANDS", ("compare",))
    return rig.cli.main
