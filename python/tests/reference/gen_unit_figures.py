"""Writes unit_figures.txt: every line of the course unit that names one of its figures.

The unit (``seed/unit-2-moving-frames-and-rigid-bodies.md``, kept beside the repository, not in
it) marks each figure with a caption line ("Fig: 2.1", "Fig.: 2.5", ...) and refers to figures
in its text ("as shown in fig.2.3", "Fig.(2.12a)"). test_plots_unit.py reads the figure
numbers from these lines, so that a figure missing from ``poinsot.plots.UNIT_FIGURES`` fails
it, and compares this file with the unit itself when the unit is at hand.

    python python/tests/reference/gen_unit_figures.py PATH/TO/unit-2-moving-frames-and-rigid-bodies.md
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

#: A line naming a figure: "Fig", "fig." or "figure" (any case) as a word.
FIGURE_LINE = re.compile(r"\bfig(?:ure)?\b", re.IGNORECASE)


def figure_lines(unit_text: str) -> list[str]:
    """The unit's lines that name a figure, stripped, in the unit's order."""
    return [line.strip() for line in unit_text.splitlines() if FIGURE_LINE.search(line)]


def main() -> None:
    unit = Path(sys.argv[1])
    out = Path(__file__).with_name("unit_figures.txt")
    out.write_text(
        "\n".join(figure_lines(unit.read_text(encoding="utf-8"))) + "\n", encoding="utf-8"
    )
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
