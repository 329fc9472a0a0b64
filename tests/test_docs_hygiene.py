"""Docs hygiene over the tracked files: citations by key, no paths of a machine, no history markers.

The project cites its sources as [Koziarski], [Zhao], [Oscillating] and its own Equations and Hard cases pages
(docs/equations.md, docs/hard-cases.md). A tracked file must not name the source documents by the numbers or paths
they had where the project was started, nor a folder outside the repository, nor a branch that is not in it; user
documentation (docs/*.md, README.md) and docstrings carry no commit ids (CHANGELOG.md may). Skips cleanly when the
tree is not a git checkout (an installed package, an sdist).
"""

from __future__ import annotations

import ast
import re
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
THIS = Path(__file__).resolve()

FORBIDDEN = re.compile(r"seed 00|seed notes|seed-notes|\.\./shared", re.IGNORECASE)
MACHINE_PATH = re.compile(r"(?<![\w.~-])/(?:work|root|home)/")
TMP_PATH = re.compile(r"(?<![\w.~-])/tmp/")
# Branches some history mentioned that are not in the repository: a study on them cannot be reproduced.
GONE_BRANCHES = re.compile(r"(?<![\w-])(?:h-slip|h-prof|h-layer|h-growth|calib)(?![\w-])")
# A commit id: 7-40 hex digits with at least one letter and one digit, not part of a number or a word.
COMMIT_ID = re.compile(r"(?<![\w.])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}(?![\w.])")
# Hex ids that are not commits of this repository: the version of Vollebregt's CONTACT program the reference
# tables were made with (docs/examples/exact_pure_spin_circle.toml says how).
NOT_OUR_COMMITS = {"d431cdbd"}


def _tracked() -> list[Path]:
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout: the tracked files are not known")
    listed = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, check=True).stdout
    return [ROOT / name for name in listed.decode().split("\0") if name]


def _text(path: Path) -> str | None:
    try:
        raw = path.read_bytes()
    except OSError:  # listed but deleted in the work tree
        return None
    if b"\0" in raw:
        return None
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return None


def _texts():
    for path in _tracked():
        if path.resolve() == THIS:
            continue
        text = _text(path)
        if text is not None:
            yield path, text


def _hits(pattern: re.Pattern, path: Path, text: str) -> list[str]:
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        if pattern.search(line):
            found.append(f"{path.relative_to(ROOT)}:{number}: {line.strip()[:120]}")
    return found


def _docstrings(text: str) -> str:
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return ""
    nodes = [tree] + [n for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef))]
    return "\n".join(doc for doc in (ast.get_docstring(n, clean=False) for n in nodes) if doc)


def _user_docs(path: Path) -> bool:
    relative = path.relative_to(ROOT)
    return relative.as_posix() == "README.md" or (relative.parts[0] == "docs" and path.suffix == ".md")


def test_sources_are_cited_by_key_not_by_seed_number_or_shared_path():
    hits = [hit for path, text in _texts() for hit in _hits(FORBIDDEN, path, text)]
    assert not hits, "cite [Koziarski]/[Zhao]/[Oscillating] or 'Equations §N' instead:\n" + "\n".join(hits)


def test_no_absolute_path_of_a_machine():
    hits = [hit for path, text in _texts() for hit in _hits(MACHINE_PATH, path, text)]
    hits += [hit for path, text in _texts() if _user_docs(path) for hit in _hits(TMP_PATH, path, text)]
    assert not hits, "use a path relative to the repository or out/:\n" + "\n".join(hits)


def test_no_branch_that_is_not_in_the_repository():
    hits = [hit for path, text in _texts() for hit in _hits(GONE_BRANCHES, path, text)]
    assert not hits, "say what the variant did, or that it is not reproducible:\n" + "\n".join(hits)


def _commit_ids(line: str) -> bool:
    return any(token not in NOT_OUR_COMMITS for token in COMMIT_ID.findall(line))


def test_no_commit_id_in_user_docs_or_docstrings():
    class _Ids:
        search = staticmethod(_commit_ids)

    hits = []
    for path, text in _texts():
        if path.name == "CHANGELOG.md":
            continue
        if _user_docs(path):
            hits += _hits(_Ids, path, text)
        elif path.suffix == ".py":
            hits += _hits(_Ids, path, _docstrings(text))
    assert not hits, "history (commit ids) belongs in CHANGELOG.md:\n" + "\n".join(hits)


def test_the_patterns_catch_what_they_are_for():
    # The checks above pass on a clean tree; these cases show that each pattern can fail.
    assert FORBIDDEN.search("as in Seed 000 eq. (21)") and FORBIDDEN.search("see ../shared/spec/x.md")
    assert not FORBIDDEN.search("rng seed 42, [Koziarski] eq. (21)")
    assert MACHINE_PATH.search("python /work/main/x.py") and not MACHINE_PATH.search("out/work/x")
    assert GONE_BRANCHES.search("on branch h-slip") and not GONE_BRANCHES.search("calibration, h-slipping")
    assert _commit_ids("fixed in c253507") and _commit_ids("main 9f2f2bd4e1")
    assert not _commit_ids("nu = 0.0386564, 1000000 points, deadbeef, CONTACT d431cdbd")
