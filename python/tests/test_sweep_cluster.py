"""poinsot.sweep on a Dask cluster: a LocalCluster of two worker processes on loopback (one
module-scoped fixture). The same sweeps as here return the same numbers bit for bit, a worker
killed mid-sweep is recovered by Dask without losing or duplicating a chunk, bad input is
refused before any chunk is sent, and an error raised on a worker names the point in the whole
sweep's indices. Only a local cluster is tested; docs/sweeps.md shows the same calls on
dask-jobqueue and Kubernetes clusters."""

from __future__ import annotations

import logging
import os
import signal
import time
from pathlib import Path

import numpy as np
import poinsot as ps
import pytest
from poinsot import sweep

distributed = pytest.importorskip("distributed")
pytest.importorskip("xarray")


@pytest.fixture(scope="module")
def client():
    """A client of two single-threaded worker processes on 127.0.0.1, which import the same
    poinsot as the tests."""
    here = str(Path(ps.__file__).resolve().parents[1])
    old = os.environ.get("PYTHONPATH")
    os.environ["PYTHONPATH"] = here + (os.pathsep + old if old else "")
    try:
        with (
            distributed.LocalCluster(
                n_workers=2,
                threads_per_worker=1,
                processes=True,
                host="127.0.0.1",
                dashboard_address=None,
            ) as cluster,
            distributed.Client(cluster) as c,
        ):
            yield c
    finally:
        if old is None:
            del os.environ["PYTHONPATH"]
        else:
            os.environ["PYTHONPATH"] = old


def _assert_same(a, b) -> None:
    """Bit for bit: every variable and coordinate equal (strings too), same dims."""
    assert set(a.data_vars) == set(b.data_vars)
    for name in a.variables:
        assert a[name].dims == b[name].dims, name
        assert np.array_equal(np.asarray(a[name].values), np.asarray(b[name].values)), name


def _tasks_on_scheduler(client) -> set[str]:
    """The keys of the tasks the scheduler holds (an earlier test's may still be leaving)."""
    return client.run_on_scheduler(lambda dask_scheduler: {str(k) for k in dask_scheduler.tasks})


def test_the_cluster_returns_the_local_numbers_bit_for_bit(client, tmp_path) -> None:
    top = dict(
        I1=1.0,
        I3=0.5,
        mgl=1.0,
        theta=np.linspace(5.0, 85.0, 17),
        psi_dot=np.linspace(30.0, 1200.0, 23),
        phi_dot=[-60.0, 0.0, 40.0],
        degrees=True,
    )
    local = sweep.heavy_top(**top)
    remote = sweep.heavy_top(**top, client=client, chunks={"theta": 4, "psi_dot": 10})
    _assert_same(local, remote)
    assert remote.attrs == local.attrs
    # Vector keywords along their own dimensions, a direction in degrees.
    body = dict(
        moments=[[1.0, 2.0, 3.0], [1.0, 1.5, 2.2]],
        omega_magnitude=[0.5, 3.0],
        omega_polar=np.linspace(1.0, 179.0, 13),
        omega_azimuth=np.linspace(0.0, 180.0, 7),
        degrees=True,
    )
    _assert_same(sweep.free_body(**body), sweep.free_body(**body, client=client, chunks=3))
    # An ensemble under a torque (paired initial states), integrated by simulate_batch.
    rng = np.random.default_rng(0)
    q = rng.normal(size=(12, 4))
    ens = dict(
        moments=[1.0, 2.0, 3.0],
        omega0=rng.normal(size=(12, 3)),
        attitude0=q / np.linalg.norm(q, axis=1, keepdims=True),
        paired={"member": ("omega0", "attitude0")},
        duration=2.0,
        torque=ps.GravityTorque(mgl=0.5),
        method="rk4",
        dt=1e-3,
    )
    _assert_same(sweep.simulate(**ens), sweep.simulate(**ens, client=client, chunks=5))
    # The Earth, and a random sample drawn once, here.
    drops = dict(
        height=[5.0, 50.0, 500.0],
        latitude=sweep.uniform(-80.0, 80.0),
        samples=9,
        seed=4,
        degrees=True,
    )
    _assert_same(sweep.drop(**drops), sweep.drop(**drops, client=client, chunks=2))
    # Into zarr from the workers, chunk by chunk.
    z = sweep.heavy_top(**top, client=client, chunks={"theta": 5}, to_zarr=tmp_path / "t.zarr")
    _assert_same(local, z.compute())


def test_dask_array_inputs_run_lazily_on_the_active_cluster(client) -> None:
    da = pytest.importorskip("dask.array")
    theta = np.linspace(0.1, 1.5, 21)
    local = sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=theta, omega3=[5.0, 10.0])
    lazy = sweep.heavy_top(
        I1=1.0, I3=0.5, mgl=1.0, theta=da.from_array(theta, chunks=6), omega3=[5.0, 10.0]
    )
    assert lazy.motion_class.chunks == ((6, 6, 6, 3), (2,))
    _assert_same(local, lazy.compute())  # the active client (the fixture's) computes it


