"""Rotations (filled by the rotation work)."""
__all__: list[str] = []
