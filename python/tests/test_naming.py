"""The naming contract (docs/naming.md): every public type of the core is listed, each Python name
in it exists, each exemption gives its reason, and the argument orders of the Python binding are
the core's. The JavaScript half is web/tests/naming.test.mjs (it reads the same tables)."""

from __future__ import annotations

import dataclasses
import inspect
import re
import sys
from pathlib import Path

import poinsot
import pytest
from poinsot import _core

ROOT = Path(__file__).resolve().parents[2]
CORE = ROOT / "crates" / "poinsot" / "src"
DOC = ROOT / "docs" / "naming.md"


def _table(title: str) -> list[list[str]]:
    """The rows of the markdown table under the heading ``## title`` (cells stripped of
    backticks), header and rule excluded."""
    text = DOC.read_text(encoding="utf-8")
    section = text.split(f"## {title}\n", 1)[1].split("\n## ", 1)[0]
    rows = [line for line in section.splitlines() if line.startswith("|")]
    return [[c.strip().replace("`", "") for c in row.strip("|").split("|")] for row in rows[2:]]


TYPES = _table("Types")
ORDERS = _table("Argument orders")


def core_public_types() -> dict[str, Path]:
    """Every ``pub struct``, ``pub enum`` and ``pub trait`` of the core crate (not ``pub(crate)``,
    not the doctest-only README holder), by name."""
    found: dict[str, Path] = {}
    pattern = re.compile(r"^pub (?:struct|enum|trait) ([A-Z][A-Za-z0-9]*)", re.M)
    for path in sorted(CORE.rglob("*.rs")):
        text = path.read_text(encoding="utf-8")
        for m in pattern.finditer(text):
            attributes = []
            for line in reversed(text[: m.start()].rstrip().splitlines()):
                if not line.startswith("#["):
                    break
                attributes.append(line)
            if any("cfg(doctest)" in a for a in attributes):
                continue
            found[m.group(1)] = path
    return found


def resolve_python(name: str) -> object:
    """``poinsot.<name>`` along its dots; a dataclass field counts as an attribute."""
    obj: object = poinsot
    for part in name.split("."):
        if hasattr(obj, part):
            obj = getattr(obj, part)
        elif dataclasses.is_dataclass(obj) and part in {f.name for f in dataclasses.fields(obj)}:
            obj = part
        else:
            raise AttributeError(f"{name}: {obj!r} has no {part!r}")
    return obj


def test_every_public_core_type_is_listed_once() -> None:
    listed = [row[0] for row in TYPES]
    assert len(listed) == len(set(listed)), sorted(n for n in listed if listed.count(n) > 1)
    core = core_public_types()
    assert len(core) > 50  # the scan found the crate
    missing = sorted(set(core) - set(listed))
    stale = sorted(set(listed) - set(core))
    assert not missing, f"public core types missing from docs/naming.md: {missing}"
    assert not stale, f"docs/naming.md lists types the core does not have: {stale}"


@pytest.mark.parametrize("row", TYPES, ids=[row[0] for row in TYPES])
def test_each_python_name_exists_or_is_exempt_with_a_reason(row: list[str]) -> None:
    core, python, javascript, notes = row
    if python == "—":
        assert notes, f"{core}: not in Python, and no reason given"
    else:
        resolve_python(python)
    if javascript == "—":
        assert notes, f"{core}: not in JavaScript, and no reason given"


def test_resolution_can_fail() -> None:
    # Negative control: a misspelt name is refused.
    with pytest.raises(AttributeError):
        resolve_python("HeavyTop.motionClass")


def _rust_params(signature: str) -> list[str]:
    """Parameter names of a core function, ``Type::name``, read from its source; a parameter of
    type ``EulerState`` stands for that struct's fields in order."""
    if "(" in signature:  # written out in the table
        typ, rest = signature.split("::", 1)
        fname, args = rest.split("(", 1)
        names = [a.strip() for a in args.rstrip(")").split(",")]
    else:
        typ, fname = signature.split("::")
        names = []
    path = core_public_types()[typ]
    src = path.read_text(encoding="utf-8")
    impl = re.search(rf"^impl(?:<[^>]*>)? {typ}\b[^{{]*{{", src, re.M)
    assert impl, f"{signature}: no impl {typ} in {path}"
    m = re.compile(rf"pub fn {fname}\s*\((.*?)\)\s*->", re.S).search(src, impl.end())
    assert m, f"{signature}: no pub fn {fname} in {path}"
    params = [p.split(":")[0].strip() for p in m.group(1).split(",") if ":" in p]
    types = [p.split(":")[1].strip() for p in m.group(1).split(",") if ":" in p]
    if names:
        assert names == params, f"{signature}: the table says {names}, the source {params}"
    out: list[str] = []
    for p, t in zip(params, types):
        if t == "EulerState":
            state_src = core_public_types()["EulerState"].read_text(encoding="utf-8")
            body = state_src.split("pub struct EulerState {", 1)[1].split("}", 1)[0]
            out += re.findall(r"pub (\w+):", body)
        else:
            out.append(p)
    return out


