"""What a fit is fitted to: points of one quantity each, with uncertainty and contact conditions.

Two sources (docs/fit.md):
* a digitised contact curve (WebPlotDigitizer CSV + TOML sidecar, as ``rig compare`` reads):
  nu_T, nu_v or nu_0 (eqs. 26-28) versus alpha', l/a or c/a, the other conditions from the
  sidecar; the uncertainty u of the digitised y is given by the caller (the format has none);
* a stand-A run (``log.h5`` or its ``reduced.csv`` next to it): the measured F_y/F_N = mu nu_v
  (eq. 28), u from the dynamometer's stated u(F_y), the covariance between points from its one
  calibration and its zero drift since then (when the log records the drift); l/a, c/a, i_k as reduced (eqs. 29-32) and
  alpha' = mu K with K = 10 (b/a)(v/w0)/R_x from the stand's geometry (eq. 21, line contact).
The data is never modified; NaN in a used column is a ParameterError naming the row.
"""

from __future__ import annotations

import dataclasses

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import pandas as pd

from rig import validate
from rig.errors import ParameterError
from rig.fit.common_errors import CommonErrors, read_common_errors

CONTACT_QUANTITIES = ("nu_T", "nu_v", "nu_0")
X_COLUMNS = ("alpha", "l_over_a", "c_over_a")
DEFAULT_N = 16


@dataclass(frozen=True)
class ContactCondition:
    """The contact model fixed for the fit: model, shape, Poisson ratio [1], grid n."""

    model: str
    shape: str
    poisson: float
    n: int


@dataclass(frozen=True, eq=False)
class Observations:
    """Points to fit (arrays of one length N).

    quantity: "nu_T", "nu_v", "nu_0" (contact coefficients) or "F_y_per_F_N" (= mu nu_v);
    y, u: value and standard uncertainty [1]; x: the plotted abscissa (x_label names it);
    l, c: rolling point [units of a]; u_l: the standard uncertainty of the measured regressor
    (``regressor``: l_over_a for a run, the x axis of a digitised curve; 0 when exact);
    alpha: alpha' [1] where fixed by the data, NaN where alpha' = mu alpha_per_mu;
    b_over_a [1]; series: label of each point's curve; stand: the Stand when the data is a run;
    common: errors shared between points (rig.fit.common_errors: the dynamometer's one calibration
    and its zero drift since then), already inside u; None when there is none.
    """

    quantity: np.ndarray
    y: np.ndarray
    u: np.ndarray
    x: np.ndarray
    x_label: str
    l: np.ndarray
    c: np.ndarray
    u_l: np.ndarray
    alpha: np.ndarray
    alpha_per_mu: np.ndarray
    b_over_a: np.ndarray
    series: np.ndarray
    contact: ContactCondition
    fixed_effects: Mapping[str, float]
    source: str
    stand: object | None = None
    geometry: object | None = None
    notes: tuple[str, ...] = field(default_factory=tuple)
    common: CommonErrors | None = None
    regressor: str = "l_over_a"

    @property
    def size(self) -> int:
        return int(self.y.size)

    @property
    def u_independent(self) -> np.ndarray:
        """The part of u not shared with other points [units of y]: u^2 less the common errors'
        variance at the measured y, where the reduction propagated them."""
        if self.common is None:
            return self.u
        return np.sqrt(np.clip(self.u**2 - self.common.variance(self.y), 0.0, None))

    @property
    def mu_dependent(self) -> bool:
        """True when alpha' depends on mu (stand data): the model must be re-evaluated per mu."""
        return bool(np.any(np.isnan(self.alpha)))


def _finite(name: str, values: np.ndarray, rows: np.ndarray | None = None) -> np.ndarray:
    values = np.asarray(values, dtype=float)
    bad = np.flatnonzero(~np.isfinite(values))
    if bad.size:
        row = int(bad[0]) if rows is None else int(rows[bad[0]])
        raise ParameterError(f"{name}[{row}]", values[bad[0]], "a finite number (the data has NaN or inf there)")
    return values


