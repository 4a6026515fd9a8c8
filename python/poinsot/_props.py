"""Read-only properties that read the compiled core's object of an instance (``self._core``)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def core_property(name: str, doc: str, convert: Callable[[Any], Any] | None = None) -> Any:
    """A read-only property: the core object's attribute ``name`` (converted by ``convert``:
    ``float``, ``str``, ``np.asarray``; as it is when ``None``), documented by ``doc``."""
    if convert is None:
        return property(lambda self: getattr(self._core, name), doc=doc)
    return property(lambda self: convert(getattr(self._core, name)), doc=doc)
