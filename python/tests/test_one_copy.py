"""One copy of each piece of plumbing in ``python/poinsot`` (issue 22, "one boundary": the
repeated-code pairs). Each test fails when a private copy of a shared helper comes back:
before the clean-up every derive module had its own unevaluated ``_add``/``_mul``/``_eq``,
three plot modules their own ``_lw``, and the sweeps five copies of the options every sweep
takes."""

from __future__ import annotations

import inspect
import re
from typing import Any

import poinsot as ps
import poinsot.plots as plots
import pytest
from poinsot import sweep
from poinsot.derive import _core as derive_core
from poinsot.derive import earth, euler_angles, euler_equations, frames, heavy_top, rigid_body

#: The unevaluated builders of the derive modules (printed as written) and their one home.
SHARED = {
    "_add": derive_core.add,
    "_mul": derive_core.mul,
    "_eq": derive_core.eq,
    "_pow": derive_core.power,
}


@pytest.mark.parametrize(
    "module", [earth, euler_angles, euler_equations, frames, heavy_top, rigid_body]
)
def test_derive_modules_use_the_shared_builders(module: object) -> None:
    for name, shared in SHARED.items():
        if hasattr(module, name):
            assert getattr(module, name) is shared, f"{module.__name__}.{name} is a copy"
    if module is frames:  # the frames module spells its sum _sum
        assert frames._sum is derive_core.add


def test_plots_read_one_line_width() -> None:
    for module in (plots.earth, plots.free, plots.top):
        assert not hasattr(module, "_lw"), module.__name__
        assert module.line_width is plots._mpl.line_width


def test_plots_all_is_the_modules_lists() -> None:
    """The package lists the drawing functions its modules list (unit's helpers left out)."""
    modules = (plots.inertia, plots.free, plots.top, plots.earth, plots.gyrocompass, plots.unit)
    listed = [name for m in modules for name in m.__all__]
    assert set(plots.__all__) <= set(listed)
    assert [n for n in listed if n in plots.__all__] == plots.__all__
    assert "unit_figure" in plots.__all__ and "UNIT_FIGURES" not in plots.__all__


@pytest.mark.parametrize("name", sweep.__all__[:5])
def test_every_sweep_ends_with_the_same_options(name: str) -> None:
    params = list(inspect.signature(getattr(sweep, name)).parameters.values())
    tail = [p.name for p in params[-9:]]
    assert tail == [n for n, _, _ in sweep._OPTIONS] + ["keywords"]
    assert all(p.kind is p.KEYWORD_ONLY for p in params[:-1])
    assert params[-1].kind is inspect.Parameter.VAR_KEYWORD


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (
            lambda: ps.RigidBody.from_density(lambda p: "dense", [[0, 1], [0, 1], [0, 1]]),
            "density: the callable must return real numbers, got str",
        ),
        (
            lambda: ps.simulate_particle(
                ps.MovingFrame(), [1, 0, 0], [0, 0, 0], 1.0, force=lambda t, r, v: "push"
            ),
            "force: the callable must return 3 real numbers, got 'push'",
        ),
    ],
)
def test_a_callable_returning_text_is_refused_naming_it(call: Any, message: str) -> None:
    """One helper (``_validate.returned``) reads what the user's callables return: the
    message names the argument and shows what came back."""
    with pytest.raises(ps.PoinsotError, match=f"^{re.escape(message)}$"):
        call()
