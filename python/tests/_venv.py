"""A fresh virtual environment with a distribution of poinsot installed by its own pip, as a user
gets it: the wheel's (test_wheel.py) and the sdist's (test_sdist.py) tests share it."""

from __future__ import annotations

import os
import subprocess
import venv
from pathlib import Path


def install_in_fresh_venv(
    root: Path,
    pip_args: list[str],
    *,
    drop: tuple[str, ...],
    path: tuple[list[str], str],
    timeout: float,
    extra_env: dict[str, str] | None = None,
) -> tuple[Path, dict[str, str]]:
    """Creates ``root/venv`` (with pip), runs its ``pip install -q *pip_args`` in ``root``, and
    returns its scripts folder and the environment to run it in: this process's variables but
    those starting with a prefix of ``drop``, PATH the folders ``path[0]``, the venv's scripts
    and ``path[1]``, no user site, matplotlib's Agg, no pip version check, and ``extra_env``."""
    env_dir = root / "venv"
    venv.EnvBuilder(with_pip=True, clear=True).create(env_dir)
    bindir = env_dir / ("Scripts" if os.name == "nt" else "bin")
    env = {k: v for k, v in os.environ.items() if not k.startswith(drop)}
    before, after = path
    env["PATH"] = os.pathsep.join([*before, str(bindir), after])
    env["PYTHONNOUSERSITE"] = "1"
    env["MPLBACKEND"] = "Agg"
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env.update(extra_env or {})
    subprocess.run(
        [str(bindir / "python"), "-m", "pip", "install", "-q", *pip_args],
        env=env,
        cwd=root,
        check=True,
        timeout=timeout,
    )
    return bindir, env
