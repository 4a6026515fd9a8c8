"""poinsot.sweep here, without a cluster: every point of a sweep is the scalar API's answer at
that point (bit for bit: the same core code on the same numbers), the labels (dimensions in the
order given, coordinates, units) are right, the chunked, lazy and zarr paths return the same
numbers as the one-call path, and bad input is refused by name. The cluster is
test_sweep_cluster.py."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import poinsot as ps
import pytest
from poinsot import sweep

xr = pytest.importorskip("xarray")

THETA = np.radians(np.linspace(5.0, 85.0, 9))
PSI_DOT = np.linspace(0.5, 20.0, 11)
PHI_DOT = np.array([-1.0, 0.0, 0.7])


def _top_sweep(**extra):
    return sweep.heavy_top(
        I1=1.0, I3=0.5, mgl=1.0, theta=THETA, psi_dot=PSI_DOT, phi_dot=PHI_DOT, **extra
    )


def _assert_same(a, b) -> None:
    """Bit for bit: every variable and coordinate equal (strings too), same dims."""
    assert set(a.data_vars) == set(b.data_vars)
    for name in a.variables:
        assert a[name].dims == b[name].dims, name
        assert np.array_equal(np.asarray(a[name].values), np.asarray(b[name].values)), name


def test_heavy_top_points_are_the_scalar_tops() -> None:
    ds = _top_sweep()
    assert ds.motion_class.dims == ("theta", "psi_dot", "phi_dot")
    assert ds.turning_points.dims == ("theta", "psi_dot", "phi_dot", "turning_point")
    rng = np.random.default_rng(3)
    for _ in range(25):
        i, j, k = rng.integers(len(THETA)), rng.integers(len(PSI_DOT)), rng.integers(len(PHI_DOT))
        top = ps.HeavyTop(1.0, 0.5, 1.0, THETA[i], psi_dot=PSI_DOT[j], phi_dot=PHI_DOT[k])
        at = ds.isel(theta=i, psi_dot=j, phi_dot=k)
        assert at.motion_class.item() == top.motion_class
        assert tuple(at.turning_points.values) == top.turning_points
        assert at.nutation_period.item() == top.nutation_period
        assert at.mean_precession_rate.item() == top.mean_precession_rate
        assert at.p_phi.item() == top.p_phi and at.energy.item() == top.energy
        assert bool(at.is_sleeping_stable) == top.is_sleeping_stable
    # The sweep covers more than one class (φ̇₀ = 0 gives cusps, the others waves or loops).
    assert {"cusps", "loops", "waves"} <= set(np.unique(ds.motion_class.values))
    assert set(np.unique(ds.motion_class.values)) <= set(ps.MOTION_CLASSES)
    assert ds.motion_class.attrs["categories"] == list(ps.MOTION_CLASSES)


def test_labels_units_and_the_order_given() -> None:
    ds = sweep.heavy_top(
        psi_dot=PSI_DOT, I1=1.0, theta=np.degrees(THETA), I3=0.5, mgl=1.0, degrees=True
    )
    assert list(ds.motion_class.dims) == ["psi_dot", "theta"]
    assert ds.theta.attrs["units"] == "deg" and ds.psi_dot.attrs["units"] == "deg/s"
    assert ds.I1.attrs["units"] == "kg m^2" and ds.I1.ndim == 0
    assert ds.turning_points.attrs["units"] == "rad"
    assert "long_name" in ds.nutation_period.attrs and ds.nutation_period.attrs["units"] == "s"
    assert ds.attrs["model"] == "HeavyTop"
    # Degrees convert angles and rates as HeavyTop(degrees=True) does.
    top = ps.HeavyTop(1.0, 0.5, 1.0, np.degrees(THETA[2]), psi_dot=PSI_DOT[4], degrees=True)
    at = ds.isel(psi_dot=4, theta=2)
    assert tuple(at.turning_points.values) == top.turning_points
    # quantities= keeps what is asked; an input is not repeated as a result.
    small = sweep.heavy_top(
        I1=1.0,
        I3=0.5,
        mgl=1.0,
        theta=THETA,
        omega3=PSI_DOT,
        quantities=["motion_class", "mean_precession_rate"],
    )
    assert set(small.data_vars) == {"motion_class", "mean_precession_rate"}
    with pytest.raises(ps.PoinsotError, match="^quantities: 'omega3' is not a result"):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=THETA, omega3=PSI_DOT, quantities="omega3")


def test_free_body_points_and_the_closed_forms() -> None:
    polar = np.linspace(0.1, np.pi - 0.1, 7)
    azimuth = np.linspace(0.0, np.pi, 6)
    moments = np.array([[1.0, 2.0, 3.0], [2.0, 2.0, 1.0]])
    ds = sweep.free_body(
        moments=moments, omega_magnitude=2.0, omega_polar=polar, omega_azimuth=azimuth
    )
    assert ds.period.dims == ("moments_index", "omega_polar", "omega_azimuth")
    assert ds.moments.dims == ("moments_index", "axis") and ds.axis_stability.dims[-1] == "axis"
    for b in range(2):
        for i in range(0, 7, 2):
            for j in range(0, 6, 2):
                w = 2.0 * np.array(
                    [
                        np.sin(polar[i]) * np.cos(azimuth[j]),
                        np.sin(polar[i]) * np.sin(azimuth[j]),
                        np.cos(polar[i]),
                    ]
                )
                at = ds.isel(moments_index=b, omega_polar=i, omega_azimuth=j)
                assert np.array_equal(at.omega0.values, w)
                body = ps.FreeRigidBody(moments[b], w)
                assert at.period.item() == body.period
                assert at.flip_interval.item() == body.flip_interval
                assert at.regime.item() == body.regime
                assert at.energy.item() == body.energy
                assert at.pole_axis.item() == (-1 if body.pole_axis is None else body.pole_axis)
                stab = ps.axis_stability(moments[b], 2.0)
                assert list(at.axis_stability.values) == [s.stability for s in stab]
                assert list(at.axis_rate.values) == [s.rate for s in stab]
    # The symmetric body (2, 2, 1): the period of ω is 2π/|Ω| with Ω = (I₁ − I₃) ω₃ / I₁ (2.83).
    sym = ds.isel(moments_index=1)
    omega3 = 2.0 * np.cos(polar)[:, None] * np.ones(6)
    assert np.allclose(
        sym.period.values, 2 * np.pi / np.abs((2.0 - 1.0) * omega3 / 2.0), rtol=1e-13
    )
    assert (sym.regime == "symmetric").all()
    # The tennis-racket theorem: the intermediate axis of (1, 2, 3) is unstable.
    assert (ds.isel(moments_index=0).axis_stability.sel(axis=1) == "unstable").all()
    # Near the intermediate axis the flip interval grows without bound (the separatrix).
    near = sweep.free_body(
        moments=[1.0, 2.0, 3.0],
        omega_magnitude=1.0,
        omega_polar=np.pi / 2,
        omega_azimuth=np.pi / 2 - np.logspace(-1, -6, 6),
    )
    assert np.all(np.diff(near.flip_interval.values) > 0)


def test_simulate_ensembles_are_simulate_batch_rows() -> None:
    omega0 = np.array([[1.0, 0.1, 1.0], [0.1, 3.0, 0.1], [-0.5, 0.2, 2.0]])
    attitude0 = np.array([[1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.5, 0.5, 0.5, 0.5]])
    torque = ps.BodyTorque([0.0, 0.1, 0.0])
    ds = sweep.simulate(
        moments=[1.0, 2.0, 3.0],
        omega0=omega0,
        attitude0=attitude0,
        paired={"member": ("omega0", "attitude0")},
        duration=1.5,
        torque=torque,
        dt=1e-3,
    )
    assert ds.omega.dims == ("member", "axis") and ds.attitude.dims == ("member", "quaternion")
    assert list(ds.quaternion.values) == ["w", "x", "y", "z"]
    w, q = ps.simulate_batch(
        np.tile([1.0, 2.0, 3.0], (3, 1)), omega0, 1.5, attitude0=attitude0, torque=torque, dt=1e-3
    )
    assert np.array_equal(ds.omega.values, w) and np.array_equal(ds.attitude.values, q)
    # Not paired: the product of the two arrays (3 × 3 bodies).
    grid = sweep.simulate(
        moments=[1.0, 2.0, 3.0],
        omega0=omega0,
        attitude0=attitude0,
        duration=1.5,
        torque=torque,
        dt=1e-3,
    )
    assert grid.omega.dims == ("omega0_index", "attitude0_index", "axis")
    assert np.array_equal(grid.omega.values[[0, 1, 2], [0, 1, 2]], w)
    assert ds.attrs["method"] == "rk4" and ds.attrs["duration"] == 1.5


def test_drops_and_projectiles_are_the_earths_runs() -> None:
    earth = ps.Earth()
    lat = np.array([-40.0, 0.0, 30.0, 60.0])
    height = np.array([10.0, 100.0, 1000.0])
    ds = sweep.drop(latitude=lat, height=height, degrees=True)
    assert ds.east.dims == ("latitude", "height")
    for i, la in enumerate(lat):
        for j, h in enumerate(height):
            f = earth.drop(h, la, degrees=True)
            at = ds.isel(latitude=i, height=j)
            assert (at.time.item(), at.east.item(), at.north.item()) == (f.time, f.east, f.north)
            assert at.first_order_east.item() == f.first_order_east
    # The unit's 2.42: the eastward deflection to first order in ω.
    assert np.allclose(ds.east, ds.first_order_east, rtol=2e-3)
    shots = sweep.projectile(
        speed=[100.0, 400.0],
        elevation=[20.0, 45.0],
        azimuth=[0.0, 90.0],
        latitude=45.0,
        degrees=True,
    )
    f = earth.projectile(400.0, 45.0, 90.0, 45.0, degrees=True)
    at = shots.isel(speed=1, elevation=1, azimuth=1)
    assert (at.range.item(), at.drift.item()) == (f.range, f.drift)
    assert (shots.drift > 0).all()  # to the right in the north
    assert shots.height.item() == 0.0


def test_random_samples_are_seeded_and_within_their_ranges() -> None:
    kw = dict(
        I1=1.0,
        I3=0.5,
        mgl=1.0,
        theta=sweep.uniform(0.2, 1.2),
        psi_dot=sweep.log_uniform(1.0, 100.0),
        phi_dot=PHI_DOT,
        samples=50,
        seed=7,
    )
    a = sweep.heavy_top(**kw)
    b = sweep.heavy_top(**kw)
    _assert_same(a, b)
    assert a.motion_class.dims == ("sample", "phi_dot")
    assert a.theta.dims == ("sample",) and a.attrs["seed"] == 7 and a.attrs["samples"] == 50
    assert float(a.theta.min()) >= 0.2 and float(a.theta.max()) <= 1.2
    assert float(a.psi_dot.min()) >= 1.0 and float(a.psi_dot.max()) <= 100.0
    # log-uniform: about as many draws below 10 as above.
    assert 10 < int((a.psi_dot < 10).sum()) < 40
    top = ps.HeavyTop(1.0, 0.5, 1.0, float(a.theta[3]), psi_dot=float(a.psi_dot[3]), phi_dot=0.7)
    assert a.isel(sample=3, phi_dot=2).turning_points.values.tolist() == list(top.turning_points)
    other = sweep.heavy_top(**{**kw, "seed": 8})
    assert not np.array_equal(other.theta.values, a.theta.values)
    # A vector drawn component by component.
    ens = sweep.free_body(
        moments=[1.0, 2.0, 3.0],
        omega0=sweep.uniform([0.9, -0.1, 0.9], [1.1, 0.1, 1.1]),
        samples=20,
        seed=1,
    )
    assert ens.omega0.dims == ("sample", "axis")
    assert (np.abs(ens.omega0.sel(axis=1)) <= 0.1).all()


def test_chunked_lazy_and_zarr_paths_equal_the_one_call(tmp_path) -> None:
    da = pytest.importorskip("dask.array")
    local = _top_sweep()
    # Chunk by chunk here (chunks= without a client).
    _assert_same(local, _top_sweep(chunks={"theta": 2, "psi_dot": 4}))
    _assert_same(local, _top_sweep(chunks=1))
    # Dask arrays given: a lazy Dataset, one chunk per block of theta.
    lazy = sweep.heavy_top(
        I1=1.0,
        I3=0.5,
        mgl=1.0,
        theta=da.from_array(THETA, chunks=4),
        psi_dot=PSI_DOT,
        phi_dot=PHI_DOT,
    )
    assert lazy.motion_class.chunks[0] == (4, 4, 1)
    _assert_same(local, lazy.compute(scheduler="synchronous"))
    # Into zarr, chunk by chunk, then read back lazily: the same numbers and labels.
    z = _top_sweep(to_zarr=tmp_path / "top.zarr", chunks={"theta": 3})
    assert z.motion_class.chunks is not None
    _assert_same(local, z.compute())
    assert z.theta.attrs["units"] == "rad"
    with pytest.raises(ps.PoinsotError, match="^to_zarr: .* exists already"):
        _top_sweep(to_zarr=tmp_path / "top.zarr")
    # A sweep of a single point (no dimension) through every path.
    one = dict(I1=1.0, I3=0.5, mgl=1.0, theta=0.3, psi_dot=5.0)
    single = sweep.heavy_top(**one)
    assert single.motion_class.dims == () and single.motion_class.item() == "cusps"
    _assert_same(single, sweep.heavy_top(**one, chunks=1))
    _assert_same(single, sweep.heavy_top(**one, to_zarr=tmp_path / "one.zarr").compute())
    # Plain xarray sees the categories as codes into their attribute.
    raw = xr.open_zarr(tmp_path / "top.zarr", consolidated=False)
    codes = raw.motion_class.values
    assert np.array_equal(
        np.asarray(raw.motion_class.attrs["categories"])[codes], local.motion_class.values
    )


def test_progress_is_reported_and_can_stop_the_sweep() -> None:
    seen: list[float] = []
    sweep.heavy_top(
        I1=1.0,
        I3=0.5,
        mgl=1.0,
        theta=np.linspace(0.1, 1.5, 300),
        psi_dot=np.linspace(0.5, 20.0, 300),
        progress=seen.append,
    )
    assert seen and seen[-1] == 1.0 and all(0 <= f <= 1 for f in seen)
    assert seen == sorted(seen)

    class Stop(Exception):
        pass

    def stop(fraction: float) -> None:
        raise Stop

    with pytest.raises(Stop):
        sweep.heavy_top(
            I1=1.0,
            I3=0.5,
            mgl=1.0,
            theta=np.linspace(0.1, 1.5, 500),
            psi_dot=np.linspace(0.5, 20.0, 500),
            progress=stop,
        )
    chunked: list[float] = []
    _top_sweep(chunks={"theta": 3}, progress=chunked.append)
    assert chunked == [1 / 3, 2 / 3, 1.0]


def test_bad_points_are_refused_by_keyword_and_index() -> None:
    theta = THETA.copy()
    theta[4] = 3.5
    with pytest.raises(
        ps.PoinsotError,
        match=r"^theta: must be finite and in \[0, pi\], got 3.5 \(at theta\[4\], psi_dot\[0\]\)$",
    ):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=theta, psi_dot=PSI_DOT)
    # The same before any chunk is sent out, and with the whole sweep's indices.
    with pytest.raises(ps.PoinsotError, match=r"\(at theta\[4\], psi_dot\[0\]\)$"):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=theta, psi_dot=PSI_DOT, chunks=2)
    with pytest.raises(ps.InvalidInertiaError, match=r"^I3: .*\(at I1\[1\]\)$"):
        sweep.heavy_top(I1=[1.0, 0.1], I3=0.5, mgl=1.0, theta=0.5)
    with pytest.raises(ps.InvalidInertiaError, match=r"^moments: .*\(at moments_index\[1\]\)$"):
        sweep.free_body(moments=[[1, 2, 3], [1, 1, 5]], omega0=[0.0, 1.0, 0.0])
    with pytest.raises(ps.PoinsotError, match=r"^latitude: .*\(at latitude\[2\]\)$"):
        sweep.drop(height=10.0, latitude=[0.0, 45.0, 95.0], degrees=True)
    with pytest.raises(ps.PoinsotError, match="^I1: must be given"):
        sweep.heavy_top(I3=0.5, mgl=1.0, theta=THETA)
    # Negative control: the same sweeps with good values run.
    assert sweep.heavy_top(I1=[1.0, 0.3], I3=0.5, mgl=1.0, theta=0.5).motion_class.size == 2


def test_malformed_calls_are_refused_by_name() -> None:
    with pytest.raises(
        ps.ArgumentTypeError, match="^spin: is not a keyword of poinsot.sweep.heavy_top"
    ):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=THETA, spin=3.0)
    with pytest.raises(
        ps.PoinsotError, match=r"^theta: must be a number or a 1-D array .* got shape \(3, 3\)"
    ):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=np.ones((3, 3)))
    with pytest.raises(ps.PoinsotError, match=r"^omega0: must have shape \(3,\) or \(N, 3\)"):
        sweep.free_body(moments=[1, 2, 3], omega0=np.ones((2, 2)))
    with pytest.raises(ps.PoinsotError, match="^psi_dot: must not be empty"):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=THETA, psi_dot=[])
    with pytest.raises(
        ps.PoinsotError,
        match=r"^attitude0: is paired with omega0 along 'member' and must have as many entries \(3\), got 2",
    ):
        sweep.simulate(
            moments=[1, 2, 3],
            omega0=np.ones((3, 3)),
            attitude0=np.tile([1.0, 0, 0, 0], (2, 1)),
            paired={"member": ("omega0", "attitude0")},
            duration=1.0,
        )
    with pytest.raises(ps.PoinsotError, match="^paired: 'I1' is not given"):
        sweep.heavy_top(
            theta=THETA, I3=0.5, mgl=1.0, psi_dot=PSI_DOT, paired={"p": ("theta", "I1")}
        )
    with pytest.raises(ps.PoinsotError, match="^theta: a range .* give samples=N"):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=sweep.uniform(0.1, 1.0))
    with pytest.raises(ps.PoinsotError, match="^samples: no keyword is a range"):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=THETA, samples=10)
    with pytest.raises(ps.PoinsotError, match="^high: must be >= low"):
        sweep.uniform(2.0, 1.0)
    with pytest.raises(ps.PoinsotError, match="^chunks: 'phi' is not a dimension"):
        _top_sweep(chunks={"phi": 2})
    with pytest.raises(ps.ArgumentTypeError, match="^client: must be a dask.distributed.Client"):
        _top_sweep(client="localhost:8786")
    with pytest.raises(ps.ArgumentTypeError, match="^torque: a sweep takes the built-in torques"):
        sweep.simulate(
            moments=[1, 2, 3],
            omega0=[1.0, 0.0, 0.0],
            duration=1.0,
            torque=lambda t, w, q: [0.0, 0.0, 0.0],
        )
    with pytest.raises(ps.PoinsotError, match="^duration: must be finite and > 0"):
        sweep.simulate(moments=[1, 2, 3], omega0=[1.0, 0.0, 0.0], duration=-1.0)


@pytest.mark.parametrize("bad", [1.5, {"motion_class": 1}, [1, 2], [["motion_class"]], object()])
def test_quantities_of_the_wrong_type_are_refused_by_name(bad) -> None:
    """``quantities`` is a name or a list of names; anything else is refused naming it (found by
    the fuzz suite: a float gave Python's own "'float' object is not iterable")."""
    with pytest.raises(ps.ArgumentTypeError, match=r"^quantities: must"):
        sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=0.5, quantities=bad)
    ok = sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=0.5, quantities=("motion_class",))
    assert list(ok.data_vars) == ["motion_class"]


