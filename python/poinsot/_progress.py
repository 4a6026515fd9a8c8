"""The delayed progress bar of long work (a render of the CLI, a sweep): a rich bar on stderr
that appears only once the work has run :data:`SHOW_PROGRESS_AFTER_S`, so that short work stays
silent, and is removed when the work ends. No click: the library's sweeps use it too."""

from __future__ import annotations

import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any, Callable

#: A progress bar appears once the work has run this long (s): shorter work stays silent.
SHOW_PROGRESS_AFTER_S = 1.0


def stderr_interactive() -> bool:
    """Whether stderr is a terminal: progress bars are drawn there, and only there."""
    try:
        return sys.stderr.isatty()
    except (AttributeError, ValueError):
        return False


@contextmanager
def delayed_bar(
    description: str, *, show: bool, delay: float = SHOW_PROGRESS_AFTER_S
) -> Iterator[Callable[[float, float], None]]:
    """A callback ``update(done, total)`` drawing a rich bar on stderr once ``delay`` seconds
    have passed (nothing when ``show`` is false); the bar is removed on leaving."""
    start = time.perf_counter()
    bar: Any = None
    task: Any = None

    def update(done: float, total: float) -> None:
        nonlocal bar, task
        if not show:
            return
        if bar is None:
            if time.perf_counter() - start < delay:
                return
            from rich.console import Console
            from rich.progress import Progress

            bar = Progress(console=Console(stderr=True), transient=True)
            bar.start()
            task = bar.add_task(description, total=total)
        bar.update(task, completed=done, total=total)

    try:
        yield update
    finally:
        if bar is not None:
            bar.stop()
