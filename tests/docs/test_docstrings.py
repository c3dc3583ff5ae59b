"""The API reference's parameter tables, checked against the code.

The reference (docs/pages/reference/, mkdocstrings) builds each function's table of parameters
from its numpy-style docstring, as griffe parses it, and its "Default" column from what griffe
derives: the value after ``default:`` in the type, else the first of a ``{"a", "b"}`` choice list
(numpydoc's rule: the default comes first), else the signature's default of the FIRST name of
the entry (so ``a, b : float`` gives ``b`` the default of ``a``). This test loads the package as
the reference does (griffe, numpy docstrings, no inspection) and, for every public function,
method and constructor reachable from the public modules (each module's ``__all__``, or its
public members where it has none, aliases followed to their targets), requires:

1. a docstring with a Parameters section naming every parameter of the signature but ``self``
   and ``cls`` (``*args`` and ``**kwargs`` with or without their stars). A dataclass may name its
   fields in an Attributes section instead, as the records do.
2. no documented parameter that the signature lacks.
3. the docstring-derived default equal to the signature's: both absent, or both present and of
   equal value. Values are compared as Python literals; a signature default that is an
   expression (``_LIGHT["diffuse"]``, a native default) is evaluated in its module, and one that
   names a private object must be stated in the docstring (``default: (1.0, 1.0, 1.0, 1.0)``),
   since the reference would otherwise show the private expression.
"""

from __future__ import annotations

import ast
import importlib
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from conftest import require

griffe: Any = require("griffe")

ROOT = Path(__file__).resolve().parents[2]

# The public modules, as the API reference shows them.
MODULES = (
    "glshade",
    "glshade.presets",
    "glshade.meshes",
    "glshade.glsl",
    "glshade.dask",
    "glshade.lab.report",
    "glshade.lab.studies",
    "glshade.lab.timing",
    "glshade.lab.machine",
)

PARAMETER_SECTIONS = {"parameters", "other parameters"}
VARIADIC = {"variadic positional": "*", "variadic keyword": "**"}


@dataclass(frozen=True)
class Entry:
    """One documented callable: its public name (how a user reaches it) and griffe's object."""

    public: str
    obj: Any

    @property
    def name(self) -> str:
        path = self.obj.path
        return self.public if path == self.public else f"{self.public} ({path})"


def _load() -> Any:
    return griffe.load(
        "glshade",
        search_paths=[str(ROOT / "python")],
        docstring_parser="numpy",
        allow_inspection=False,
    )


def _resolved(obj: Any) -> Any:
    return obj.final_target if obj.is_alias else obj


def _public_names(module: Any) -> list[str]:
    """The module's ``__all__``, or its public members where it has none; imported names from
    outside glshade (``np``, ``annotations``) are not members of its API."""
    if module.exports is not None:
        return [str(name) for name in module.exports]
    return [
        name
        for name, member in module.members.items()
        if not name.startswith("_")
        and not (member.is_alias and not member.target_path.startswith("glshade"))
    ]


def _entries() -> Iterator[Entry]:
    package = _load()
    seen: set[str] = set()
    for module_path in MODULES:
        module = package if module_path == "glshade" else package[module_path.split(".", 1)[1]]
        for name in _public_names(module):
            if name.startswith("__"):  # __version__: a string from the native module
                continue
            obj = _resolved(module.members[name])
            public = f"{module_path}.{name}"
            if obj.is_function and obj.path not in seen:
                seen.add(obj.path)
                yield Entry(public, obj)
            elif obj.is_class and obj.path not in seen:
                seen.add(obj.path)
                yield Entry(public, obj)
                for member_name, member in obj.all_members.items():
                    if member_name.startswith("_"):
                        continue
                    method = _resolved(member)
                    if method.is_function and "property" not in method.labels:
                        if method.path not in seen:
                            seen.add(method.path)
                            yield Entry(f"{public}.{member_name}", method)


ENTRIES = list(_entries())


def _sections(entry: Entry) -> list[Any]:
    """The parsed docstring sections the reference shows: a class's own and its ``__init__``'s
    (mkdocstrings merges the two)."""
    obj = entry.obj
    docstrings = [obj.docstring]
    if obj.is_class and "__init__" in obj.members:
        docstrings.append(obj.members["__init__"].docstring)
    return [section for d in docstrings if d is not None for section in d.parsed]


def _signature(entry: Entry) -> dict[str, Any]:
    """The signature's parameters but self and cls, by name."""
    return {p.name: p for p in entry.obj.parameters if p.name not in ("self", "cls")}


def _documented(entry: Entry) -> dict[str, Any]:
    """Documented parameters by name (stars dropped), from the Parameters sections."""
    return {
        p.name.lstrip("*"): p
        for section in _sections(entry)
        if section.kind.value in PARAMETER_SECTIONS
        for p in section.value
    }