def test_a_worker_killed_mid_sweep_is_recovered_without_losing_or_doubling_a_chunk(client) -> None:
    kw = dict(
        I1=1.0,
        I3=0.5,
        mgl=1.0,
        theta=np.linspace(0.05, 3.0, 240),
        psi_dot=np.linspace(-20.0, 40.0, 300),
        phi_dot=0.4,
    )
    local = sweep.heavy_top(**kw)
    pids = client.run(os.getpid)  # {worker address: process id}
    victim = sorted(pids)[0]
    killed: list[float] = []
    seen: list[float] = []

    def progress(fraction: float) -> None:
        seen.append(fraction)
        if not killed and fraction >= 0.2:
            os.kill(pids[victim], signal.SIGKILL)
            killed.append(fraction)

    # The scheduler runs in this process: its log says which finished chunks the kill lost.
    lost: list[str] = []
    handler = logging.Handler(logging.WARNING)
    handler.emit = lambda record: lost.append(record.getMessage())  # type: ignore[method-assign]
    logger = logging.getLogger("distributed.scheduler")
    logger.addHandler(handler)
    try:
        remote = sweep.heavy_top(**kw, client=client, chunks={"theta": 4}, progress=progress)
    finally:
        logger.removeHandler(handler)
    # The kill happened mid-sweep (60 chunks; killed after a fifth of them were done), and lost
    # chunks the killed worker had finished: Dask computed them again elsewhere.
    assert killed and killed[0] < 0.5 and len(seen) >= 60 and all(0 < f <= 1 for f in seen)
    assert any("lose already computed task" in m and "block_results" in m for m in lost), lost
    # Every point present once, with the local numbers: nothing lost, nothing doubled.
    _assert_same(local, remote)
    assert remote.motion_class.size == 240 * 300
    # The nanny replaced the killed worker by a new process.
    client.wait_for_workers(2, timeout=60)
    deadline = time.monotonic() + 60
    while victim in client.run(os.getpid) and time.monotonic() < deadline:
        time.sleep(0.2)
    now = client.run(os.getpid)
    assert pids[victim] not in now.values()
    # The restored cluster computes as before.
    _assert_same(
        local.isel(theta=slice(0, 8)),
        sweep.heavy_top(**{**kw, "theta": kw["theta"][:8]}, client=client, chunks=2),
    )


def test_bad_input_is_refused_before_any_chunk_is_sent(client) -> None:
    from distributed import get_task_stream

    theta = np.linspace(0.1, 1.5, 40)
    # The scheduler's task stream records every task run while it is open (an earlier test's
    # tasks may still be leaving the scheduler: counting them would race with that).
    with get_task_stream(client) as stream:
        before = _tasks_on_scheduler(client)
        bad = theta.copy()
        bad[27] = -0.2
        with pytest.raises(
            ps.PoinsotError, match=r"^theta: .*got -0.2 \(at theta\[27\], psi_dot\[0\]\)$"
        ):
            sweep.heavy_top(
                I1=1.0, I3=0.5, mgl=1.0, theta=bad, psi_dot=[1.0, 2.0], client=client, chunks=5
            )
        with pytest.raises(ps.ArgumentTypeError, match="^spin: is not a keyword"):
            sweep.heavy_top(I1=1.0, I3=0.5, mgl=1.0, theta=0.3, spin=1.0, client=client)
        assert _tasks_on_scheduler(client) <= before  # no new task on the scheduler
    assert stream.data == []  # and none ran
    # Negative control: the same sweep with good input runs its chunks on the workers.
    with get_task_stream(client) as stream:
        sweep.heavy_top(
            I1=1.0, I3=0.5, mgl=1.0, theta=theta, psi_dot=[1.0, 2.0], client=client, chunks=5
        )
    assert len(stream.data) >= 8


def test_an_error_on_a_worker_names_the_point_of_the_whole_sweep(client) -> None:
    # The default step resolves each body's fastest rate: the fast body needs more steps than
    # max_steps allows, which only its integration finds out, on a worker.
    omega0 = np.array([[1.0, 0.0, 0.0]] * 5 + [[1e4, 0.0, 0.0]] + [[1.0, 0.0, 0.0]] * 2)
    kw = dict(moments=[1.0, 2.0, 3.0], omega0=omega0, duration=10.0, max_steps=20_000)
    with pytest.raises(ps.PoinsotError, match=r"^max_steps: .*\(at omega0_index\[5\]\)$"):
        sweep.simulate(**kw, client=client, chunks=2)
    # Negative control: the same sweep without the fast body runs.
    ok = sweep.simulate(**{**kw, "omega0": np.delete(omega0, 5, axis=0)}, client=client, chunks=2)
    assert ok.omega.shape == (7, 3)