def test_quantities_as_a_numpy_array_of_names() -> None:
    """A 0-d numpy array of a name is that name, a 1-D one a list of names (issue 21, item 10:
    ``np.array('motion_class')`` raised Python's "iteration over a 0-d array", found by the
    fuzz suite at 20,000 examples); a 2-D one is refused naming ``quantities``."""
    one = sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=0.5, quantities=np.array("motion_class"))
    want = sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=0.5, quantities="motion_class")
    _assert_same(one, want)
    two = sweep.heavy_top(
        I1=1.0, I3=0.5, mgl=1.0, theta=0.5, quantities=np.array(["motion_class", "omega3"])
    )
    assert list(two.data_vars) == ["motion_class", "omega3"]
    for bad in (np.array([["motion_class"]]), np.array(3.0), np.array([1, 2])):
        with pytest.raises(ps.ArgumentTypeError, match=r"^quantities: must"):
            sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=0.5, quantities=bad)


def test_a_client_that_is_not_a_running_dask_client_is_refused_by_name() -> None:
    """A ThreadPoolExecutor has ``submit`` but no ``gather``: it passed the old check and failed
    with a bare AttributeError; a closed Client raised distributed's ClosedClientError from
    inside the run (issue 21, item 10). Both are refused first, naming ``client``."""
    import concurrent.futures

    distributed = pytest.importorskip("distributed")
    with (
        concurrent.futures.ThreadPoolExecutor(1) as pool,
        pytest.raises(ps.ArgumentTypeError, match=r"^client: must be a dask.distributed"),
    ):
        _top_sweep(client=pool)
    client = distributed.Client(
        processes=False, n_workers=1, threads_per_worker=1, dashboard_address=None
    )
    try:  # negative control: the running client computes the sweep
        _assert_same(_top_sweep(client=client), _top_sweep())
    finally:
        client.close()
    with pytest.raises(ps.PoinsotError, match=r"^client: is closed"):
        _top_sweep(client=client)


