"""Every public name of the API reference has a numpydoc docstring.

The public names are the ``__all__`` lists of rig and of the packages the reference documents.
A function (or a method of the script API's classes) that takes arguments has a ``Parameters``
section and one that returns something a ``Returns`` section; a class or a module has a docstring.
"""

from __future__ import annotations

import importlib
import inspect

import pytest

DOCUMENTED = ("rig", "rig.contact", "rig.stands", "rig.reduction", "rig.compare", "rig.fit", "sensors")
SCRIPT_API_CLASSES = ("Scene", "Run")


def _public(module_name: str):
    module = importlib.import_module(module_name)
    assert module.__all__, module_name
    return [(f"{module_name}.{name}", getattr(module, name, None) or importlib.import_module(f"{module_name}.{name}"))
            for name in module.__all__]  # a name of __all__ may be a submodule (rig.reduction)


def _missing_sections(function) -> list[str]:
    doc = inspect.getdoc(function) or ""
    signature = inspect.signature(function)
    takes = [p for p in signature.parameters.values() if p.name not in ("self", "cls")]
    gives = signature.return_annotation not in (inspect.Signature.empty, None, "None")
    needed = (["Parameters"] if takes else []) + (["Returns"] if gives else [])
    return [section for section in needed if f"{section}\n{'-' * len(section)}" not in doc]


PUBLIC = [item for name in DOCUMENTED for item in _public(name)]


@pytest.mark.parametrize(("name", "obj"), PUBLIC, ids=[name for name, _ in PUBLIC])
def test_public_name_has_a_numpydoc_docstring(name, obj):
    if not (inspect.isfunction(obj) or inspect.isclass(obj) or inspect.ismodule(obj)):
        pytest.skip("data: documented by the attribute's docstring in the source")
    doc = inspect.getdoc(obj)
    assert doc and doc.strip(), f"{name} has no docstring"
    if inspect.isfunction(obj):
        assert _missing_sections(obj) == [], f"{name} lacks numpydoc sections"


@pytest.mark.parametrize("class_name", SCRIPT_API_CLASSES)
def test_script_api_methods_have_numpydoc_sections(class_name):
    cls = getattr(importlib.import_module("rig"), class_name)
    for name, member in vars(cls).items():
        if name.startswith("_"):
            continue
        function = member.__func__ if isinstance(member, (classmethod, staticmethod)) else member
        if inspect.isfunction(function):
            assert _missing_sections(function) == [], f"rig.{class_name}.{name} lacks numpydoc sections"
        else:  # a property: its own docstring
            assert inspect.getdoc(member), f"rig.{class_name}.{name} has no docstring"
