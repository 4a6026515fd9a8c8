"""The plan of a sweep: the model's keywords as given (numbers, 1-D arrays, ranges to sample),
turned into named dimensions and the core's columns; the labels (units, long names) of inputs
and results. Pure numpy: no xarray, no dask (dask arrays given as keywords are recognised by
their type and read here)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Callable, NamedTuple, Optional

import numpy as np

from .. import _core
from .._units import is_quantity
from .._validate import FloatArray, as_count, as_flag, as_float_array
from ..errors import ArgumentTypeError, PoinsotError

#: The names of the components of a vector keyword or result (the ``axis`` dimension): the
#: principal axes, as indices into ``moments``.
AXIS = (0, 1, 2)
#: The components of a quaternion (the ``quaternion`` dimension), scalar first.
QUATERNION = ("w", "x", "y", "z")
_COMPONENT_DIM = {3: "axis", 4: "quaternion"}
_COMPONENT_LABELS: dict[str, Sequence[Any]] = {"axis": AXIS, "quaternion": QUATERNION}

#: The dimension of a random sample (``samples=N``).
SAMPLE = "sample"


@dataclass(frozen=True)
class Key:
    """A keyword of a model: its name, what it is, its SI units, how many numbers an entry
    holds (1, 3 for a vector, 4 for a quaternion) and whether ``degrees=True`` converts it
    (``"angle"``: deg → rad, ``"rate"``: deg/s → rad/s)."""

    name: str
    long_name: str
    units: str
    width: int = 1
    angle: Optional[str] = None

    def user_units(self, degrees: bool) -> str:
        if degrees and self.angle == "angle":
            return "deg"
        if degrees and self.angle == "rate":
            return "deg/s"
        return self.units


@dataclass(frozen=True)
class Output:
    """A result of a model: its name, what it is, its units (``""`` for none), its kind
    (``"float"``, ``"category"``, ``"bool"``, ``"int"``), the extra dimension of a vector or
    pair (``"axis"``, ``"quaternion"``, ``"turning_point"``) and, for a category, the name of
    its table in ``_core.sweep_categories()``."""

    name: str
    long_name: str
    units: str
    kind: str = "float"
    extra: Optional[str] = None
    table: Optional[str] = None


@dataclass(frozen=True)
class Model:
    """A sweepable model: its name in ``poinsot.sweep``, the scalar API it batches, its keywords
    (the core's list, with labels), its results, the compiled sweep function, and the number of
    points a chunk holds by default."""

    name: str
    api: str
    keys: tuple[Key, ...]
    outputs: tuple[Output, ...]
    core: Callable[..., Any]
    chunk_points: int

    def key(self, name: str) -> Key:
        for k in self.keys:
            if k.name == name:
                return k
        raise KeyError(name)


class Range:
    """A range of values to draw a keyword from in a random sample (``samples=N``): uniform
    between ``low`` and ``high``, or log-uniform (``log=True``: uniform in the logarithm, for
    quantities spanning decades such as a spin). ``low`` and ``high`` are numbers, or for a
    vector keyword arrays of its width (each component drawn on its own). Build one with
    :func:`poinsot.sweep.uniform` or :func:`poinsot.sweep.log_uniform`."""

    __slots__ = ("high", "log", "low")

    def __init__(self, low: Any, high: Any, *, log: bool = False) -> None:
        lo = as_float_array(low, "low")
        hi = as_float_array(high, "high")
        if lo.shape != hi.shape or lo.ndim > 1:
            raise PoinsotError(
                f"high: must have the shape of low (a number, or a vector), got {hi.shape} and {lo.shape}"
            )
        if np.any(hi < lo):
            raise PoinsotError(
                f"high: must be >= low, got low = {lo.tolist()}, high = {hi.tolist()}"
            )
        log = as_flag(log, "log")
        if log and not np.all(lo > 0):
            raise PoinsotError(f"low: must be > 0 for a log-uniform range, got {lo.tolist()}")
        self.low = lo
        self.high = hi
        self.log = log

    def __repr__(self) -> str:
        kind = "log_uniform" if self.log else "uniform"
        return f"{kind}({self.low.tolist()}, {self.high.tolist()})"

    def draw(self, rng: np.random.Generator, n: int, width: int, name: str) -> FloatArray:
        """``n`` draws, shape (n,) or (n, width)."""
        if width > 1 and self.low.shape not in ((), (width,)):
            raise PoinsotError(
                f"{name}: a range of vectors needs low and high of shape ({width},), got {self.low.shape}"
            )
        if width == 1 and self.low.ndim != 0:
            raise PoinsotError(
                f"{name}: a range needs numbers low and high, got shape {self.low.shape}"
            )
        lo = np.broadcast_to(self.low, (width,)) if width > 1 else self.low
        hi = np.broadcast_to(self.high, (width,)) if width > 1 else self.high
        size = (n,) if width == 1 else (n, width)
        if self.log:
            return np.exp(rng.uniform(np.log(lo), np.log(hi), size=size))
        return rng.uniform(lo, hi, size=size)


def _is_dask_array(value: Any) -> bool:
    cls = type(value)
    return cls.__module__.startswith("dask.array") and hasattr(value, "chunks")


@dataclass
class Dim:
    """A dimension of the sweep: its name, length, the keywords along it, and the chunk sizes
    a dask array gave it (None: to be chosen)."""

    name: str
    size: int
    members: list[str] = field(default_factory=list)
    chunks: Optional[tuple[int, ...]] = None

    @property
    def argument(self) -> str:
        """The user's argument that makes it, which the core's errors about it name (its
        length, the memory budget): the keyword it sweeps, ``samples`` for a random sample,
        the first keyword of a paired dimension."""
        if self.name == SAMPLE:
            return "samples"
        return self.name if self.name in self.members else self.members[0]


@dataclass
class Column:
    """A keyword as given: its values in the user's units (``user``: shape (), (w,), (n,) or
    (n, w)), in the core's units as a flat C-contiguous array (``core``), and its dimension."""

    key: Key
    user: FloatArray
    core: FloatArray
    dim: Optional[int]