def test_to_zarr_must_be_a_writable_path(tmp_path, monkeypatch) -> None:
    """``to_zarr=42`` wrote the store ``./42``; an unwritable path failed with the file
    system's bare error once the run had started (issue 21, item 10). Now: a str or
    os.PathLike only, and the directory is tried before any work, naming ``to_zarr``."""
    from poinsot.sweep import _run

    monkeypatch.chdir(tmp_path)
    written = []
    monkeypatch.setattr(_run, "block_to_zarr", lambda *a: written.append(a) or 0)
    for bad in (42, 4.2, b"x.zarr", ["x.zarr"], ""):
        with pytest.raises(ps.ArgumentTypeError, match=r"^to_zarr: must be"):
            _top_sweep(to_zarr=bad)
    assert list(tmp_path.iterdir()) == []  # no ./42
    for bad in ("/proc/x.zarr", tmp_path / "missing" / "x.zarr", tmp_path / "f" / "x.zarr"):
        if str(bad).startswith(str(tmp_path / "f")):
            (tmp_path / "f").write_text("a file, not a directory")
        if str(bad).startswith("/proc") and not os.path.isdir("/proc"):
            continue
        with pytest.raises(ps.PoinsotError, match=r"^to_zarr: cannot write"):
            _top_sweep(to_zarr=bad)
    assert written == []  # refused before any block was computed
    assert not (tmp_path / "missing").exists()


