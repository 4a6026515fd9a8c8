"""Every ```python block of the README runs (in order, in one namespace), as a user would."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(r"```python\n(.*?)```", re.DOTALL)


def _blocks(path: Path) -> list[str]:
    return BLOCK.findall(path.read_text(encoding="utf-8"))


def test_readme_has_python_blocks() -> None:
    assert len(_blocks(ROOT / "README.md")) >= 3


@pytest.mark.parametrize("doc", ["README.md", "CONVENTIONS.md"])
def test_code_blocks_run(doc: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    namespace: dict[str, object] = {"__name__": "__readme__"}
    for i, block in enumerate(_blocks(ROOT / doc)):
        try:
            exec(compile(block, f"{doc}[block {i}]", "exec"), namespace)
        except Exception as exc:  # pragma: no cover - the failure message is the point
            raise AssertionError(f"{doc} block {i} failed:\n{block}") from exc


def test_readme_opens_with_make_demo_and_make_test() -> None:
    head = "\n".join((ROOT / "README.md").read_text(encoding="utf-8").splitlines()[:40])
    assert "make demo" in head and "make test" in head
