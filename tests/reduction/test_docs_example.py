"""docs/reduction.md shows exactly what docs/examples/reduction_stand_a.py prints (no stale numbers)."""

from __future__ import annotations

import runpy
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BEGIN, END = "<!-- BEGIN worked-example", "<!-- END worked-example -->"


def test_worked_example_block_matches_the_script():
    text = (ROOT / "docs" / "reduction.md").read_text(encoding="utf-8")
    block = text[text.index(BEGIN):text.index(END)].split("\n", 1)[1].strip()
    produced = runpy.run_path(str(ROOT / "docs" / "examples" / "reduction_stand_a.py"))["main"]()
    assert produced.strip() == block
    assert "| mu_T | 0.39" in block  # truth 0.4, the balance step reads 0.0058 N m low
