"""Recovery of known mu and Psi by ``rig fit``: simulate a stand-A sweep with them, reduce it, fit it.

One repeat (:func:`one_repeat`): the built-in fig10 procedure (stand A, dynamic drive, instrument
effects on) with mu, Psi, the seed, the points per series, the gate and the grid changed
(:func:`recovery_scene`), run and reduced as ``rig run`` does, then ``fit_data(reduced.csv,
["mu", "psi"])``: whether the truth lies in the 95 % profile intervals and which effect set ranks
first by AIC. experiments/fit_recovery.py repeats it over seeds (docs/fit.md quotes the rates).
"""

from __future__ import annotations

import time
from pathlib import Path

from rig.api import Scene, load_scene, run
from rig.fit.run import fit_data

BASE_SCENE = "fig10"
"""The built-in scene whose procedure a repeat simulates."""


def recovery_scene(*, mu: float, psi: float, seed: int, points: int, gate_s: float, n: int = 16,
                   table_points: tuple[int, int, int] = (21, 3, 5), radius_x: float | None = None) -> Scene:
    """The fig10 scene with the truth and the cost of a recovery repeat changed.

    Parameters
    ----------
    mu : float
        True friction coefficient [1].
    psi : float
        True plastic-slip factor Psi [1] ([Koziarski] eq. (25)); 1: the effect is off.
    seed : int
        The run's seed.
    points : int
        Operating points per series (fig10: 24).
    gate_s : float
        Gate time [s] (fig10: 20).
    n : int, optional
        Contact grid, cells across 2a (default 16).
    table_points : tuple of int, optional
        Nodes of the contact-law table along l/a, c/a, log alpha' (default (21, 3, 5)).
    radius_x : float, optional
        R_x of the line contact [m] (None: fig10's), which alone sets alpha' ([Koziarski] eq. (21)).

    Returns
    -------
    Scene
        The changed scene, named ``recovery_<seed>``.
    """
    document = load_scene(BASE_SCENE).to_dict()
    document["scene"]["seed"] = seed
    document["parameters"]["mu"] = mu
    if radius_x is not None:
        document["parameters"]["radius_x_m"] = radius_x
    document["contact"].update(n=n, table_points=list(table_points))
    if psi != 1.0:
        document["contact"]["effects"] = {"psi": psi}
    document["procedure"]["gate_time_s"] = gate_s
    for series in document["procedure"]["series"]:
        for sweep in series["sweep"].values():
            sweep["num"] = points
    return Scene.from_dict(document, name=f"recovery_{seed}")


def one_repeat(seed: int, *, mu: float, psi: float, points: int, gate_s: float, folder: Path, n: int = 16,
               table_points: tuple[int, int, int] = (21, 3, 5), radius_x: float | None = None) -> dict:
    """Simulate, reduce and fit once.

    A run already in ``folder/run_<seed>`` (kept from an earlier call) is reduced again with the
    current code instead of simulated again (the simulation is seeded: it would give the same log).

    Parameters
    ----------
    seed : int
        The run's seed.
    mu, psi, points, gate_s, n, table_points, radius_x
        As for :func:`recovery_scene`.
    folder : pathlib.Path
        Where the run folder ``run_<seed>`` goes.

    Returns
    -------
    dict
        ``mu``, ``psi`` and their 95 % bounds (``mu_lo``, ``mu_hi``, ``psi_lo``, ``psi_hi``) [1];
        ``mu_covered``, ``psi_covered`` (truth inside); ``psi_ranks_first`` (mu + psi above mu alone
        by AIC); ``psi_interval_has_1``; ``chi2_dof``; ``fit_s`` (fit time [s]); ``polished``.
    """
    out = Path(folder) / f"run_{seed}"
    if (out / "reduced.csv").is_file():
        from rig.runner import reduce_log_file

        reduce_log_file(out / "log.h5")
    else:
        scene = recovery_scene(mu=mu, psi=psi, seed=seed, points=points, gate_s=gate_s, n=n,
                               table_points=table_points, radius_x=radius_x)
        run(scene, out)
    t0 = time.perf_counter()
    report = fit_data(out / "reduced.csv", ["mu", "psi"])
    seconds = time.perf_counter() - t0
    est = {e.name: e for e in report.full.estimates}
    ranks = {m.label: m.rank for m in report.models}
    return dict(
        seed=seed, mu=est["mu"].value, mu_lo=est["mu"].lo95, mu_hi=est["mu"].hi95,
        psi=est["psi"].value, psi_lo=est["psi"].lo95, psi_hi=est["psi"].hi95,
        mu_covered=est["mu"].lo95 <= mu <= est["mu"].hi95, psi_covered=est["psi"].lo95 <= psi <= est["psi"].hi95,
        psi_ranks_first=ranks["mu + psi"] < ranks["mu"], psi_interval_has_1=est["psi"].lo95 <= 1.0,
        chi2_dof=report.full.chi2 / report.full.dof, fit_s=seconds, polished=report.full.polished,
    )
