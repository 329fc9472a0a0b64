"""The fit as one call: load the data, fit the nested effect sets, rank them (``rig.fit.fit_data``)."""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

from rig.errors import ParameterError
from rig.fit import parameters as P
from rig.fit.choice import RankedModel, rank_models
from rig.fit.data import Observations, is_digitised, load_digitised, load_stand_a_run
from rig.fit.engine import FitResult
from rig.fit.stand_b import is_stand_b_run, load_stand_b_run


@dataclass(frozen=True)
class FitReport:
    """Everything a fit produced: the data, the full set's fit (``full``), all ranked sets, cost [s]."""

    obs: Observations
    free: tuple[P.FitParameter, ...]
    fixed: dict[str, float]
    models: list[RankedModel]
    seconds: float

    @property
    def full(self) -> FitResult:
        """The fit with every requested parameter free (the one fit.csv reports)."""
        return self.models[-1].result

    @property
    def best(self) -> RankedModel:
        """The effect set ranked first by AIC."""
        return min(self.models, key=lambda m: m.rank)


def load_data(data: str | Path, *, sidecar=None, sigma=None, scene=None, n: int | None = None,
              effects: Mapping[str, float] | None = None, datasets: Sequence[str] | None = None) -> Observations:
    """Observations from a digitised curve (with sidecar and sigma) or a stand-A or stand-B log / reduced.csv."""
    path = Path(data)
    if not path.is_file():
        raise ParameterError("DATA", str(path), "an existing log.h5, reduced.csv or digitised .csv")
    if is_digitised(path, sidecar):
        if scene is not None:
            raise ParameterError("scene", str(scene), "none for a digitised curve (its sidecar states the conditions)")
        return load_digitised(path, sidecar, sigma, n=16 if n is None else n, effects=effects,
                              datasets=None if datasets is None else list(datasets))
    if sigma is not None:
        raise ParameterError("sigma", sigma, "none for a stand run (u comes from the instruments in the log)")
    if scene is not None and not hasattr(scene, "build_stand"):
        from rig.scenes.load import load_scene

        scene = load_scene(scene)
    if is_stand_b_run(path, scene):  # stand B's readings F_T, F_V, T_Mo (rig.fit.stand_b)
        obs = load_stand_b_run(path, scene, n=n)
    else:
        obs = load_stand_a_run(path, scene, n=n)
    if effects:
        obs = dataclasses.replace(obs, fixed_effects={**obs.fixed_effects, **effects})
    return obs


def fit_data(data: str | Path, params: Sequence[str], *, sidecar=None, sigma=None, scene=None,
             effects: Mapping[str, float] | None = None, start: Mapping[str, float] | None = None,
             n: int | None = None, profile: bool = True, polish: str = "auto",
             datasets: Sequence[str] | None = None) -> FitReport:
    """Fit ``params`` (e.g. ["mu", "psi"]) to DATA; other parameters stay fixed (scene or ``effects``).

    sigma: u of digitised y (number or "name=value,..."); start: start values (default: each
    parameter's own); n: contact grid (default: the scene's, 16 for a digitised curve);
    datasets: the digitised datasets to fit (default all).
    """
    t0 = time.perf_counter()
    free = P.parse_names(params)
    fixed_effects = P.check_values(effects or {}, "effects.")
    clash = [p.name for p in free if p.name in fixed_effects]
    if clash:
        raise ParameterError(f"effects.{clash[0]}", fixed_effects[clash[0]], "not also a free parameter")
    starts = {p.name: p.start for p in free}
    starts.update(P.check_values(start or {}, "start value of "))
    obs = load_data(data, sidecar=sidecar, sigma=sigma, scene=scene, n=n, effects=fixed_effects, datasets=datasets)
    if obs.stand is not None and "pressure_exponent" in {p.name for p in free} | set(fixed_effects):
        raise ParameterError("params", "pressure_exponent", "a parameter of a digitised contact curve: stand A has "
                             "no pressure-dependent mu (its mu(p0) per load is done for stand B only)")
    free_names = {p.name for p in free}
    if free_names & set(obs.fixed_effects):  # a free parameter is not also fixed by the scene
        obs = dataclasses.replace(obs, fixed_effects={
            k: v for k, v in obs.fixed_effects.items() if k not in free_names})
    if obs.size <= len(free):
        raise ParameterError("data points", obs.size, f"> {len(free)} (the number of free parameters)")
    fixed = {}
    if not any(p.name == "mu" for p in free) and obs.mu_dependent:
        fixed["mu"] = obs.stand.params.mu
    scatter = None if obs.common is not None else 0.0  # run data: u states the calibration only
    if obs.stand is not None and polish == "auto":
        polish = "check"  # the stand's table is the law the twin simulates with: direct solves are not closer
    models = rank_models(obs, free, fixed, starts, profile=profile, polish=polish, scatter=scatter)
    return FitReport(obs, free, fixed, models, time.perf_counter() - t0)
