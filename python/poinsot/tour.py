"""``poinsot tour``: the unit's topics, computed (grows with each topic)."""

from __future__ import annotations


def run_tour() -> None:
    """Print the tour to the terminal."""
    print("poinsot tour")
