"""Issue 5, acceptance 2: `rig compare` on the shipped exact-theory curves (Kalker's theory computed
with CONTACT) and the kinematic model at default settings: max |d nu_v| <= 0.03, max |d nu_0| <= 0.02."""

import json
from pathlib import Path

import rig.cli

REFERENCE = Path(__file__).parent / "data" / "exact_pure_spin_circle.csv"


def test_kinematic_model_meets_the_exact_theory_through_rig_compare(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert rig.cli.main(["run", "pure_spin", "-o", "run"]) == 0
    status = rig.cli.main(["compare", "run/characteristics.csv", str(REFERENCE), "-o", "cmp", "--no-plot",
                           "--max-abs", "nu_v=0.03", "--max-abs", "nu_0=0.02"])
    assert status == 0
    metrics = {m["dataset"]: m for m in json.loads((tmp_path / "cmp" / "compare_metrics.json").read_text())["datasets"]}
    assert metrics["nu_v"]["max_abs_dev"] <= 0.03 and metrics["nu_0"]["max_abs_dev"] <= 0.02
    assert metrics["nu_v"]["n_compared"] == metrics["nu_0"]["n_compared"] == 33, "every reference point in range"
