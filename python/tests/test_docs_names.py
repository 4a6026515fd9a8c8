"""Docs promise only what the code has (issue 21, item 14: ``FreeRigidBody.max_time`` was
documented but missing): every ``ClassName.attribute`` cited in backticks in ``docs/*.md``, the
README, ARCHITECTURE and CONVENTIONS, whose class is one of poinsot's public Python classes, is
an attribute of that class (a method, property, dataclass or named-tuple field, class constant).

Instance attributes set in ``__init__`` (``self.omega = ...``) count. The browser's names are
the wasm classes' (the functions of ``impl Class`` in ``crates/poinsot-wasm/src``): accepted in
the JavaScript column of a table and on the lab's page (docs/lab.md); camelCase names
(``flipInterval``) are not matched at all (``web/tests/naming.test.mjs`` checks those), nor a
``Rust::path``. Negative control: a made-up attribute of a real class is reported, a browser
name outside the browser's places is reported, one of an unknown class is not.
"""

from __future__ import annotations

import dataclasses
import inspect
import re
from pathlib import Path

import poinsot as ps
import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGES = sorted((ROOT / "docs").glob("*.md")) + [
    ROOT / name for name in ("README.md", "ARCHITECTURE.md", "CONVENTIONS.md")
]

#: ``ClassName.attribute`` at the start of a backticked span (``Screw.apply(x)`` included).
CITED = re.compile(r"`([A-Z][A-Za-z0-9]*)\.([a-z_][a-z0-9_]*)\b(?![A-Za-z0-9.])")


def public_classes() -> dict[str, type]:
    """poinsot's public classes by name: poinsot's and its public submodules' ``__all__``."""
    out: dict[str, type] = {}
    modules = [ps] + [
        getattr(ps, m) for m in ("special", "sweep", "rotation", "free") if hasattr(ps, m)
    ]
    for mod in modules:
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name, None)
            if inspect.isclass(obj):
                out[name] = obj
    return out


def has_attribute(cls: type, attr: str) -> bool:
    """``attr`` is on the class, or an instance field the class declares or sets."""
    if hasattr(cls, attr):
        return True
    if dataclasses.is_dataclass(cls) and attr in {f.name for f in dataclasses.fields(cls)}:
        return True
    if attr in getattr(cls, "_fields", ()):
        return True
    for k in cls.__mro__:
        if attr in getattr(k, "__annotations__", {}):
            return True
        try:
            src = inspect.getsource(k)
        except (OSError, TypeError):
            continue
        if re.search(rf"\bself\.{attr}\s*(:[^=\n]+)?=[^=]", src):
            return True
    return False


def wasm_names() -> dict[str, set[str]]:
    """The functions of each ``impl Class`` block of the wasm crate (Rust names), including the
    blocks a macro writes: an indented ``impl Class {`` in a ``macro_rules!`` takes the text up
    to the next block (the macro's invocation, with its entries' attributes), and
    ``calls!(Class::new {`` writes the constructor of ``Class``."""
    out: dict[str, set[str]] = {}
    for path in sorted((ROOT / "crates" / "poinsot-wasm" / "src").glob("*.rs")):
        text = path.read_text(encoding="utf-8")
        parts = re.split(r"^\s*impl (\w+) \{", text, flags=re.M)
        for cls_name, body in zip(parts[1::2], parts[2::2]):
            names = out.setdefault(cls_name, set())
            names.update(re.findall(r"pub fn (\w+)", body))
            if "wasm_bindgen(constructor)" in body:
                names.add("constructor")  # JavaScript's `new Class(...)`
        for cls_name in re.findall(r"^calls!\((\w+)::new \{", text, flags=re.M):
            out.setdefault(cls_name, set()).add("constructor")
    return out


def broken(
    text: str, classes: dict[str, type], browser: dict[str, set[str]] | None = None
) -> list[str]:
    """Cited attributes that the class lacks (``browser``: also accept the wasm class's)."""
    out = []
    for m in CITED.finditer(text):
        cls_name, attr = m.groups()
        if cls_name not in classes or has_attribute(classes[cls_name], attr):
            continue
        if browser is not None and attr in browser.get(cls_name, set()):
            continue
        out.append(f"{cls_name}.{attr}")
    return out


def split_browser_cells(text: str) -> tuple[str, str]:
    """(the text but for the cells of tables' JavaScript columns, those cells)."""
    python_part, js_part, js_col = [], [], None
    for line in text.splitlines():
        if not line.startswith("|"):
            js_col = None
            python_part.append(line)
            continue
        cells = line.split("|")
        if js_col is None and "JavaScript" in cells:
            js_col = cells.index("JavaScript")
        elif js_col is None:
            for k, c in enumerate(cells):
                if c.strip() == "JavaScript":
                    js_col = k
        if js_col is not None and js_col < len(cells):
            js_part.append(cells[js_col])
            cells[js_col] = ""
        python_part.append("|".join(cells))
    return "\n".join(python_part), "\n".join(js_part)


def test_the_check_finds_a_missing_attribute() -> None:
    classes, browser = public_classes(), wasm_names()
    assert {"FreeRigidBody", "FreeSymmetricTop", "Screw", "HeavyTop", "Earth"} <= set(classes)
    text = "`FreeRigidBody.no_such_thing` and `Screw.apply(x)` and `Unknown.thing`, `Screw.axis`"
    assert broken(text, classes) == ["FreeRigidBody.no_such_thing"]
    # an instance attribute set in __init__; a browser-only name only where the browser's are
    assert broken("`Trajectory.omega`", classes) == []
    assert "state" in browser["HeavyTop"] and not hasattr(ps.HeavyTop, "state")
    assert broken("`HeavyTop.state`", classes) == ["HeavyTop.state"]
    assert broken("`HeavyTop.state`", classes, browser) == []
    table = "| Rust | Python | JavaScript |\n|---|---|---|\n| `a` | `HeavyTop.nope` | `HeavyTop.state` |"
    py_text, js_text = split_browser_cells(table)
    assert broken(py_text, classes) == ["HeavyTop.nope"] and "`HeavyTop.state`" in js_text


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_cited_attribute_exists(page: Path) -> None:
    classes, browser = public_classes(), wasm_names()
    text = page.read_text(encoding="utf-8")
    if page.name == "lab.md":  # the browser lab's page: its names are the wasm classes' too
        missing = broken(text, classes, browser)
    else:
        python_text, js_text = split_browser_cells(text)
        missing = broken(python_text, classes) + broken(js_text, classes, browser)
    assert not missing, f"{page.name} cites attributes poinsot lacks: {sorted(set(missing))}"