def parse_sigma(given: str | float | Mapping[str, float] | None, datasets: list[str], what: str = "sigma",
                zero: bool = False) -> dict[str, float]:
    """Uncertainty per dataset from "0.01", "nu_v=0.01,nu_0=0.005", a number or a mapping
    (``what`` names it in errors; zero: 0 allowed)."""
    if given is None:
        raise ParameterError(what, None, "the standard uncertainty of the digitised y, e.g. --sigma 0.01 "
                             "or --sigma nu_v=0.01,nu_0=0.005 (the digitised format states none)")
    if isinstance(given, str) and "=" not in given:
        given = float(given) if _is_number(given) else given
    if isinstance(given, (int, float)) and not isinstance(given, bool):
        value = validate.number(what, given, 0.0, lo_open=not zero)
        return {name: value for name in datasets}
    if isinstance(given, str):
        pairs = {}
        for item in given.split(","):
            key, _, value = item.partition("=")
            pairs[key.strip()] = float(value) if _is_number(value) else value.strip()
        given = pairs
    validate.known_keys(f"dataset in {what}", given, datasets)
    out = {name: validate.number(f"{what}.{name}", v, 0.0, lo_open=not zero) for name, v in given.items()}
    missing = [name for name in datasets if name not in out]
    if missing:
        raise ParameterError(f"{what}.{missing[0]}", None, "a positive number for every dataset fitted")
    return out


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def load_digitised(path: str | Path, sidecar: str | Path | None, sigma, *, model: str = "kinematic",
                   n: int = DEFAULT_N, datasets: list[str] | None = None,
                   effects: Mapping[str, float] | None = None, sigma_x=None) -> Observations:
    """Observations from a digitised contact curve: every dataset (or ``datasets``) of the export.

    sigma: u of the digitised y per dataset; sigma_x: u of the digitised x (None: exact), a
    number or "name=value,...", in the x axis's units; carried to y by the effective variance
    (df/dx sigma_x)^2 with df/dx at the fitted parameters (rig.fit.engine).

    The sidecar's conditions must give shape, b_over_a, poisson and the two of alpha, l_over_a,
    c_over_a that are not the x axis; datasets must be nu_T, nu_v or nu_0 (magnitudes allowed).
    """
    from rig.compare.comparison import default_sidecar_path
    from rig.compare.digitizer import digitised_frames, read_export
    from rig.compare.sidecar import load_sidecar

    path = Path(path)
    sidecar_path = Path(sidecar) if sidecar is not None else default_sidecar_path(path)
    spec = load_sidecar(sidecar_path)
    _, curves = read_export(path)
    frames = digitised_frames(curves, spec, str(path))
    names = list(frames) if datasets is None else [validate.choice("dataset", d, list(frames)) for d in datasets]
    sigmas = parse_sigma(sigma, names)
    sigmas_x = {name: 0.0 for name in names} if sigma_x is None else parse_sigma(sigma_x, names, "sigma-x", zero=True)
    x_col = validate.choice(f"x axis of {sidecar_path}", spec.x.column, X_COLUMNS)
    parts = []
    for name in names:
        ds = spec.dataset(name)
        if ds.y.column not in CONTACT_QUANTITIES:
            raise ParameterError(f"datasets.{name}", ds.y.column,
                                 "one of " + ", ".join(CONTACT_QUANTITIES) + " for a contact-level fit")
        cond = dict(ds.conditions)
        frame = frames[name]
        x = _finite(f"{name}.x", frame[x_col].to_numpy())
        y = _finite(f"{name}.y", frame.iloc[:, 1].to_numpy())
        cond_values = {}
        for key in X_COLUMNS + ("b_over_a", "poisson"):
            if key == x_col:
                cond_values[key] = x
            elif key in cond:
                cond_values[key] = np.full(x.size, validate.number(f"conditions.{key}", cond[key]))
            else:
                raise ParameterError(f"conditions.{key}", None, f"a value in the sidecar {sidecar_path} "
                                     "(the fit needs every contact condition)")
        shape = cond.get("shape")
        if not isinstance(shape, str):
            raise ParameterError("conditions.shape", shape, f"a shape name in the sidecar {sidecar_path}")
        parts.append((name, ds.y.column, ds.y.magnitude, x, y, sigmas[name], cond_values, shape, sigmas_x[name]))
    shapes = {p[7] for p in parts}
    poissons = {float(p[6]["poisson"][0]) for p in parts}
    if len(shapes) != 1 or len(poissons) != 1:
        raise ParameterError("conditions", sorted(map(str, shapes | poissons)), "one shape and one poisson per fit")
    cat = lambda k: np.concatenate([p[6][k] for p in parts])  # noqa: E731
    quantity = np.concatenate([np.full(p[3].size, p[1]) for p in parts])
    return Observations(
        quantity=quantity,
        y=np.concatenate([p[4] for p in parts]),
        u=np.concatenate([np.full(p[3].size, p[5]) for p in parts]),
        x=np.concatenate([p[3] for p in parts]),
        x_label=spec.x.label,
        l=cat("l_over_a"), c=cat("c_over_a"), u_l=np.concatenate([np.full(p[3].size, p[8]) for p in parts]),
        alpha=_finite("alpha", cat("alpha")), alpha_per_mu=np.full(quantity.size, np.nan),
        b_over_a=cat("b_over_a"),
        series=np.concatenate([np.full(p[3].size, p[0]) for p in parts]),
        contact=ContactCondition(model, shapes.pop(), poissons.pop(), validate.integer("n", n, 4, 512)),
        fixed_effects=dict(effects or {}),
        source=f"{path} (sidecar {sidecar_path}), u as given: {sigmas}"
               + (f", u of {x_col} as given: {sigmas_x}" if sigma_x is not None else f", {x_col} taken as exact"),
        regressor=x_col,
        notes=tuple(f"{p[0]} is |{p[1]}|" for p in parts if p[2]),
    )


