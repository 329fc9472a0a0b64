"""Shared builders for the stand-B tests (fast closed-form law unless a test says otherwise)."""

from __future__ import annotations

import pytest

from rig.stands.base import ContactSpec, DriveMode
from rig.stands.disc_roller.stand import DiscRollerStand
from tests.stands.disc_roller.laws import smooth_factory

SPEC = ContactSpec("rigid", 16, 0.5)


def make_stand(effects=None, drive=DriveMode.DYNAMIC, parameters=None, factory=smooth_factory) -> DiscRollerStand:
    """A stand with the smooth stand-in law (tests/stands/disc_roller/laws.py)."""
    return DiscRollerStand(parameters or {}, effects or {}, SPEC, drive, law_factory=factory)


def settings(**change) -> dict[str, float]:
    """A text operating point: 36 N (b/a = 1), l = 10 mm, c = 0, 24 rpm, forward."""
    base = dict(normal_force_N=36.0, l_m=0.010, sigma_rad=0.0, speed_step=1, direction=1)
    base.update(change)
    return base


@pytest.fixture(autouse=True)
def _private_cache(tmp_path, monkeypatch):
    """Surrogate tables built by a test go to a temporary folder, never the user's cache."""
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path / "cache"))
