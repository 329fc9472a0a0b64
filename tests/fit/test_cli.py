"""`rig fit` end to end on a small digitised curve: exit status, the four files, their columns."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pandas as pd

from rig.cli import main as rig_main

EXAMPLES = Path(__file__).resolve().parents[2] / "docs" / "examples"


def _small_curve(folder: Path) -> Path:
    """Every third nu_v point of the exact pure-spin curve with alpha' in [1, 200] (headerless export)."""
    table = pd.read_csv(EXAMPLES / "exact_pure_spin_circle.csv", skiprows=2, header=None).iloc[:, :2]
    table = table[(table[0] >= 1.0) & (table[0] <= 200.0)].iloc[::3]
    path = folder / "spin.csv"
    path.write_text("".join(f"{x},{y}\n" for x, y in table.itertuples(index=False)))
    sidecar = (EXAMPLES / "exact_pure_spin_circle.toml").read_text()
    sidecar = sidecar[: sidecar.index("[datasets.nu_0]")]
    (folder / "spin.toml").write_text(sidecar)
    return path


def test_rig_fit_writes_its_files_and_exits_0(tmp_path, capsys):
    data = _small_curve(tmp_path)
    before = data.read_bytes()
    out = tmp_path / "out"
    status = rig_main(["fit", str(data), "--params", "psi", "--sigma", "0.01", "-o", str(out)])
    assert status == 0
    assert sorted(p.name for p in out.iterdir()) == ["fit.csv", "fit.png", "models.csv", "summary.txt"]
    fit = pd.read_csv(out / "fit.csv")
    assert list(fit.columns[:6]) == ["parameter", "value", "u", "lo95", "hi95", "unit"]
    row = fit.iloc[0]
    assert row["parameter"] == "psi" and row["lo95"] <= row["value"] <= row["hi95"]
    models = pd.read_csv(out / "models.csv")
    assert sorted(models["rank"]) == [1, 2]
    assert np.allclose(models["aic"], models["chi2"] + 2 * models["k"])
    assert np.allclose(models["bic"], models["chi2"] + models["k"] * np.log(models["n_points"]))
    assert "effect sets" in (out / "summary.txt").read_text()
    assert "answer:" in capsys.readouterr().out
    assert data.read_bytes() == before
    assert not list(out.glob(".*tmp"))  # no temporary file left behind


def test_missing_params_is_an_argparse_error(tmp_path):
    data = _small_curve(tmp_path)
    try:
        rig_main(["fit", str(data)])
    except SystemExit as stop:
        assert stop.code == 2
    else:
        raise AssertionError("rig fit without --params must stop")


def test_mu_does_not_enter_a_curve_versus_alpha_and_is_flagged(tmp_path):
    from rig.fit import fit_data

    report = fit_data(_small_curve(tmp_path), ["mu"], sigma=0.01)
    assert any("mu is not identifiable" in w for w in report.full.warnings)
    mu = report.full.estimate("mu")
    assert mu.open_lo and mu.open_hi
