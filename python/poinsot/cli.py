"""The ``poinsot`` command line (click + rich). ``python -m poinsot`` is the same command."""

from __future__ import annotations

import click


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(package_name="poinsot")
def main() -> None:
    """poinsot: moving frames and the motion of rigid bodies."""


@main.command()
def tour() -> None:
    """The whole unit, computed: a guided tour of what poinsot does."""
    from .tour import run_tour

    run_tour()