def test_a_failed_integration_names_the_users_argument_and_the_point() -> None:
    """The integrators name their own variables (t, y0); a sweep names the user's argument, as
    the scalar API does — height for a drop, speed for a projectile, duration for simulate —
    and the point (found by the fuzz suite)."""
    with pytest.raises(ps.IntegrationError, match=r"^height: .*\(at height\[1\]\)$"):
        sweep.drop(height=[100.0, 1e308], latitude=0.5)
    with pytest.raises(ps.IntegrationError, match=r"^height: "):
        ps.Earth().drop(1e308, 0.5)  # the scalar API says the same
    with pytest.raises(ps.IntegrationError, match=r"^speed: .*\(at speed\[1\]\)$"):
        sweep.projectile(speed=[50.0, 1e308], elevation=0.5, azimuth=0.3, latitude=0.7)
    torque = ps.BodyTorque([1e308, 0.0, 0.0])
    with pytest.raises(ps.IntegrationError, match=r"^duration: .*\(at omega0_index\[0\]\)$"):
        sweep.simulate(
            moments=[1.0, 2.0, 3.0],
            omega0=[[1.0, 0.1, 1.0], [0.0, 0.5, 1.0]],
            duration=0.5,
            dt=1e-2,
            torque=torque,
        )
    with pytest.raises(ps.IntegrationError, match=r"^duration: "):
        ps.simulate_batch([[1.0, 2.0, 3.0]], [[1.0, 0.1, 1.0]], 0.5, torque=torque, dt=1e-2)
    # Control: the same sweeps at sane values compute.
    assert np.isfinite(sweep.drop(height=[100.0, 200.0], latitude=0.5).east).all()


