"""What ``rig fit`` checks before it loads or solves anything: the file, its kind, the grid.

Every check here reads at most the first bytes of DATA and its neighbours (a sidecar, a log
beside a reduced.csv); a failure is a :class:`DataFileError` (a ParameterError naming DATA, the
file and what a fit needs), printed by the CLI as one line with exit status 2.

Kinds (:func:`data_kind`), each loaded by its own function in rig.fit.data:
* ``"digitised"``: a WebPlotDigitizer CSV with its TOML sidecar (given, or DATA.toml beside it);
* ``"log"``: an HDF5 measurement log (``log.h5``) of a stand run;
* ``"reduced"``: a stand run's ``reduced.csv`` with its ``log.h5`` beside it.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

from rig import validate
from rig.errors import ParameterError

HDF5_SIGNATURE = b"\x89HDF\r\n\x1a\n"
SNIFF_BYTES = 65536  # bytes read to tell text from binary
MAX_CSV_BYTES = 1 << 30  # 1 GiB of CSV (~1e7 reduced rows): the fit's memory is O(rows), refused beyond
GRID_N_RANGE = (4, 512)  # cells across 2a of the contact grid (rig.contact.solve's range)


class DataFileError(ParameterError):
    """DATA is not a file a fit can read: names the file, what is wrong and what a fit needs."""

    def __init__(self, path: Path, problem: str, valid: str) -> None:
        super().__init__("DATA", str(path), valid, hint=problem)
        self.problem = problem


def check_grid(n: object) -> int | None:
    """--n: None (the scene's grid, 16 for a digitised curve) or an integer in GRID_N_RANGE."""
    return None if n is None else validate.integer("n", n, *GRID_N_RANGE)


def _sniff_text(path: Path, what: str) -> str:
    """The first SNIFF_BYTES of a text file as text; DataFileError when empty, binary or not UTF-8."""
    size = path.stat().st_size
    if size == 0:
        raise DataFileError(path, "an empty file", f"a {what} with a header and data rows")
    with path.open("rb") as handle:
        head = handle.read(SNIFF_BYTES)
    if head.startswith(HDF5_SIGNATURE):
        raise DataFileError(path, "an HDF5 file named .csv", f"a {what} (text), or pass the log as log.h5")
    if b"\x00" in head:
        raise DataFileError(path, "binary, not text", f"a {what} (UTF-8 text)")
    try:
        text = head.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        if error.start < len(head) - 4:  # not a multi-byte character cut by the sniff's end
            raise DataFileError(path, f"not UTF-8 text: byte 0x{head[error.start]:02x} at offset {error.start}",
                                f"a {what} (UTF-8 text)") from None
        text = head[: error.start].decode("utf-8-sig")
    if not text.strip():
        raise DataFileError(path, "blank (no characters but white space)", f"a {what} with a header and data rows")
    return text


def _is_sidecar(toml: Path) -> bool:
    try:
        return "datasets" in tomllib.loads(toml.read_text(encoding="utf-8-sig"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError):
        return True  # let the sidecar reader name the syntax error


def data_kind(path: str | Path, sidecar: str | Path | None = None) -> str:
    """"digitised", "log" or "reduced" for DATA, from its name, first bytes and neighbours (module docstring)."""
    path = Path(path)
    if not path.exists():
        raise DataFileError(path, "no such file", "an existing log.h5, reduced.csv or digitised .csv")
    if not path.is_file():
        raise DataFileError(path, "a folder, not a file", "a log.h5, a reduced.csv or a digitised .csv")
    if path.suffix in (".h5", ".hdf5"):
        with path.open("rb") as handle:
            head = handle.read(len(HDF5_SIGNATURE))
        if head != HDF5_SIGNATURE:
            problem = "an empty file" if not head else "not an HDF5 file (its first bytes are not HDF5's signature)"
            raise DataFileError(path, problem, "a measurement log written by rig run")
        if sidecar is not None:
            raise ParameterError("sidecar", str(sidecar), "none for a measurement log (its scene states the conditions)")
        return "log"
    if path.suffix != ".csv":
        raise DataFileError(path, f"suffix {path.suffix or '(none)'!r}", "a log.h5, a reduced.csv or a digitised .csv")
    size = path.stat().st_size
    if size > MAX_CSV_BYTES:
        raise DataFileError(path, f"{size / 2**20:.0f} MiB", f"a CSV of at most {MAX_CSV_BYTES >> 20} MiB "
                            "(split the data, or fit a subset)")
    toml = Path(sidecar) if sidecar is not None else path.with_suffix(".toml")
    log = path.with_name("log.h5")
    if sidecar is not None or (toml.is_file() and _is_sidecar(toml)):
        if sidecar is not None and not toml.is_file():
            raise ParameterError("sidecar", str(toml), "an existing TOML sidecar")
        _sniff_text(path, "digitised CSV")
        return "digitised"
    if log.is_file():
        _sniff_text(path, "reduced.csv")
        return "reduced"
    raise DataFileError(path, f"neither a sidecar {toml.name} nor a log.h5 beside it",
                        "a digitised .csv with its TOML sidecar (--sidecar), or a reduced.csv in its run's folder "
                        "beside log.h5")
