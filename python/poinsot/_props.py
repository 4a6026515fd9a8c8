"""Read-only properties that read the compiled core's object of an instance (``self._core``)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar, overload

T = TypeVar("T")


@overload
def core_property(name: str, doc: str) -> Any: ...
@overload
def core_property(name: str, doc: str, convert: Callable[[Any], T]) -> T: ...
def core_property(name: str, doc: str, convert: Callable[[Any], Any] | None = None) -> Any:
    """A read-only property: the core object's attribute ``name`` (converted by ``convert``:
    ``float``, ``str``, ``np.asarray``; a number as it is when ``None``), documented by ``doc``.

    Typed for the checker as what ``convert`` returns; without it, the class annotates the
    attribute (``radius: float = core_property("radius", ...)``), so that users' type checkers
    see the type each property had when it was written out. At run time it is a ``property``."""
    if convert is None:
        return property(lambda self: getattr(self._core, name), doc=doc)
    return property(lambda self: convert(getattr(self._core, name)), doc=doc)
