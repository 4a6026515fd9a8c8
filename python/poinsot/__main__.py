"""``python -m poinsot`` is the ``poinsot`` command."""

from .cli import main

main()
