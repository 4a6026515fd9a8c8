"""The catalogue's entries, one module per topic, each a list ``ENTRIES`` of
:class:`~poinsot.experiments.Experiment` (collected by :func:`poinsot.experiments.catalogue`;
a module whose name starts with ``_`` is skipped)."""
