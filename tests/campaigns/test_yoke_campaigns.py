"""Stand A's campaigns fig10 and fig11 ([Koziarski] Figs. 10-11): shortened copies of the built-in
scenes run through rig.runner, and the acceptance statements asserted on their outputs.

Shortened: kinematic law with n = 8 and 9 x 2 x 3 surrogate tables (one per b/a, shared by both
scenes through a session-scoped RIG_CACHE_DIR), three set-points per load, 2 s gates. The
reduction evaluates the same law the stand simulated, so reduced-vs-truth agreement does not
depend on the table's coarseness. Independent numbers: the scenes' mu = 0.4; eq. (32) with the
the Equations page's geometry (section 3.1: l1 = 42.76 mm, l2 = -50.50 mm, a = 1.215 mm, Delta h = 1.06 mm)
gives c/a = 0.40002 - l/(87.98 a), the caption says 0.4 - l/(87.7 a); the b/a pairing 1 / 2 at
96.2 / 385 N is the text's.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rig.campaigns import PAPER_FIGURES, paper_figure
from rig.campaigns.yoke_figures import K, QUANTITIES, campaign_points, caption_line, matched_contrast
from rig.runner import run_scene
from rig.scenes import load_scene, parse_scene

SHORT = {  # the 385 N set-points put l/a inside the 96.2 N span (l/a ~ 0.63 T_set and 0.19 T_set per N m)
    "n = 32 ": "n = 8 ",
    "table_points = [21, 3, 5]": "table_points = [9, 2, 3]",
    "{ start = 0.1, stop = 1.6, num = 24 }": "[0.3, 0.9, 1.5]",  # brake only (T_set = 0 would make mu_T 0/D)
    "gate_time_s = 20.0 ": "gate_time_s = 2.0 ",
}
SHORT_385 = {"fig10": "{ start = 0.3, stop = 5.2, num = 24 }", "fig11": "{ start = 0.3, stop = 5.1, num = 24 }"}
L1, L2, A, DELTA_H = 42.76e-3, -50.50e-3, 1.215e-3, 1.06e-3  # Equations §3.1 [m]


def _short(name: str):
    text = load_scene(name).text
    for old, new in (SHORT | {SHORT_385[name]: "[1.5, 3.0, 4.5]"}).items():
        assert old in text, (name, old)
        text = text.replace(old, new)
    return parse_scene(text, name=f"{name}_short")


@pytest.fixture(scope="session")
def runs(tmp_path_factory):
    """{name: (report, reduced table, campaign points, run folder)} of the shortened fig10 and fig11,
    run once per session with one surrogate-table cache (RIG_CACHE_DIR) that both scenes share."""
    cache, out = tmp_path_factory.mktemp("surrogate_cache"), {}
    with pytest.MonkeyPatch.context() as patch:
        patch.setenv("RIG_CACHE_DIR", str(cache))
        for name in ("fig10", "fig11"):
            folder = tmp_path_factory.mktemp(name)
            report = run_scene(_short(name), folder, progress=False)
            reduced = pd.read_csv(folder / "reduced.csv", index_col="point")
            out[name] = (report, reduced, campaign_points(reduced, folder / "log.h5"), folder)
    assert len(list(cache.glob("surrogate-*.npz"))) == 2  # one table per b/a, reused by fig11
    return out


def test_builtin_scenes_meet_the_benchmark_configuration():
    for name in ("fig10", "fig11"):
        scene = load_scene(name)
        assert scene.outputs.paper_figure == name and PAPER_FIGURES[name].endswith(f":{name}")
        assert scene.procedure.n_points >= 40 and scene.procedure.gate_time_s >= 20.0
        assert [series.fixed["normal_force_N"] for series in scene.procedure.series] == [96.2, 385.0]
        assert scene.procedure.fixed["delta_h_m"] == (0.0 if name == "fig10" else 1.06e-3)
        assert scene.text.startswith("# [Koziarski] Fig. 1")


@pytest.mark.parametrize("name", ["fig10", "fig11"])
def test_campaign_runs_and_writes_its_figure(runs, name):
    report, reduced, points, folder = runs[name]
    assert report.failures == () and report.in_log == 6
    assert {"log.h5", "reduced.csv", f"{name}.png", "summary.txt"} <= set(report.files)
    assert (folder / f"{name}.png").stat().st_size > 10_000
    assert f"paper figure ({name}):" in report.summary
    assert sorted(points["b_over_a"].round(9).unique()) == [1.0, 2.0]  # text: b/a = 1 at 96.2 N, 2 at 385 N


@pytest.mark.parametrize("name", ["fig10", "fig11"])
def test_reduced_points_agree_with_truth_within_their_uncertainty(runs, name):
    report, reduced, points, _ = runs[name]
    assert np.allclose(points["true_mu_T"], 0.4) and np.allclose(points["true_mu_v"], 0.4)  # the scene's mu
    for column in ("l_over_a", "F_y_N", "mu_v", "mu_T", "T2_N_m"):
        z = np.abs(points[column] - points[f"true_{column}"]) / points[f"u_{column}"]
        assert (z <= 3.0).all(), (column, z.round(2).tolist())
        for b in (1, 2):  # the summary states the same count per b/a
            within = int((z[points["b_over_a"].round(6) == b] <= K).sum())
            line = next(x for x in report.summary.splitlines() if f"b/a = {b}, within 2u of the truth" in x)
            assert f"{QUANTITIES[column]} {within}/3" in line, (column, line)


@pytest.mark.parametrize("name", ["fig10", "fig11"])
def test_b_over_a_effect_on_F_y_is_beyond_the_uncertainty(runs, name):
    report, _, points, _ = runs[name]
    low, high = (points[points["b_over_a"].round(6) == b].sort_values("l_over_a") for b in (1.0, 2.0))
    for column in ("F_y_N", "F_y_per_F_N"):
        c = matched_contrast(low, high, column, 1.0, 2.0)
        assert c is not None and c.n == 3  # the 385 N points lie inside the 96.2 N span of l/a
        assert c.z_min > K and c.beyond_uncertainty, (column, c)
    assert "paper's claim (F_y depends strongly on b/a at fixed c/a) holds" in report.summary


def test_fig10_and_fig11_differ_in_F_y_beyond_the_uncertainty(runs):
    """Delta h = 1.06 mm moves C off the contact line (c/a = 0.4): F_y grows at both loads."""
    f10, f11 = runs["fig10"][2], runs["fig11"][2]
    for b in (1.0, 2.0):
        a, c = (p[p["b_over_a"].round(6) == b].sort_values("l_over_a") for p in (f10, f11))
        z = (c["F_y_N"].to_numpy() - a["F_y_N"].to_numpy()) / np.hypot(c["u_F_y_N"], a["u_F_y_N"]).to_numpy()
        assert (z > K).all(), z


def test_fig11_c_over_a_follows_the_caption(runs):
    _, reduced, points, _ = runs["fig11"]
    l = points["true_l_over_a"].to_numpy()
    eq32 = DELTA_H * (L1 - l * A) / (A * (L1 - L2))  # Equations §2, eq. (32)
    assert np.allclose(points["true_c_over_a"], eq32, atol=1e-6)
    assert np.abs(points["true_c_over_a"] - caption_line(l)).max() < 1e-4  # 87.98 vs 87.7: <= 4e-5 at |l/a| <= 1
    assert np.abs(reduced["c_over_a"] - caption_line(reduced["l_over_a"])).max() < 1e-3
    summary = runs["fig11"][0].summary
    assert "c/a vs caption 0.4 - l/(87.7 a), reduced: 6 points" in summary and "fit c/a = 0.4000 - l/(87.9" in summary


def test_fig10_has_c_zero_and_no_caption_check(runs):
    _, reduced, points, _ = runs["fig10"]
    assert (points["true_c_over_a"] == 0.0).all() and "c/a vs caption" not in runs["fig10"][0].summary


def test_one_load_only_says_the_contrast_needs_two(runs, tmp_path):
    _, reduced, _, folder = runs["fig10"]
    one = reduced[reduced.index < 3]
    outcome = paper_figure("fig10")(one, folder / "log.h5", tmp_path, "one load")
    assert (tmp_path / "fig10.png").is_file()
    assert any("needs two b/a values, the run has 1" in line for line in outcome.summary)


def _curve(l, offset, u, u_l=0.0):
    """A campaign curve y = 0.3 l + offset with constant u."""
    return pd.DataFrame({"l_over_a": l, "u_l_over_a": u_l, "y": 0.3 * np.asarray(l) + offset, "u_y": u})


@settings(max_examples=50, deadline=None)
@given(offset=st.floats(-5, 5), u_low=st.floats(0.01, 1), u_high=st.floats(0.01, 1),
       shift=st.floats(0.01, 0.99))
def test_matched_contrast_recovers_a_known_offset(offset, u_low, u_high, shift):
    """Linear curves: interpolation is exact, u adds (1-w)^2 + w^2 of the low curve's u in quadrature."""
    low = _curve(np.arange(-1.0, 1.01, 0.5), 1.0, u_low)
    high = _curve(np.array([-0.5 + shift * 0.5]), 1.0 + offset, u_high)
    c = matched_contrast(low, high, "y", 1.0, 2.0)
    w = shift
    u = math.sqrt(u_high**2 + ((1 - w) ** 2 + w**2) * u_low**2)
    assert c.n == 1 and c.difference == pytest.approx(offset, abs=1e-9) and c.u == pytest.approx(u, rel=1e-9)
    assert c.z_min == pytest.approx(abs(offset) / u, rel=1e-9, abs=1e-9)


