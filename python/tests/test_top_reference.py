"""poinsot.HeavyTop against the 40-digit mpmath integration of the Lagrangian
(python/tests/reference/gen_heavy_top.py → heavy_top_mpmath.json): every case, every sample time,
angles and rates, the constants p_phi, p_psi, E and the class of the axis' path."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from poinsot import HeavyTop

DATA = json.loads((Path(__file__).parent / "reference" / "heavy_top_mpmath.json").read_text())
# Round-off of the exact solution: 1e-12 absolute for |x| <= 1, relative above (phi, psi grow).
REFERENCE_TOL = 1e-12


@pytest.mark.parametrize("case", DATA["cases"], ids=[c["name"] for c in DATA["cases"]])
def test_exact_motion_matches_mpmath(case: dict) -> None:
    init = case["initial"]
    top = HeavyTop(
        case["I1"],
        case["I3"],
        case["mgl"],
        init["theta"],
        theta_dot=init["theta_dot"],
        phi_dot=init["phi_dot"],
        psi_dot=init["psi_dot"],
    )
    assert top.motion_class == case["class"]
    for key in ("p_phi", "p_psi", "energy"):
        ref = float(case[key])
        assert abs(getattr(top, key) - ref) <= REFERENCE_TOL * max(1.0, abs(ref))
    t = np.array(case["times"])
    got = dict(zip(("phi", "theta", "psi"), top.euler_angles(t)))
    got.update(zip(("phi_dot", "theta_dot", "psi_dot"), top.euler_rates(t)))
    for key, values in got.items():
        ref = np.array(case["trajectory"][key])
        err = np.abs(values - ref) / np.maximum(1.0, np.abs(ref))
        assert np.max(err) < REFERENCE_TOL, (key, float(np.max(err)))
    # The slow path (Jacobi sn and Carlson's R_J at every time) gives the same numbers.
    slow = top._core.euler_angles_carlson(t)
    for i, key in enumerate(("phi", "theta", "psi")):
        ref = np.array(case["trajectory"][key])
        assert np.max(np.abs(slow[:, i] - ref) / np.maximum(1.0, np.abs(ref))) < REFERENCE_TOL
