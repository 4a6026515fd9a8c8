"""The ``poinsot`` command line (click + rich). ``python -m poinsot`` is the same command.

Every computing command takes ``--json`` and then prints one JSON document on stdout and
nothing else, so that its output can be piped into other programs.

Failures never show a traceback: each ends with one line on stderr, ``error: ...``, naming the
option (or argument) at fault, and an exit status (:data:`EXIT_STATUSES`, also in ``poinsot
--help``): 2 when the command line itself is wrong, 1 when poinsot refuses the input or cannot
finish, 130 when interrupted (Ctrl+C).
"""

from __future__ import annotations

import contextlib
import errno
import json
import math
import os
import stat
import sys
import time
import warnings
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import Any, NoReturn, cast

import click
import numpy as np

from . import _answers
from ._core import DEFAULTS as _DEFAULTS
from ._progress import SHOW_PROGRESS_AFTER_S, delayed_bar, stderr_interactive
from ._units import ARGUMENTS as _ARGUMENTS
from .errors import PoinsotError
from .plots._mpl import STYLES

SHAPES = {
    # name: (constructor, the dimension options it needs)
    "sphere": ("solid_sphere", ("radius",)),
    "shell": ("spherical_shell", ("radius",)),
    "cylinder": ("solid_cylinder", ("radius", "height")),
    "cone": ("solid_cone", ("radius", "height")),
    "cuboid": ("cuboid", ("sides",)),
    "ellipsoid": ("ellipsoid", ("semi_axes",)),
    "rod": ("thin_rod", ("length",)),
    "disk": ("thin_disk", ("radius",)),
    "ring": ("thin_ring", ("radius",)),
}

#: Exit status of a command line that is wrong: an unknown command or option, a missing one, a
#: value that is not a finite number or not one of the choices, options that do not go
#: together, a path that does not exist or is of the wrong kind (a directory, a device).
EXIT_USAGE = 2
#: Exit status of input poinsot refuses, or of a run that cannot finish: a value outside the
#: physics' range (poinsot's error, naming the option), a file that is not a readable mesh, an
#: output that cannot be written, a result that is not a finite number, a missing extra.
EXIT_REFUSED = 1
#: Exit status after Ctrl+C (128 + SIGINT, as shells report it).
EXIT_INTERRUPTED = 130

EXIT_STATUSES = (
    f"Exit status: 0 done; {EXIT_USAGE} the command line is wrong (unknown or missing option, a "
    "value that is not a finite number, options that do not go together, a path that does not "
    f"exist or is a directory or device); {EXIT_REFUSED} the input is refused or the run cannot "
    "finish (a value out of range, a file that is not a readable mesh, an output that cannot be "
    f"written, a result that is not a finite number, a missing extra); {EXIT_INTERRUPTED} "
    'interrupted (Ctrl+C). Every failure is one line on stderr, "error: ...", naming the option.'
    "\n\n"
    'In --json output, "inf" stands for a value the API documents as infinite (the period of a '
    "steady motion, the fast precession rate at 90°, ...); any other non-finite number is refused."
)

#: Largest mesh file `poinsot inertia` reads (bytes). A mesh at this size has millions of
#: triangles (a binary STL stores 50 bytes a triangle); the check comes before any byte is
#: read, so a device or an endless file is never read into memory.
MAX_MESH_FILE_BYTES = 256 * 1024 * 1024

#: Result fields that the API documents as infinite in limiting cases: the period of ω and
#: the flip interval of a steady rotation (FreeRigidBody.period, .flip_interval), the nutation
#: period of a top that never returns (HeavyTop.nutation_period), the precession period of a
#: top whose axis does not turn on average (HeavyTop.precession_period), the cubic's root u3 when
#: m g l = 0 (HeavyTop.cubic_roots), the fast steady-precession rate at θ0 = 90° and the
#: fast-top approximations 2.120/2.121 where they diverge (HeavyTop.steady_precession), the
#: hours of one full turn of the Foucault pendulum at the equator and the simulated plane's
#: period of a turn where it does not turn (FoucaultRun.full_turn_period). NaN is refused everywhere,
#: and any other infinity.
MAY_BE_INFINITE = frozenset(
    {
        "period",
        "flip_interval",
        "nutation_period",
        "precession_period",
        "cubic_roots",
        "steady_precession_at_theta0",
        "full_turn_hours",
        "full_turn_period",
    }
)

#: Argument names of the Python API that a command's option spells differently (the error
#: messages of the core name the API's argument; the command line names its option).
API_NAMES = {
    "free": {"omega0": "omega", "t_end": "duration"},
    "inertia": {"path": "shape"},
    "top": {"pivot_distance": "pivot", "omega3": "spin"},
}


class WithUnit(float):
    """A number given on the command line with a unit (``5cm``, ``30deg``), converted to SI:
    an angle in radians whatever ``--degrees`` (:func:`_read_units`)."""


def _dimension(ctx: click.Context | None, param: click.Parameter | None) -> str | None:
    """The dimension of the option ``param`` (a key of ``_units.DIMENSIONS``): that of the API
    argument it stands for (``_units.ARGUMENTS``, through :data:`API_NAMES`), or None."""
    if param is None or param.name is None:
        return None
    command = ctx.command.name if ctx is not None else None
    renamed = {v: k for k, v in API_NAMES.get(command or "", {}).items()}
    name = renamed.get(param.name, param.name)
    dims = _ARGUMENTS_LOWER.get(name.lower())
    return dims[0] if dims else None


