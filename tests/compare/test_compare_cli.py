"""``rig compare`` end to end: the shipped exact-theory curves against analytic limits; exit codes; outputs.

Independent numbers: the rigid full-sliding limit of pure spin of a Hertz circle, nu_0 = 3 pi/16
and nu_v = 0 (Equations §1.10(a)); the linear (full stick) limit nu_v alpha' ->
30 (1 - nu) C23 sqrt(b/a) / pi (Equations §1.7) with Kalker's C23 for the circle
(1.47 at nu = 0.25, 1.63 at nu = 0.5, Equations §1.10(b)); the reference curves themselves were
computed with Vollebregt's CONTACT (see the sidecar).
"""

from __future__ import annotations

import json
import math
import shutil
from unittest import mock
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from rig.compare.comparison import compare_files
from rig.compare.digitizer import read_export
from rig.compare.overlay import overlay_figure

DATA = Path(__file__).parent / "data"
REFERENCE = DATA / "exact_pure_spin_circle.csv"
CONDITIONS = dict(shape="ellipse", b_over_a=1.0, poisson=0.28, c_over_a=0.0, l_over_a=0.0)


def _rigid_result(path: Path) -> Path:
    """RESULT of the rigid (full sliding) model, which does not depend on alpha'."""
    alpha = np.array([0.01, 0.03, 0.1, 0.3])
    nu_0 = 3 * math.pi / 16
    frame = pd.DataFrame(dict(alpha=alpha, nu_T=0.0, nu_v=0.0, nu_0=nu_0, **CONDITIONS, model="rigid", n=32))
    frame.to_csv(path, index=False)
    return path


def _metrics(directory: Path) -> pd.DataFrame:
    return pd.read_csv(directory / "compare_metrics.csv").set_index("dataset")


