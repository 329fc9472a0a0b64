"""Run a scene from a script and read a run folder back as pandas objects.

:func:`run` does what ``rig run SCENE -o FOLDER`` does (rig.runner.run_scene: the same log,
outputs, resume of an interrupted run and folder lock); :func:`open_run` reads a folder a run
wrote. A :class:`Run` reads its files when asked, once.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator, Mapping
from pathlib import Path

from rig.api.scene import Scene, load_scene
from rig.errors import ParameterError

LOG_GROUPS = ("settings", "readings", "calibration", "counters")
"""The columnar groups of a log that :attr:`Run.log` reads, one row per operating point."""

TABLE_FILES = ("reduced.csv", "characteristics.csv", "oscillation_sweep.csv")
"""The main result table of a stand, a contact-characteristics and an oscillation run."""


class LogGroups(Mapping):
    """The measurement groups of a run's log.h5 as DataFrames, read on first access.

    Keys are :data:`LOG_GROUPS`: ``settings`` (the operator's set-points), ``readings`` (scalar
    instrument readings), ``calibration`` (calibration records), ``counters`` (counter totals and
    gate time). Every frame has one row per operating point (index ``point``) and units in its
    column names (``F_N_N``, ``T2_N_m``, ``gate_time_s``; docs/log-format.md).
    """

    def __init__(self, log_path: Path) -> None:
        self._path = log_path
        self._frames: dict = {}

    def __getitem__(self, group: str):
        if group not in LOG_GROUPS:
            raise KeyError(group)
        if group not in self._frames:
            from rig.logbook import reader

            self._frames[group] = getattr(reader, f"read_{group}")(self._path)
        return self._frames[group]

    def __iter__(self) -> Iterator[str]:
        return iter(LOG_GROUPS)

    def __len__(self) -> int:
        return len(LOG_GROUPS)

    def __repr__(self) -> str:
        return f"<log groups {', '.join(LOG_GROUPS)} of {self._path}>"


class Run:
    """A run folder: its scene, result tables, log groups, summary and figure.

    Made by :func:`run` (after running) or :func:`open_run` (an existing folder). Files are read
    when an attribute is first used.

    Attributes
    ----------
    folder : pathlib.Path
        The run folder.
    report : rig.runner.RunReport or None
        What :func:`run` did (points planned, resumed, failed, damaged); None after :func:`open_run`.
    """

    def __init__(self, folder: str | Path, scene: Scene | None = None, report=None) -> None:
        self.folder = Path(folder)
        self.report = report
        self._scene = scene
        if not self.folder.is_dir():
            raise ParameterError("run folder", str(self.folder), "an existing folder written by rig run")
        if not any((self.folder / name).is_file() for name in ("log.h5", "summary.txt", *TABLE_FILES)):
            raise ParameterError("run folder", str(self.folder),
                                 "a folder written by rig run (log.h5, summary.txt, a result table)")

    def __repr__(self) -> str:
        return f"<rig.Run {str(self.folder)!r}>"

    @property
    def log_path(self) -> Path:
        """The measurement log, ``folder/log.h5`` (pathlib.Path; stand runs only)."""
        return self.folder / "log.h5"

    def _need_log(self) -> Path:
        if not self.log_path.is_file():
            raise ParameterError("run folder", str(self.folder),
                                 "a stand run's folder with log.h5 (contact-characteristics and oscillation "
                                 "runs write no log: see Run.table)")
        return self.log_path

    @functools.cached_property
    def scene(self) -> Scene | None:
        """The scene the run ran (Scene; from the log for a stand run, named after the folder).

        None for an opened contact-characteristics or oscillation folder (they store no scene).
        """
        if self._scene is not None:
            return self._scene
        if not self.log_path.is_file():
            return None
        from rig.logbook import read_metadata

        return Scene.from_toml(read_metadata(self.log_path).scene_toml, name=self.folder.name)

    @functools.cached_property
    def reduced(self):
        """The reduction, one row per operating point (pandas.DataFrame, index ``point``).

        The columns of reduced.csv: ``l_over_a``, ``c_over_a`` [1], ``mu_v``, ``mu_T`` [1] (eqs.
        (29)-(36)), each with its standard uncertainty ``u_<name>`` and the simulation's
        ``true_<name>``; other columns carry their unit in the name. ``attrs["units"]`` maps
        every column to its unit ("1": dimensionless).

        Raises
        ------
        LogFormatError
            The log was not reduced (``[outputs] reduce = false``); ``rig reduce`` reduces it.
        """
        from rig.logbook import read_reduced

        return read_reduced(self._need_log())

    @functools.cached_property
    def truth(self):
        """What the simulation knew at each point (pandas.DataFrame, index ``point``).

        Columns ``<name>_<unit>`` (e.g. true l, c, mu, forces; docs/log-format.md).
        """
        from rig.logbook.truth import read_truth

        return read_truth(self._need_log())

    @functools.cached_property
    def log(self) -> LogGroups:
        """The log's measurement groups: a mapping group name -> pandas.DataFrame (:class:`LogGroups`)."""
        return LogGroups(self._need_log())

    def channels(self, point: int) -> dict:
        """The sampled channels of one operating point.

        Parameters
        ----------
        point : int
            The point's index (``run.reduced.index``).

        Returns
        -------
        dict of str to pandas.DataFrame
            Channel name -> samples, column ``time_s`` [s] and the value with its unit in the name.
        """
        from rig.logbook import read_channels

        return read_channels(self._need_log(), point)

    @functools.cached_property
    def table(self):
        """The run's main result table as written (pandas.DataFrame): reduced.csv for a stand run,
        characteristics.csv or oscillation_sweep.csv otherwise; units in the column names."""
        import pandas as pd

        for name in TABLE_FILES:
            if (self.folder / name).is_file():
                return pd.read_csv(self.folder / name)
        raise ParameterError("run folder", str(self.folder), "a folder with one of " + ", ".join(TABLE_FILES))

    @property
    def summary(self) -> str:
        """The text of summary.txt (str): points, failures, the reduction against the truth."""
        return (self.folder / "summary.txt").read_text(encoding="utf-8")

    def plot(self):
        """The reduced quantities with their uncertainties next to the truth, one panel each.

        Returns
        -------
        matplotlib.figure.Figure
            A new figure (no pyplot state, not shown; ``fig.savefig(path)`` saves it).

        Raises
        ------
        ParameterError
            The run has no reduced quantities to draw.
        """
        from rig.runner.figures import draw_reduced_vs_truth

        scene = self.scene
        validated = None if scene is None else scene.validated
        if validated is None or not hasattr(validated, "procedure"):
            raise ParameterError("run folder", str(self.folder), "a stand run (Run.plot draws the reduction)")
        figure = draw_reduced_vs_truth(self.reduced, validated.procedure.points(), validated.procedure,
                                       f"{scene.name}: {scene.description}")
        if figure is None:
            raise ParameterError("run folder", str(self.folder), "a run whose reduction has l/a, c/a, mu_v or mu_T")
        return figure

    def compare(self, digitised: str | Path, sidecar: str | Path | None = None, options=None):
        """Compare the run's result table with a digitised figure, as ``rig compare`` does.

        Parameters
        ----------
        digitised : str or pathlib.Path
            A WebPlotDigitizer CSV export (docs/compare.md).
        sidecar : str or pathlib.Path, optional
            Its TOML description (default: the export's name with suffix .toml).
        options : rig.compare.CompareOptions, optional
            Interpolation, model selection, x-shift tolerance.

        Returns
        -------
        pandas.DataFrame
            One row per dataset and model: RMSE, max |dev| and max relative deviation, in the
            units of the sidecar's y axis.
        """
        from rig.compare.comparison import compare_files
        from rig.compare.report import metrics_table

        result = next((self.folder / n for n in TABLE_FILES if (self.folder / n).is_file()), None)
        if result is None:
            raise ParameterError("run folder", str(self.folder), "a folder with one of " + ", ".join(TABLE_FILES))
        described, items = compare_files(result, digitised, sidecar, options)
        return metrics_table(described, items)