class FiniteFloat(click.ParamType):
    """A finite real number: ``nan``, ``inf`` and numbers that overflow a double (``1e400``)
    are usage errors, like words that are not numbers. A number may carry a unit of the
    option's dimension (``5cm``, ``1500rpm``, ``50d53m``, ``12kn``; ``_units.parse``), returned
    in SI as a :class:`WithUnit`; a unit of another dimension is a usage error saying which
    ("--latitude: expected an angle, got 3 m")."""

    name = "number"

    def convert(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> float:
        if isinstance(value, float) and math.isfinite(value):
            return value
        try:
            f = float(value)
        except (TypeError, ValueError, OverflowError):
            f = self._with_unit(value, param, ctx)
        if not math.isfinite(f):
            self.fail(f"{value!r} is not a finite number", param, ctx)
        return f

    def _with_unit(
        self, value: Any, param: click.Parameter | None, ctx: click.Context | None
    ) -> float:
        from . import _units

        if not isinstance(value, str):
            self.fail(f"{value!r} is not a number", param, ctx)
        dim = _dimension(ctx, param)
        try:
            if dim is None:
                number, given = _units.parse(value, "number")
            else:
                number, given = _units.parse(value, dim)
        except ValueError as exc:
            if "not a number" in str(exc):
                self.fail(f"{value!r} is not a number", param, ctx)
            flag = _flag(param) if param is not None else "value"
            raise click.UsageError(f"{flag}: {exc}", ctx) from None
        except OverflowError:
            self.fail(f"{value!r} is not a finite number", param, ctx)
        return WithUnit(number) if given else number


#: The dimensions of ``_units.ARGUMENTS`` by lower-case name (an option's parameter name is
#: lower case: --I1 is i1).
_ARGUMENTS_LOWER = {name.lower(): dims for name, dims in _ARGUMENTS.items()}


def _read_units(ctx: click.Context) -> None:
    """With ``--degrees``, an angle (and for ``top`` an angular rate) given with a unit goes back
    to degrees, since the command converts all its angles from degrees: ``--theta 0.5rad
    --degrees`` is 0.5 rad, like ``--theta 28.65 --degrees``."""
    if not ctx.params.get("degrees"):
        return
    read = ("angle", "angular rate") if ctx.command.name == "top" else ("angle",)
    for p in ctx.command.params:
        value = ctx.params.get(p.name or "")
        if isinstance(value, WithUnit) and _dimension(ctx, p) in read:
            ctx.params[p.name or ""] = math.degrees(value)


def _degrees_hint(ctx: click.Context, param: click.Parameter) -> str:
    """The hint "; did you mean --degrees (or 30deg)?" for an angle given without unit,
    refused in radians, where the command reads degrees with --degrees and the number is a
    plausible angle in degrees; else ""."""
    value = ctx.params.get(param.name or "")
    if (
        not isinstance(value, float)
        or isinstance(value, WithUnit)
        or _dimension(ctx, param) != "angle"
        or "degrees" not in ctx.params
        or ctx.params["degrees"]
        or not abs(value) <= 360.0
    ):
        return ""
    return f"; did you mean --degrees (or {value:g}deg)?"


#: The type of every real-valued option.
FINITE = FiniteFloat()


def _number(
    flag: str, *decls_help: str, call: str | None = None, **kwargs: Any
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """A finite-number option: ``flag``, its other declarations (its parameter name) and its
    help; with ``call``, the default (shown) the core's for that call's argument of the
    option's name (``poinsot._core.DEFAULTS``); required unless it has a default. ``kwargs``
    are click's (``nargs``, ``type`` for a choice)."""
    *decls, help_ = decls_help
    if call is not None:
        name = decls[0] if decls else flag.lstrip("-").replace("-", "_")
        table = cast("dict[str, dict[str, Any]]", _DEFAULTS)  # read by a name given here
        kwargs.update(default=table[call][name], show_default=True)
    kwargs.setdefault("type", FINITE)
    return click.option(flag, *decls, required="default" not in kwargs, help=help_, **kwargs)


class Refused(click.ClickException):
    """Input poinsot refuses, or a run that cannot finish (exit status :data:`EXIT_REFUSED`)."""

    exit_code = EXIT_REFUSED


def _one_line(text: str) -> str:
    return " ".join(str(text).split())


def _fail(message: str, code: int) -> NoReturn:
    """Ends the command: ``error: message`` as one line on stderr, exit status ``code``."""
    try:
        click.echo(f"error: {_one_line(message)}", err=True)
    except OSError:  # stderr is gone too: the exit status still tells
        pass
    sys.exit(code)


def _flag(param: click.Parameter) -> str:
    if isinstance(param, click.Option):
        return max(param.opts, key=len)
    return (param.name or "").upper()


def _given(ctx: click.Context) -> str:
    """The options and arguments given on the command line, as the user could retype them."""
    from click.core import ParameterSource

    parts = []
    for p in ctx.command.params:
        if p.name is None or ctx.get_parameter_source(p.name) not in (
            ParameterSource.COMMANDLINE,
            ParameterSource.ENVIRONMENT,
        ):
            continue
        value = ctx.params.get(p.name)
        if isinstance(p, click.Option) and p.is_flag:
            parts.append(_flag(p))
            continue
        shown = " ".join(str(v) for v in value) if isinstance(value, (tuple, list)) else str(value)
        parts.append(shown if isinstance(p, click.Argument) else f"{_flag(p)} {shown}")
    return " ".join(parts)


def _option_for(ctx: click.Context, api_name: str) -> click.Parameter | None:
    """The option of ``ctx``'s command that stands for the API's argument ``api_name``."""
    alias = API_NAMES.get(ctx.command.name or "", {}).get(api_name, api_name)
    for p in ctx.command.params:
        if p.name is not None and p.name.lower() == alias.lower():
            return p
    return None


def _explain(ctx: click.Context, exc: PoinsotError) -> str:
    """poinsot's message with the API's argument replaced by the command's option; where the
    message names a derived quantity instead, the options given are added."""
    text = _one_line(str(exc))
    name, sep, rest = text.partition(":")
    if sep and name.replace("_", "").isalnum():
        param = _option_for(ctx, name.strip())
        if param is not None:
            return f"{_flag(param)}:{rest}{_degrees_hint(ctx, param)}"
    given = _given(ctx)
    return f"{text} (given {given})" if given else text


class _PoinsotCommand(click.Command):
    """Runs a command so that it ends in one line, never a traceback: poinsot's errors name
    the option (:data:`EXIT_REFUSED`), Ctrl+C prints "interrupted" (:data:`EXIT_INTERRUPTED`),
    an output that cannot be written is refused, anything unforeseen is one line too."""

    def get_short_help_str(self, limit: int = 45) -> str:
        """The summary ``poinsot --help`` lists: the first paragraph of the help, whole (click
        would cut it at the first full stop, "(eqs." included, or at ``limit`` characters with
        "..."); the help formatter wraps it to the terminal instead."""
        if self.short_help or not self.help:
            return super().get_short_help_str(limit)
        return " ".join(self.help.split("\n\n")[0].split())

    def invoke(self, ctx: click.Context) -> Any:
        _read_units(ctx)
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt:
            _fail_interrupted()
        except PoinsotError as exc:
            _fail(_explain(ctx, exc), EXIT_REFUSED)
        except click.ClickException:
            raise
        except ImportError as exc:  # an optional extra (plot, mesh) that is not installed
            _fail(f"{exc} (given {_given(ctx)})", EXIT_REFUSED)
        except OSError as exc:
            if exc.errno == errno.EPIPE:  # the reader of our output went away: nothing to say
                _quiet_broken_pipe()
            where = f" {exc.filename}" if exc.filename else " the output"
            _fail(f"cannot write{where}: {exc.strerror or exc}", EXIT_REFUSED)
        except MemoryError:
            _fail(f"not enough memory for this request (given {_given(ctx)})", EXIT_REFUSED)
        except Exception as exc:  # a bug: still one line, with what is needed to report it
            if os.environ.get("POINSOT_TRACEBACK"):
                raise
            _fail(
                f"internal error, please report it: {type(exc).__name__}: {exc} (given {_given(ctx)}; "
                "POINSOT_TRACEBACK=1 shows where)",
                EXIT_REFUSED,
            )


def _fail_interrupted() -> NoReturn:
    _fail_line("interrupted", EXIT_INTERRUPTED)


def _fail_line(line: str, code: int) -> NoReturn:
    with contextlib.suppress(OSError):
        click.echo(line, err=True)
    sys.exit(code)


def _quiet_broken_pipe() -> NoReturn:
    # Point stdout at /dev/null so that the interpreter's final flush does not complain.
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass
    sys.exit(EXIT_REFUSED)


class _PoinsotGroup(click.Group):
    """The ``poinsot`` group: its commands are :class:`_PoinsotCommand`; usage errors are one
    line (:data:`EXIT_USAGE`) instead of click's usage block."""

    command_class = _PoinsotCommand

    def main(
        self,
        args: Any = None,
        prog_name: str | None = None,
        complete_var: str | None = None,
        standalone_mode: bool = True,
        **extra: Any,
    ) -> Any:
        if not standalone_mode:
            return super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        try:
            rv = super().main(args, prog_name, complete_var, standalone_mode=False, **extra)
        except click.UsageError as exc:
            no_args_help = getattr(click.exceptions, "NoArgsIsHelpError", None)
            if no_args_help is not None and isinstance(exc, no_args_help):
                exc.show()
                sys.exit(EXIT_USAGE)
            hint = f" (see '{exc.ctx.command_path} --help')" if exc.ctx is not None else ""
            _fail(exc.format_message() + hint, EXIT_USAGE)
        except click.ClickException as exc:
            _fail(exc.format_message(), exc.exit_code)
        except (click.Abort, KeyboardInterrupt, EOFError):
            _fail_interrupted()
        except OSError as exc:
            if exc.errno == errno.EPIPE:
                _quiet_broken_pipe()
            raise
        sys.exit(rv if isinstance(rv, int) else 0)


def _jsonable(value: Any) -> Any:
    """numpy arrays and scalars → plain lists and floats (inf/nan → strings, as JSON has none)."""
    if isinstance(value, dict):
        return {k: _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, np.ndarray):
        return _jsonable(value.tolist())
    if isinstance(value, (np.floating, float)):
        f = float(value)
        return f if np.isfinite(f) else str(f)
    if isinstance(value, np.integer):
        return int(value)
    return value


def _numbers(value: Any, path: str, top: str) -> Iterator[tuple[str, str, float]]:
    """Every real number in a result: (where, its top-level field, value)."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _numbers(v, f"{path}.{k}" if path else str(k), top or str(k))
    elif isinstance(value, (list, tuple, np.ndarray)):
        items = value.ravel().tolist() if isinstance(value, np.ndarray) else value
        for i, v in enumerate(items):
            yield from _numbers(v, f"{path}[{i}]", top)
    elif isinstance(value, (float, np.floating)):
        yield path, top, float(value)


def require_finite(data: dict[str, Any]) -> None:
    """Refuses (:class:`Refused`, naming the options given) a result holding a NaN or an
    infinity, except an infinity in the fields of :data:`MAY_BE_INFINITE` (documented limits,
    such as the period of a steady motion)."""
    for where, field, v in _numbers(data, "", ""):
        if math.isnan(v) or (math.isinf(v) and field not in MAY_BE_INFINITE):
            ctx = click.get_current_context(silent=True)
            given = _given(ctx) if ctx is not None else ""
            raise Refused(
                f"the result is not a finite number ({where} = {v}) for {given}: these inputs "
                "are beyond what poinsot can compute, so nothing is printed"
            )


def _interactive() -> bool:
    """Whether stdout is a terminal: progress bars only there (piped output stays clean)."""
    try:
        return sys.stdout.isatty()
    except (AttributeError, ValueError):
        return False


#: Whether stderr is a terminal (render progress bars are drawn there, and only there).
_stderr_interactive = stderr_interactive


@contextlib.contextmanager
def render_progress(description: str) -> Iterator[Callable[[int, int], None]]:
    """A callback ``progress(done, total)`` for a render (frames of an animation, pictures of
    a set) that draws a rich progress bar on stderr once the render has taken longer than
    :data:`SHOW_PROGRESS_AFTER_S`, and only when stderr is a terminal (piped or captured output
    stays clean, as with the CLI's other progress bars); the bar is removed when done."""
    with delayed_bar(
        description, show=_stderr_interactive(), delay=SHOW_PROGRESS_AFTER_S
    ) as update:
        yield update


def _picture_options(
    plot_help: str, animate_help: str | None = None
) -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """The options ``--plot PATH``, ``--animate PATH`` (when ``animate_help`` is given) and
    ``--style`` of a computing command."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        f = click.option(
            "--style",
            type=click.Choice(list(STYLES)),
            default="paper",
            show_default=True,
            help=f"Style of {'--plot and --animate' if animate_help else '--plot'}: paper (a "
            "page) or slides (a projector: larger text, thicker lines, 200 dpi).",
        )(f)
        file = click.Path(dir_okay=False)
        if animate_help is not None:
            more = " A .gif, or a .mp4 when ffmpeg is installed."
            f = click.option("--animate", "animate_path", type=file, help=animate_help + more)(f)
        more = " The suffix picks the format (.png, .pdf, .svg, ...)."
        return click.option("--plot", "plot_path", type=file, help=plot_help + more)(f)

    return deco


#: Suffixes ``--animate`` writes: the writer and the program it needs (None: Pillow, always
#: there with matplotlib).
ANIMATION_SUFFIXES = {".gif": None, ".mp4": "ffmpeg"}


def _check_animation_path(path: str) -> None:
    """--animate must name a file in an existing directory, ending in .gif, or in .mp4 with
    ffmpeg on PATH: a usage error (naming --animate) otherwise, before any work starts."""
    import shutil

    target = Path(path)
    if not target.parent.is_dir():
        raise click.UsageError(
            f"--animate: no directory '{target.parent}' to save {target.name} into"
        )
    suffix = target.suffix.lower()
    if suffix not in ANIMATION_SUFFIXES:
        raise click.UsageError(
            f"--animate: cannot write '{target.suffix or target.name}' animations; give a path "
            "ending in .gif (or .mp4, with ffmpeg installed)"
        )
    program = ANIMATION_SUFFIXES[suffix]
    if program is not None and shutil.which(program) is None:
        raise click.UsageError(
            f"--animate: writing {suffix} needs {program}, which is not installed (not on "
            "PATH); give a .gif path, or install ffmpeg"
        )
    try:
        import matplotlib  # noqa: F401
    except ImportError as exc:
        raise Refused(
            "--animate needs matplotlib, which is not installed: pip install 'poinsot[plot]'"
        ) from exc


def _check_pictures(plot_path: str | None, animate_path: str | None = None) -> None:
    """Checks --plot and --animate before any work starts (usage errors naming them)."""
    if plot_path is not None:
        _check_picture_path(plot_path)
    if animate_path is not None:
        _check_animation_path(animate_path)


def _echo_saved(data: dict[str, Any]) -> None:
    """Says where the pictures of --plot and --animate went (after the table)."""
    for p in data.get("plots", []):
        click.echo(f"saved {p}")


#: ``--json`` of the computing commands (read by :func:`_report`).
_JSON = click.option(
    "--json", "as_json", is_flag=True, help="Print one JSON document instead of a table."
)


def _keep_picture(
    data: dict[str, Any], path: str | None, draw: str, /, *args: Any, **kw: Any
) -> None:
    """--plot: when ``path`` is given, saves the figure ``draw(*args, **kw)`` (``draw`` a
    function of :mod:`poinsot.plots`, "module.function", imported only then) and lists
    ``path`` in ``data["plots"]``."""
    if path is not None:
        _save_figure(_plotter(draw)(*args, **kw), path)
        data.setdefault("plots", []).append(path)


def _keep_animation(
    data: dict[str, Any],
    path: str | None,
    draw: str,
    rate: int,
    what: str,
    /,
    *args: Any,
    **kw: Any,
) -> None:
    """--animate: as :func:`_keep_picture`, the animation ``draw(*args, **kw)`` written at
    ``rate`` frames a second under a progress bar that says ``what``."""
    if path is not None:
        _save_animation(_plotter(draw)(*args, **kw), path, rate, what)
        data.setdefault("plots", []).append(path)


def _plotter(name: str) -> Callable[..., Any]:
    """The function "module.function" of :mod:`poinsot.plots` (matplotlib imported now)."""
    import importlib

    module, function = name.rsplit(".", 1)
    return getattr(importlib.import_module(f"{__package__}.plots.{module}"), function)  # type: ignore[no-any-return]


def _report(
    data: dict[str, Any],
    as_json: bool,
    title: str,
    columns: tuple[str, ...],
    rows: Iterable[tuple[str, ...]],
    notes: Iterable[str] = (),
    lines: Iterable[str] = (),
) -> None:
    """A command's output: ``data`` as one JSON document (--json), or else its answer in plain
    words (``data["summary"]``, :mod:`poinsot._answers`), a table (its ``columns``: the first
    the quantity's name, the others right-aligned), the ``notes`` under it (rich's text),
    ``lines`` as they are, and where the pictures went."""
    if as_json:
        emit_json(data)
        return
    from rich.console import Console
    from rich.table import Table

    table = Table(title=title)
    table.add_column(columns[0])
    for column in columns[1:]:
        table.add_column(column, justify="right")
    for row in rows:
        table.add_row(*row)
    console = Console()
    _print_summary(console, data)
    console.print(table)
    for note in notes:
        console.print(note)
    for line in lines:
        click.echo(line)
    _echo_saved(data)


def _print_summary(console: Any, data: dict[str, Any]) -> None:
    """The answer in plain words, wrapped to the terminal, before the tables."""
    if "summary" in data:
        console.print(data["summary"], markup=False, highlight=False)
        console.print()


#: Samples of a Foucault run drawn by --plot and --animate, per half swing (between turning
#: points), and at most in all: enough for a smooth track and a bob that does not jump.
FOUCAULT_SAMPLES_PER_TURN = 24
FOUCAULT_MAX_SAMPLES = 200_001


def _save_figure(fig: Any, path: str | Path, option: str = "--plot") -> None:
    """Saves a figure of --plot (or ``option``; at its style's dpi), a write failure refused
    naming the option."""
    from .plots._mpl import pyplot

    try:
        fig.savefig(path)
    except OSError as exc:
        raise Refused(f"{option}: cannot write {path}: {exc.strerror or exc}") from exc
    finally:
        pyplot().close(fig)


def _save_animation(anim: Any, path: str, fps: int, description: str) -> None:
    """Saves an animation of --animate with a progress bar, a write failure refused naming
    --animate."""
    from .plots._mpl import pyplot, save_animation

    try:
        with render_progress(description) as progress:
            save_animation(anim, path, fps, progress=progress)
    except OSError as exc:
        raise Refused(f"--animate: cannot write {path}: {exc.strerror or exc}") from exc
    finally:
        pyplot().close(anim._fig)


#: A printed value is 0 when it is within this many machine epsilons (2.2e-16) of the size
#: of the quantities it was computed from (see :func:`at_precision`).
PRECISION_EPS = 8


def at_precision(value: float, scale: float, spec: str = ".9g") -> str:
    """``value`` formatted with ``spec`` — or ``"0"`` when it is below the precision of the
    computation that produced it: |value| ≤ 8 ε × |scale|, with ε = 2.2e-16 the machine
    epsilon of a double and ``scale`` the size of the quantities the value was computed from.

    A value computed from numbers of size S carries a round-off error of a few ε × S, so
    anything smaller is that error, not a result: the drift of a shot fired on a planet that
    does not turn, the landing point's component across the line of fire, comes out as
    8.1e-28 m or 3.6e-12 m for a range of 65 km (ε × range = 1.4e-11 m) and reads 0. A value
    above the bound is printed as it is, however small: a drift of 1e-9 m over a range of
    1 m is a result. NaN and infinities are printed as they are. The rule is documented in
    docs/limits.md ("What the command line prints")."""
    v, k = float(value), abs(float(scale))
    if (
        math.isfinite(v)
        and math.isfinite(k)
        and abs(v) <= PRECISION_EPS * sys.float_info.epsilon * k
    ):
        return "0"
    return format(v, spec)


def emit_json(data: dict[str, Any]) -> None:
    """Print ``data`` as one JSON document on stdout."""
    click.echo(json.dumps(_jsonable(data), indent=2))


@click.group(
    cls=_PoinsotGroup,
    context_settings={"help_option_names": ["-h", "--help"]},
    epilog=EXIT_STATUSES,
)
@click.version_option(package_name="poinsot")
def main() -> None:
    """poinsot: moving frames and the motion of rigid bodies.

    Start with `poinsot tour`, the course unit computed from end to end. Each computing command
    opens with its answer in plain words, then the tables it is made from.
    """


@main.command()
def tour() -> None:
    """The whole unit, computed: a guided tour of what poinsot does."""
    from .tour import run_tour

    run_tour()


@main.command()
@click.argument("shape")
@_number("--mass", "Mass in kg (standard shapes; default 1).", default=None)
@_number("--radius", "Radius in m (sphere, shell, cylinder, cone, disk, ring).", default=None)
@_number("--height", "Height in m (cylinder, cone).", default=None)
@_number("--length", "Length in m (rod).", default=None)
@_number("--sides", "Side lengths a b c in m along x y z (cuboid).", nargs=3, default=None)
@_number("--semi-axes", "semi_axes", "Semi-axes a b c in m (ellipsoid).", nargs=3, default=None)
@_number("--density", "Density in kg/m³ (mesh files; default 1).", default=None)
@_picture_options("Save a picture of the inertia ellipsoid and principal axes to this file.")
@_JSON
def inertia(
    shape: str,
    mass: float | None,
    radius: float | None,
    height: float | None,
    length: float | None,
    sides: tuple[float, float, float] | None,
    semi_axes: tuple[float, float, float] | None,
    density: float | None,
    plot_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """Mass properties of a standard SHAPE or of a closed mesh file.

    SHAPE is one of sphere, shell, cylinder, cone, cuboid, ellipsoid, rod, disk, ring
    (symmetry axis along z; the cone's apex at the origin), or a path to a mesh file (.stl,
    .obj, ...; needs the `mesh` extra, trimesh). Prints mass, centre of mass, the inertia tensor about
    the centre of mass (products of inertia negated, eqs. 2.46–2.50), principal moments and
    axes, and the kind of top.

    \b
    Examples:
      poinsot inertia cuboid --mass 2 --sides 1 2 3
      poinsot inertia cone --mass 1 --radius 0.5 --height 2 --json
      poinsot inertia part.stl --density 7850
    """
    from .body import RigidBody

    if shape in SHAPES:
        ctor, needs = SHAPES[shape]
        given = {
            "radius": radius,
            "height": height,
            "length": length,
            "sides": sides,
            "semi_axes": semi_axes,
        }
        missing = [n for n in needs if given[n] is None]
        if missing:
            opts = ", ".join("--" + n.replace("_", "-") for n in missing)
            raise click.UsageError(f"shape '{shape}' needs {opts}")
        extra = [n for n, v in given.items() if v is not None and n not in needs]
        if extra:
            opts = ", ".join("--" + n.replace("_", "-") for n in extra)
            raise click.UsageError(f"shape '{shape}' does not take {opts}")
        if density is not None:
            raise click.UsageError(
                "--density applies to mesh files; give --mass for standard shapes"
            )
        if plot_path is not None:
            _check_picture_path(plot_path)
        body = getattr(RigidBody, ctor)(1.0 if mass is None else mass, *(given[n] for n in needs))
        source = shape
        name = f"{shape} {_dimensions(given, needs)}, {body.mass:g} kg"
    else:
        path = _mesh_file(shape)
        if mass is not None:
            raise click.UsageError("--mass applies to standard shapes; give --density for a mesh")
        if plot_path is not None:
            _check_picture_path(plot_path)  # before a long mesh is read
        body = _load_mesh(path, 1.0 if density is None else density)
        source = str(path)
        name = f"mesh {path.name}, {body.mass:.4g} kg"

    data = {"source": source, **body.to_dict()}
    require_finite(data)
    data["summary"] = _answers.inertia(data)
    _keep_picture(data, plot_path, "inertia.plot_inertia_ellipsoid", body, name=name, style=style)
    if as_json:
        emit_json(data)
        return
    _print_body(source, body, data)
    _echo_saved(data)


def _dimensions(given: dict[str, Any], needs: tuple[str, ...]) -> str:
    """A standard shape's dimensions as a title says them: "r = 0.5 m, h = 2 m", "1 × 2 × 3 m"."""
    symbols = {"radius": "r = ", "height": "h = ", "length": "l = ", "semi_axes": "semi-axes "}
    parts = []
    for n in needs:
        v = given[n]
        shown = " × ".join(f"{x:g}" for x in v) if isinstance(v, tuple) else f"{v:g}"
        parts.append(f"{symbols.get(n, '')}{shown} m")
    return ", ".join(parts)


def _mesh_file(shape: str) -> Path:
    """The mesh file that SHAPE names, checked before a byte is read: it must exist and be a
    regular file (not a directory, device, pipe or socket) of 1 to MAX_MESH_FILE_BYTES bytes
    (files under /proc report 0 bytes: refused too)."""
    path = Path(shape)
    try:
        st = path.stat()
    except (FileNotFoundError, NotADirectoryError):
        raise click.UsageError(
            f"'{shape}' is neither a shape ({', '.join(SHAPES)}) nor an existing mesh file"
        ) from None
    except OSError as exc:
        raise click.UsageError(f"SHAPE: cannot look up '{shape}': {exc.strerror or exc}") from None
    if stat.S_ISDIR(st.st_mode):
        raise click.UsageError(f"SHAPE: '{shape}' is a directory, not a mesh file")
    if not stat.S_ISREG(st.st_mode):
        raise click.UsageError(
            f"SHAPE: '{shape}' is not a regular file (a device, pipe or socket), not a mesh file"
        )
    if st.st_size == 0:
        raise Refused(
            f"SHAPE: '{shape}' is empty (the file system reports 0 bytes): no mesh to read"
        )
    if st.st_size > MAX_MESH_FILE_BYTES:
        raise Refused(
            f"SHAPE: '{shape}' is {st.st_size} bytes, more than the {MAX_MESH_FILE_BYTES} "
            "bytes (256 MiB) poinsot inertia reads"
        )
    if not os.access(path, os.R_OK):
        raise Refused(f"SHAPE: cannot read '{shape}': permission denied")
    return path


def _load_mesh(path: Path, density: float) -> Any:
    """RigidBody.load_mesh, its failures as one line: trimesh raises whatever its parsers
    meet in a file that is not a mesh (ValueError, KeyError, IndexError, ...)."""
    import logging

    from .body import RigidBody

    # trimesh logs parser warnings to stderr when logging is not set up: not ours to print.
    trimesh_log = logging.getLogger("trimesh")
    had_handlers = trimesh_log.handlers[:]
    if not had_handlers:
        trimesh_log.addHandler(logging.NullHandler())
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return RigidBody.load_mesh(path, density=density)
    except PoinsotError as exc:
        text = _one_line(str(exc))
        if text.startswith("density:"):
            raise
        if text.startswith("path:"):
            raise Refused(f"SHAPE:{text[len('path:') :]}") from exc
        raise Refused(f"SHAPE: '{path}' is not a valid mesh: {text}") from exc
    except ImportError as exc:
        missing = f"the Python package '{exc.name}'" if exc.name else "a Python package"
        raise Refused(
            f"SHAPE: reading '{path}' needs {missing}, which is not installed: "
            "pip install 'poinsot[mesh]'"
        ) from exc
    except (KeyboardInterrupt, MemoryError):
        raise
    except Exception as exc:
        detail = _one_line(f"{type(exc).__name__}: {exc}")[:200]
        raise Refused(f"SHAPE: trimesh cannot read '{path}' as a mesh ({detail})") from exc
    finally:
        if not had_handlers:
            trimesh_log.handlers[:] = []


def _picture_kinds(who: str) -> dict[str, str]:
    """The file types matplotlib writes (suffix: description); refused, saying that ``who``
    needs it, when matplotlib is not installed."""
    try:
        from matplotlib.backend_bases import FigureCanvasBase
    except ImportError as exc:
        raise Refused(
            f"{who} needs matplotlib, which is not installed: pip install 'poinsot[plot]'"
        ) from exc
    return FigureCanvasBase.get_supported_filetypes()  # type: ignore[no-any-return]


def _check_picture_path(plot_path: str) -> None:
    """--plot must name a file in an existing directory, with a suffix matplotlib can write."""
    target = Path(plot_path)
    parent = target.parent
    if not parent.is_dir():
        raise click.UsageError(f"--plot: no directory '{parent}' to save {target.name} into")
    suffix = target.suffix.lower().lstrip(".")
    if suffix:
        kinds = _picture_kinds("--plot")
        if suffix not in kinds:
            raise click.UsageError(
                f"--plot: matplotlib cannot write '.{suffix}' files; use one of "
                + ", ".join(sorted(kinds))
            )


def _print_body(source: str, body: Any, data: dict[str, Any]) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console()
    _print_summary(console, data)
    fmt = "{:.6g}".format
    table = Table(title=f"mass properties of {source}", show_header=False)
    table.add_row("mass", f"{fmt(body.mass)} kg")
    table.add_row("centre of mass", "(" + ", ".join(fmt(c) for c in body.center_of_mass) + ") m")
    rows = [" ".join(f"{v:>11.6g}" for v in row) for row in body.inertia]
    table.add_row("inertia about c.o.m.", "\n".join(rows) + "  kg·m²")
    table.add_row("principal moments", ", ".join(fmt(m) for m in body.principal_moments) + " kg·m²")
    axes = body.principal_axes
    table.add_row(
        "principal axes",
        "\n".join(
            f"e{i + 1} = (" + ", ".join(f"{v: .4f}" for v in axes[:, i]) + ")" for i in range(3)
        ),
    )
    table.add_row("kind", body.kind)
    console.print(table)


def _earth(solar_day: bool) -> Any:
    from .earth import Earth

    return Earth.solar_day() if solar_day else Earth()


def _angle_unit(degrees: bool) -> str:
    return "°" if degrees else " rad"


@main.command()
@_number("--height", "Drop height in m (> 0).")
@_number("--latitude", "Latitude, north-positive (rad, or degrees with --degrees).")
@click.option("--degrees", is_flag=True, help="Read --latitude in degrees.")
@click.option(
    "--solar-day",
    "solar_day",
    is_flag=True,
    help="Use the unit's rate 2π/86400 instead of the sidereal rate.",
)
@_number(
    "--gravity",
    "Uniform gravity (the unit's model) or g falling off with height.",
    call="Earth.drop",
    type=click.Choice(["uniform", "inverse-square"]),
)
@_picture_options(
    "Save a picture of the fall to this file: east and south displacement against height, "
    "beside 2.42 and the second-order south."
)
@_JSON
def fall(
    height: float,
    latitude: float,
    degrees: bool,
    solar_day: bool,
    gravity: str,
    plot_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """A body dropped from rest on the rotating Earth (eqs. 2.32–2.42).

    Integrates the fall exactly in the rotating frame and prints the landing point beside
    the unit's first-order eastward deflection (2.42) and the second-order southward one.

    \b
    Examples:
      poinsot fall --height 100 --latitude 45 --degrees          # the unit's 1.55e-2 m
      poinsot fall --height 100 --latitude 45 --degrees --solar-day --json
      poinsot fall --height 100 --latitude 45 --degrees --plot fall.png --style slides
    """
    _check_pictures(plot_path)
    earth = _earth(solar_day)
    res = earth.drop(height, latitude, degrees, gravity=gravity)
    data = {
        "height": height,
        "latitude": latitude,
        "degrees": degrees,
        "rotation_rate": earth.rotation_rate,
        "g": earth.g,
        "gravity": gravity,
        "time": res.time,
        "east": res.east,
        "north": res.north,
        "first_order_east": res.first_order_east,
        "second_order_south": res.second_order_south,
    }
    require_finite(data)
    data["summary"] = _answers.fall(data)
    _keep_picture(data, plot_path, "earth.plot_trajectory", res, style=style)
    _report(
        data,
        as_json,
        f"drop from {height:g} m at latitude {latitude:g}{_angle_unit(degrees)} "
        f"(ω = {earth.rotation_rate:.7g} rad/s, g = {earth.g:g} m/s², {gravity} gravity)",
        ("quantity", "exact (rotating frame)", "closed form"),
        [
            (
                "time of fall (s)",
                f"{res.time:.9g}",
                f"{earth.fall_time(height):.9g}  √(2h/g), 2.41",
            ),
            ("east (m)", f"{res.east:.6e}", f"{res.first_order_east:.6e}  eq. 2.42"),
            ("south (m)", f"{-res.north:.6e}", f"{res.second_order_south:.6e}  ¾ω² sin2λ h²/g"),
        ],
    )


@main.command()
@_number("--speed", "Launch speed in m/s.")
@_number("--elevation", "Elevation above the horizon (rad, or degrees with --degrees).")
@_number(
    "--azimuth", "Azimuth clockwise from north (0 north, 90° east).", default=0.0, show_default=True
)
@_number("--latitude", "Latitude, north-positive.")
@_number("--height", "Launch height in m.", call="Earth.projectile")
@click.option("--degrees", is_flag=True, help="Read the angles in degrees.")
@click.option("--solar-day", "solar_day", is_flag=True, help="Use the unit's rate 2π/86400.")
@_picture_options("Save a picture of the flight (its track in east, north, up) to this file.")
@_JSON
def projectile(
    speed: float,
    elevation: float,
    azimuth: float,
    latitude: float,
    height: float,
    degrees: bool,
    solar_day: bool,
    plot_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """A projectile on the rotating Earth, with and without its rotation.

    Prints the time of flight, range and the drift across the line of fire (to the right in
    the northern hemisphere, to the left in the southern: the missiles of the unit).

    \b
    Example:
      poinsot projectile --speed 800 --elevation 45 --azimuth 90 --latitude 50 --degrees
    """
    _check_pictures(plot_path)
    earth = _earth(solar_day)
    kw = {"degrees": degrees, "height": height}
    spin = earth.projectile(speed, elevation, azimuth, latitude, **kw)
    still = earth.projectile(speed, elevation, azimuth, latitude, rotation=False, **kw)
    keys = ("time", "range", "downrange", "drift", "east", "north")
    data = {
        "speed": speed,
        "elevation": elevation,
        "azimuth": azimuth,
        "latitude": latitude,
        "height": height,
        "degrees": degrees,
        "rotation_rate": earth.rotation_rate,
        "with_rotation": {k: getattr(spin, k) for k in keys},
        "without_rotation": {k: getattr(still, k) for k in keys},
    }
    require_finite(data)
    data["summary"] = _answers.projectile(data, at_precision(spin.drift, spin.range))
    _keep_picture(data, plot_path, "earth.plot_trajectory", spin, style=style)

    def row(k: str, label: str) -> tuple[str, ...]:
        a, b = getattr(spin, k), getattr(still, k)
        # each value computed from numbers of the size of its flight's time or range
        size = "time" if k == "time" else "range"
        sa, sb = getattr(spin, size), getattr(still, size)
        diff = at_precision(a - b, max(abs(sa), abs(sb)), "+.4g")
        return label, at_precision(a, sa), at_precision(b, sb), diff

    _report(
        data,
        as_json,
        f"{speed:g} m/s at elevation {elevation:g}{_angle_unit(degrees)}, azimuth "
        f"{azimuth:g}{_angle_unit(degrees)}, latitude {latitude:g}{_angle_unit(degrees)}",
        ("quantity", "rotating Earth", "no rotation", "difference"),
        [
            row("time", "time of flight (s)"),
            row("range", "range (m)"),
            row("downrange", "downrange (m)"),
            row("drift", "drift, right + (m)"),
        ],
    )


@main.command()
@_number("--latitude", "Latitude, north-positive.")
@click.option("--degrees", is_flag=True, help="Read --latitude in degrees.")
@_number("--length", "Pendulum length in m (the Panthéon's 67 m).", call="Earth.foucault")
@_number("--amplitude", "Release displacement in m.", call="Earth.foucault")
@_number("--duration", "Simulated time in s.", call="Earth.foucault")
@click.option("--solar-day", "solar_day", is_flag=True, help="Use the unit's rate 2π/86400.")
@_picture_options(
    "Save the rosette to this file: the track seen from above, and the swing plane's angle "
    "at every turning point against time.",
    "Save an animation of the bob seen from above to this file (200 frames over the run).",
)
@_JSON
def foucault(
    latitude: float,
    degrees: bool,
    length: float,
    amplitude: float,
    duration: float,
    solar_day: bool,
    plot_path: str | None,
    animate_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """The Foucault pendulum, simulated in the rotating frame.

    Measures the turn of the swing plane from the simulation and compares it with ω sin λ
    (clockwise seen from above in the northern hemisphere), and says when the run shows no
    steady turn (the regime: near the equator, too few swings, a planet spinning fast).

    \b
    Example:
      poinsot foucault --latitude 48.85 --degrees --duration 7200
      poinsot foucault --latitude 45 --degrees --duration 600 --plot rosette.png --animate bob.gif
    """
    _check_pictures(plot_path, animate_path)
    earth = _earth(solar_day)
    run = earth.foucault(
        latitude,
        degrees,
        length=length,
        amplitude=amplitude,
        duration=duration,
        samples=2,
        progress=not as_json and _interactive(),
    )
    hours = run.expected_full_turn_period / 3600
    data = {
        "latitude": latitude,
        "degrees": degrees,
        "length": length,
        "amplitude": amplitude,
        "duration": duration,
        "rotation_rate": earth.rotation_rate,
        "precession_rate": run.precession_rate,
        "full_turn_period": run.full_turn_period,
        "expected_rate": run.expected_rate,
        "theory_rate": run.theory_rate,
        "sense": run.sense,
        "regime": run.regime,
        "regime_note": run.regime_note,
        "turning_points": len(run.turn_times),
        "full_turn_hours": hours,
    }
    require_finite(data)
    data["summary"] = _answers.foucault(data)
    if plot_path is not None or animate_path is not None:
        # The table needs only the measurement; a picture needs the track: the same run,
        # sampled FOUCAULT_SAMPLES_PER_TURN times between turning points.
        samples = min(
            max(2, FOUCAULT_SAMPLES_PER_TURN * (len(run.turn_times) + 1) + 1), FOUCAULT_MAX_SAMPLES
        )
        track = earth.foucault(
            latitude,
            degrees,
            length=length,
            amplitude=amplitude,
            duration=duration,
            samples=samples,
        )
        data["plots"] = []
        _keep_picture(data, plot_path, "earth.plot_foucault_rosette", track, style=style)
        _keep_animation(
            data,
            animate_path,
            "earth.animate_foucault",
            25,
            "animating the pendulum",
            track,
            frames=200,
            fps=25,
            style=style,
        )

    def rate(value: float | None) -> str:
        return "—" if value is None else f"{value:.6e}"

    _report(
        data,
        as_json,
        f"Foucault pendulum, L = {length:g} m, latitude {latitude:g}{_angle_unit(degrees)}, "
        f"{duration:g} s simulated",
        ("quantity", "value"),
        [
            ("regime", run.regime),
            ("swing-plane rate, simulated (rad/s)", rate(run.precession_rate)),
            ("small-swing theory (rad/s)", rate(run.theory_rate)),
            ("−ω sin λ (rad/s)", f"{run.expected_rate:.6e}"),
            ("sense seen from above", run.sense),
            ("one full turn (h)", f"{hours:.4g}"),
            ("turning points used", str(len(run.turn_times))),
        ],
        [run.regime_note],
    )


@main.command()
@click.option(
    "--moments", nargs=3, type=FINITE, required=True, help="Principal moments I1 I2 I3 (kg·m²)."
)
@click.option(
    "--omega", nargs=3, type=FINITE, required=True, help="Body angular velocity at t = 0 (rad/s)."
)
@_number("--duration", "Simulated time in s.", default=10.0, show_default=True)
@_number(
    "--method",
    "Integrator (auto: the exact flow).",
    call="simulate",
    type=click.Choice(["auto", "exact", "rk4", "dop853", "splitting2", "splitting4", "splitting6"]),
)
@_number("--dt", "Step of rk4/splitting (s); default 1/1000 turn.", default=None)
@click.option(
    "--samples", type=int, default=201, show_default=True, help="Evenly spaced output times."
)
@_picture_options(
    "Save a picture of ω(t) in the body to this file: the chosen method beside the exact solution.",
    "Save an animation of the body in space to this file (its principal axes and inertia "
    "ellipsoid, L fixed, ω moving): 200 frames over --duration.",
)
@_JSON
def free(
    moments: tuple[float, float, float],
    omega: tuple[float, float, float],
    duration: float,
    method: str,
    dt: float | None,
    samples: int,
    plot_path: str | None,
    animate_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """The torque-free body: the exact solution beside an integrator.

    Reports the regime (which axis ω circles), the period of ω, the invariants and how well the
    chosen method keeps them, and ω and the attitude at the end, against the exact solution.

    \b
    Example:
      poinsot free --moments 1 2 3 --omega 1 0.1 1 --duration 1000 --method splitting6 --dt 0.01
      poinsot free --moments 1 2 3 --omega 0.01 3 0.01 --duration 20 --animate flip.gif
    """
    from .dynamics import simulate

    _check_pictures(plot_path, animate_path)
    from .free import FreeRigidBody

    exact = FreeRigidBody(moments, omega)
    show_bar = (
        not as_json
        and _interactive()
        and method not in ("auto", "exact")
        and duration * np.linalg.norm(omega) > 1e4
    )
    t0 = time.perf_counter()
    if show_bar:
        from rich.progress import Progress

        with Progress(transient=True) as bar:
            task = bar.add_task(f"{method}: {duration:g} s", total=1.0)
            tr = simulate(
                moments,
                omega,
                duration,
                method=method,
                dt=dt,
                samples=samples,
                progress=lambda f: bar.update(task, completed=f),
            )
    else:
        tr = simulate(moments, omega, duration, method=method, dt=dt, samples=samples)
    wall = time.perf_counter() - t0
    w_end, q_end = exact.state(duration)
    q_err = float(
        min(np.linalg.norm(tr.attitude[-1] - q_end), np.linalg.norm(tr.attitude[-1] + q_end))
    )
    stab = exact.axis_stability()
    data = {
        "moments": list(moments),
        "omega0": list(omega),
        "duration": duration,
        "method": tr.method,
        "step": tr.step,
        "steps": tr.steps,
        "wall_time_s": wall,
        "regime": exact.regime,
        "steady_rate": exact.steady_rate,
        "pole_axis": exact.pole_axis,
        "flips_about": exact.flips_about,
        "period": exact.period,
        "parameter": exact.parameter,
        "flip_interval": exact.flip_interval,
        "energy": exact.energy,
        "angular_momentum": exact.angular_momentum,
        "angular_momentum_magnitude": exact.angular_momentum_magnitude,
        "max_energy_error": float(tr.energy_error().max()),
        "max_momentum_error": float(tr.momentum_error().max()),
        "omega_final": tr.omega[-1],
        "attitude_final": tr.attitude[-1],
        "omega_exact": w_end,
        "attitude_exact": q_end,
        "omega_error": float(np.linalg.norm(tr.omega[-1] - w_end)),
        "attitude_error": q_err,
        "axis_stability": [s.stability for s in stab],
    }
    require_finite(data)
    data["summary"] = _answers.free(data)
    _keep_picture(data, plot_path, "free.plot_omega", tr, exact, style=style)
    _keep_animation(
        data,
        animate_path,
        "free.animate_free_body",
        25,
        "animating the body",
        exact,
        duration=duration,
        frames=200,
        fps=25,
        style=style,
    )
    _report(
        data,
        as_json,
        f"free rigid body I = {moments}, ω₀ = {omega}, {duration:g} s by {tr.method}",
        ("quantity", "value"),
        [
            ("regime", exact.regime),
            ("period of ω (s)", f"{exact.period:.10g}"),
            ("Jacobi parameter m", f"{exact.parameter:.10g}"),
            (
                "T (J) / |L| (kg·m²/s)",
                f"{exact.energy:.10g} / {data['angular_momentum_magnitude']:.10g}",
            ),
            ("stability of axes 1, 2, 3", ", ".join(data["axis_stability"])),
            (
                "max |ΔE/E| / max |Δ|L|/|L||",
                f"{data['max_energy_error']:.2e} / {data['max_momentum_error']:.2e}",
            ),
            ("ω at the end (rad/s)", np.array2string(tr.omega[-1], precision=10)),
            ("|ω − ω_exact| / |q − q_exact|", f"{data['omega_error']:.2e} / {q_err:.2e}"),
            ("steps / wall time", f"{tr.steps} / {wall:.3g} s"),
        ],
    )


#: The symmetric solids ``poinsot top --shape`` makes (poinsot.RigidBody's constructors, their
#: axis of symmetry z), with the dimensions each takes.
_TOP_SHAPES = ("disk", "ring", "cylinder", "cone")


def _top_body(
    shape: str | None,
    mass: float | None,
    radius: float | None,
    height: float | None,
    pivot: float | None,
    moments: tuple[float | None, ...],
) -> Any:
    """The :class:`~poinsot.RigidBody` of ``top --shape`` (None without ``--shape``), after
    checking that the options given go together: a body (``--shape``, ``--mass``, ``--radius``,
    ``--height`` for a cylinder or cone, ``--pivot``) or the moments (``--I1 --I3 --mgl``)."""
    from .body import RigidBody

    body_options = {"--mass": mass, "--radius": radius, "--height": height, "--pivot": pivot}
    moment_options = dict(zip(("--I1", "--I3", "--mgl"), moments))
    if shape is None:
        extra = [flag for flag, v in body_options.items() if v is not None]
        if extra:
            raise click.UsageError(f"{', '.join(extra)} go with --shape")
        missing = [flag for flag, v in moment_options.items() if v is None]
        if missing:
            raise click.UsageError(
                f"missing {', '.join(missing)} (or a body: --shape, --mass, --radius, --pivot)"
            )
        return None
    extra = [flag for flag, v in moment_options.items() if v is not None]
    if extra:
        raise click.UsageError(f"{', '.join(extra)} do not go with --shape (the body gives them)")
    needed = ["--mass", "--radius", "--pivot"]
    if shape in ("cylinder", "cone"):
        needed.append("--height")
    elif height is not None:
        raise click.UsageError(f"--height does not go with --shape {shape}")
    missing = [flag for flag in needed if body_options[flag] is None]
    if missing:
        raise click.UsageError(f"--shape {shape} needs {', '.join(missing)}")
    m, r, h = cast("tuple[float, float, float]", (mass, radius, height))  # given, as checked
    if shape == "disk":
        return RigidBody.thin_disk(m, r)
    if shape == "ring":
        return RigidBody.thin_ring(m, r)
    if shape == "cylinder":
        return RigidBody.solid_cylinder(m, r, h)
    # The cone's apex is at the origin; its symmetry axis is z as the others'.
    return RigidBody.solid_cone(m, r, h)


@main.command()
@_number("--I1", "i1", "Moment about a transverse axis through the pivot (kg·m²).", default=None)
@_number("--I3", "i3", "Moment about the symmetry axis (kg·m², ≤ 2 I1).", default=None)
@_number("--mgl", "m g l: weight × pivot-to-centre-of-mass distance (N·m).", default=None)
@click.option(
    "--shape",
    type=click.Choice(_TOP_SHAPES),
    default=None,
    help="Or a real body instead of --I1/--I3/--mgl: its shape (with --mass, --radius, "
    "--height for a cylinder or cone, and --pivot).",
)
@_number("--mass", "Mass of the body (kg; e.g. 0.2kg or 200g).", default=None)
@_number("--radius", "Radius of the body (m; e.g. 5cm).", default=None)
@_number("--height", "Height of a cylinder or cone (m).", default=None)
@_number(
    "--pivot",
    "Distance from the pivot to the centre of mass along the symmetry axis (m; e.g. 10cm).",
    default=None,
)
@_number(
    "--theta",
    "--tilt",
    "theta",
    "Initial nutation angle θ₀ from the upward vertical (rad, or degrees; e.g. 30deg).",
)
@_number("--phi-dot", "phi_dot", "Initial precession rate φ̇₀ (rad/s).", call="HeavyTop.__init__")
@_number("--psi-dot", "psi_dot", "Initial spin rate ψ̇₀ (rad/s).", call="HeavyTop.__init__")
@_number(
    "--spin",
    "Or the spin ω₃ instead of --psi-dot (rad/s; e.g. 1500rpm).",
    default=None,
)
@_number("--theta-dot", "theta_dot", "Initial nutation rate θ̇₀ (rad/s).", call="HeavyTop.__init__")
@click.option(
    "--degrees", is_flag=True, help="Read θ₀ in degrees and the rates in degrees per second."
)
@_picture_options(
    "Save a picture of the axis' path seen from above (waves, loops or cusps between the "
    "turning circles θ₁ and θ₂) to this file.",
    "Save an animation of the top (two nutation periods) to this file.",
)
@click.option(
    "--plot-dir",
    "plot_dir",
    type=click.Path(file_okay=False),
    help="Save the four pictures (V(θ), the axis' path, θ/φ̇/ψ̇ against t, steady rates "
    "against spin: potential.png, axis_locus.png, angles.png, steady_precession.png) and an "
    "animation (top.gif) into this folder (made if needed).",
)
@_JSON
def top(
    i1: float | None,
    i3: float | None,
    mgl: float | None,
    shape: str | None,
    mass: float | None,
    radius: float | None,
    height: float | None,
    pivot: float | None,
    theta: float,
    phi_dot: float,
    psi_dot: float,
    spin: float | None,
    theta_dot: float,
    degrees: bool,
    plot_path: str | None,
    plot_dir: str | None,
    animate_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """The heavy symmetric top (eqs. 2.98–2.121), solved exactly.

    Opens with what the top does in words, then prints the constants of the motion (p_φ, p_ψ,
    E, E′), the turning points θ₁ ≤ θ₂, the motion class (waves, loops, cusps, steady
    precession, sleeping, ...), the nutation period, the mean precession and spin rates, the
    precession period 2π/abs(⟨φ̇⟩), and the steady-precession rates at θ₀ for this spin (exact
    roots of 2.116 beside the unit's 2.120 (corrected) and 2.121, minimum spin 2.119).

    \b
    Examples:
      poinsot top --I1 1 --I3 0.5 --mgl 1 --theta 0.8 --psi-dot 6            # cusps
      poinsot top --I1 1 --I3 0.5 --mgl 0.3 --theta 0.6 --psi-dot 40 --json
      poinsot top --I1 1 --I3 0.5 --mgl 1 --theta 0.8 --phi-dot -0.5 --psi-dot 6 --plot loops.png
      poinsot top --I1 1 --I3 0.5 --mgl 1 --theta 45 --degrees --phi-dot -30 --psi-dot 340 --plot-dir out/
      poinsot top --I1 1 --I3 0.5 --mgl 1 --theta 0.8 --phi-dot -0.5 --psi-dot 6 --animate top.gif
      poinsot top --shape disk --mass 0.2 --radius 5cm --pivot 10cm --spin 1500rpm --tilt 30deg
    """
    from .top import HeavyTop

    _check_pictures(plot_path, animate_path)

    body = _top_body(shape, mass, radius, height, pivot, (i1, i3, mgl))
    if body is not None:  # the moments from the body: HeavyTop.from_body
        made = HeavyTop.from_body(body, cast(float, pivot), theta, spin or 0.0, degrees=degrees)
        i1, i3, mgl = made.I1, made.I3, made.mgl
    assert i1 is not None and i3 is not None and mgl is not None  # checked by _top_body
    if spin is not None:
        if psi_dot:
            raise click.UsageError("--spin and --psi-dot do not go together")
        t = HeavyTop.from_spin(
            i1, i3, mgl, theta, spin, theta_dot=theta_dot, phi_dot=phi_dot, degrees=degrees
        )
    else:
        t = HeavyTop(
            i1,
            i3,
            mgl,
            theta,
            theta_dot=theta_dot,
            phi_dot=phi_dot,
            psi_dot=psi_dot,
            degrees=degrees,
        )
    theta0 = t.initial_state["theta"]
    t1, t2 = t.turning_points
    steady: dict[str, Any]
    try:
        s = HeavyTop.steady_precession(i1, i3, mgl, theta0, t.omega3)
        steady = {
            "slow": s.slow,
            "fast": s.fast,
            "slow_approx_2_121": s.slow_approx,
            "fast_approx_2_120": s.fast_approx,
            "fast_2_120_as_printed": s.fast_approx_as_printed,
            "min_spin_2_119": s.min_spin,
        }
    except PoinsotError as exc:
        steady = {"error": str(exc), "min_spin_2_119": HeavyTop.min_spin(i1, i3, mgl, theta0)}
    data: dict[str, Any] = {
        "I1": i1,
        "I3": i3,
        "mgl": mgl,
        "initial_state": t.initial_state,
        "p_phi": t.p_phi,
        "p_psi": t.p_psi,
        "omega3": t.omega3,
        "energy": t.energy,
        "reduced_energy": t.reduced_energy,
        "turning_points": [t1, t2],
        "cubic_roots": list(t.cubic_roots),
        "motion_class": t.motion_class,
        "vertical_pass": t.vertical_pass,
        "nutation_period": t.nutation_period,
        "mean_precession_rate": t.mean_precession_rate,
        "precession_period": t.precession_period,
        "mean_spin_rate": t.mean_spin_rate,
        "steady_precession_at_theta0": steady,
        "sleeping_threshold": HeavyTop.sleeping_threshold(i1, i3, mgl),
        "sleeping_stable": t.is_sleeping_stable,
    }
    if body is not None:  # what the moments were made of (SI: kg, m)
        data["body"] = {
            "shape": shape,
            "mass": body.mass,
            "radius": radius,
            **({} if height is None else {"height": height}),
            "pivot_distance": pivot,
        }
    require_finite(data)
    data["summary"] = _answers.top(data)
    saved: list[str] = []
    if plot_dir is not None:
        from .plots.top import save_top_plots

        try:
            with render_progress("drawing the top") as progress:
                paths = save_top_plots(t, plot_dir, animation=True, style=style, progress=progress)
            saved = [str(p) for p in paths]
        except OSError as exc:
            raise Refused(
                f"--plot-dir: cannot write into {plot_dir}: {exc.strerror or exc}"
            ) from exc
    if saved:
        data["plots"] = saved
    _keep_picture(data, plot_path, "top.plot_axis_locus", t, style=style)
    _keep_animation(data, animate_path, "top.animate_top", 24, "animating the top", t, style=style)
    rows = [
        ("p_ψ = I₃ω₃ (kg·m²/s)", f"{t.p_psi:.10g}", "2.103"),
        ("p_φ = L_Z (kg·m²/s)", f"{t.p_phi:.10g}", "2.104"),
        ("ω₃ (rad/s)", f"{t.omega3:.10g}", "2.99"),
        ("E (J)", f"{t.energy:.10g}", "2.105"),
        ("E′ = E − p_ψ²/2I₃ (J)", f"{t.reduced_energy:.10g}", "2.109"),
        ("turning points θ₁, θ₂ (rad)", f"{t1:.10g}, {t2:.10g}", "2.110"),
        ("turning points θ₁, θ₂ (°)", f"{np.degrees(t1):.8g}, {np.degrees(t2):.8g}", ""),
        ("motion class", t.motion_class, ""),
        ("nutation period (s)", f"{t.nutation_period:.10g}", "2.112"),
        ("mean precession rate ⟨φ̇⟩ (rad/s)", f"{t.mean_precession_rate:.10g}", "2.106"),
        ("precession period 2π/|⟨φ̇⟩| (s)", f"{t.precession_period:.10g}", ""),
        ("mean spin rate ⟨ψ̇⟩ (rad/s)", f"{t.mean_spin_rate:.10g}", "2.99"),
    ]
    if "error" in steady:
        rows.append(("steady precession at θ₀", "none: spin below the minimum", "2.118"))
    else:
        rows += [
            (
                "steady precession at θ₀: slow / fast (rad/s)",
                f"{steady['slow']:.8g} / {steady['fast']:.8g}",
                "2.116",
            ),
            (
                "  fast-top slow ≈ mgl/p_ψ (rad/s)",
                "none (no spin)"
                if steady["slow_approx_2_121"] is None
                else f"{steady['slow_approx_2_121']:.8g}",
                "2.121",
            ),
            (
                "  fast-top fast ≈ p_ψ/(I₁ cos θ₀) (rad/s)",
                f"{steady['fast_approx_2_120']:.8g}",
                "2.120*",
            ),
        ]
    rows += [
        (
            "minimum spin for steady precession at θ₀ (rad/s)",
            f"{steady['min_spin_2_119']:.8g}",
            "2.119",
        ),
        (
            "sleeping threshold 2√(mgl I₁)/I₃ (rad/s)",
            f"{data['sleeping_threshold']:.8g}",
            "stable" if t.is_sleeping_stable else "unstable",
        ),
    ]
    _report(
        data,
        as_json,
        f"heavy top: I₁ = {i1:g} kg·m², I₃ = {i3:g} kg·m², m g l = {mgl:g} N·m, "
        f"θ₀ = {theta0:.6g} rad",
        ("quantity", "value", "unit's eq."),
        rows,
        lines=[
            "* 2.120 corrected: the unit prints p_ψ/(2 I₁ cos θ₀), a factor 2 too small (see "
            "docs/heavy_top.md)."
        ],
    )


@main.command()
@click.option(
    "--port",
    type=click.IntRange(0, 65535),
    default=0,
    show_default=True,
    help="Port on 127.0.0.1 (0: a free one).",
)
@click.option("--no-browser", "no_browser", is_flag=True, help="Do not open a web browser.")
@click.option("--verbose", is_flag=True, help="Log every request.")
@click.option(
    "--export",
    "export_path",
    metavar="FILE.html",
    help="Write the lab as one self-contained HTML file (about 2 MB) instead of serving it: it "
    "opens by double-click, offline, and can be e-mailed or put on any web space.",
)
def lab(port: int, no_browser: bool, verbose: bool, export_path: str | None) -> None:
    """The browser lab: every scene of the unit to play with, on the same core (WebAssembly).

    Serves the page built into the package on 127.0.0.1 only, and only the page's own files.
    Stop it with Ctrl+C. Build the page from a source checkout with `make lab`. With
    `--export FILE.html`, writes the lab as one file instead (no server).
    """
    from ._labserver import LabServer, export_file, page_dir

    if export_path is not None:
        _export_lab(export_file(), Path(export_path))
        return
    root = page_dir()
    if not (root / "index.html").is_file():
        raise click.ClickException(
            f"the lab page is not built (no {root / 'index.html'}): run `make lab` in a source checkout "
            "(it needs the rust wasm32 target, wasm-bindgen-cli and node)"
        )
    try:
        server = LabServer(root, port, verbose=verbose)
    except OSError as exc:
        raise click.ClickException(f"port {port}: {exc.strerror or exc}") from exc
    click.echo(f"poinsot lab: serving {server.url} (Ctrl+C to stop)")
    sys.stdout.flush()
    if not no_browser:
        import webbrowser

        webbrowser.open(server.url)
    try:
        server.serve_forever()
    except KeyboardInterrupt:
        click.echo("poinsot lab: stopped")
    finally:
        server.server_close()


def _export_lab(source: Path, target: Path) -> None:
    """``poinsot lab --export``: the built one-file lab ``source`` copied to ``target``, a new or
    replaced ``.html`` file in an existing, writable folder (refused otherwise, naming --export)."""
    import shutil

    if not source.is_file():
        raise click.ClickException(
            f"the one-file lab is not built (no {source}): run `make lab-build` in a source "
            "checkout (it needs the rust wasm32 target, wasm-bindgen-cli and node)"
        )
    if target.is_dir():
        raise click.UsageError(
            f"--export: '{target}' is a folder; give a file name, e.g. {target / source.name}"
        )
    if not target.parent.is_dir():
        raise click.UsageError(f"--export: no folder '{target.parent}' to write {target.name} into")
    if target.suffix.lower() not in (".html", ".htm"):
        raise click.UsageError(
            f"--export: '{target.name}' does not end in .html; a browser opens the lab by "
            "double-click only from an .html file"
        )
    try:
        shutil.copyfile(source, target)
    except OSError as exc:
        raise click.ClickException(
            f"--export: cannot write '{target}': {exc.strerror or exc}"
        ) from exc
    size = target.stat().st_size
    click.echo(
        f"poinsot lab: wrote {target} ({size / 1e6:.1f} MB), the lab in one file: open it by "
        "double-click (offline, in any recent browser), e-mail it, or put it on any web space"
    )


# -- poinsot notebooks: the teaching notebooks, copied out of the package --------------------------
#: The teaching notebooks installed with the package (python/poinsot/notebooks in a checkout).
NOTEBOOKS_DIR = Path(__file__).parent / "notebooks"


@main.command()
@click.argument("directory", type=click.Path(file_okay=False))
@click.option("--force", is_flag=True, help="Overwrite notebooks already in DIRECTORY.")
def notebooks(directory: str, force: bool) -> None:
    """Copy the teaching notebooks into DIRECTORY, to open in Jupyter.

    The four lessons in the unit's order (rotating frames and Coriolis; the falling body and
    Foucault; inertia, Euler and Dzhanibekov; the heavy top) and the published experiments
    against the unit (world), installed with poinsot. DIRECTORY is made if needed; a notebook
    already there is kept unless --force. They need matplotlib, pint and Jupyter:
    pip install 'poinsot[plot,units]' jupyterlab.

    \b
    Example:
      poinsot notebooks lessons && jupyter lab lessons
    """
    import shutil

    sources = sorted(NOTEBOOKS_DIR.glob("*.ipynb"))
    if not sources:
        raise Refused(f"no notebook installed in {NOTEBOOKS_DIR}: reinstall poinsot")
    target = Path(directory)
    clashes = [target / src.name for src in sources if (target / src.name).exists()]
    if clashes and not force:
        raise click.UsageError(
            f"DIRECTORY: {', '.join(str(c) for c in clashes)} already there; give --force to "
            "overwrite, or another DIRECTORY"
        )
    try:
        target.mkdir(parents=True, exist_ok=True)
        for src in sources:
            shutil.copyfile(src, target / src.name)
            click.echo(f"saved {target / src.name}")
    except OSError as exc:
        raise Refused(f"DIRECTORY: cannot write into {target}: {exc.strerror or exc}") from exc
    click.echo(f"open them with: jupyter lab {target}  (pip install 'poinsot[plot]' jupyterlab)")


# -- poinsot figure: the unit's own figures (docs/figures.md) ------------------------------------
@main.command()
@click.argument("number", required=False)
@click.option(
    "--style",
    type=click.Choice(["paper", "slides"]),
    default="paper",
    show_default=True,
    help="paper: for a page (10 pt, 150 dpi); slides: for a projector (16 pt, thick lines, 200 dpi).",
)
@click.option(
    "--out",
    "out_path",
    type=click.Path(dir_okay=False),
    default=None,
    help="The picture to write (.png, .pdf, .svg, ...); default fig-NUMBER.png "
    "(fig-NUMBER-slides.png with --style slides) in the current folder.",
)
@click.option(
    "--list", "list_all", is_flag=True, help="List the unit's figures and what draws them."
)
def figure(number: str | None, style: str, out_path: str | None, list_all: bool) -> None:
    """The unit's figure NUMBER, drawn from poinsot's numbers.

    NUMBER is one of the unit's figures, 2.1 to 2.15 (2.12a to 2.12d for the four steps of
    Euler's angles): each is drawn with a classroom example's numbers, every value computed by
    poinsot (docs/figures.md lists them, with the Python call that draws each).

    \b
    Examples:
      poinsot figure --list
      poinsot figure 2.5                                  # writes fig-2.5.png
      poinsot figure 2.12b --style slides --out euler-b.png
    """
    from .plots.unit import UNIT_FIGURES, unit_figure

    if list_all:
        if number is not None:
            raise click.UsageError("--list lists every figure: give it without NUMBER")
        for n, entry in UNIT_FIGURES.items():
            click.echo(f"{n:<6} {entry.caption}  [{entry.function.__name__}]")
        return
    if number is None:
        raise click.UsageError(
            "NUMBER: missing; give one of the unit's figures (poinsot figure --list shows them)"
        )
    if number not in UNIT_FIGURES:
        raise click.UsageError(
            f"NUMBER: the unit has no figure '{number}'; give one of {', '.join(UNIT_FIGURES)}"
        )
    path = Path(
        out_path or (f"fig-{number}.png" if style == "paper" else f"fig-{number}-{style}.png")
    )
    _check_figure_out(path)
    _save_figure(unit_figure(number, style=style), path, "--out")
    click.echo(f"Fig. {number}, {UNIT_FIGURES[number].caption}: saved to {path}")


def _check_figure_out(path: Path) -> None:
    """``poinsot figure --out``: a file in an existing folder, of a kind matplotlib writes."""
    if not path.parent.is_dir():
        raise click.UsageError(f"--out: no folder '{path.parent}' to save {path.name} into")
    if path.is_dir():
        raise click.UsageError(f"--out: '{path}' is a folder; give a file name")
    suffix = path.suffix.lower().lstrip(".")
    kinds = _picture_kinds("poinsot figure")
    if suffix not in kinds:
        raise click.UsageError(
            f"--out: matplotlib cannot write {'.' + suffix if suffix else 'a file without a suffix'}"
            f"; use one of {', '.join('.' + k for k in sorted(kinds))}"
        )


# -- poinsot derive: the unit, derived (poinsot.derive, the symbolic extra) ------------------------
@main.command()
@click.argument("name", required=False)
@click.option("--list", "list_all", is_flag=True, help="List the derivations and what they derive.")
@click.option(
    "--latex", "as_latex", is_flag=True, help="Write the derivation as LaTeX instead of text."
)
@click.option(
    "--markdown",
    "as_markdown",
    is_flag=True,
    help="Write the derivation as Markdown with $$ math (MyST, Jupyter, GitHub).",
)
def derive(name: str | None, list_all: bool, as_latex: bool, as_markdown: bool) -> None:
    """The unit's derivation NAME, step by step, checked by sympy.

    NAME is one of the derivations (``--list`` shows them, in the unit's order), or
    ``questions`` (the unit's question bank with the package's answers) or ``errata`` (the
    unit's printed equations that do not follow from the derivations, with the derived form).
    Needs sympy: ``pip install 'poinsot[symbolic]'``.

    \b
    Examples:
      poinsot derive --list
      poinsot derive heavy_top
      poinsot derive rigid_body --markdown > rigid_body.md
      poinsot derive errata
      poinsot derive questions
    """
    try:
        from . import derive as d
    except ImportError as exc:
        raise Refused(
            "poinsot derive needs sympy, which is not installed: pip install 'poinsot[symbolic]'"
        ) from exc
    if as_latex and as_markdown:
        raise click.UsageError("--latex and --markdown: give one of them, not both")
    special = ("questions", "errata")
    if list_all:
        if name is not None:
            raise click.UsageError("--list lists every derivation: give it without NAME")
        for one in [*d.derivations(), *(d.derivation(n) for n in d.applied())]:
            click.echo(f"{one.name:<16} {one.title}")
            click.echo(f"{'':<16} derives {', '.join(one.result)}")
        click.echo(f"{'questions':<16} The unit's question bank, answered from the package")
        click.echo(f"{'errata':<16} The unit's printed equations that do not follow")
        return
    if name is None:
        raise click.UsageError(
            "NAME: missing; give a derivation (poinsot derive --list shows them), "
            "'questions' or 'errata'"
        )
    if name not in d.names() + d.applied() and name not in special:
        known = d.names() + d.applied() + list(special)
        raise click.UsageError(f"NAME: no derivation '{name}'; give one of {', '.join(known)}")
    if name == "questions":
        if as_latex:
            raise click.UsageError("--latex: the question bank is written as text or Markdown")
        from .derive.questions import render

        click.echo(render(d.questions(), markdown=as_markdown))
        return
    if name == "errata":
        from .derive._core import render_errata

        style = "latex" if as_latex else "markdown" if as_markdown else "text"
        click.echo(render_errata(d.errata(), style))
        return
    one = d.derivation(name)
    click.echo(one.latex() if as_latex else one.markdown() if as_markdown else one.text())


# -- poinsot earth: the Earth as a rigid top (poinsot.RigidEarth, issue 25) ----------------------

#: The Love numbers ``poinsot earth`` uses by default for the Chandler period: k2 = 0.30 (the
#: elastic Earth's) and ks = 0.938 (the secular, fluid one), the inputs of the catalogue's
#: ``vicente-wilson-1997`` entry (a test holds the two equal).
CHANDLER_LOVE_NUMBERS = (0.30, 0.938)

#: The catalogue entries whose measured values ``poinsot earth`` prints beside its numbers:
#: key of ``data["measured"]`` → (entry name, the unit as pint reads it, as it is printed).
EARTH_MEASURED = {
    "chandler_period": ("vicente-wilson-1997", "day", "d"),
    "precession_rate": ("capitaine-2003", "arcsec / julian_year", "″/yr"),
    "nutation_longitude": ("mathews-2002-longitude", "arcsec", "″"),
    "nutation_obliquity": ("mathews-2002-obliquity", "arcsec", "″"),
}

_ARCSEC = math.pi / 648_000
_JULIAN_YEAR = 365.25 * 86_400.0


def _earth_measured() -> dict[str, Any] | None:
    """The measured values of :data:`EARTH_MEASURED`, read from the experiments catalogue (in
    the units printed, with the uncertainty the source states and its citation); None without
    pint (the catalogue needs it)."""
    try:
        from . import experiments as x
    except ImportError:
        return None
    out: dict[str, Any] = {}
    for key, (name, unit, shown) in EARTH_MEASURED.items():
        e = x.get(name)
        u = None if e.uncertainty is None else float(x.parse(e.uncertainty).to(unit).magnitude)
        s = e.sources[0]
        out[key] = {
            "value": float(x.parse(e.measured).to(unit).magnitude),
            "uncertainty": u,
            "uncertainty_kind": e.uncertainty_kind,
            "unit": shown,
            "experiment": name,
            "source": s.publication,
        }
    return out


@main.command()
@_number(
    "--k2",
    "The Love number k2 of the elastic Earth.",
    default=CHANDLER_LOVE_NUMBERS[0],
    show_default=True,
)
@_number(
    "--ks",
    "The secular (fluid) Love number ks.",
    default=CHANDLER_LOVE_NUMBERS[1],
    show_default=True,
)
@_number(
    "--dynamical-flattening",
    "dynamical_flattening",
    "H = (C − A)/C, in (0, 1); default IERS 2010.",
    call="RigidEarth.__init__",
)
@_number(
    "--obliquity",
    "The tilt of the equator to the ecliptic (rad, or with a unit: 23.44deg); default J2000.",
    call="RigidEarth.__init__",
)
@_picture_options(
    "Save a picture of the precession cone and of each prediction against its measured value "
    "to this file."
)
@_JSON
def earth(
    k2: float,
    ks: float,
    dynamical_flattening: float,
    obliquity: float,
    plot_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """The Earth as a rigid top: its free wobble and the precession of the equinoxes.

    Euler's free wobble of the rigid Earth (the unit's eq. 2.83) and the elastic Earth's
    Chandler period for the Love numbers --k2 and --ks; the luni-solar precession from the Sun's
    and the Moon's torques on the bulge, averaged over their orbits, with its two parts; the
    principal (18.6-year) nutation. Each beside its measured value from the experiments
    catalogue (poinsot experiments NAME: the source and what the rigid model leaves out; they
    need pint). --plot FILE draws the pole's precession cone and each prediction's difference
    from its measured value.

    \b
    Examples:
      poinsot earth
      poinsot earth --k2 0.35 --json
      poinsot earth --obliquity 22.1deg
      poinsot earth --plot earth.png
    """
    from .rigid_earth import RigidEarth

    _check_pictures(plot_path)

    e = RigidEarth(dynamical_flattening=dynamical_flattening, obliquity=obliquity)
    sidereal_day = 2 * math.pi / e.rotation_rate
    sun, moon = e.precession_parts
    dpsi, deps = e.nutation_amplitudes
    euler, chandler = e.euler_period, e.chandler_period(k2, ks)
    rate, period = e.precession_rate, e.precession_period
    measured = _earth_measured()
    data: dict[str, Any] = {
        "dynamical_flattening": e.dynamical_flattening,
        "rotation_rate": e.rotation_rate,
        "obliquity": e.obliquity,
        "k2": k2,
        "ks": ks,
        "euler_period": euler,
        "euler_period_days": euler / 86_400,
        "euler_period_sidereal_days": euler / sidereal_day,
        "chandler_period": chandler,
        "chandler_period_days": chandler / 86_400,
        "precession_rate": rate,
        "precession_rate_arcsec_per_year": -rate * _JULIAN_YEAR / _ARCSEC,
        "precession_parts": [sun, moon],
        "precession_parts_arcsec_per_year": [-p * _JULIAN_YEAR / _ARCSEC for p in (sun, moon)],
        "moon_to_sun": moon / sun,
        "precession_period": period,
        "precession_period_years": period / _JULIAN_YEAR,
        "nutation_amplitudes": [dpsi, deps],
        "nutation_amplitudes_arcsec": [dpsi / _ARCSEC, deps / _ARCSEC],
        "measured": measured,
    }
    require_finite(data)
    data["summary"] = _answers.rigid_earth(data)
    m = measured or {}

    def beside(key: str) -> str:
        """The measured value (± the stated uncertainty) and its entry, or "—"."""
        if key not in m:
            return "—"
        v = m[key]
        text = f"{v['value']:.10g}" + (f" ± {v['uncertainty']:.3g}" if v["uncertainty"] else "")
        return f"{text} {v['unit']} ({v['experiment']})"

    def g(x: float) -> str:
        return f"{x:.6g}"

    parts = data["precession_parts_arcsec_per_year"]
    nutation = data["nutation_amplitudes_arcsec"]
    rows = [
        (
            "Euler's free wobble (rigid)",
            f"{g(data['euler_period_sidereal_days'])} sidereal d = "
            f"{g(data['euler_period_days'])} d",
            "— (the Earth is not rigid)",
        ),
        (
            f"Chandler period (k2 = {k2:g}, ks = {ks:g})",
            f"{g(data['chandler_period_days'])} d",
            beside("chandler_period"),
        ),
        (
            "luni-solar precession (westward)",
            f"{g(data['precession_rate_arcsec_per_year'])} ″/yr",
            beside("precession_rate"),
        ),
        ("  the Sun's part", f"{g(parts[0])} ″/yr", "—"),
        ("  the Moon's part", f"{g(parts[1])} ″/yr", "—"),
        ("precession period", f"{g(data['precession_period_years'])} yr", "—"),
        ("nutation in longitude Δψ₀", f"{g(nutation[0])} ″", beside("nutation_longitude")),
        ("nutation in obliquity Δε₀", f"{g(nutation[1])} ″", beside("nutation_obliquity")),
    ]
    notes = [
        f"inputs: H = {e.dynamical_flattening:.9g}, ω = {e.rotation_rate:.9g} rad/s, "
        f"ε = {math.degrees(e.obliquity):.7g}°"
    ]
    if measured is None:
        notes.append("the measured values need pint: pip install 'poinsot[units]'")
    else:
        sources: dict[str, list[str]] = {}
        for v in measured.values():
            sources.setdefault(v["source"], []).append(v["experiment"])
        notes += [_esc(f"{', '.join(names)}: {source}") for source, names in sources.items()]
        notes.append(
            "poinsot experiments NAME: each comparison, and what the rigid model leaves out."
        )
    seen = m.get("chandler_period")
    observed = None
    if seen is not None and seen["unit"] == "d":
        observed = (float(seen["value"]), float(seen["uncertainty"] or 0.0))
    draw = "earth.plot_rigid_earth"
    _keep_picture(data, plot_path, draw, e, k2=k2, ks=ks, chandler_observed=observed, style=style)
    title = "the Earth as a rigid top"
    _report(data, as_json, title, ("quantity", "poinsot", "measured"), rows, notes=notes)


# -- poinsot experiments: the unit against the world (poinsot.experiments, the units extra) -------
@main.command()
@click.argument("name", required=False)
@_JSON
def experiments(name: str | None, as_json: bool) -> None:
    """Published measurements, reproduced: measured vs poinsot's prediction.

    Without NAME, the catalogue: each experiment (Reich's drops down a mine shaft, Foucault's
    pendulums, ...) with what was measured, what poinsot predicts through its public API, the
    unit's closed form and the verdict in units of the measurement's stated uncertainty. With
    NAME, that experiment: its inputs as published, the model's assumptions and its sources.
    Needs pint: ``pip install 'poinsot[units]'``.

    \b
    Examples:
      poinsot experiments
      poinsot experiments reich-1831
      poinsot experiments reich-1831 --json
    """
    try:
        from . import experiments as x
    except ImportError as exc:
        raise Refused(
            "poinsot experiments needs pint, which is not installed: pip install 'poinsot[units]'"
        ) from exc
    if name is None:
        results = x.run_all()
        data: dict[str, Any] = {
            "summary": x.catalogue_summary(results),
            "experiments": [r.to_dict() for r in results],
        }
        if as_json:
            emit_json(data)
            return
        from rich.console import Console
        from rich.table import Table

        table = Table(title="the unit against the world")
        table.add_column("experiment", no_wrap=True)
        for column in ("measured", "poinsot", "closed form"):
            table.add_column(column, justify="right", overflow="fold")
        table.add_column("verdict", overflow="fold")
        for r in results:
            table.add_row(
                r.name,
                r.shown_measured(),
                r.shown("predicted"),
                r.shown("closed_form"),
                r.short_verdict,
            )
        console = Console()
        _print_summary(console, data)
        console.print(table)
        console.print("poinsot experiments NAME shows one, with its sources and assumptions.")
        return
    try:
        r = x.run(name)
    except PoinsotError as exc:
        raise click.UsageError(f"NAME: {str(exc).removeprefix('name: ')}") from None
    data = r.to_dict()
    rows = [
        (f"{r.quantity}, measured", r.shown("measured")),
        (f"uncertainty ({r.uncertainty_kind})", r.shown("uncertainty")),
        ("poinsot's prediction", r.shown("predicted")),
        ("the closed form", r.shown("closed_form")),
        ("(measured − predicted) / uncertainty", "—" if r.sigma is None else f"{r.sigma:.3g} σ"),
        ("verdict", r.verdict),
    ]
    rows += [(f"input: {k}", v) for k, v in r.inputs.items()]
    notes = ["assumptions: " + ", ".join(r.assumptions)]
    notes += [
        f"source: {s.who}, {s.where}, {s.when}. {s.publication}, {s.page}"
        + (f" <{s.url}>" if s.url else "")
        for s in r.sources
    ]
    misquoted = x.get(name).misquoted
    if misquoted:
        notes.append(f"misquoted: {misquoted}")
    _report(data, as_json, r.title, ("quantity", "value"), rows, notes=[_esc(n) for n in notes])


def _esc(text: str) -> str:
    """``text`` with rich's markup escaped (a citation's square brackets are text)."""
    from rich.markup import escape

    return escape(text)


# -- poinsot exercises / poinsot check: problem sets for teachers (poinsot.exercises) -------------
def _exercises_module() -> Any:
    try:
        from . import exercises as x
    except ImportError as exc:
        raise Refused(f"{exc}") from exc
    return x


@main.command(short_help="Problem sets with checked answers.")
@click.argument("topics", nargs=-1, required=True)
@click.option("--n", "n", type=int, default=30, show_default=True, help="Number of problems.")
@click.option("--seed", type=int, default=2026, show_default=True, help="The set's seed.")
@click.option(
    "--format",
    "format",
    type=click.Choice(["markdown", "latex", "pdf", "gift", "moodle-xml", "json"]),
    default="markdown",
    show_default=True,
    help="Sheets (markdown, latex, pdf), a Moodle quiz (gift, moodle-xml) or json.",
)
@click.option("--out", type=click.Path(file_okay=False), default=None, help="Folder to write to.")
def exercises(topics: tuple[str, ...], n: int, seed: int, format: str, out: str | None) -> None:
    """Problem sets with checked answers.

    TOPIC is a topic ("moving frames", earth, "rigid bodies", "free tops", "euler angles",
    "heavy top"), a template's name, or all. Each problem is a seeded variant whose answer
    poinsot computed by two independent routes; the solution sheet has worked steps from
    poinsot.derive. The same seed gives the same files on every machine. Without --out the files
    are printed (pdf needs --out and a TeX engine: apt install texlive-latex-base latexmk).

    \b
    Examples:
      poinsot exercises earth --n 5 --seed 2026
      poinsot exercises all --n 30 --format moodle-xml --out quiz/
      poinsot exercises dropped-ball top-min-spin --format latex --out sheets/
    """
    x = _exercises_module()
    variants = x.generate(list(topics), n=n, seed=seed)
    if out is None and format == "pdf":
        raise click.UsageError("--format pdf: give --out DIR for the PDF files")
    if out is not None:
        for path in x.write(variants, format, out):
            click.echo(str(path))
        return
    for name, text in x.render(variants, format).items():
        if len(x.FORMATS[format]) > 1:
            click.echo(f"<!-- {name} -->" if format == "markdown" else f"% {name}")
        click.echo(text)


@main.command(short_help="Checks an answer to an exercise.")
@click.argument("template")
@click.option("--seed", type=int, required=True, help="The seed printed with the problem.")
@click.option("--answer", required=True, help="Your answer: a number in the unit asked, or 12mm.")
@_JSON
def check(template: str, seed: int, answer: str, as_json: bool) -> None:
    """Checks an answer to an exercise.

    Says whether ANSWER to the problem TEMPLATE --seed N (as printed on the sheet) is right,
    how far off it is, and, when it is what a common mistake gives (a Coriolis sign, degrees
    for radians, the solar for the sidereal day, a misprint of the unit), which step of the
    worked solution to look at.

    \b
    Examples:
      poinsot check dropped-ball --seed 123456 --answer 64.6
      poinsot check dropped-ball --seed 123456 --answer 6.46cm --json
    """
    x = _exercises_module()
    result = x.check(template, seed, answer)
    if as_json:
        emit_json(result.to_dict())
        return
    click.echo(result.verdict)


# -- poinsot gyrocompass: the pendulous gyrocompass (issue 26) -----------------------------------
@main.command()
@_number("--latitude", "The compass's latitude, north-positive (rad, or with a unit: 50deg).")
@_number("--speed", "The ship's speed (m/s, or with a unit: 20kn); 0: at rest.", default=0.0)
@_number("--course", "The ship's course, clockwise from north (rad, or 45deg).", default=0.0)
@_number(
    "--angular-momentum",
    "angular_momentum",
    "The rotor's angular momentum H (kg·m²/s, > 0).",
    call="Gyrocompass.__init__",
)
@_number("--pendulosity", "The pendulosity m g l (N·m, > 0).", call="Gyrocompass.__init__")
@_number(
    "--damping",
    "The damping ratio ζ of the settling swing, in [0, 1).",
    call="Gyrocompass.__init__",
)
@_picture_options(
    "Save a picture of the settling heading and tilt against time (the full simulation, three "
    "periods from 10° east of north, on --course at --speed) with the linearised settled "
    "heading and envelope to this file."
)
@_JSON
def gyrocompass(
    latitude: float,
    speed: float,
    course: float,
    angular_momentum: float,
    pendulosity: float,
    damping: float,
    plot_path: str | None,
    style: str,
    as_json: bool,
) -> None:
    """The gyrocompass: its period and its errors.

    A pendulous gyrocompass (poinsot.Gyrocompass with its default rotor, pendulosity and
    damping) at --latitude: the period of its settling swing about the meridian,
    2π √(H/(m g l Ω cos λ)), beside Schuler's 2π √(R/g) = 84.4 min and the rotor momentum that
    tunes it to that; the latitude (damping) error of the settled compass; and, for a ship at
    --speed on --course, the speed (steaming) error atan(V cos C / (Ω R cos λ + V sin C)) beside
    the manufacturers' small-angle form. Errors are what the compass reads minus the truth
    (positive: reads high).

    \b
    Examples:
      poinsot gyrocompass --latitude 50deg
      poinsot gyrocompass --latitude 50deg --speed 20kn --course 0deg --json
      poinsot gyrocompass --latitude 50deg --damping 0.5 --plot compass.png
    """
    from .gyrocompass import Gyrocompass

    _check_pictures(plot_path)
    c = Gyrocompass(latitude, angular_momentum, pendulosity, damping=damping)
    tuned = Gyrocompass.schuler_tuned(latitude, pendulosity, damping=damping)
    data: dict[str, Any] = {
        "latitude": c.latitude,
        "angular_momentum": c.angular_momentum,
        "pendulosity": c.pendulosity,
        "damping": c.damping,
        "period": c.period,
        "schuler_period": Gyrocompass.schuler_period(),
        "schuler_angular_momentum": tuned.angular_momentum,
        "settle_error": c.settle_error,
        "settle_tilt": c.settle_tilt,
        "speed": speed,
        "course": course,
        "speed_error": c.speed_error(speed, course),
        "speed_error_small_angle": c.speed_error_small_angle(speed, course),
    }
    require_finite(data)
    deg = math.degrees
    data["summary"] = _answers.gyrocompass(data)
    rows = [
        ("settling period", f"{c.period / 60:.6g} min"),
        ("Schuler period 2π√(R/g)", f"{data['schuler_period'] / 60:.6g} min"),
        ("H for Schuler tuning", f"{tuned.angular_momentum:.6g} kg·m²/s"),
        ("latitude (damping) error", f"{deg(c.settle_error):+.6g}°"),
        ("speed error", f"{deg(data['speed_error']):+.6g}°"),
        ("speed error, small-angle form", f"{deg(data['speed_error_small_angle']):+.6g}°"),
    ]
    notes = [
        f"H = {c.angular_momentum:g} kg·m²/s, m g l = {c.pendulosity:g} N·m, ζ = {c.damping:g}; "
        "errors: reading minus truth (positive reads high)."
    ]
    draw = "gyrocompass.plot_gyrocompass"
    _keep_picture(data, plot_path, draw, c, speed=speed, course=course, style=style)
    _report(data, as_json, "the gyrocompass", ("quantity", "value"), rows, notes=notes)
