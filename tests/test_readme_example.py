"""The README's Python example runs as printed (in a temporary folder, as a new user would run it).

Independent fact used: the example sets mu = 0.45 on the default scene, so the median of the reduced mu_v
([Koziarski] eq. (33)) must come back near 0.45; otherwise the contract is that it runs, prints the
reduction and writes the figure it names.
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def readme_example() -> str:
    blocks = re.findall(r"```python\n(.*?)```", (ROOT / "README.md").read_text(encoding="utf-8"), re.S)
    assert len(blocks) == 1, "the README has exactly one Python example"
    return blocks[0]


def test_readme_is_short_and_starts_with_the_two_commands():
    lines = (ROOT / "README.md").read_text(encoding="utf-8").splitlines()
    assert len(lines) <= 150
    commands = [line for line in lines[:12] if line.startswith("    python3 -m venv .venv")]
    assert len(commands) == 2 and "rig run" in commands[0] and "pytest" in commands[1]


def test_readme_example_runs(tmp_path):
    code = readme_example()
    assert len(code.strip().splitlines()) <= 6
    done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-2000:]
    assert "mu_T" in done.stdout and "l_over_a" in done.stdout
    assert (tmp_path / "out" / "mu045" / "reduced_vs_truth.png").stat().st_size > 10_000
    reduced = __import__("pandas").read_csv(tmp_path / "out" / "mu045" / "reduced.csv")
    assert abs(reduced["mu_v"].median() - 0.45) < 0.02  # the value the example set, recovered by eq. (33)
