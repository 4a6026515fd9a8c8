"""Running a planned sweep: locally in one call of the core (all cores, a progress bar), chunk
by chunk on a dask cluster (``client=``) or lazily (dask arrays given), and into zarr chunk by
chunk (``to_zarr=``); then labelling the results as an xarray ``Dataset``.

Every chunk is computed by the core from the slices of the keywords with the offsets of the
chunk (``Plan.core_call``): the same code on the same numbers as the whole sweep in one
call, hence the same results bit for bit, and errors naming the indices of the whole sweep.
"""

from __future__ import annotations

import importlib
import itertools
import math
import os
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from typing import Any, Callable, Optional

import numpy as np

from .. import _core
from .._progress import delayed_bar, stderr_interactive
from .._validate import as_callable, as_count
from ..errors import ArgumentTypeError, PoinsotError
from ._spec import CoreCall, Output, Plan, bytes_per_point, component_dim, component_labels

#: The optional extra that brings xarray, dask, distributed and zarr.
EXTRA = "parallel"

_CATEGORIES: dict[str, list[str]] = _core.sweep_categories()


def require(module: str) -> Any:
    """``module`` imported, or an ImportError naming the extra that installs it."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise ImportError(
            f"poinsot.sweep needs {module.split('.')[0]}, which comes with the optional extra "
            f"'{EXTRA}': pip install 'poinsot[{EXTRA}]' ({exc})"
        ) from exc


# ---- progress ------------------------------------------------------------------------------


@contextmanager
def progress_reporter(
    progress: Any, description: str
) -> Iterator[Optional[Callable[[float], Any]]]:
    """A ``report(fraction)`` callable for ``progress``: the user's callable; None for
    ``progress=False``; for ``progress=None`` a rich bar on stderr, shown once the sweep has run
    :data:`poinsot._progress.SHOW_PROGRESS_AFTER_S` and only when stderr is a terminal (else
    None; ``progress=True`` shows it in any case)."""
    if progress is False:
        yield None
        return
    if progress is not None and progress is not True:
        yield as_callable(progress, "progress")
        return
    if progress is None and not stderr_interactive():
        yield None
        return
    with delayed_bar(description, show=True) as update:
        yield lambda fraction: update(fraction, 1.0)


# ---- one block, anywhere -------------------------------------------------------------------


def block_results(
    call: CoreCall,
    names: Sequence[str],
    progress: Optional[Callable[[float], Any]] = None,
    decode: bool = True,
) -> dict[str, np.ndarray]:
    """The results ``names`` of one block (or of the whole sweep), ``call``: arrays of
    the block's shape (plus a components' dimension), categories as strings (``decode``) or
    their uint8 codes. Runs where it is called: in this process, or on a dask worker (it is
    imported there by name)."""
    from . import MODELS

    model = MODELS[call.model]
    shape = tuple(d[1] for d in call.dims)
    # Arrays unpickled on a worker may be unaligned (small ones, in a message's buffer): the
    # core reads aligned, C-contiguous float64.
    columns = [(k, np.require(v, np.float64, ["C", "A"]), d) for k, v, d in call.columns]
    out = model.core(call.dims, columns, *call.settings, False, progress)
    result = {}
    for o in model.outputs:
        if o.name not in names:
            continue
        arr = np.asarray(out[o.name])
        if o.kind == "category" and decode:
            assert o.table is not None
            arr = np.asarray(_CATEGORIES[o.table])[arr]
        result[o.name] = arr.reshape(shape + arr.shape[1:])
    return result


def block_to_zarr(call: CoreCall, outputs: Sequence[Output], path: str) -> int:
    """Computes one block, ``call``, and writes it into its region of the zarr store at
    ``path`` (made by :func:`run` with one zarr chunk a block); returns its number of points."""
    xr = require("xarray")
    names = [o.name for o in outputs]
    results = block_results(call, names, decode=False)
    dims = call.dims
    region = {name: slice(offset, offset + n) for name, n, offset, _ in dims}
    data = {}
    for o in outputs:
        arr = results[o.name]
        vdims = [d[0] for d in dims] + ([o.extra] if o.extra else [])
        if o.extra:
            region[o.extra] = slice(0, arr.shape[-1])
        data[o.name] = (vdims, arr)
    # A sweep of one point (no dimension) writes its arrays whole.
    xr.Dataset(data).to_zarr(path, region=region if dims else None, mode="r+", consolidated=False)
    return int(math.prod(d[1] for d in dims))


# ---- chunks --------------------------------------------------------------------------------


def chunk_sizes(plan: Plan, chunks: Any) -> list[tuple[int, ...]]:
    """The sizes of the chunks along each dimension: from ``chunks`` (an int for every
    dimension, or ``{dimension: size}``; the others not split), else a dask array's chunks,
    else blocks of about ``model.chunk_points`` points, contiguous in row-major order."""
    names = [d.name for d in plan.dims]
    sizes: list[Optional[int]] = [None] * len(plan.dims)
    if chunks is not None:
        if isinstance(chunks, dict):
            for name, size in chunks.items():
                if name not in names:
                    raise PoinsotError(
                        f"chunks: {name!r} is not a dimension of this sweep ({', '.join(names) or 'none'})"
                    )
                sizes[names.index(name)] = as_count(size, "chunks", 1)
            sizes = [s if s is not None else d.size for s, d in zip(sizes, plan.dims)]
        elif isinstance(chunks, (int, np.integer)) and not isinstance(chunks, bool):
            size = as_count(chunks, "chunks", 1)
            sizes = [size] * len(plan.dims)
        else:
            raise ArgumentTypeError(
                f"chunks: must be an int or a dict {{dimension: size}}, got {type(chunks).__name__}"
            )
    out: list[Optional[tuple[int, ...]]] = [None] * len(plan.dims)
    for k, d in enumerate(plan.dims):
        if sizes[k] is not None:
            s = min(int(sizes[k] or 1), d.size)
            out[k] = tuple([s] * (d.size // s) + ([d.size % s] if d.size % s else []))
        elif d.chunks is not None:
            out[k] = d.chunks
    # The rest: whole trailing dimensions while they fit in a chunk, then split one.
    budget = plan.model.chunk_points
    for k in reversed(range(len(plan.dims))):
        if out[k] is not None:
            budget = max(1, budget // max(out[k] or (1,)))
            continue
        n = plan.dims[k].size
        s = max(1, min(n, budget))
        out[k] = tuple([s] * (n // s) + ([n % s] if n % s else []))
        budget = max(1, budget // s)
    return [c or (1,) for c in out]


def blocks(sizes: list[tuple[int, ...]]) -> list[list[tuple[int, int]]]:
    """Every block, in row-major order, as ``[(start, stop)]`` per dimension."""
    edges = []
    for s in sizes:
        starts = np.concatenate([[0], np.cumsum(s)]).astype(int)
        edges.append([(int(a), int(b)) for a, b in zip(starts[:-1], starts[1:])])
    return [list(b) for b in itertools.product(*edges)]


# ---- running -------------------------------------------------------------------------------


def run(
    plan: Plan,
    *,
    client: Any,
    chunks: Any,
    to_zarr: Any,
    progress: Any,
) -> Any:
    """Runs ``plan`` and returns its Dataset (see :mod:`poinsot.sweep`); an error about a
    dimension names the user's argument that makes it (the core's ``Dim.argument``)."""
    xr = require("xarray")
    names = [o.name for o in plan.outputs]
    model = plan.model
    distributed = client is not None or plan.lazy or to_zarr is not None or chunks is not None
    if client is not None:
        _check_client(client)
    if to_zarr is not None:
        to_zarr = _check_zarr_path(to_zarr)
    if not distributed:
        # Locally: one call of the core over the whole sweep (it checks every point first).
        with progress_reporter(progress, f"sweep.{model.name}") as report:
            whole = block_results(plan.core_call(), names, report)
        return dataset(xr, plan, whole)

    # Chunk by chunk: every point checked here first (cheap), then the chunks sent out.
    whole_call = plan.core_call()
    model.core(whole_call.dims, whole_call.columns, *plan.settings, True, None)
    sizes = chunk_sizes(plan, chunks)
    todo = blocks(sizes)
    path = None
    if to_zarr is not None:
        path = _zarr_template(xr, plan, sizes, to_zarr)
    elif client is not None or not plan.lazy:
        _core.sweep_check_memory(whole_call.dims, bytes_per_point(plan.outputs))

    if plan.lazy and client is None and path is None:
        return _lazy(xr, plan, sizes, todo)

    def task(block: list[tuple[int, int]]) -> tuple[Any, ...]:
        if path is not None:
            return (block_to_zarr, plan.core_call(block), plan.outputs, path)
        return (block_results, plan.core_call(block), names)

    results: list[Any]
    with progress_reporter(progress, f"sweep.{model.name}") as report:
        if client is not None:
            results = _on_cluster(client, [task(b) for b in todo], report)
        else:
            results = []
            for i, b in enumerate(todo):
                fn, *args = task(b)
                results.append(fn(*args))
                if report is not None:
                    report((i + 1) / len(todo))
    if path is not None:
        written = sum(results)
        if written != plan.points:  # every block once: a lost or doubled one is a bug
            raise RuntimeError(f"wrote {written} points of {plan.points}")
        return open_zarr(path)
    return dataset(xr, plan, _assemble(plan, sizes, results, names))


def _check_client(client: Any) -> None:
    """A running ``dask.distributed.Client``, or an error naming ``client``."""
    distributed = require("distributed")
    if not isinstance(client, distributed.Client):
        raise ArgumentTypeError(
            f"client: must be a dask.distributed.Client or None, got {type(client).__name__}"
        )
    status = getattr(client, "status", None)
    if status in ("closing", "closed"):
        raise PoinsotError(f"client: is {status}; give a running dask.distributed.Client")


def _check_zarr_path(path: Any) -> str:
    """``to_zarr`` as a path whose directory exists and is writable, checked before any
    work; an error naming ``to_zarr`` otherwise."""
    if not isinstance(path, (str, os.PathLike)) or isinstance(path, bytes):
        raise ArgumentTypeError(
            f"to_zarr: must be a path (str or os.PathLike), got {type(path).__name__}"
        )
    text = os.fspath(path)
    if not isinstance(text, str) or not text.strip():
        raise ArgumentTypeError(f"to_zarr: must be a non-empty path, got {text!r}")
    if os.path.lexists(text):
        raise PoinsotError(f"to_zarr: {text!r} exists already; give a new path")
    parent = os.path.dirname(os.path.abspath(text))
    try:  # the store is a directory: made and removed again here, before any work
        os.mkdir(text)
        os.rmdir(text)
    except FileNotFoundError:
        raise PoinsotError(
            f"to_zarr: cannot write {text!r}: its directory {parent!r} does not exist or "
            "refuses new entries"
        ) from None
    except OSError as exc:
        raise PoinsotError(
            f"to_zarr: cannot write {text!r} ({type(exc).__name__}: {exc.strerror or exc})"
        ) from None
    return text


def _on_cluster(
    client: Any, tasks: list[tuple[Any, ...]], report: Optional[Callable[[float], Any]]
) -> list[Any]:
    """The tasks' results, in order, computed on the cluster of ``client``. A task whose worker
    dies is computed again by Dask (its result is only ever taken once)."""
    distributed = require("distributed")
    # Keys of this call's own (pure=False): a sweep that failed or was stopped cancels its
    # futures, which must not cancel the same chunk of a later sweep.
    futures = [client.submit(fn, *args, pure=False) for fn, *args in tasks]
    try:
        if report is not None:
            for done, _ in enumerate(distributed.as_completed(futures), start=1):
                report(min(1.0, done / len(futures)))
        return list(client.gather(futures))
    except BaseException:
        client.cancel(futures)
        raise


def _assemble(
    plan: Plan, sizes: list[tuple[int, ...]], results: list[dict[str, np.ndarray]], names: list[str]
) -> dict[str, np.ndarray]:
    """The blocks' results (in the row-major order of :func:`blocks`) put together: each block
    once, in its place."""
    out = {}
    for name in names:
        first = results[0][name]
        whole = np.empty(plan.shape + first.shape[len(plan.dims) :], dtype=first.dtype)
        for block, res in zip(blocks(sizes), results):
            whole[tuple(slice(a, b) for a, b in block)] = res[name]
        out[name] = whole
    return out


def _lazy(
    xr: Any, plan: Plan, sizes: list[tuple[int, ...]], todo: list[list[tuple[int, int]]]
) -> Any:
    """The Dataset of dask arrays: one delayed core call a block (dask arrays were given)."""
    dask = require("dask")
    da = require("dask.array")
    names = [o.name for o in plan.outputs]
    grid = tuple(len(s) for s in sizes)
    pieces: dict[str, dict[tuple[int, ...], Any]] = {n: {} for n in names}
    for index, block in zip(itertools.product(*[range(g) for g in grid]), todo):
        res = dask.delayed(block_results, pure=True)(plan.core_call(block), names)
        shape = tuple(b - a for a, b in block)
        for o in plan.outputs:
            dtype = _DTYPES[o.kind] if o.kind != "category" else _category_dtype(o)
            pieces[o.name][index] = da.from_delayed(res[o.name], shape + _tail(o), dtype=dtype)

    def join(parts: dict[tuple[int, ...], Any], prefix: tuple[int, ...]) -> Any:
        # Concatenated along the sweep's dimensions only (not along a vector's components).
        axis = len(prefix)
        if axis == len(grid):
            return parts[prefix]
        return da.concatenate([join(parts, prefix + (i,)) for i in range(grid[axis])], axis=axis)

    return dataset(xr, plan, {n: join(pieces[n], ()) for n in names})


_DTYPES: dict[str, Any] = {
    "float": np.float64,
    "bool": np.bool_,
    "int": np.int8,
    "category": np.uint8,
}


def _category_dtype(o: Output) -> Any:
    """The dtype of a category's strings: that of its table, as :func:`block_results` gives."""
    assert o.table is not None
    return np.asarray(_CATEGORIES[o.table]).dtype


