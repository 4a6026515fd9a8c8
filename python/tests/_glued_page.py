"""Run a docs chapter's code cells as the site build does (myst-nb's glue replaced by a stand-in
that records each value), for the chapter tests that check every number the prose shows."""

from __future__ import annotations

import numbers
import re
from pathlib import Path
from typing import Any

import pytest

#: A ``{glue:text}`key:format``` role in the prose: the key it shows.
USED = re.compile(r"\{glue:text\}`([A-Za-z_0-9]+)(?::[^`]*)?`")
#: A code cell of the page (hidden or not): its source.
CELL = re.compile(r"```\{code-cell\} python\n(?::tags: \[remove-cell\]\n)?(.*?)```", re.S)


def glued(page: Path) -> dict[str, Any]:
    """The values the page's cells glue, by key (the cells run in order, in one namespace)."""
    pytest.importorskip("pint")
    pytest.importorskip("myst_nb")
    pytest.importorskip("matplotlib")
    text = page.read_text(encoding="utf-8")
    values: dict[str, Any] = {}

    def glue(name: str, value: Any, display: bool = True) -> None:
        assert not display, name
        if isinstance(value, numbers.Number):
            # myst-nb formats a {glue:text} number from its repr: numpy's scalars print as
            # np.float64(…), which the site build refuses (a warning, an error under -W).
            try:
                float(repr(value))
            except ValueError:
                raise AssertionError(
                    f"glue {name!r}: its repr {value!r} is not a plain number (wrap it in float())"
                ) from None
        values[name] = value

    namespace: dict[str, Any] = {"glue": glue, "__name__": "page"}
    for source in CELL.findall(text):  # the page's cells in order, as the build runs them
        code = source.replace("from myst_nb import glue\n", "").replace("%matplotlib inline\n", "")
        exec(compile(code, str(page), "exec"), namespace)
    import matplotlib.pyplot as plt

    plt.close("all")
    return values


def missing(text: str, values: dict[str, Any]) -> list[str]:
    """The glue keys the prose shows that the cells do not glue."""
    return sorted(set(USED.findall(text)) - set(values))
