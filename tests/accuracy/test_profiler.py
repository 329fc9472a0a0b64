"""Where the time goes: module-name attribution and the CPU-weighted stack sampler."""

from __future__ import annotations

import time

import pytest

from rig.accuracy.profiler import Part, Profile, StackSampler, categorize, classify_stack
from rig.errors import ParameterError


@pytest.mark.parametrize(("module", "part"), [
    ("rig.contact.solve", Part.CONTACT),
    ("rig.contact.models.kinematic", Part.CONTACT),
    ("rig.stands.contact_law", Part.CONTACT),
    ("rig.stands.yoke.contact_forces", Part.CONTACT),
    ("rig.contact.surrogate_cache", Part.TABLE),
    ("sensors.counter", Part.INSTRUMENTS),
    ("rig.stands.yoke.instruments", Part.INSTRUMENTS),
    ("h5py._hl.dataset", Part.IO),
    ("rig.logbook.writer", Part.IO),
    ("rig.reduction.stand_a", Part.REDUCTION),
    ("rig.stands.yoke.reduction", Part.REDUCTION),
    ("scipy.integrate._ivp.radau", Part.DRIVE),
    ("rig.stands.yoke.drive_train", Part.DRIVE),
    ("rig.stands.disc_roller.integration", Part.DRIVE),
    ("numpy.linalg", Part.OTHER),
    ("rig.contactless", Part.OTHER),
    ("rig.runner.operator", Part.OTHER),
])
def test_module_names_map_to_parts(module, part):
    assert categorize(module) is part


def test_the_highest_priority_part_on_the_stack_wins():
    # innermost first, as a stack is walked: numpy inside a contact law called from the ODE's rhs
    assert classify_stack(["numpy.core", "rig.stands.contact_law", "rig.stands.yoke.drive_train",
                           "scipy.integrate._ivp.radau", "rig.runner.operator"]) is Part.CONTACT
    # solves made while building a table count as the table build
    assert classify_stack(["rig.contact.solve", "rig.contact.surrogate", "rig.contact.surrogate_cache",
                           "rig.stands.yoke.laws"]) is Part.TABLE
    # the reduction reading the log is I/O; its own arithmetic is reduction
    assert classify_stack(["h5py._hl.group", "rig.logbook.reader", "rig.stands.yoke.reduction"]) is Part.IO
    assert classify_stack(["numpy", "rig.reduction.iteration", "rig.runner.reduction"]) is Part.REDUCTION
    assert classify_stack(["numpy", "builtins"]) is Part.OTHER


def test_contact_solves_are_filed_under_contact():
    from rig.contact.solve import solve

    with StackSampler() as sampler:
        end = time.process_time() + 0.3
        while time.process_time() < end:
            solve("rigid", shape="line", b_over_a=1.0, poisson=0.3, n=12, alpha=1.0, c_over_a=0.0, l_over_a=0.3)
    profile = sampler.profile()
    assert profile.samples > 10
    assert profile.fractions()[Part.CONTACT] > 0.9


def test_waiting_weighs_nothing_with_a_thread_cpu_clock():
    with StackSampler() as sampler:
        end = time.perf_counter() + 0.2
        while time.perf_counter() < end:
            time.sleep(0.002)
    profile = sampler.profile()
    if not profile.cpu_weighted:
        pytest.skip("no per-thread CPU clock on this platform")
    assert profile.samples > 10
    assert sum(profile.weights.values()) < 0.05  # [s] of CPU in 0.2 s of sleeping


def test_empty_profile_and_bad_interval():
    assert set(Profile({}, 0, True).fractions().values()) == {0.0}
    shares = Profile({Part.IO: 3.0, Part.DRIVE: 1.0}, 4, True).fractions()
    assert shares[Part.IO] == 0.75 and shares[Part.DRIVE] == 0.25 and shares[Part.CONTACT] == 0.0
    with pytest.raises(ParameterError, match="interval_s"):
        StackSampler(0.0)