class CoreCall(NamedTuple):
    """One call of a model's core function, over the whole sweep or one block of it (sent to
    dask workers by value): the model's name (a key of ``MODELS``), the core's dimensions
    ``(name, length, offset, argument)`` and columns ``(keyword, values, dimension)``, and the
    model's settings."""

    model: str
    dims: list[tuple[str, int, int, str]]
    columns: list[tuple[str, FloatArray, Optional[int]]]
    settings: tuple[Any, ...]


@dataclass
class Plan:
    """A sweep ready to run: the model, its dimensions and columns, the model's settings (the
    core function's arguments after the columns), the dataset's attributes, whether a keyword
    was a dask array (the result is then lazy), and the results kept."""

    model: Model
    dims: list[Dim]
    columns: list[Column]
    settings: tuple[Any, ...]
    attrs: dict[str, Any]
    lazy: bool
    outputs: list[Output]

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(d.size for d in self.dims)

    @property
    def points(self) -> int:
        return math.prod(self.shape)

    def core_call(self, block: Optional[Sequence[tuple[int, int]]] = None) -> CoreCall:
        """The core's call over the whole sweep, or over the block of ``[(start, stop)]`` per
        dimension (the keywords' slices, with offsets)."""
        if block is None:
            block = [(0, d.size) for d in self.dims]
        dims = [
            (d.name, stop - start, start, d.argument) for d, (start, stop) in zip(self.dims, block)
        ]
        cols = []
        for c in self.columns:
            values = c.core
            if c.dim is not None:
                start, stop = block[c.dim]
                w = c.key.width
                values = values[start * w : stop * w]
            cols.append((c.key.name, np.require(values, np.float64, ["C", "A"]), c.dim))
        return CoreCall(self.model.name, dims, cols, self.settings)