def _tail(o: Output) -> tuple[int, ...]:
    if o.extra is None:
        return ()
    return (len(component_labels(o.extra)),)


def _zarr_template(xr: Any, plan: Plan, sizes: list[tuple[int, ...]], path: Any) -> str:
    """Creates the zarr store at ``path``: coordinates written, the results' arrays empty with
    one zarr chunk per block (so that blocks write their regions independently)."""
    da = require("dask.array")
    path = str(path)
    arrays = {}
    encoding = {}
    for o in plan.outputs:
        tail = _tail(o)
        dtype = _DTYPES[o.kind]
        chunks = tuple(max(s) for s in sizes) + tail
        arrays[o.name] = da.zeros(plan.shape + tail, chunks=chunks, dtype=dtype)
        encoding[o.name] = {"chunks": chunks}
    template = dataset(xr, plan, arrays)
    # Labels as variable-length strings (zarr v3 has no specification of fixed-width ones).
    for name, coord in template.coords.items():
        if coord.dtype.kind == "U":
            template.coords[name] = coord.astype(object)
    try:
        template.to_zarr(path, compute=False, mode="w-", encoding=encoding, consolidated=False)
    except FileExistsError:
        raise PoinsotError(f"to_zarr: {path!r} exists already; give a new path") from None
    except OSError as exc:  # a directory that refuses it (read-only, /proc, ...)
        raise PoinsotError(
            f"to_zarr: cannot write {path!r} ({type(exc).__name__}: {exc.strerror or exc})"
        ) from None
    return path


