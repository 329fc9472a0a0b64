"""The command starts without the heavy libraries, lists every subcommand by its own help, and names
the extra the lab needs. (The start-up CPU time is measured by benchmarks/bench_startup.py, not here.)"""

from __future__ import annotations

import argparse
import importlib
import subprocess
import sys

import pytest

from rig.cli import SUBCOMMAND_HELP

HEAVY = ("pandas", "matplotlib", "scipy", "h5py", "simpy", "numba", "flask")


def _imported_by(argv: list[str], prelude: str = "") -> tuple[list[str], subprocess.CompletedProcess]:
    probe = (f"import sys\n{prelude}from rig.cli import main\ncode = main({argv!r})\n"
             f"print('HEAVY', sorted(m for m in {HEAVY!r} if m in sys.modules))\nsys.exit(code)")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    line = next(line for line in done.stdout.splitlines() if line.startswith("HEAVY "))
    return eval(line[len("HEAVY "):]), done  # noqa: S307 - our own probe's printed list


@pytest.mark.parametrize("argv", [[], ["scenes"]])
def test_help_and_scenes_import_no_heavy_library(argv):
    heavy, done = _imported_by(argv)
    assert done.returncode == 0, done.stderr
    assert heavy == []
    assert ("default" in done.stdout) if argv else all(name in done.stdout for name in SUBCOMMAND_HELP)


class _Recorder:
    """Stands in for argparse's subparsers: keeps the help each subcommand module registers."""

    def __init__(self) -> None:
        self.help: dict[str, str] = {}

    def add_parser(self, name: str, **options) -> argparse.ArgumentParser:
        self.help[name] = options["help"]
        return argparse.ArgumentParser(prog=f"rig {name}")


def test_the_listed_help_is_each_subcommands_own():
    recorder = _Recorder()
    for name in SUBCOMMAND_HELP:
        importlib.import_module(f"rig.cli.{name}").add_parser(recorder)
    assert recorder.help == SUBCOMMAND_HELP


def test_rig_lab_without_flask_names_the_extra():
    blocked = "for name in ('flask', 'werkzeug', 'werkzeug.serving'):\n    sys.modules[name] = None\n"
    probe = f"import sys\n{blocked}from rig.cli import main\nsys.exit(main(['lab', '--no-browser']))"
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=120)
    assert done.returncode == 2
    assert done.stderr.splitlines() == ['rig lab: error: rig lab needs Flask, which is not installed: '
                                        'pip install "friction-rig[lab]"']


def test_import_rig_is_cheap_until_a_name_is_used():
    probe = (f"import sys, rig\nbefore = sorted(m for m in {HEAVY!r} if m in sys.modules)\n"
             "rig.list_scenes\nprint(before, 'pandas' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True, timeout=120)
    assert done.stdout.strip() == "[] True"  # the API's names load the package when first used
