"""The fit as one call: load the data, fit the nested effect sets, rank them (``rig.fit.fit_data``)."""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.stats import chi2 as chi2_dist

from rig import validate
from rig.errors import ParameterError
from rig.fit import parameters as P
from rig.fit.choice import RankedModel, decide, rank_models
from rig.fit.data import Observations, load_digitised, load_run
from rig.fit.inputs import check_grid, data_kind
from rig.fit.engine import MISFIT_ALPHA as GOF_ALPHA  # chi2 p below which the data scatter too much
from rig.fit.engine import FitResult


MISFIT_WARNING = ("the model does not describe these data: look for an effect not in --params, or a wrong scene")


@dataclass(frozen=True)
class Goodness:
    """chi2 of the full set against the scatter the stated u expects (chi2 with dof degrees of freedom).

    p: P(chi2_dof >= chi2); misfit: p < GOF_ALPHA; birge: sqrt(chi2/dof), the factor by which the
    u would have to grow for chi2/dof = 1 (>= 1 only when the data scatter more than stated).
    """

    chi2: float
    dof: int
    p: float
    misfit: bool

    @property
    def birge(self) -> float:
        return float(np.sqrt(self.chi2 / self.dof)) if self.dof > 0 else float("nan")


def goodness_of(result: FitResult) -> Goodness:
    p = float(chi2_dist.sf(result.chi2, result.dof)) if result.dof > 0 else float("nan")
    return Goodness(result.chi2, result.dof, p, bool(p < GOF_ALPHA))


@dataclass(frozen=True)
class FitReport:
    """Everything a fit produced: the data, the full set's fit (``full``), all ranked sets, cost [s];
    extra_scatter: what the user asked for (None: none, "fit": estimated, or a value [units of y])."""

    obs: Observations
    free: tuple[P.FitParameter, ...]
    fixed: dict[str, float]
    models: list[RankedModel]
    seconds: float
    extra_scatter: object = None

    @property
    def goodness(self) -> Goodness:
        """The full set's chi2 against the stated u (with the extra scatter when the user named one)."""
        return goodness_of(self.full)

    @property
    def warnings(self) -> list[str]:
        """Warnings for the reader, the most important first (the misfit line leads)."""
        out = []
        g = self.goodness
        if g.misfit:
            out.append(f"{MISFIT_WARNING} (chi2 = {g.chi2:.4g} for {g.dof} degrees of freedom, p = {g.p:.2g}; "
                       f"the data scatter {g.birge:.2g}x more than {self._scatter_words()} explain)")
            if self.full.birge > 1:
                out.append(f"intervals and u widened by the Birge ratio R = sqrt(chi2/dof) = {self.full.birge:.3g} "
                           "(every point's u scaled by R; the u of a digitised curve is a guess)")
        out.extend(self.full.warnings)
        return out

    def _scatter_words(self) -> str:
        if self.obs.stand is not None:
            words = "the instruments' stated noise, resolution and calibration"
        else:
            words = "the stated u of the digitised points"
        return words + (" and the extra scatter" if self.full.scatter > 0 else "")

    @property
    def full(self) -> FitResult:
        """The fit with every requested parameter free (the one fit.csv reports)."""
        return self.models[-1].result

    @property
    def best(self) -> RankedModel:
        """The effect set ranked first by AIC."""
        return min(self.models, key=lambda m: m.rank)

    @property
    def decision(self) -> RankedModel:
        """The effect set the data call for: from the smallest set, each next set is taken while its
        likelihood-ratio test against the previous one gives p < DECISION_ALPHA (rig.fit.choice)."""
        return decide(self.models)


def load_data(data: str | Path, *, sidecar=None, sigma=None, sigma_x=None, scene=None, n: int | None = None,
              effects: Mapping[str, float] | None = None, datasets: Sequence[str] | None = None,
              force_scene: bool = False) -> Observations:
    """Observations from a digitised curve (with sidecar and sigma) or a stand run's log / reduced.csv.

    The file's kind is told from its name and first bytes before anything is loaded
    (rig.fit.inputs.data_kind); each kind has its own loader.
    """
    path = Path(data)
    n = check_grid(n)
    if data_kind(path, sidecar) == "digitised":
        if scene is not None:
            raise ParameterError("scene", str(scene), "none for a digitised curve (its sidecar states the conditions)")
        return load_digitised(path, sidecar, sigma, n=16 if n is None else n, effects=effects,
                              datasets=None if datasets is None else list(datasets), sigma_x=sigma_x)
    if sigma is not None:
        raise ParameterError("sigma", sigma, "none for a stand run (u comes from the instruments in the log)")
    if sigma_x is not None:
        raise ParameterError("sigma-x", sigma_x, "none for a stand run (u(l/a) comes from the reduction)")
    if scene is not None and not hasattr(scene, "build_stand"):
        from rig.scenes.load import load_scene

        scene = load_scene(scene)
    obs = load_run(path, scene, n=n, force_scene=force_scene)
    if effects:
        obs = dataclasses.replace(obs, fixed_effects={**obs.fixed_effects, **effects})
    return obs