def _values(key: Key, value: Any) -> tuple[FloatArray, bool, Optional[tuple[int, ...]]]:
    """A keyword's values in the user's units, whether it spans a dimension, and the chunks of
    a dask array. Refuses (naming the keyword) other shapes, and empty arrays."""
    chunks = None
    if _is_dask_array(value):
        if value.ndim >= 1:
            chunks = tuple(int(c) for c in value.chunks[0])
        value = np.asarray(value.compute())
    arr = as_float_array(value, key.name, finite=False)
    w = key.width
    if w == 1:
        if arr.ndim == 0:
            return arr, False, None
        if arr.ndim != 1:
            raise PoinsotError(
                f"{key.name}: must be a number or a 1-D array (one dimension of the sweep), got shape {arr.shape}"
            )
    else:
        if arr.shape == (w,):
            return arr, False, None
        if arr.ndim != 2 or arr.shape[1] != w:
            raise PoinsotError(
                f"{key.name}: must have shape ({w},) or (N, {w}) (N entries along one dimension of the sweep), "
                f"got {arr.shape}"
            )
    if arr.shape[0] == 0:
        raise PoinsotError(
            f"{key.name}: must not be empty: a dimension of the sweep needs at least one value"
        )
    return arr, True, chunks


def _to_core(key: Key, user: FloatArray, degrees: bool) -> FloatArray:
    core = np.radians(user) if degrees and key.angle else user
    return np.require(core, np.float64, ["C", "A"]).reshape(-1)


def plan(
    model: Model,
    keywords: Mapping[str, Any],
    *,
    degrees: Any,
    samples: Any,
    seed: Any,
    paired: Any,
    quantities: Any,
    settings: tuple[Any, ...] = (),
    attrs: Optional[dict[str, Any]] = None,
) -> Plan:
    """The plan of ``model`` over ``keywords`` (in the order given: each array a dimension, in
    that order; a dimension shared by ``paired`` keywords, or by the sampled ones, where the
    first of them stands). Refuses, naming the argument: a keyword that is not the model's, a
    value that is not a number or a 1-D array (an (N, w) array for a vector keyword), an empty
    array, paired keywords of different lengths, ranges without ``samples`` and ``samples``
    without a range."""
    deg = as_flag(degrees, "degrees")
    known = [k.name for k in model.keys]
    for name in keywords:
        if name not in known:
            raise ArgumentTypeError(
                f"{name}: is not a keyword of poinsot.sweep.{model.name} (the keywords of {model.api}: "
                f"{', '.join(known)})"
            )
    pairs = _pairs(paired, keywords, known)
    ranged = [name for name, v in keywords.items() if isinstance(v, Range)]
    n_samples = None
    if samples is not None:
        n_samples = as_count(samples, "samples", 1)
        if not ranged:
            raise PoinsotError(
                "samples: no keyword is a range to draw from (give one as poinsot.sweep.uniform(low, high))"
            )
    elif ranged:
        raise PoinsotError(
            f"{ranged[0]}: a range ({keywords[ranged[0]]!r}) is drawn from in a random sample: give samples=N"
        )
    if seed is not None and n_samples is None:
        raise PoinsotError("seed: draws a random sample: give samples=N with it")
    rng = np.random.default_rng(None if seed is None else as_count(seed, "seed"))

    dims: list[Dim] = []
    dim_of: dict[str, int] = {}  # a dimension's name -> its index
    columns: list[Column] = []
    lazy = False
    for name, value in keywords.items():
        key = model.key(name)
        if isinstance(value, Range):
            assert n_samples is not None
            user = value.draw(rng, n_samples, key.width, name)
            dim_name, spans, chunks = SAMPLE, True, None
        else:
            user, spans, chunks = _values(key, value)
            if deg and key.angle and is_quantity(value):  # in rad or rad/s: the user's units
                user = np.degrees(user)
            lazy = lazy or chunks is not None
            dim_name = pairs.get(name, name if key.width == 1 else f"{name}_index")
            if not spans and name in pairs:
                raise PoinsotError(
                    f"{name}: is paired along {pairs[name]!r} but is a single value, not an array"
                )
        dim = None
        if spans:
            n = user.shape[0]
            if dim_name in dim_of:
                d = dims[dim_of[dim_name]]
                if d.size != n:
                    first = d.members[0]
                    raise PoinsotError(
                        f"{name}: is paired with {first} along {dim_name!r} and must have as many entries "
                        f"({d.size}), got {n}"
                    )
                d.members.append(name)
                d.chunks = d.chunks or chunks
            else:
                dim_of[dim_name] = len(dims)
                dims.append(Dim(dim_name, n, [name], chunks))
            dim = dim_of[dim_name]
        columns.append(Column(key, user, _to_core(key, user, deg), dim))

    outputs = _quantities(model, quantities, set(keywords))
    base = {
        "model": model.api,
        "poinsot_version": _core.__version__,
        "degrees": int(deg),
    }
    if n_samples is not None:
        base["samples"] = n_samples
        base["seed"] = "none" if seed is None else int(seed)
        base["ranges"] = ", ".join(f"{k} = {keywords[k]!r}" for k in ranged)
    base.update(attrs or {})
    return Plan(model, dims, columns, settings, base, lazy, outputs)