REDUCED_COLUMNS = ("point", "l_over_a", "u_l_over_a", "c_over_a", "F_y_N", "u_F_y_N", "i_k")


def read_run_table(path: str | Path) -> tuple[pd.DataFrame, Path]:
    """(reduced table with a ``point`` column, path of the log) from a ``log.h5`` or a ``reduced.csv``
    beside one; every unreadable, empty or header-only table is a DataFileError naming the file."""
    from rig.fit.inputs import DataFileError
    from rig.logbook.reduced import read_reduced

    path = Path(path)
    if path.suffix == ".csv":
        log = path.with_name("log.h5")
        try:
            table = pd.read_csv(path)
        except pd.errors.EmptyDataError:
            raise DataFileError(path, "no columns (empty or blank)", "a reduced.csv with a header and data rows") \
                from None
        except (pd.errors.ParserError, UnicodeDecodeError, ValueError) as error:
            raise DataFileError(path, f"not a readable CSV: {str(error).splitlines()[0][:120]}",
                                "a reduced.csv as rig run writes it") from None
    else:
        log = path
        table = read_reduced(path).reset_index()
    if table.empty:
        raise DataFileError(path, "a header and no data rows" if len(table.columns) else "no data",
                            "a reduced table with at least one point")
    return table, log


class SceneMismatchError(ParameterError):
    """--scene describes another run than the log's stored scene: names the first difference."""


SCENE_LOAD_SETTINGS = ("normal_force_N",)  # settings whose set of values must agree (the loads)