def test_reference_curves_meet_the_full_sliding_limit(tmp_path, rig_main, capsys):
    result = _rigid_result(tmp_path / "result.csv")
    assert rig_main(["compare", str(result), str(REFERENCE), "--sidecar", str(REFERENCE.with_suffix(".toml"))]) == 0
    metrics = _metrics(tmp_path)  # default output directory: next to RESULT
    nu_0, nu_v = metrics.loc["nu_0"], metrics.loc["nu_v"]
    assert (nu_0.n_compared, nu_0.n_skipped) == (5, 28)  # alpha' = 0.0407 ... 0.257 lie inside [0.01, 0.3]
    assert nu_0.model == "rigid"
    assert nu_0.max_abs_dev == pytest.approx(3 * math.pi / 16 - 0.588231, rel=1e-6)  # worst at alpha' = 0.257
    assert nu_0.x_at_max_abs_dev == pytest.approx(0.256999)
    assert nu_0.max_rel_dev < 2e-3
    assert nu_v.max_abs_dev == pytest.approx(0.0386564)  # F_y = 0 exactly in full sliding
    assert nu_v.max_rel_dev == pytest.approx(1.0)
    assert (tmp_path / "compare_overlay.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    out = capsys.readouterr().out
    assert "pure spin, circular Hertz contact" in out and "compare_metrics.json" in out


def test_thresholds_give_exit_status_1_with_one_line_per_failing_dataset(tmp_path, rig_main, capsys):
    shutil.copy(REFERENCE, tmp_path / "fig.csv")
    shutil.copy(REFERENCE.with_suffix(".toml"), tmp_path / "fig.toml")  # found as DIGITISED.toml
    result = _rigid_result(tmp_path / "result.csv")
    base = ["compare", str(result), str(tmp_path / "fig.csv"), "-o", str(tmp_path / "out"), "--no-plot"]
    with mock.patch("rig.cli.compare.save_overlay") as save_overlay:
        assert rig_main(base + ["--max-abs", "nu_0=1e-3"]) == 0
    save_overlay.assert_not_called()  # --no-plot: the figure is never built
    capsys.readouterr()
    assert rig_main(base + ["--max-abs", "nu_0=5e-4", "--max-abs", "nu_v=0.05"]) == 1
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["rig compare: FAIL nu_0 (model rigid): max |dev| 0.0008176 > 0.0005 [1]"]
    assert rig_main(base + ["--max-rmse", "0.01"]) == 1  # nu_v RMSE 0.024 fails, nu_0 RMSE 5e-4 passes
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("rig compare: FAIL nu_v (model rigid): RMSE 0.02")
    document = json.loads((tmp_path / "out" / "compare_metrics.json").read_text())
    assert document["passed"] is False and len(document["failures"]) == 1
    assert document["x"] == {"column": "alpha", "units": "1", "scale": "log"}
    assert document["datasets"][0]["x_shift"] is None
    assert not (tmp_path / "out" / "compare_overlay.png").exists()


def test_per_dataset_export_with_decimal_commas_against_the_linear_limit(tmp_path, rig_main):
    """nu_v of the reference (headerless, ';', decimal commas) against Kalker's full-stick asymptote."""
    _, (nu_v, _) = read_export(REFERENCE)
    lines = [f"{float(x)!r};{float(y)!r}".replace(".", ",") for x, y in zip(nu_v.x, nu_v.y)]
    (tmp_path / "nu_v.csv").write_text("\n".join(lines) + "\n\n", encoding="utf-8")
    (tmp_path / "nu_v.toml").write_text(
        'figure = "nu_v, pure spin of a circle"\n'
        '[conditions]\nshape = "ellipse"\nb_over_a = 1.0\npoisson = 0.28\n'
        '[x]\nquantity = "alpha\'"\nunits = "1"\nscale = "log"\n'
        '[datasets.nu_v]\nquantity = "|F_y| / (mu F_N)"\nunits = "1"\nscale = "log"\n',
        encoding="utf-8",
    )
    c23 = 1.47 + (0.28 - 0.25) / 0.25 * (1.63 - 1.47)  # Kalker, circle, linear in nu
    alpha = np.logspace(3, 5.1, 8)
    nu = 30 * (1 - 0.28) * c23 / (math.pi * alpha)
    pd.DataFrame(dict(alpha=alpha, nu_v=-nu, shape="ellipse", b_over_a=1.0, poisson=0.28)).to_csv(
        tmp_path / "linear.csv", index=False
    )
    status = rig_main(["compare", str(tmp_path / "linear.csv"), str(tmp_path / "nu_v.csv"), "--max-abs", "nu_v=1e-3"])
    assert status == 0
    row = _metrics(tmp_path).loc["nu_v"]
    assert (row.n_compared, row.n_skipped) == (11, 22)  # alpha' = 1023 ... 102313
    assert row.max_rel_dev == pytest.approx(0.0055, abs=5e-4)  # (10.296 - 10.239) / 10.296 at alpha' = 1023
    assert pd.isna(row.model)


def test_x_shift_tolerance_is_reported(tmp_path, rig_main):
    x = np.linspace(0.0, 4.0, 801)
    pd.DataFrame(dict(x_m=x, y_N=x**2)).to_csv(tmp_path / "r.csv", index=False)
    x_ref = np.linspace(1.0, 3.0, 9)
    (tmp_path / "d.csv").write_text("\n".join(f"{a},{(a + 0.03) ** 2}" for a in x_ref) + "\n")
    (tmp_path / "d.toml").write_text(
        'figure = "parabola"\n[x]\ncolumn = "x_m"\nunits = "m"\n[datasets.y]\ncolumn = "y_N"\nunits = "N"\n'
    )
    args = ["compare", str(tmp_path / "r.csv"), str(tmp_path / "d.csv"), "--max-rmse", "1e-3"]
    assert rig_main(args) == 1
    assert rig_main(args + ["--x-shift-tolerance", "0.05"]) == 0
    row = _metrics(tmp_path).loc["y"]
    assert row.x_shift == pytest.approx(0.03, abs=1e-4) and row.x_shift_units == "m"


@pytest.mark.parametrize(
    ("mutate", "words"),
    [
        (lambda d: (d / "fig.csv").write_text("nu_v,,nu_0,\nX,Y,X,Y\n0.1,0.2,0.1,zero\n"), "fig.csv, line 3:"),
        (lambda d: (d / "fig.toml").unlink(), "an existing TOML file"),
        (lambda d: (d / "result.csv").write_text("alpha,nu_v\n1,2\n"), "column of RESULT"),
    ],
)
def test_bad_input_gives_exit_status_2(tmp_path, rig_main, capsys, mutate, words):
    shutil.copy(REFERENCE, tmp_path / "fig.csv")
    shutil.copy(REFERENCE.with_suffix(".toml"), tmp_path / "fig.toml")
    _rigid_result(tmp_path / "result.csv")
    mutate(tmp_path)
    assert rig_main(["compare", str(tmp_path / "result.csv"), str(tmp_path / "fig.csv")]) == 2
    err = capsys.readouterr().err
    assert err.startswith("rig compare: error:") and words in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize(
    ("option", "words"),
    [(["--max-abs", "nu_v"], "QUANTITY=VALUE"), (["--max-abs", "nu_v=-1"], "[0, inf)"),
     (["--max-abs", "nu_w=0.1"], "did you mean 'nu_v'"), (["--model", "kinematic"], "one of rigid"),
     (["--x-shift-tolerance", "2"], "x_shift_tolerance")],
)  # fmt: skip
def test_bad_options_give_exit_status_2(tmp_path, rig_main, capsys, option, words):
    result = _rigid_result(tmp_path / "result.csv")
    sidecar = REFERENCE.with_suffix(".toml")
    assert rig_main(["compare", str(result), str(REFERENCE), "--sidecar", str(sidecar), "--no-plot", *option]) == 2
    assert words in capsys.readouterr().err


def test_overlay_has_a_curve_and_a_residual_panel_per_dataset(tmp_path):
    result = _rigid_result(tmp_path / "result.csv")
    sidecar, items = compare_files(result, REFERENCE)
    figure = overlay_figure(sidecar, items)
    assert len(figure.axes) == 4  # (curve, residual) x (nu_v, nu_0)
    top, residual = figure.axes[1], figure.axes[3]  # nu_0 column: row-major order of subplots
    assert top.get_xscale() == "log" and top.get_title() == "nu_0"
    x, dev = residual.get_lines()[0].get_data()
    np.testing.assert_allclose(dev, 3 * math.pi / 16 - items[1].comparison.y_ref[items[1].comparison.compared])
    assert x.size == 5
