"""Surrogate tables (rig.contact.surrogate, surrogate_cache, tensor_spline): exact at the nodes,
accurate between them, derivatives, the alpha' = 0 bridge, domain errors, the on-disk cache."""

from __future__ import annotations

import dataclasses
import math
import threading
import time
import zipfile
from unittest import mock

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import rig
from rig.contact import surrogate_cache
from rig.contact.solve import solve
from rig.contact.surrogate import TableDomain, build_table, rigid_sliding, table_inputs
from rig.contact.surrogate_cache import CacheStatus, TableFileError, cache_dir, load_or_build, load_table, table_path
from rig.contact.tensor_spline import TensorSpline
from rig.errors import ConvergenceError, ParameterError, UnknownNameError

STAND_A = TableDomain(l_over_a=(-1.5, 1.5), c_over_a=(0.0, 0.9), alpha=(0.3, 3.0))
SETTINGS = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
OUT = ("nu_T", "nu_v", "nu_0")


def _inputs(model="rigid", points=(13, 10, 4), domain=STAND_A, n=16, shape="ellipse", **extra):
    args = dict(shape=shape, b_over_a=1.0, poisson=0.3, n=n, effects=None, domain=domain, points=points)
    args.update(extra)
    return table_inputs(model, **args)


def _direct(inputs, l, c, alpha):
    r = solve(inputs.model, shape=inputs.shape, b_over_a=inputs.b_over_a, alpha=alpha, c_over_a=c, l_over_a=l,
              poisson=inputs.poisson, n=inputs.n, **dict(inputs.effects))
    return np.array([r.nu_T, r.nu_v, r.nu_0])


@pytest.fixture(scope="module")
def rigid_table():
    """Rigid sliding, Hertz circle: l/a nodes every 0.2 (0.25 is between nodes), c/a every 0.1."""
    return build_table(_inputs(domain=TableDomain((-1.2, 1.2), (0.0, 0.9), (0.3, 3.0))))


@pytest.fixture(scope="module")
def kinematic_table():
    """Kinematic model, n = 8, line contact b/a = 1 (stand A at 96.2 N), stand-A-like domain."""
    return build_table(_inputs("kinematic", points=(9, 5, 4), n=8, shape="line"))


# --- the spline kernel -----------------------------------------------------------------------------


def test_spline_reproduces_a_cubic_and_its_derivatives_exactly():
    """A tensor-product cubic is in the spline space: value and every first/mixed derivative exact."""
    axes = [np.linspace(-1.5, 1.5, 7), np.linspace(0.0, 0.9, 5), np.linspace(-1.2, 1.1, 6)]
    def f(x, y, z):
        return x**3 * y - 2.0 * z**3 * x + y**2 * z
    x, y, z = np.meshgrid(*axes, indexing="ij")
    spline = TensorSpline.fit(axes, f(x, y, z)[..., None])
    rng = np.random.default_rng(np.random.SeedSequence(1))
    p = np.stack([rng.uniform(-1.5, 1.5, 50), rng.uniform(0, 0.9, 50), rng.uniform(-1.2, 1.1, 50)])
    r = spline.evaluate(p)[:, 0]
    x, y, z = p
    np.testing.assert_allclose(r[:, 0], f(x, y, z), atol=1e-12)
    np.testing.assert_allclose(r[:, 4], 3 * x**2 * y - 2 * z**3, atol=1e-11)  # d/dx
    np.testing.assert_allclose(r[:, 2], x**3 + 2 * y * z, atol=1e-11)  # d/dy
    np.testing.assert_allclose(r[:, 1], -6 * z**2 * x + y**2, atol=1e-11)  # d/dz
    np.testing.assert_allclose(r[:, 5], -6 * z**2, atol=1e-10)  # d2/dx dz
    one = np.array([spline.evaluate_one(tuple(p[:, i]))[0] for i in range(p.shape[1])])
    np.testing.assert_allclose(one, r, atol=1e-12)
    value = np.array([spline.value_one(tuple(p[:, i]))[0] for i in range(p.shape[1])])  # the value-only path
    np.testing.assert_allclose(value, f(x, y, z), atol=1e-12)


# --- nodes, between nodes, independent numbers -----------------------------------------------------


def test_rigid_table_matches_the_full_sliding_reference_values(rigid_table):
    """Equations §1.10(a), Hertz circle (4000^2 quadrature): at nodes and between them (l/a = 0.25)."""
    cases = [((0.0, 0.0), (0.0, 0.0, 3 * math.pi / 16)), ((0.0, 0.4), (0.0, 0.45239, 0.68141)),
             ((0.25, 0.0), (-0.28992, 0.0, 0.62558)), ((0.5, 0.4), (-0.52867, 0.42294, 0.81818)),
             ((1.0, 0.0), (-0.88357, 0.0, 1.10447))]
    for (l, c), expected in cases:
        values, _ = rigid_table.evaluate(l, c, 1.0)
        np.testing.assert_allclose(values[:, 0], expected, atol=4e-3, err_msg=f"l/a={l}, c/a={c}")