def _pairs(paired: Any, keywords: Mapping[str, Any], known: list[str]) -> dict[str, str]:
    """``{keyword: dimension name}`` from ``paired={"name": ("kw1", "kw2", ...)}``."""
    if paired is None:
        return {}
    if not isinstance(paired, Mapping):
        raise ArgumentTypeError(
            f"paired: must be a dict {{dimension name: (keyword, ...)}}, got {type(paired).__name__}"
        )
    out: dict[str, str] = {}
    for dim, names in paired.items():
        if not isinstance(dim, str) or not dim.isidentifier():
            raise PoinsotError(f"paired: a dimension's name must be an identifier, got {dim!r}")
        if dim in known or dim == SAMPLE or dim in _COMPONENT_LABELS:
            raise PoinsotError(
                f"paired: {dim!r} is the name of a keyword or of a dimension of its own; name the paired "
                "dimension otherwise"
            )
        if isinstance(names, str) or not isinstance(names, Sequence) or not names:
            raise ArgumentTypeError(f"paired: {dim!r} must name a tuple of keywords, got {names!r}")
        for name in names:
            if name not in known:
                raise PoinsotError(
                    f"paired: {name!r} is not a keyword of the model ({', '.join(known)})"
                )
            if name not in keywords:
                raise PoinsotError(f"paired: {name!r} is not given")
            if name in out:
                raise PoinsotError(f"paired: {name!r} is paired twice")
            if isinstance(keywords[name], Range):
                raise PoinsotError(
                    f"paired: {name!r} is a range: the sampled keywords share the {SAMPLE!r} dimension already"
                )
            out[name] = dim
    return out


def _quantities(model: Model, quantities: Any, given: set[str]) -> list[Output]:
    """The results kept: all the model's (but those that are inputs of this sweep), or those
    named."""
    available = [o for o in model.outputs if o.name not in given]
    if quantities is None:
        return available
    if isinstance(quantities, np.ndarray):  # numpy's names: a 0-d array is one name
        if quantities.ndim > 1:
            raise ArgumentTypeError(
                "quantities: must be a result's name or a 1-D list of names, got an array of "
                f"shape {quantities.shape}"
            )
        quantities = quantities.tolist()
    if isinstance(quantities, str):
        quantities = [quantities]
    if isinstance(quantities, Mapping) or not isinstance(quantities, (Sequence, np.ndarray)):
        raise ArgumentTypeError(
            "quantities: must be a result's name or a list of names, got "
            f"{type(quantities).__name__}"
        )
    names = {o.name: o for o in available}
    out = []
    for q in quantities:
        if not isinstance(q, str):
            raise ArgumentTypeError(
                f"quantities: must hold the results' names (text), got {type(q).__name__} {q!r}"
            )
        if q not in names:
            raise PoinsotError(
                f"quantities: {q!r} is not a result of poinsot.sweep.{model.name} "
                f"(its results: {', '.join(o.name for o in available)})"
            )
        out.append(names[q])
    if not out:
        raise PoinsotError("quantities: must name at least one result")
    return out


def component_dim(width: int) -> str:
    """The name of the dimension of a vector's components."""
    return _COMPONENT_DIM[width]


def component_labels(dim: str) -> Sequence[Any]:
    """The coordinate of a components' dimension."""
    if dim == "turning_point":
        return ("theta1", "theta2")
    return _COMPONENT_LABELS[dim]


def bytes_per_point(outputs: Sequence[Output]) -> int:
    """The bytes a point's results take in memory (category strings as 4 bytes a character of
    the longest name)."""
    total = 0
    for o in outputs:
        n = 2 if o.extra == "turning_point" else (3 if o.extra == "axis" else (4 if o.extra else 1))
        size = {"float": 8, "bool": 1, "int": 1, "category": 4 * 20}[o.kind]
        total += n * size
    return total