def scene_differences(given, stored) -> list[str]:
    """What differs between a scene given for a fit and the scene stored in the log: the stand, its
    parameters except mu (geometry, stiffness ...), the contact law (model, poisson, shape) and the
    loads; each as "name: given vs stored". Empty when they describe the same stand and loads."""
    out = []
    if given.stand != stored.stand:
        return [f"stand: {given.stand} vs {stored.stand}"]
    names = sorted((set(given.parameters) | set(stored.parameters)) - {"mu"})
    defaults = getattr(given.stand_class, "PARAMETERS", {})
    for name in names:
        default = getattr(defaults.get(name), "default", None)
        a, b = given.parameters.get(name, default), stored.parameters.get(name, default)
        if a != b:
            out.append(f"{name}: {a} vs {b}")
    for key in ("model", "poisson"):
        a, b = getattr(given.contact, key, None), getattr(stored.contact, key, None)
        if a != b:
            out.append(f"contact {key}: {a} vs {b}")
    for setting in SCENE_LOAD_SETTINGS:
        a, b = (sorted({float(p.settings[setting]) for p in s.procedure.points() if setting in p.settings})
                for s in (given, stored))
        if a != b:
            out.append(f"{setting}: {a} vs {b}")
    return out


def load_run(path: str | Path, scene=None, *, n: int | None = None, force_scene: bool = False) -> Observations:
    """Observations from a stand run (``log.h5`` or its ``reduced.csv``), by the loader of its stand
    (RUN_LOADERS: stand name -> function(table, log, scene, stand, path, n)).

    scene: None (the scene stored in the log) or a scene that must describe the same stand,
    geometry, contact law and loads as the stored one (scene_differences), else a
    SceneMismatchError; force_scene: take the given scene anyway (the summary says so).
    """
    from rig.logbook.reader import read_metadata
    from rig.scenes.load import parse_scene

    path = Path(path)
    table, log = read_run_table(path) if path.suffix == ".csv" else (None, path)  # a table given is checked first
    meta = read_metadata(log)
    stored = parse_scene(meta.scene_toml, name=f"stored in {log}", source=str(log))
    forced = []
    if scene is None:
        scene = stored
    else:
        differences = scene_differences(scene, stored)
        if differences and not force_scene:
            raise SceneMismatchError("scene", scene.name, f"the scene of {log} or --force-scene",
                                     hint="it differs from the log's stored scene in " + "; ".join(differences[:3])
                                     + (f" and {len(differences) - 3} more" if len(differences) > 3 else ""))
        forced = [f"--force-scene: scene {scene.name} differs from the log's own in " + "; ".join(differences)] \
            if differences else []
    stand = scene.build_stand()
    name = getattr(stand, "name", "")
    if name not in RUN_LOADERS:
        raise ParameterError("stand", name, "one of " + ", ".join(RUN_LOADERS) + " (the stands rig fit reads)")
    if table is None and name in READS_REDUCED_TABLE:  # stand B reads its readings only
        table = read_run_table(path)[0]
    obs = RUN_LOADERS[name](table, log, scene, stand, path, n)
    if forced:
        obs = dataclasses.replace(obs, notes=tuple(forced) + obs.notes)
    return obs


def load_stand_a_run(path: str | Path, scene=None, *, n: int | None = None) -> Observations:
    """Observations F_y/F_N versus l/a from a stand-A run: ``log.h5`` or ``reduced.csv`` beside it.

    scene: a loaded scene (None: the scene stored in the log). Points whose reduction gave NaN
    in l/a or F_y (with a reason) are left out and counted in ``notes``; NaN anywhere else in
    a used column is an error.
    """
    obs = load_run(path, scene, n=n)
    if obs.stand is None or getattr(obs.stand, "name", "") != "yoke":
        raise ParameterError("stand", getattr(obs.stand, "name", None), "yoke (stand A)")
    return obs