def _attributes(entry: Entry) -> set[str]:
    """Names of an Attributes section (``a, b : type`` names two)."""
    return {
        name.strip()
        for section in _sections(entry)
        if section.kind.value == "attributes"
        for attribute in section.value
        for name in attribute.name.split(",")
    }


def _private_names(expression: str) -> list[str]:
    try:
        tree = ast.parse(expression, mode="eval")
    except SyntaxError:
        return []
    return [node.id for node in ast.walk(tree) if isinstance(node, ast.Name) and node.id[0] == "_"]


def _value(expression: str, module: str | None) -> tuple[bool, Any]:
    """(True, value) of a literal, or of an expression evaluated in `module`; (False, text) for
    anything else (a docstring's words, an expression that does not evaluate)."""
    if expression in ("inf", "-inf"):  # how numpy and the reference print an infinite default
        return True, float(expression)
    try:
        return True, ast.literal_eval(expression)
    except (ValueError, SyntaxError, TypeError, MemoryError, RecursionError):
        pass
    if module is not None:
        try:
            namespace = vars(importlib.import_module(module))
            return True, eval(expression, dict(namespace))
        except Exception:
            pass
    return False, expression


def _same(a: Any, b: Any) -> bool:
    """Equal values, a sequence equal to a sequence of equal items, and bools only to bools."""
    if isinstance(a, list | tuple) and isinstance(b, list | tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, bool) or isinstance(b, bool):
        return type(a) is type(b) and a == b
    try:
        return bool(a == b)
    except Exception:
        return False


def _ids(entries: list[Entry]) -> list[str]:
    return [e.public for e in entries]


def test_the_walk_reaches_the_public_api() -> None:
    """The walk sees functions, classes, methods and the lab: a broken walk would pass all."""
    found = {e.public for e in ENTRIES}
    for name in (
        "glshade.shade",
        "glshade.Scene",
        "glshade.Scene.plan",
        "glshade.Camera.look_at",
        "glshade.presets.learnopengl",
        "glshade.meshes.torus",
        "glshade.glsl.render",
        "glshade.dask.shade_mesh",
        "glshade.Report.write",
        "glshade.lab.timing.ratio",
        "glshade.lab.machine.describe",
    ):
        assert name in found, f"{name} is not among the {len(found)} callables found"


@pytest.mark.parametrize("entry", ENTRIES, ids=_ids(ENTRIES))
def test_every_parameter_is_documented(entry: Entry) -> None:
    signature = _signature(entry)
    if not signature:
        return
    documented = _documented(entry)
    dataclass_fields = _attributes(entry) if "dataclass" in entry.obj.labels else set()
    if not documented and not dataclass_fields:
        has_docstring = entry.obj.docstring is not None
        pytest.fail(
            f"{entry.name}: "
            + ("no Parameters section" if has_docstring else "no docstring")
            + f" for its parameters {', '.join(signature)}",
            pytrace=False,
        )
    missing = [
        VARIADIC.get(p.kind.value, "") + name
        for name, p in signature.items()
        if name not in documented and name not in dataclass_fields
    ]
    assert not missing, f"{entry.name}: parameters missing from the docstring: {missing}"


@pytest.mark.parametrize("entry", ENTRIES, ids=_ids(ENTRIES))
def test_every_documented_parameter_exists(entry: Entry) -> None:
    signature = _signature(entry)
    extra = [name for name in _documented(entry) if name not in signature]
    assert not extra, (
        f"{entry.name}: the docstring documents parameters the signature lacks: {extra} "
        f"(the signature has {list(signature)})"
    )


@pytest.mark.parametrize("entry", ENTRIES, ids=_ids(ENTRIES))
def test_documented_defaults_are_the_signatures(entry: Entry) -> None:
    signature = _signature(entry)
    module = entry.obj.module.path
    problems = []
    for name, documented in _documented(entry).items():
        parameter = signature.get(name)
        if parameter is None or parameter.kind.value in VARIADIC:
            continue
        shown = None if documented.default is None else str(documented.default)
        actual = None if parameter.default is None else str(parameter.default)
        where = f"{entry.name}, parameter {name!r}"
        if shown is None or actual is None:
            if shown != actual:
                problems.append(
                    f"{where}: the docstring's default is "
                    f"{'none (required)' if shown is None else shown}, the signature's "
                    f"{'none (required)' if actual is None else actual}"
                )
            continue
        if shown == actual and _private_names(actual):
            problems.append(
                f"{where}: the reference would show the signature's expression {actual}; "
                f"state its value in the docstring (``type, default: value``)"
            )
            continue
        ok_shown, shown_value = _value(shown, None)
        ok_actual, actual_value = _value(actual, module)
        if ok_shown and ok_actual:
            same = _same(shown_value, actual_value)
        else:
            same = shown.replace('"', "'") == actual.replace('"', "'")
        if not same:
            value = f" = {actual_value!r}" if ok_actual and repr(actual_value) != actual else ""
            problems.append(
                f"{where}: the docstring's default is {shown}, the signature's {actual}{value}"
            )
    assert not problems, "\n".join(problems)
