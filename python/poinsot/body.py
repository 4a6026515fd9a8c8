"""Rigid bodies (filled by the inertia work)."""
__all__: list[str] = []
