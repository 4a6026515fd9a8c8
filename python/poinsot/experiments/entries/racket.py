"""The tennis racket: a racquet tossed about its intermediate axis, its flip timed by a phone's
gyroscope (Bubbar and Zhu, University of British Columbia, 2025).

The prediction is the period of ω in the body of :class:`poinsot.FreeRigidBody` (the exact
torque-free motion, Jacobi's elliptic functions) for the measured moments and the gyroscope's
first reading of the toss; the closed form is Landau and Lifshitz's 4K(m)/λ (Mechanics §37),
from the body's Jacobi parameter m and rate λ with :func:`poinsot.special.ellipk`.

No other published flip period with the object's measured moments was found: Peterson and
Schwalm (Am. J. Phys. 89, 349 (2021)) model the T-handle filmed in orbit without its moments
(their notebook "made no attempt to adjust the model to fit the period"); of Wheatland et al.
(Am. J. Phys. 89, 342 (2021), arXiv:2011.02024), a tossed phone's gyroscope record, only the
abstract could be read. Mardešić, Gutierrez Guillen, Van Damme and Sugny, "Geometric origin
of the tennis racket effect" (PRL 125, 064301, 2020; its abstract read) is theory: the twist
of the handle and its bounds, no measurement; Van Damme, Mardešić and Sugny (Physica D 338,
2017) was not found in the stored texts.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from poinsot import FreeRigidBody
from poinsot.special import ellipk

from .._catalogue import Experiment, Source, ureg

__all__ = ["ENTRIES"]


def _body(inputs: Mapping[str, Any]) -> tuple[list[float], list[float]]:
    """The moments (kg·m²; primary, intermediate, tertiary) of the flat racquet, I₂ = I₁ − I₃
    (the perpendicular-axis theorem), and the first ω of the toss (rad/s) along the same axes."""
    i1 = float(inputs["moment_primary"].to("kg * m**2").magnitude)
    i3 = float(inputs["moment_tertiary"].to("kg * m**2").magnitude)
    omega = [
        float(inputs[f"omega_{axis}"].to("rad/s").magnitude)
        for axis in ("primary", "intermediate", "tertiary")
    ]
    return [i1, i1 - i3, i3], omega


def _flip_period(inputs: Mapping[str, Any]) -> Any:
    """The period of ω in the body of the free racquet (exact solution), s."""
    moments, omega = _body(inputs)
    return ureg.Quantity(FreeRigidBody(moments, omega).period, "s")


def _closed_flip_period(inputs: Mapping[str, Any]) -> Any:
    """4K(m)/λ (Landau & Lifshitz §37): the complete elliptic integral of the body's Jacobi
    parameter m = k² over the rate λ of its elliptic argument, s."""
    moments, omega = _body(inputs)
    body = FreeRigidBody(moments, omega)
    return ureg.Quantity(4 * ellipk(body.parameter) / body.frequency, "s")


_REPORT = Source(
    who="Felix Bubbar and Leo Zhu (Science One, University of British Columbia)",
    first_hand=True,
    where="Vancouver, British Columbia",
    when="2025 (the toss: 14 February 2025)",
    publication=(
        "Bubbar, F. and Zhu, L. (2025), 'The Intermediate Axis Theorem: A Model for the Period "
        "and a Phenomenal Explanation', UBC Undergraduate Research (cIRcle), issued 2025-03-21"
    ),
    page=(
        "Appendix, table 'Results of the physical and torsional pendulum experiments' (I₁ = "
        "20.7 ± 3.8, I₂ = 18.8 ± 5.7, I₃ = 1.391 ± 0.076 g·m²); Methods, 'Modelling the "
        "Period' (T from the zeros and extrema of ω₂, its uncertainty from the spread of Δt)"
    ),
    url="https://doi.org/10.14288/1.0448943",
    note=(
        "read first-hand in the report's source as submitted to cIRcle (github.com/fbubbar/"
        "sci1-t2, report/main.typ at fe4f87e; its abstract matches the cIRcle page: χ² = 1.58, "
        "'within 20%'). The moments agree with the code's PRQ_I (analyse/num_sim.py: "
        "0.020703, 0.018816, 0.0013911 kg·m²)"
    ),
)

_TRIAL = Source(
    who="Felix Bubbar and Leo Zhu (the data and analysis the report points to)",
    first_hand=True,
    where="Vancouver, British Columbia",
    when="2025-02-14 (the record 'Gyroscope rotation rate 2025-02-14 09-35-02')",
    publication=(
        "github.com/fbubbar/sci1-t2 (the report's 'Materials': all data and source code), "
        "analyse/combined.ipynb, the filtered period data (63 trials)"
    ),
    page=(
        "the first filtered trial: 'initial angular speed: 10.12 rad/s, period: 0.9690 ± "
        "0.0507 seconds (rel. 5.24%)'; its first gyroscope row (t = 78.2298 s) in data/round3/"
        "Gyroscope rotation rate 2025-02-14 09-35-02/Raw Data.csv: x 10.12208, y −4.61593, "
        "z −1.55574 rad/s"
    ),
    note=(
        "read first-hand, and the notebook's period re-derived here with its own code from the "
        "raw data (same 0.9690 ± 0.0507 s). The notebook prints the trial as 'segment 4': after "
        "filtering it pairs the kept trials with the unfiltered labels; it is segment 5 "
        "(78.22–79.22 s). Axes as the code maps them: primary z, intermediate x, tertiary y "
        "(the handle)"
    ),
)

ENTRIES = [
    Experiment(
        name="bubbar-zhu-2025",
        title="A tossed tennis racquet's flip, timed by a phone's gyroscope",
        topic="free rotation",
        sources=(_REPORT, _TRIAL),
        inputs={
            "moment_primary": "20.7 g * m**2",
            "moment_tertiary": "1.391 g * m**2",
            "omega_primary": "-1.5557 rad/s",
            "omega_intermediate": "10.1221 rad/s",
            "omega_tertiary": "-4.6159 rad/s",
        },
        quantity="period of ω in the body (one full loop: two flips)",
        measured="0.9690 s",
        uncertainty="0.0507 s",
        uncertainty_kind=(
            "stated by the authors for this toss: the spread of its quarter-period intervals "
            "(4 × the standard deviation of Δt)"
        ),
        predict=_flip_period,
        closed_form=_closed_flip_period,
        assumptions=(
            "no torque (air drag neglected; the report measures −0.048 ± 0.026 N·m)",
            "flat racquet: I₂ = I₁ − I₃ (the perpendicular-axis theorem)",
            "the phone's axes are the racquet's principal axes",
            "exact solution (Jacobi's elliptic functions)",
        ),
        story=(
            "In 1985 the cosmonaut Vladimir Dzhanibekov watched a wing nut spin off its bolt on "
            "Salyut 7 and flip over every few turns: rotation about the axis of intermediate "
            "moment is unstable (Euler, Poinsot), the tennis-racket theorem. No flip filmed in "
            "orbit was found timed against the object's measured moments; in 2025 two students "
            "at the University of British Columbia timed one on the ground. Felix Bubbar and Leo "
            "Zhu zip-tied an iPhone 12 to the strings of a 27-inch racquet, tossed it 113 times "
            "about its intermediate axis, recorded ω with the phone's gyroscope (phyphox, "
            "100 Hz), and measured the racquet's moments with a torsional and a physical "
            "pendulum. Their central moments cannot all be right: 1.391 + 18.8 < 20.7 g·m², so "
            "I₂ + I₃ < I₁ by 0.51 g·m² (2.5 % of I₁), which no distribution of mass allows. A "
            "racquet is nearly flat, for which I₁ = I₂ + I₃; within their uncertainties the "
            "three agree with it (I₂ = I₁ − I₃ = 19.3 against their 18.8 ± 5.7). Taken flat, the "
            "flip rate near the intermediate axis, λ² = ω₂²(1 − 2I₃/I₁), depends only on I₃/I₁, "
            "so the poorly known I₁ − I₂ drops out and the moments' uncertainties move the "
            "prediction by about 2 % only. For their first toss of 14 February 2025, starting at "
            "ω = (−1.56, 10.12, −4.62) rad/s, poinsot's exact solution loops in 0.924 s; the "
            "gyroscope's ω₂ took 0.969 ± 0.051 s."
        ),
        unit="s",
    ),
]
