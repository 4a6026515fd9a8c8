"""The last line of defence at the Python boundary (issue 10): a Rust panic must never reach a
user as ``pyo3_runtime.PanicException`` (a ``BaseException`` that escapes ``except
Exception``). Every public function, constructor, method and property of poinsot is wrapped
once, at import, so that a panic — a bug, since the core validates its input first — becomes
a :class:`poinsot.PoinsotError` saying so. Other exceptions pass through untouched.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable
from typing import Any

from .errors import InternalError


def _is_panic(exc: BaseException) -> bool:
    cls = type(exc)
    return cls.__name__ == "PanicException" and cls.__module__ == "pyo3_runtime"


def _guarded(func: Callable[..., Any], name: str) -> Callable[..., Any]:
    if getattr(func, "__poinsot_guarded__", False):
        return func

    @functools.wraps(func)
    def call(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except BaseException as exc:
            if _is_panic(exc):
                raise InternalError(
                    f"{name}: internal error in poinsot's core ({exc}); this is a bug, please report it "
                    "with the call that caused it"
                ) from None
            raise

    call.__poinsot_guarded__ = True  # type: ignore[attr-defined]
    return call


def guard(namespace: dict[str, Any], names: list[str]) -> None:
    """Wrap the public callables ``names`` of ``namespace`` (a module's globals) in place:
    functions, and the public methods, class methods, static methods and properties of
    classes (exceptions and warnings are left alone)."""
    for name in names:
        obj = namespace.get(name)
        if inspect.isclass(obj):
            if issubclass(obj, BaseException):
                continue
            for attr, raw in list(vars(obj).items()):
                if attr.startswith("_") and attr != "__init__":
                    continue
                qual = f"{name}.{attr}" if attr != "__init__" else name
                if isinstance(raw, staticmethod):
                    setattr(obj, attr, staticmethod(_guarded(raw.__func__, qual)))
                elif isinstance(raw, classmethod):
                    setattr(obj, attr, classmethod(_guarded(raw.__func__, qual)))
                elif isinstance(raw, property):
                    setattr(
                        obj,
                        attr,
                        property(
                            _guarded(raw.fget, qual) if raw.fget else None,
                            raw.fset,
                            raw.fdel,
                            raw.__doc__,
                        ),
                    )
                elif inspect.isfunction(raw):
                    setattr(obj, attr, _guarded(raw, qual))
        elif inspect.isfunction(obj):
            namespace[name] = _guarded(obj, name)
