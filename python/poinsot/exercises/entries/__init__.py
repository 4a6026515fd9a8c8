"""The templates, one module per part of the unit; each holds ``ENTRIES``."""