def test_the_memory_budget_is_checked_before_work() -> None:
    previous = ps.set_memory_budget(1 << 20)
    try:
        with pytest.raises(
            ps.PoinsotError, match=r"^psi_dot: a sweep of 1000000 points .* memory budget"
        ):
            sweep.heavy_top(
                I1=1.0,
                I3=0.5,
                mgl=1.0,
                theta=np.linspace(0.1, 1.0, 1000),
                psi_dot=np.linspace(1.0, 2.0, 1000),
                progress=False,
            )
        with pytest.raises(ps.PoinsotError, match="^psi_dot: .*memory budget"):
            sweep.heavy_top(
                I1=1.0,
                I3=0.5,
                mgl=1.0,
                theta=np.linspace(0.1, 1.0, 1000),
                psi_dot=np.linspace(1.0, 2.0, 1000),
                chunks=100,
            )
        # A dimension not named after a keyword is named by the user's argument.
        with pytest.raises(ps.PoinsotError, match="^samples: a sweep of 100000 points"):
            sweep.heavy_top(
                I1=1.0,
                I3=0.5,
                mgl=1.0,
                theta=sweep.uniform(0.1, 1.0),
                psi_dot=np.linspace(1.0, 2.0, 10),
                samples=10_000,
            )
        with pytest.raises(ps.PoinsotError, match="^omega0: a sweep of 20000 points"):
            sweep.simulate(moments=[1.0, 2.0, 3.0], omega0=np.ones((20_000, 3)), duration=1.0)
    finally:
        ps.set_memory_budget(previous)