def open_zarr(path: Any) -> Any:
    """A store written by a sweep, opened lazily, with its categories (stored as uint8 codes
    into their attribute ``categories``) decoded into strings as in memory."""
    xr = require("xarray")
    ds = xr.open_zarr(str(path), consolidated=False)
    for name, var in ds.data_vars.items():
        categories = var.attrs.get("categories")
        if categories is None or var.dtype.kind != "u":
            continue
        table = np.asarray(categories)
        ds[name] = xr.apply_ufunc(
            lambda codes, table=table: table[codes],
            var,
            dask="parallelized",
            output_dtypes=[table.dtype],
            keep_attrs=True,
        )
    for name, coord in ds.coords.items():
        if coord.dtype.kind in "OT":
            ds.coords[name] = (coord.dims, np.array(coord.values.tolist()), coord.attrs)
    return ds


# ---- labelling -----------------------------------------------------------------------------


def dataset(xr: Any, plan: Plan, results: dict[str, Any]) -> Any:
    """The Dataset of ``results`` (arrays of the sweep's shape, plus components) with the
    keywords as coordinates (units and long names in their attributes)."""
    deg = bool(plan.attrs.get("degrees"))
    dim_names = [d.name for d in plan.dims]
    coords: dict[str, Any] = {}
    used_components: list[str] = []
    for c in plan.columns:
        key_attrs = {"units": c.key.user_units(deg), "long_name": c.key.long_name}
        if not key_attrs["units"]:
            del key_attrs["units"]
        cdims: list[str] = []
        if c.dim is not None:
            cdims.append(dim_names[c.dim])
        if c.key.width > 1:
            comp = component_dim(c.key.width)
            cdims.append(comp)
            used_components.append(comp)
        coords[c.key.name] = (cdims, c.user, key_attrs)
    data_vars = {}
    for o in plan.outputs:
        vdims = list(dim_names)
        if o.extra:
            vdims.append(o.extra)
            used_components.append(o.extra)
        attrs: dict[str, Any] = {"long_name": o.long_name}
        if o.units:
            attrs["units"] = o.units
        if o.kind == "category":
            assert o.table is not None
            attrs["categories"] = list(_CATEGORIES[o.table])
        if o.kind == "int" and o.name == "pole_axis":
            attrs["none"] = -1
        data_vars[o.name] = (vdims, results[o.name], attrs)
    for comp in dict.fromkeys(used_components):
        coords[comp] = (comp, list(component_labels(comp)))
    return xr.Dataset(data_vars, coords=coords, attrs=dict(plan.attrs))