@pytest.mark.parametrize("fixture", ["rigid_table", "kinematic_table"])
def test_table_reproduces_direct_calls_at_its_nodes(fixture, request):
    table = request.getfixturevalue(fixture)
    l_nodes, c_nodes, _ = table.inputs.axes()
    alphas = table.inputs.alpha_nodes()
    for i, j, k in [(0, 0, 0), (3, 2, 1), (len(l_nodes) - 1, len(c_nodes) - 1, len(alphas) - 1), (5, 4, 2)]:
        values, _ = table.evaluate(l_nodes[i], c_nodes[j], alphas[k])
        np.testing.assert_allclose(values[:, 0], _direct(table.inputs, l_nodes[i], c_nodes[j], alphas[k]),
                                   rtol=0, atol=1e-12)
        one, _ = table.evaluate_one(float(l_nodes[i]), float(c_nodes[j]), float(alphas[k]))
        np.testing.assert_allclose(one, values[:, 0], atol=1e-13)
    # the alpha' = 0 slice: the model's own rigid-sliding limit, vectorised without solve()
    values, _ = table.evaluate(l_nodes[3], c_nodes[2], 0.0)
    np.testing.assert_allclose(values[:, 0], _direct(table.inputs, l_nodes[3], c_nodes[2], 0.0), atol=1e-12)


def test_kinematic_table_between_nodes_is_within_the_models_own_grid_error(kinematic_table):
    """Random states (seeded) inside the domain and on the bridge 0 <= alpha' < 0.3.

    Measured (n = 8, nodes 9 x 5 x 4): max |error| 0.018 (nu_T), 0.009 (nu_v), 0.001 (nu_0), the
    same size as the n = 8 model's own grid error (the same states differ between n = 8 and 16 by
    up to 0.010; checked below). Tolerance 0.025 for both. The benchmark measures n = 16 on finer
    tables (docs/stands-contact.md).
    """
    rng = np.random.default_rng(np.random.SeedSequence(2024))
    l = rng.uniform(-1.5, 1.5, 12)
    c = rng.uniform(0.0, 0.9, 12)
    alpha = np.concatenate([np.exp(rng.uniform(math.log(0.3), math.log(3.0), 8)), rng.uniform(0.0, 0.3, 4)])
    table_values, _ = kinematic_table.evaluate(l, c, alpha)
    direct = np.array([_direct(kinematic_table.inputs, *s) for s in zip(l, c, alpha)]).T
    error = np.abs(table_values - direct)
    assert error.max() < 0.025, error.max(axis=1)
    finer = dataclasses.replace(kinematic_table.inputs, n=16)
    grid_error = max(np.abs(_direct(finer, *s) - d).max() for s, d in zip(zip(l[:4], c[:4], alpha[:4]), direct.T[:4]))
    assert grid_error < 0.025


# --- derivatives, bridge, domain ------------------------------------------------------------------


@SETTINGS
@given(l=st.floats(-1.5, 1.5), c=st.floats(0.0, 0.9), alpha=st.floats(0.0, 3.0))
def test_derivatives_match_finite_differences(kinematic_table, l, c, alpha):
    h = 1e-6
    _, jac = kinematic_table.evaluate(l, c, alpha)
    for axis, (lo, hi) in enumerate(((-1.5, 1.5), (0.0, 0.9), (0.0, 3.0))):
        x = np.array([l, c, alpha])
        up, down = x.copy(), x.copy()
        up[axis] = min(x[axis] + h, hi)
        down[axis] = max(x[axis] - h, lo)
        fd = (kinematic_table.evaluate(*up)[0] - kinematic_table.evaluate(*down)[0])[:, 0] / (up[axis] - down[axis])
        np.testing.assert_allclose(jac[:, axis, 0], fd, atol=2e-4 * (1 + np.abs(fd).max()), err_msg=f"axis {axis}")


def test_bridge_meets_the_spline_with_equal_value_and_slope(kinematic_table):
    lo = STAND_A.alpha[0]
    for eps in (1e-9,):
        below, j_below = kinematic_table.evaluate(0.4, 0.3, lo * (1 - eps))
        above, j_above = kinematic_table.evaluate(0.4, 0.3, lo * (1 + eps))
        np.testing.assert_allclose(below, above, atol=1e-8)
        np.testing.assert_allclose(j_below, j_above, atol=1e-6)


