"""Every ```python block of docs/frames.md and docs/earth.md runs (in order, one namespace per page)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(r"```python\n(.*?)```", re.DOTALL)


@pytest.mark.parametrize("doc", ["docs/frames.md", "docs/earth.md"])
def test_doc_blocks_run(doc: str) -> None:
    blocks = BLOCK.findall((ROOT / doc).read_text(encoding="utf-8"))
    assert blocks
    namespace: dict[str, object] = {"__name__": "__doc__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"{doc}[block {i}]", "exec"), namespace)
