"""The ``poinsot`` command line (click + rich). ``python -m poinsot`` is the same command.

Every computing command takes ``--json`` and then prints one JSON document on stdout and
nothing else, so that its output can be piped into other programs.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import click
import numpy as np

from .errors import PoinsotError

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


def emit_json(data: dict[str, Any]) -> None:
    """Print ``data`` as one JSON document on stdout."""
    click.echo(json.dumps(_jsonable(data), indent=2))


class _PoinsotGroup(click.Group):
    """Shows poinsot's errors as one clear line (exit status 2) instead of a traceback."""

    def invoke(self, ctx: click.Context) -> Any:
        try:
            return super().invoke(ctx)
        except PoinsotError as exc:
            click.echo(f"error: {exc}", err=True)
            sys.exit(2)


@click.group(cls=_PoinsotGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="poinsot")
def main() -> None:
    """poinsot: moving frames and the motion of rigid bodies.

    Start with `poinsot tour`, the course unit computed from end to end.
    """


@main.command()
def tour() -> None:
    """The whole unit, computed: a guided tour of what poinsot does."""
    from .tour import run_tour

    run_tour()


@main.command()
@click.argument("shape")
@click.option("--mass", type=float, default=None, help="Mass in kg (standard shapes; default 1).")
@click.option("--radius", type=float, default=None, help="Radius in m (sphere, shell, cylinder, cone, disk, ring).")
@click.option("--height", type=float, default=None, help="Height in m (cylinder, cone).")
@click.option("--length", type=float, default=None, help="Length in m (rod).")
@click.option("--sides", type=float, nargs=3, default=None, help="Side lengths a b c in m along x y z (cuboid).")
@click.option("--semi-axes", "semi_axes", type=float, nargs=3, default=None, help="Semi-axes a b c in m (ellipsoid).")
@click.option("--density", type=float, default=None, help="Density in kg/m³ (mesh files; default 1).")
@click.option("--plot", "plot_path", type=click.Path(dir_okay=False), default=None,
              help="Save a picture of the inertia ellipsoid and principal axes to this file.")
@click.option("--json", "as_json", is_flag=True, help="Print one JSON document instead of a table.")
def inertia(shape: str, mass: float | None, radius: float | None, height: float | None,
            length: float | None, sides: tuple[float, float, float] | None,
            semi_axes: tuple[float, float, float] | None, density: float | None,
            plot_path: str | None, as_json: bool) -> None:
    """Mass properties of a standard SHAPE or of a closed mesh file (.stl, .obj, ...).

    SHAPE is one of sphere, shell, cylinder, cone, cuboid, ellipsoid, rod, disk, ring
    (symmetry axis along z; the cone's apex at the origin), or a path to a mesh file
    (needs the `mesh` extra, trimesh). Prints mass, centre of mass, the inertia tensor about
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
        given = {"radius": radius, "height": height, "length": length, "sides": sides,
                 "semi_axes": semi_axes}
        missing = [n for n in needs if given[n] is None]
        if missing:
            opts = ", ".join("--" + n.replace("_", "-") for n in missing)
            raise click.UsageError(f"shape '{shape}' needs {opts}")
        extra = [n for n, v in given.items() if v is not None and n not in needs]
        if extra:
            opts = ", ".join("--" + n.replace("_", "-") for n in extra)
            raise click.UsageError(f"shape '{shape}' does not take {opts}")
        if density is not None:
            raise click.UsageError("--density applies to mesh files; give --mass for standard shapes")
        body = getattr(RigidBody, ctor)(1.0 if mass is None else mass, *(given[n] for n in needs))
        source = shape
    else:
        path = Path(shape)
        if not path.exists():
            raise click.UsageError(
                f"'{shape}' is neither a shape ({', '.join(SHAPES)}) nor an existing mesh file")
        if mass is not None:
            raise click.UsageError("--mass applies to standard shapes; give --density for a mesh")
        body = RigidBody.load_mesh(path, density=1.0 if density is None else density)
        source = str(path)

    if plot_path is not None:
        from .plots import plot_inertia_ellipsoid

        fig = plot_inertia_ellipsoid(body, title=source)
        fig.savefig(plot_path, dpi=120, bbox_inches="tight")

    if as_json:
        emit_json({"source": source, **body.to_dict()})
        return
    _print_body(source, body)
    if plot_path is not None:
        click.echo(f"picture saved to {plot_path}")


def _print_body(source: str, body: Any) -> None:
    from rich.console import Console
    from rich.table import Table

    console = Console()
    fmt = "{:.6g}".format
    table = Table(title=f"mass properties of {source}", show_header=False)
    table.add_row("mass", f"{fmt(body.mass)} kg")
    table.add_row("centre of mass", "(" + ", ".join(fmt(c) for c in body.center_of_mass) + ") m")
    rows = [" ".join(f"{v:>11.6g}" for v in row) for row in body.inertia]
    table.add_row("inertia about c.o.m.", "\n".join(rows) + "  kg·m²")
    table.add_row("principal moments", ", ".join(fmt(m) for m in body.principal_moments) + " kg·m²")
    axes = body.principal_axes
    table.add_row("principal axes", "\n".join(
        f"e{i + 1} = (" + ", ".join(f"{v: .4f}" for v in axes[:, i]) + ")" for i in range(3)))
    table.add_row("kind", body.kind)
    console.print(table)