def fit_data(data: str | Path, params: Sequence[str], *, sidecar=None, sigma=None, sigma_x=None, scene=None,
             effects: Mapping[str, float] | None = None, start: Mapping[str, float] | None = None,
             n: int | None = None, profile: bool = True, polish: str = "auto",
             datasets: Sequence[str] | None = None, force_scene: bool = False,
             extra_scatter: str | float | None = None) -> FitReport:
    """Fit ``params`` to measured or digitised data; the other parameters stay fixed.

    Parameters
    ----------
    data : str or pathlib.Path
        log.h5, reduced.csv (log.h5 beside it) or a digitised curve (docs/fit.md).
    params : sequence of str
        The parameters to estimate, e.g. ``["mu", "psi"]`` (mu [1], Psi [1], ...).
    sidecar : str or pathlib.Path, optional
        The digitised curve's TOML sidecar.
    sigma : float or str, optional
        u of digitised y [y units]: a number or ``"name=value,..."``.
    sigma_x : float or str, optional
        u of digitised x [x units], same forms (effective variance); None: x exact.
    scene : str or pathlib.Path, optional
        The scene whose fixed parameters apply (default: the log's).
    effects : Mapping[str, float], optional
        Fixed contact effects.
    start : Mapping[str, float], optional
        Start values (default: each parameter's own).
    n : int, optional
        Contact grid, cells across 2a (default: the scene's, 16 for a digitised curve).
    profile : bool, optional
        Profile-likelihood 95 % intervals (default True).
    polish : str, optional
        ``"auto"`` (default: a direct-solve refit when the table's error at the optimum matters),
        ``"check"``, ``"never"`` or ``"always"`` (rig.fit.engine.fit).
    datasets : sequence of str, optional
        The digitised datasets to fit (default all).
    force_scene : bool, optional
        Fit with ``scene`` although it differs from the log's stored one (default False: a named error).
    extra_scatter : float or str, optional
        An independent scatter s added to every point's u (u^2 + s^2) [units of y]: None (the
        default: the stated u alone), a value, or ``"fit"`` (s such that chi2/dof = 1 for the full
        set, held for the smaller sets).

    Returns
    -------
    FitReport
        The full set's fit (``full``: estimates with 95 % intervals), all ranked effect sets by AIC, cost [s].
    """
    t0 = time.perf_counter()
    n = check_grid(n)  # every argument is checked before DATA is read
    scatter = _check_extra_scatter(extra_scatter)
    free = P.parse_names(params)
    fixed_effects = P.check_values(effects or {}, "effects.")
    clash = [p.name for p in free if p.name in fixed_effects]
    if clash:
        raise ParameterError(f"effects.{clash[0]}", fixed_effects[clash[0]], "not also a free parameter")
    starts = {p.name: p.start for p in free}
    starts.update(P.check_values(start or {}, "start value of "))
    data_kind(data, sidecar)
    obs = load_data(data, sidecar=sidecar, sigma=sigma, sigma_x=sigma_x, scene=scene, n=n, effects=fixed_effects,
                    datasets=datasets, force_scene=force_scene)
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
    if obs.stand is not None and polish == "auto":
        polish = "check"  # the stand's table is the law the twin simulates with: direct solves are not closer
    widen = obs.stand is None and extra_scatter is None  # a digitised curve's u is a guess: Birge-widen a misfit
    models = rank_models(obs, free, fixed, starts, profile=profile, polish=polish, scatter=scatter, widen_misfit=widen)
    return FitReport(obs, free, fixed, models, time.perf_counter() - t0, extra_scatter)


def _check_extra_scatter(given: str | float | None) -> float | None:
    """None -> 0.0 (no extra scatter), "fit" -> None (estimated), a number -> that value (>= 0)."""
    if given is None:
        return 0.0
    if isinstance(given, str) and given.strip().lower() == "fit":
        return None
    if isinstance(given, str):
        try:
            given = float(given)
        except ValueError:
            raise ParameterError("extra-scatter", given, "'fit' or a number >= 0 [units of the fitted quantity]") \
                from None
    return validate.number("extra-scatter", given, 0.0)