def _stand_a_observations(table: pd.DataFrame, log: Path, scene, stand, path: Path, n: int | None) -> Observations:
    """Stand A (the yoke): see :func:`load_stand_a_run`."""
    from rig.logbook.reader import read_calibration, read_readings, read_settings

    settings = read_settings(log)
    for column in REDUCED_COLUMNS:
        if column not in table.columns:
            raise ParameterError("DATA column", column, f"present in {path} (a stand-A reduced table)")
    table = table.copy()  # the caller's frame is never modified
    numeric = table[list(REDUCED_COLUMNS)].apply(pd.to_numeric, errors="coerce")
    usable = np.isfinite(numeric[["l_over_a", "F_y_N", "i_k"]].to_numpy(dtype=float)).all(axis=1)
    dropped = int((~usable).sum())
    if not usable.any():
        raise ParameterError("DATA", str(path), "at least one point with finite l_over_a, F_y_N and i_k",
                             hint=f"all {usable.size} rows have NaN or no number there (see the reduction's reason)")
    table = numeric[usable]
    points = table["point"].to_numpy()
    if not np.all(np.isin(points, settings.index.to_numpy())):
        missing = points[~np.isin(points, settings.index.to_numpy())]
        raise ParameterError("DATA point", f"{missing[0]:g} in {path}", f"a point of {log} "
                             f"(0-{len(settings) - 1}): the reduced table is not from this log")
    rows = points.astype(int)
    f_n = settings.loc[rows, "normal_force_N"].to_numpy(dtype=float)
    delta_h = settings.loc[rows, "delta_h_m"].to_numpy(dtype=float)
    geometries = [stand.params.geometry_at(float(d)) for d in delta_h]
    b_over_a = np.array([g.b_over_a(float(f)) for g, f in zip(geometries, f_n)])
    from rig.reduction.equations import alpha_prime_line_contact

    i_k = _finite("i_k", table["i_k"].to_numpy(), rows)
    k = np.array([alpha_prime_line_contact(1.0, b, g.r1 / (math.sin(g.alpha_1) + i), g.radius_x)
                  for g, b, i in zip(geometries, b_over_a, i_k)])
    spec = stand.contact_spec
    y = _finite("F_y_N", table["F_y_N"].to_numpy(), rows) / f_n
    u = _finite("u_F_y_N", table["u_F_y_N"].to_numpy(), rows) / f_n
    if np.any(u <= 0):
        raise ParameterError("u_F_y_N", float(u.min() * f_n[np.argmin(u)]), "> 0 N for every point fitted")
    notes = [f"{dropped} point(s) without l/a or F_y (reduction's reason) left out"] if dropped else []
    common, common_notes = read_common_errors(read_calibration(log).loc[rows], read_readings(log).loc[rows], f_n,
                                              geometries)
    notes.extend(common_notes)
    return Observations(
        quantity=np.full(y.size, "F_y_per_F_N"), y=y, u=u,
        x=_finite("l_over_a", table["l_over_a"].to_numpy(), rows), x_label="l/a",
        l=table["l_over_a"].to_numpy(dtype=float), c=_finite("c_over_a", table["c_over_a"].to_numpy(), rows),
        u_l=np.nan_to_num(table["u_l_over_a"].to_numpy(dtype=float)),
        alpha=np.full(y.size, np.nan), alpha_per_mu=k, b_over_a=b_over_a,
        series=np.array([f"F_N = {f:g} N" for f in f_n]),
        contact=ContactCondition(spec.model, "line", spec.poisson, spec.n if n is None else n),
        fixed_effects=dict(spec.effects), source=f"{path} (stand A, scene {scene.name})",
        stand=stand, geometry=geometries, notes=tuple(notes), common=common,
    )


def _stand_b_observations(table, log, scene, stand, path, n) -> Observations:
    """Stand B's readings F_T, F_V, T_Mo per point (rig.fit.stand_b; its forward model is stand B's own)."""
    from rig.fit.stand_b import load_stand_b_run

    return load_stand_b_run(path, scene, n=n)


RUN_LOADERS = {"yoke": _stand_a_observations, "disc_roller": _stand_b_observations}
"""Stand name -> loader of its run (load_run): function(table, log, scene, stand, path, n)."""
READS_REDUCED_TABLE = {"yoke"}
"""The stands whose loader takes the run's reduced table (the others read the log's readings; table None)."""
