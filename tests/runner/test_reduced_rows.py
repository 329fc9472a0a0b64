"""reduced.csv from the rows the workers formatted (rig.runner.reduction.csv_rows): the same bytes as
the whole table's to_csv, the off-truth flags added by the parent; anything else falls back."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest

from rig.runner.off_truth import with_off_truth, with_z_max
from rig.runner.reduction import FormattedRows, csv_rows, write_csv


def reduced(n: int, seed: int = 3) -> pd.DataFrame:
    """A reduced table with truth columns: values far off and exactly on the truth, NaN, a value that
    needs scientific notation, reasons with a comma and a quote."""
    rng = np.random.default_rng(seed)
    mu_v = 0.6 + 0.02 * rng.standard_normal(n)
    mu_v[::7] = 0.28  # off the truth: flagged
    mu_v[3] = math.nan
    u = np.full(n, 0.02)
    u[5] = 1.5e-17
    frame = pd.DataFrame({"mu_v": mu_v, "u_mu_v": u, "true_mu_v": np.full(n, 0.6), "count": np.arange(n),
                          "reason": ["" if i % 5 else f'clipped, "{i}" samples' for i in range(n)]},
                         index=pd.Index(np.arange(10, 10 + n), name="point"))
    frame.attrs["units"] = {c: "1" for c in frame.columns}
    return frame


def gathered(table: pd.DataFrame, path, sizes) -> FormattedRows:
    """The rows of ``table`` formatted chunk by chunk, as the workers do, in one file."""
    chunks, start = [], 0
    for size in sizes:
        chunks.append(with_z_max(table.iloc[start:start + size]))
        start += size
    path.write_bytes("".join(csv_rows(chunk) for chunk in chunks).encode())
    return FormattedRows(path, tuple(chunks[0].columns))


@pytest.mark.parametrize("sizes", [(40,), (1, 13, 26), (7, 7, 7, 7, 12)])
def test_reduced_csv_from_the_workers_rows_is_the_whole_tables_to_csv(tmp_path, sizes):
    table = reduced(40)
    rows = gathered(table, tmp_path / "rows", sizes)
    flagged = with_off_truth(table)
    assert flagged["off_truth"].sum() == 7  # points 10, 17, ..., 45 and 15 (its tiny u): the lines must get their flags
    assert flagged.columns[-2:].tolist() == ["z_max", "off_truth"]
    text = write_csv(flagged, tmp_path / "reduced.csv", rows).read_bytes()
    assert text == flagged.to_csv(index_label="point", lineterminator="\n").encode()


def test_rows_that_are_not_the_tables_fall_back_to_formatting_the_table(tmp_path):
    table = reduced(30)
    expected = with_off_truth(table).to_csv(index_label="point", lineterminator="\n").encode()
    short = gathered(table.iloc[:29], tmp_path / "short", (29,))  # one row missing (a chunk left out)
    long = gathered(pd.concat([table, table.iloc[:1]]), tmp_path / "long", (31,))  # one row too many
    other = FormattedRows(short.path, short.columns[:-1])  # other columns
    for k, rows in enumerate((short, long, other)):
        assert write_csv(with_off_truth(table), tmp_path / f"{k}.csv", rows).read_bytes() == expected, k


def test_a_value_with_a_line_break_gives_no_rows():
    table = reduced(6)
    assert csv_rows(table) is not None
    table.loc[12, "reason"] = "first line\nsecond line"
    assert csv_rows(table) is None
