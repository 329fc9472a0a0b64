"""The scaffold the tutorial scripts share (experiments/tutorial/): an output-folder option and
the two files each step writes, a figure (PNG) and its numbers (CSV)."""

from __future__ import annotations

import argparse
from pathlib import Path

import pandas as pd

DEFAULT_OUTPUT = Path("out/tutorial")


def argument_parser(doc: str | None) -> argparse.ArgumentParser:
    """A parser whose description is the script's title (its docstring's first non-empty line), with
    -o/--output [folder]. ``doc`` may be empty or None (the documentation gallery runs the scripts without it)."""
    lines = [line.strip() for line in (doc or "").splitlines() if line.strip()]
    parser = argparse.ArgumentParser(description=lines[0] if lines else None)
    parser.add_argument("-o", "--output", type=Path, default=DEFAULT_OUTPUT, help="output folder")
    return parser


def write_step(figure, table: pd.DataFrame, folder: Path, stem: str, *, index: bool = False) -> list[Path]:
    """Save ``figure`` as <stem>.png and ``table`` as <stem>.csv in ``folder`` (created); [png, csv]."""
    folder.mkdir(parents=True, exist_ok=True)
    png, csv = folder / f"{stem}.png", folder / f"{stem}.csv"
    table.to_csv(csv, index=index)
    figure.savefig(png, dpi=110)
    return [png, csv]