def test_rigid_sliding_vectorised_equals_solve_with_rolling_length():
    inputs = _inputs("kinematic", n=8, effects={"rolling_length": 0.2})
    out = rigid_sliding(inputs, np.array([0.1, -0.3]), np.array([0.7, -2.0]))
    for row, (c, l) in zip(out, ((0.1, 0.7), (-0.3, -2.0))):
        np.testing.assert_allclose(row, _direct(inputs, l, c, 0.0), atol=1e-12)


@pytest.mark.parametrize(("name", "state", "valid"), [
    ("l_over_a", (1.3, 0.2, 1.0), "[-1.2, 1.2]"), ("c_over_a", (0.0, -0.1, 1.0), "[0, 0.9]"),
    ("alpha", (0.0, 0.2, 3.5), "[0, 3]"), ("alpha", (0.0, 0.2, -1e-9), "[0, 3]"),
    ("l_over_a", (math.nan, 0.2, 1.0), "[-1.2, 1.2]"), ("alpha", (0.0, 0.2, math.inf), "[0, 3]")])
def test_outside_the_domain_is_a_named_error(rigid_table, name, state, valid):
    """No clamp: the error names the coordinate, its value and the table's range (NaN included)."""
    for evaluate in (rigid_table.evaluate, rigid_table.evaluate_one):
        with pytest.raises(ParameterError) as info:
            evaluate(*state)
        assert info.value.name == name and info.value.valid == valid and "domain" in str(info.value)


def test_linear_model_has_no_bridge_below_its_alpha_range():
    table = build_table(_inputs("linear", points=(4, 4, 4), domain=TableDomain((-1, 1), (0, 1), (10.0, 100.0))))
    assert table.sliding is None
    with pytest.raises(ParameterError, match=r"alpha = 5.0 .*\[10, 100\]"):
        table.evaluate(0.0, 0.5, 5.0)


@pytest.mark.parametrize(("kwargs", "error"), [
    (dict(domain=TableDomain((-1, 1), (0, 1), (1, 2)), points=(1, 4, 4)), ParameterError),
    (dict(model="kinematc"), UnknownNameError), (dict(effects={"psi": 2.0}), ParameterError),
    (dict(poisson=0.6), ParameterError), (dict(points=(4, 4)), ParameterError)])
def test_bad_table_inputs_are_named(kwargs, error):
    base = dict(model="rigid", shape="ellipse", b_over_a=1.0, poisson=0.3, n=8, effects=None, domain=STAND_A,
                points=(4, 4, 4))
    base.update(kwargs)
    with pytest.raises(error):
        table_inputs(base.pop("model"), **base)


@pytest.mark.parametrize("alpha", [(0.0, 1.0), (2.0, 1.0), (1.0, math.inf)])
def test_bad_domain_is_named(alpha):
    with pytest.raises(ParameterError, match="alpha"):
        TableDomain((-1, 1), (0, 1), alpha)


