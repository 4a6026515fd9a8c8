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

    def on_error(exc: BaseException) -> None:
        """Turn a panic into :class:`InternalError`; any other exception is re-raised as it is
        by the caller."""
        if _is_panic(exc):
            raise InternalError(
                f"{name}: internal error in poinsot's core ({exc}); this is a bug, please report it "
                "with the call that caused it"
            ) from None

    call = _forwarder(func, on_error)
    functools.update_wrapper(call, func)
    call.__poinsot_guarded__ = True  # type: ignore[attr-defined]
    return call


def _forwarder(func: Callable[..., Any], on_error: Callable[[BaseException], None]) -> Any:
    """A function with ``func``'s own parameters (names, kinds, defaults) that calls ``func``
    with them inside ``try``, calling ``on_error`` on an exception before re-raising it.

    Generated from ``func.__code__`` rather than written ``call(*args, **kwargs)``: packing
    and unpacking the arguments cost ~120 ns per call (most of a small call's Python overhead,
    issue 15), the exact signature ~30 ns. Its errors for a wrong call (a missing or unknown
    argument) are ``func``'s own: same names, same qualified name."""
    code = func.__code__
    names = code.co_varnames
    n_pos, n_posonly, n_kwonly = code.co_argcount, code.co_posonlyargcount, code.co_kwonlyargcount
    positional = list(names[:n_pos])
    kwonly = list(names[n_pos : n_pos + n_kwonly])
    rest = n_pos + n_kwonly
    varargs = names[rest] if code.co_flags & inspect.CO_VARARGS else None
    varkw = names[rest + (varargs is not None)] if code.co_flags & inspect.CO_VARKEYWORDS else None
    n_defaults = len(func.__defaults__ or ())
    kwdefaults = func.__kwdefaults__ or {}

    params: list[str] = []
    for i, p in enumerate(positional):
        params.append(f"{p}=None" if i >= n_pos - n_defaults else p)
        if i == n_posonly - 1:
            params.append("/")
    if varargs is not None:
        params.append(f"*{varargs}")
    elif kwonly:
        params.append("*")
    params += [f"{k}=None" if k in kwdefaults else k for k in kwonly]
    if varkw is not None:
        params.append(f"**{varkw}")
    args = positional + ([f"*{varargs}"] if varargs else [])
    args += [f"{k}={k}" for k in kwonly] + ([f"**{varkw}"] if varkw else [])

    # The inner function's name shows in errors for a wrong call on Python < 3.11 (co_name);
    # a callable whose name is not an identifier (a lambda) gets a neutral one.
    inner = func.__name__ if func.__name__.isidentifier() else "_poinsot_call"
    source = (
        f"def _make(_poinsot_func, _poinsot_on_error):\n"
        f"    def {inner}({', '.join(params)}):\n"
        f"        try:\n"
        f"            return _poinsot_func({', '.join(args)})\n"
        f"        except BaseException as _poinsot_exc:\n"
        f"            _poinsot_on_error(_poinsot_exc)\n"
        f"            raise\n"
        f"    return {inner}\n"
    )
    namespace: dict[str, Any] = {}
    exec(source, namespace)
    call = namespace["_make"](func, on_error)
    call.__defaults__ = func.__defaults__
    call.__kwdefaults__ = func.__kwdefaults__
    if hasattr(code, "co_qualname"):  # Python 3.11+: errors for a wrong call name it
        call.__code__ = call.__code__.replace(co_qualname=code.co_qualname)
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