def test_matched_contrast_counts_the_l_uncertainty_through_the_slope():
    low, high = _curve([-1.0, 1.0], 0.0, 0.0, u_l=0.1), _curve([0.0], 1.0, 0.0, u_l=0.1)
    c = matched_contrast(low, high, "y", 1.0, 2.0)  # slope 0.3, u_l = 0.1 (high) and 0.1/sqrt(2) (low)
    assert c.u == pytest.approx(0.3 * math.sqrt(0.01 + 0.005))
    assert matched_contrast(low, _curve([1.5], 0.0, 0.1), "y", 1.0, 2.0) is None  # outside the span



def test_a_log_without_truth_still_gives_the_figure_and_the_contrast(runs, tmp_path, monkeypatch):
    """A real stand's log has no truth group: no agreement check, the b/a contrast from reduced values."""
    import rig.campaigns.yoke_figures as figures
    from rig.errors import LogFormatError

    def no_truth(path):
        raise LogFormatError(f"{path}: no truth group")

    monkeypatch.setattr(figures, "read_truth", no_truth)
    _, reduced, _, folder = runs["fig11"]
    measured = reduced[[c for c in reduced.columns if not c.startswith("true_")]]
    outcome = figures.fig11(measured, folder / "log.h5", tmp_path, "no truth")
    assert (tmp_path / "fig11.png").is_file()
    assert sum("no truth in the log, agreement not checked" in line for line in outcome.summary) == 2
    assert any(line.startswith("paper's claim") and "holds" in line for line in outcome.summary)
    assert not any("c/a vs caption, truth" in line for line in outcome.summary)


@pytest.mark.parametrize("name", ["fig10", "fig11"])
def test_default_set_points_are_what_the_shoe_brake_can_do(name):
    """Issue 15, item 4: the paper's shoe brake only brakes (T_set >= 0); negative set-points need the
    idealised load device, which a scene must name (fig10/fig11 do not)."""
    scene = load_scene(name)
    values = [v for series in scene.procedure.series for key, vs in series.sweep for v in vs
              if key == "brake_setpoint_N_m"]
    assert len(values) == scene.procedure.n_points
    assert "load_device" not in scene.effects and min(values) > 0.0, (scene.effects, min(values))