def test_build_reports_progress_and_names_a_failing_node():
    inputs = _inputs("fastsim", points=(4, 4, 2), n=8)
    calls = []
    build_table(inputs, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (32, 32) and [d for d, _ in calls] == sorted(d for d, _ in calls)
    with mock.patch("rig.contact.surrogate.solve", side_effect=ConvergenceError("GMRES stalled")):
        with pytest.raises(ConvergenceError, match=r"l/a = -1.5, c/a = 0, alpha' = 0.3: GMRES stalled"):
            build_table(inputs)


def test_parallel_build_gives_the_same_table():
    inputs = _inputs("fastsim", points=(4, 4, 2), n=8)
    np.testing.assert_array_equal(build_table(inputs, workers=2).values, build_table(inputs).values)


# --- the cache -------------------------------------------------------------------------------------


def test_cache_hit_does_not_solve(tmp_path):
    inputs = _inputs("fastsim", points=(4, 4, 2), n=8)
    first, outcome = load_or_build(inputs, directory=tmp_path)
    assert outcome.status is CacheStatus.BUILT and outcome.path == table_path(inputs, tmp_path)
    with mock.patch("rig.contact.surrogate.solve") as solve_mock, \
            mock.patch.object(surrogate_cache, "build_table") as build_mock:
        second, outcome = load_or_build(inputs, directory=tmp_path)
    solve_mock.assert_not_called()
    build_mock.assert_not_called()
    assert outcome.status is CacheStatus.HIT
    np.testing.assert_array_equal(second.values, first.values)
    np.testing.assert_array_equal(second.sliding, first.sliding)


def test_threads_asking_for_one_table_at_once_build_it_once(tmp_path, monkeypatch):
    """rig lab prepares its exercises' tables in a thread while a request may ask for the same one:
    the second caller waits for the first build and loads its file (no second build)."""
    inputs = _inputs(points=(4, 4, 2))
    builds, started = [], threading.Event()

    def slow_build(*args, **kwargs):
        builds.append(threading.current_thread().name)
        started.set()
        time.sleep(0.3)  # the other thread asks while this build runs
        return build_table(*args, **kwargs)

    monkeypatch.setattr(surrogate_cache, "build_table", slow_build)
    outcomes = {}

    def ask(name):
        outcomes[name] = load_or_build(inputs, directory=tmp_path)[1].status

    first = threading.Thread(target=ask, args=("first",), name="first")
    first.start()
    assert started.wait(10)
    second = threading.Thread(target=ask, args=("second",), name="second")
    second.start()
    first.join(10)
    second.join(10)
    assert builds == ["first"]
    assert outcomes == {"first": CacheStatus.BUILT, "second": CacheStatus.HIT}


def test_every_input_changes_the_key(monkeypatch):
    base = _inputs("kinematic", n=8, points=(4, 4, 4))
    variants = [
        _inputs("fastsim", n=8, points=(4, 4, 4)), _inputs("kinematic", n=8, points=(4, 4, 4), shape="line"),
        _inputs("kinematic", n=8, points=(4, 4, 4), b_over_a=1.0 + 1e-12),
        _inputs("kinematic", n=8, points=(4, 4, 4), poisson=0.28), _inputs("kinematic", n=10, points=(4, 4, 4)),
        _inputs("kinematic", n=8, points=(4, 4, 4), effects={"psi": 1.5}),
        _inputs("kinematic", n=8, points=(4, 4, 4), effects={"psi": 1.6}),
        _inputs("kinematic", n=8, points=(4, 4, 5)),
        _inputs("kinematic", n=8, points=(4, 4, 4), domain=TableDomain((-1.5, 1.5), (0.0, 0.9), (0.3, 3.1))),
        _inputs("kinematic", n=8, points=(4, 4, 4), domain=TableDomain((-1.5, 1.5), (0.0, 0.8), (0.3, 3.0))),
        _inputs("kinematic", n=8, points=(4, 4, 4), domain=TableDomain((-1.4, 1.5), (0.0, 0.9), (0.3, 3.0))),
    ]
    keys = {base.key()} | {v.key() for v in variants}
    assert len(keys) == len(variants) + 1
    monkeypatch.setattr(rig, "__version__", "99.0")
    assert base.key() not in keys
    monkeypatch.setattr("rig.contact.surrogate.TABLE_FORMAT", 99)
    assert base.description()["table_format"] == 99


@pytest.mark.parametrize("damage", ["garbage", "truncated", "other_inputs"])
def test_damaged_cache_file_is_rebuilt_and_reported(tmp_path, damage, caplog):
    inputs = _inputs(points=(4, 4, 4))
    table, _ = load_or_build(inputs, directory=tmp_path)
    path = table_path(inputs, tmp_path)
    if damage == "garbage":
        path.write_bytes(b"not a zip file")
    elif damage == "truncated":
        path.write_bytes(path.read_bytes()[:200])
    else:  # a valid table of other inputs under this name
        other, _ = load_or_build(_inputs(points=(4, 4, 5)), directory=tmp_path)
        table_path(other.inputs, tmp_path).replace(path)
    with pytest.raises(TableFileError, match=str(path.name)):
        load_table(path, inputs)
    rebuilt, outcome = load_or_build(inputs, directory=tmp_path)
    assert outcome.status is CacheStatus.REBUILT and path.name in outcome.reason
    assert "rebuilding" in caplog.text
    np.testing.assert_array_equal(rebuilt.values, table.values)
    assert load_or_build(inputs, directory=tmp_path)[1].status is CacheStatus.HIT
    assert zipfile.is_zipfile(path) and not list(tmp_path.glob("*.tmp"))


def test_cache_folder_comes_from_the_environment(monkeypatch, tmp_path):
    monkeypatch.setenv("RIG_CACHE_DIR", str(tmp_path / "tables"))
    assert cache_dir() == tmp_path / "tables"
    inputs = _inputs(points=(4, 4, 4))
    _, outcome = load_or_build(inputs)
    assert outcome.path.parent == tmp_path / "tables" and outcome.path.exists()
    monkeypatch.delenv("RIG_CACHE_DIR")
    monkeypatch.setenv("HOME", str(tmp_path / "home"))
    assert cache_dir() == tmp_path / "home" / ".cache" / "friction-rig"


def test_table_survives_pickling_for_parallel_points(rigid_table):
    """Points may run in worker processes (rig.stands.base): a table travels by pickle unchanged."""
    import pickle

    copy = pickle.loads(pickle.dumps(rigid_table))
    np.testing.assert_array_equal(copy.evaluate(0.3, 0.2, 1.0)[1], rigid_table.evaluate(0.3, 0.2, 1.0)[1])
    np.testing.assert_array_equal(copy.evaluate_one(0.3, 0.2, 1.0)[0], rigid_table.evaluate_one(0.3, 0.2, 1.0)[0])