def _python_params(name: str) -> list[inspect.Parameter]:
    obj: object = _core
    for part in name.split("."):
        obj = getattr(obj, part)
    params = list(inspect.signature(obj).parameters.values())  # type: ignore[arg-type]
    # A method of a binding class (``RigidEarthCore.averaged_pole``), read unbound: its receiver
    # is not one of the core's parameters.
    return [p for p in params if p.name != "self"]


def _norm(name: str) -> str:
    return name.replace("_", "").lower()


BINDING = ROOT / "crates" / "poinsot-py" / "src"


def _binding_groups(python: str) -> dict[str, list[str]]:
    """The parameters of the ``_core`` function ``python`` that carry several of the core's
    arguments as one tuple (the heavy top's ``top`` = (I1, I3, mgl)), each with the names its
    binding unpacks it into, in order, read from the binding's source: ``let ((i1, i3, mgl),
    [phi, …]) = (top, state);`` in the body of that function."""
    cls, _, method = python.rpartition(".")
    for path in sorted(BINDING.glob("*.rs")):
        src = path.read_text(encoding="utf-8")
        if cls and f'name = "{cls}"' not in src:
            continue
        m = re.search(rf"fn {method}\(.*?\n    }}\n", src, re.S)
        if not m:
            continue
        let = re.search(r"let (\(.*?\)) = \(([\w, ]+)\);", m.group(0), re.S)
        if not let:
            return {}
        pattern, names = let.group(1)[1:-1], [n.strip() for n in let.group(2).split(",")]
        groups, depth, start = [], 0, 0
        for i, ch in enumerate(pattern + ","):
            depth += 1 if ch in "([" else -1 if ch in ")]" else 0
            if ch == "," and depth == 0:
                groups.append(re.findall(r"\w+", pattern[start:i]))
                start = i + 1
        assert len(groups) == len(names), f"{python}: {pattern} vs {names}"
        return dict(zip(names, groups))
    return {}


@pytest.mark.parametrize("row", ORDERS, ids=[row[0] for row in ORDERS])
def test_python_binding_takes_the_core_order(row: list[str]) -> None:
    core, python, _ = row
    want = [_norm(p) for p in _rust_params(core)]
    params = _python_params(python)
    # A tuple parameter stands for the core's arguments its binding unpacks it into, in order.
    groups = _binding_groups(python)
    got = [_norm(n) for n in _flat(params, groups)]
    # The binding may add trailing optional parameters; those it shares come in the same order.
    assert got[: len(want)] == want, f"{python}{got} vs {core}{want}"
    shared = next(i for i in range(len(params) + 1) if len(_flat(params[:i], groups)) >= len(want))
    assert all(p.default is not inspect.Parameter.empty for p in params[shared:])


def _flat(params: list[inspect.Parameter], groups: dict[str, list[str]]) -> list[str]:
    return [n for p in params for n in groups.get(p.name, [p.name])]


def test_tuple_parameters_are_read_from_the_binding(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The heavy top's binding takes (I1, I3, mgl) and the state as tuples; the order check
    above expands them from the binding's own unpacking. Negative control: the same source with
    I1 and I3 unpacked the other way round fails the check."""
    groups = _binding_groups("HeavyTopCore.from_constants")
    assert groups == {"top": ["i1", "i3", "mgl"], "constants": ["p_phi", "p_psi", "energy"]}
    src = (BINDING / "heavy_top.rs").read_text(encoding="utf-8")
    swapped = src.replace("let ((i1, i3, mgl), (p_phi", "let ((i3, i1, mgl), (p_phi")
    assert swapped != src
    (tmp_path / "heavy_top.rs").write_text(swapped, encoding="utf-8")
    monkeypatch.setattr(sys.modules[__name__], "BINDING", tmp_path)
    row = next(r for r in ORDERS if r[1] == "HeavyTopCore.from_constants")
    with pytest.raises(AssertionError, match="from_constants"):
        test_python_binding_takes_the_core_order(row)