def run(scene: Scene | str | Path, folder: str | Path, *, jobs: int = 1, scheduler: str | None = None,
        progress: bool = False) -> Run:
    """Run a scene into a folder, as ``rig run SCENE -o FOLDER`` does.

    Running again into the same folder resumes an interrupted run (the points already in the log
    are kept); a folder another run holds is refused (a named error).

    Parameters
    ----------
    scene : Scene or str or pathlib.Path
        The scene, or a built-in name / scene file for :func:`load_scene`.
    folder : str or pathlib.Path
        The output folder (created if needed): log.h5, reduced.csv, figures, summary.txt.
    jobs : int, optional
        Worker processes for a stand scene's points (default 1); results do not depend on it. Each
        worker starts by importing the calling script, so a script with ``jobs`` > 1 keeps its run
        under ``if __name__ == "__main__":``.
    scheduler : str, optional
        Address of a Dask scheduler to run the points on (extra ``dask``; with ``jobs=1``).
    progress : bool, optional
        Show a progress bar (default False).

    Returns
    -------
    Run
        The folder, with :attr:`Run.report` saying which points failed or were damaged.

    Raises
    ------
    ParameterError
        Bad ``jobs``/``scheduler``, a folder that cannot be written or is held by another run.
    """
    if not isinstance(scene, Scene):
        scene = load_scene(scene)
    from rig.runner import run_scene

    report = run_scene(scene.validated, Path(folder), jobs=jobs, scheduler=scheduler, progress=progress)
    return Run(report.out_dir, scene, report)


def open_run(folder: str | Path) -> Run:
    """An existing run folder (written by ``rig run`` or :func:`run`).

    Parameters
    ----------
    folder : str or pathlib.Path
        The run folder.

    Returns
    -------
    Run
        Its scene, tables and log, read when first used.

    Raises
    ------
    ParameterError
        ``folder`` is not a folder a run wrote.
    """
    return Run(folder)