def test_without_the_extra_the_error_names_it(monkeypatch) -> None:
    monkeypatch.setitem(sys.modules, "xarray", None)
    with pytest.raises(ImportError, match=r"poinsot\[parallel\]"):
        _top_sweep()
    # The package and poinsot.sweep import without xarray or dask: only a sweep needs them.
    code = "import sys, poinsot, poinsot.sweep; print(sorted({'xarray', 'dask', 'zarr', 'distributed'} & set(sys.modules)))"
    env = {**os.environ, "PYTHONPATH": str(Path(ps.__file__).resolve().parents[1])}
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True
    )
    assert out.stdout.strip() == "[]"


def test_the_docs_page_blocks_run() -> None:
    """Every ```python block of docs/sweeps.md runs (in order, one namespace); the cluster recipes
    are ``{code-block}`` blocks, shown, not run."""
    doc = Path(__file__).resolve().parents[2] / "docs" / "sweeps.md"
    blocks = re.findall(r"```python\n(.*?)```", doc.read_text(encoding="utf-8"), re.DOTALL)
    assert len(blocks) >= 6
    namespace: dict[str, object] = {"__name__": "__doc__"}
    for i, block in enumerate(blocks):
        exec(compile(block, f"docs/sweeps.md[block {i}]", "exec"), namespace)
