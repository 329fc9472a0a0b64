"""A small deterministic Stand for the scene, runner and CLI tests: the contract with trivial physics.

Physics (chosen for checkable numbers): the wheel carries the force F = mu * load [N]; the
dynamometer channel samples F plus the optional effects "force_noise" (white, std_N [N]) and
"force_drift" (linear, rate_N_per_s [N/s] over the gate). Settling is a first-order lag of time
constant settle_tau_s [s] from the previous point's load (0 N at rest) to 1 N: settle time
tau * ln(1 + |delta load| / 1 N) [s]; past the timeout it raises SettleTimeoutError. The counter
N1 counts marks_1 marks per revolution at speed_rad_s over the gate. Random streams come from
SeedSequence([seed, index]). The reduction is mu_T = mu_v = F_mean / load with u = F_std /
(sqrt(n) load), the truth has mu, F and l_over_a = c_over_a = 0.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from types import MappingProxyType

import numpy as np
import pandas as pd

from rig import validate
from rig.errors import ParameterError
from rig.logbook import (Channel, Counter, CounterReadings, LogSchema, PointRecord, Quantity, check_log,
                         read_counters, read_readings, read_settings)
from rig.stands.base import (EffectSpec, GateData, ParameterSpec, PointOutcome, PointSimulation, SettingSpec,
                             SettleReport, SettleTimeoutError, Stand)

SETTLED_WITHIN_N = 1.0  # settle criterion |F - F_ss| / mu < 1 N of load


class ForceNoise:
    """White noise of std_N [N] on the dynamometer channel."""

    def __init__(self, std_N: float) -> None:
        self.std_N = validate.number("std_N", std_N, 0.0)

    def apply(self, samples: np.ndarray, t_s: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return samples + rng.normal(0.0, self.std_N, samples.size)


class ForceDrift:
    """Zero drift of rate_N_per_s [N/s] from the gate opening."""

    def __init__(self, rate_N_per_s: float) -> None:
        self.rate = validate.number("rate_N_per_s", rate_N_per_s)

    def apply(self, samples: np.ndarray, t_s: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        return samples + self.rate * (t_s - t_s[0])


COMPONENTS = {"force_noise": ForceNoise, "force_drift": ForceDrift}


class FakePoint(PointSimulation):
    def __init__(self, stand: FakeStand, index: int, settings: Mapping[str, float],
                 previous: Mapping[str, float] | None, seed: int) -> None:
        self.stand, self.index, self.settings, self.seed = stand, index, dict(settings), seed
        self.start = "rest" if previous is None else "previous point"
        self.step_N = abs(settings["load_N"] - (0.0 if previous is None else previous["load_N"]))

    def settle(self, timeout_s: float) -> SettleReport:
        tau = self.stand.parameters["settle_tau_s"]
        criterion = f"|load - load_set| < {SETTLED_WITHIN_N} N"
        duration = tau * math.log1p(self.step_N / SETTLED_WITHIN_N)
        if duration > timeout_s:
            raise SettleTimeoutError(self.settings, timeout_s, self.step_N * math.exp(-timeout_s / tau), criterion)
        return SettleReport(duration, criterion, SETTLED_WITHIN_N, self.start)

    def gate(self, gate_time_s: float) -> GateData:
        rate = self.stand.parameters["sample_rate_Hz"]
        t = np.arange(int(round(gate_time_s * rate))) / rate
        force = np.full(t.size, self.stand.parameters["mu"] * self.settings["load_N"])
        rng = np.random.default_rng(np.random.SeedSequence([self.seed, self.index]))
        for component in self.stand.components.values():
            force = component.apply(force, t, rng)
        return GateData(0.0, gate_time_s, t, {"force": force, "turns": self.settings["speed_rad_s"] * t / (2 * np.pi)},
                        {"force": "N", "turns": "1"})

    def read(self, gate: GateData) -> PointOutcome:
        p = self.stand.parameters
        force = np.asarray(gate.signals["force"])
        turns = float(np.asarray(gate.signals["turns"])[-1])
        record = PointRecord(
            index=self.index,
            settings={"load": Quantity(self.settings["load_N"], "N"), "speed": Quantity(self.settings["speed_rad_s"],
                                                                                       "rad/s")},
            channels={"force": Channel(force, "N", p["sample_rate_Hz"], gate.gate_open_s)},
            counters=CounterReadings(gate.gate_time_s, {"N1": Counter(int(turns * p["marks_1"]), int(p["marks_1"]))}),
            readings={"F_mean": Quantity(float(force.mean()), "N"), "F_std": Quantity(float(force.std()), "N")},
            calibration=self.stand.calibration_records(),
        )
        truth = {"mu": Quantity(p["mu"], "1"), "F": Quantity(p["mu"] * self.settings["load_N"], "N"),
                 "l_over_a": Quantity(0.0, "1"), "c_over_a": Quantity(0.0, "1")}
        return PointOutcome(record, truth, SettleReport(0.0, "", 0.0, self.start))


MAX_LOAD_N = 900.0
"""Loads above this raise a ParameterError when the point starts (its SettingSpec allows 1000 N)."""


class FakeStand(Stand):
    """The contract with trivial physics (module docstring); counts its calibrations."""

    name = "fake"
    PARAMETERS = MappingProxyType({
        "mu": ParameterSpec(0.4, "1", 0.01, 2.0, "[assumed] test value"),
        "settle_tau_s": ParameterSpec(0.2, "s", 1e-3, 1e4, "[assumed] test value"),
        "sample_rate_Hz": ParameterSpec(100.0, "Hz", 1.0, 1e4, "[assumed] test value"),
        "marks_1": ParameterSpec(60, "1", 1, 1000, "[assumed] test value"),
    })
    EFFECTS = MappingProxyType({
        "force_noise": EffectSpec("white noise on the dynamometer", {"std_N": (0.5, "N")}),
        "force_drift": EffectSpec("linear zero drift of the dynamometer", {"rate_N_per_s": (0.01, "N/s")}),
    })
    SETTINGS = MappingProxyType({
        "load_N": SettingSpec("N", 1.0, 1000.0, "normal load"),
        "speed_rad_s": SettingSpec("rad/s", 0.1, 100.0, "wheel speed"),
    })
    LOG_SCHEMA = LogSchema(channels={"force": "N"}, settings={"load": "N", "speed": "rad/s"},
                           readings={"F_mean": "N", "F_std": "N"}, counters=("N1",))

    @classmethod
    def resolve_effects(cls, effects):
        """Fills nothing in (the scene loader already did) and checks only that values are >= 0."""
        validate.known_keys("effect", effects, cls.EFFECTS)
        for name, values in effects.items():
            for key, value in values.items():
                validate.number(f"effects.{name}.{key}", value, 0.0)
        return {name: dict(values) for name, values in effects.items()}

    def __init__(self, parameters, effects, contact, drive) -> None:
        validate.known_keys("parameter", parameters, self.PARAMETERS)
        effects = self.resolve_effects(effects)
        self.parameters = {name: spec.default for name, spec in self.PARAMETERS.items()} | dict(parameters)
        self.contact, self.drive = contact, drive
        self.components = {name: COMPONENTS[name](**values) for name, values in effects.items()}
        self.calibrations = 0
        self._calibration = None

    def calibrate(self, seed: int):
        self.calibrations += 1
        rng = np.random.default_rng(np.random.SeedSequence([seed, 999_999]))
        self._calibration = {"dynamometer": {"gain": Quantity(1.0 + 1e-3 * rng.standard_normal(), "N/V")}}
        return self._calibration

    def calibration_records(self):
        if self._calibration is None:
            raise RuntimeError("FakeStand: calibrate() was not called before reading a point")
        return self._calibration

    def start_point(self, index, settings, previous, seed) -> FakePoint:
        if settings["load_N"] > MAX_LOAD_N:  # a named error inside a point (like stand A's stall)
            raise ParameterError("load_N", settings["load_N"], f"at most {MAX_LOAD_N:g} N (the fake stand's stall)")
        return FakePoint(self, index, settings, previous, seed)

    def reduce_log(self, log_path, contact_law) -> pd.DataFrame:
        check_log(log_path, self.LOG_SCHEMA)
        readings, settings = read_readings(log_path), read_settings(log_path)
        n = self.parameters["sample_rate_Hz"] * read_counters(log_path)["gate_time_s"].to_numpy()  # samples
        load = settings["load_N"].to_numpy()
        mu = readings["F_mean_N"].to_numpy() / load
        u = readings["F_std_N"].to_numpy() / np.sqrt(n) / load
        table = pd.DataFrame({"l_over_a": 0.0, "u_l_over_a": 0.01, "c_over_a": 0.0, "u_c_over_a": 0.01,
                              "mu_v": mu, "u_mu_v": u, "mu_T": mu, "u_mu_T": u}, index=readings.index)
        table.index.name = "point"
        table.attrs["units"] = {column: "1" for column in table.columns}
        return table


SCENE = """\
# Test scene of the fake stand (tests/runner/fake_stand.py): a load sweep with noise.
[scene]
description = "fake stand load sweep"
stand = "fake"
seed = 7
drive = "quasi_static"

[parameters]
mu = 0.3

[contact]
model = "rigid"
poisson = 0.3

[effects.force_noise]
std_N = 0.2

[procedure]
settle_timeout_s = 3.0
gate_time_s = 1.0

[procedure.fixed]
speed_rad_s = 10.0

[procedure.sweep]
load_N = [5.0, 10.0, 20.0, 25.0]

[outputs]
figures = true
"""
NO_FIGURES = {"figures = true": "figures = false"}
"""Replacement that skips the figure (matplotlib takes most of a fake run's time)."""


def scene_text(replace: dict[str, str] | None = None) -> str:
    """SCENE with each ``old -> new`` text replacement applied (each ``old`` must occur)."""
    text = SCENE
    for old, new in (replace or {}).items():
        assert old in text, old
        text = text.replace(old, new)
    return text


def register(monkeypatch) -> None:
    """Make ``stand = "fake"`` resolve to FakeStand for the duration of a test."""
    import rig.stands

    monkeypatch.setitem(rig.stands.STANDS, "fake", "tests.runner.fake_stand:FakeStand")
