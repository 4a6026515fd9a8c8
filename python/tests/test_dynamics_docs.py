"""Every ```python block of docs/dynamics.md runs (in order, one namespace)."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BLOCK = re.compile(r"```python\n(.*?)```", re.DOTALL)


def test_dynamics_doc_blocks_run() -> None:
    doc = "docs/dynamics.md"
    blocks = BLOCK.findall((ROOT / doc).read_text(encoding="utf-8"))
    assert len(blocks) >= 4
    namespace: dict[str, object] = {"__name__": "__doc__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"{doc}[block {i}]", "exec"), namespace)
