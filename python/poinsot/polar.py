"""The real pole: the Earth's polar motion from the IERS, and its fit to the Chandler wobble.

:func:`polar_motion` reads the IERS EOP C04 series of the pole's coordinates (x, y), 1962 to
now, from the ``astropy-iers-data`` package (the ``poinsot[earth]`` extra) or, without it, from
the decimated extract that ships with poinsot (``poinsot/data/eop_c04_polar_motion.csv``:
every 5th day, its header names the source). :func:`fit_wobble` fits the pole to a linear
trend, the prograde Chandler circle (its period searched) and the annual circles (prograde
and retrograde, one tropical year) by least squares; the fit lives in the core
(``crates/poinsot/src/earth/wobble.rs``).

Units: x and y in radians (the IERS publish arcseconds: 1″ = π/648000 rad), x towards
Greenwich and y towards 90° W; times in seconds, dates as ``numpy.datetime64``; periods in s,
amplitudes and phases in rad.
"""

from __future__ import annotations

import dataclasses
import datetime
import math
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np
from numpy.typing import NDArray

from . import _core
from ._units import is_quantity, to_si
from ._validate import FloatArray, as_choice, as_float_array, as_scalar
from .errors import PoinsotError

__all__ = [
    "ANNUAL_PERIOD",
    "CHANDLER_SEARCH",
    "J2000",
    "PolarMotion",
    "WobbleFit",
    "WobbleTerm",
    "fit_wobble",
    "polar_motion",
]

#: The period of the annual wobble (s): the mean tropical year, 365.242190 days.
ANNUAL_PERIOD: float = _core.ANNUAL_PERIOD
#: The default band of the Chandler period search (s, s): 380 to 500 days.
CHANDLER_SEARCH: tuple[float, float] = tuple(_core.CHANDLER_SEARCH)  # type: ignore[assignment]
#: The epoch of the times :func:`fit_wobble` makes from dates: 2000-01-01 12:00 UTC (J2000.0
#: to within the minute between UTC and TT, nothing at the wobble's scale).
J2000 = np.datetime64("2000-01-01T12:00:00", "s")

#: The core's defaults of the two calls (poinsot._core.DEFAULTS).
_FIT = _core.DEFAULTS["fit_wobble"]
_READ = _core.DEFAULTS["polar_motion"]

_ARCSEC = math.pi / 648_000.0
_DAY = 86_400.0
#: MJD 0 as a date.
_MJD0 = np.datetime64("1858-11-17", "D")
#: The shipped extract (package data).
SHIPPED = "eop_c04_polar_motion.csv"


class PolarMotion:
    """The pole's path: dates, MJD, x and y (rad), and where the numbers came from.

    Attributes
    ----------
    dates:
        The sampling dates (``datetime64[D]``, 0h UTC).
    mjd:
        The same as modified Julian dates (days, float).
    x, y:
        The pole's coordinates (rad): x towards Greenwich, y towards 90° W (IERS).
    source:
        Where they came from: the C04 file of ``astropy-iers-data`` (with its version) or the
        shipped extract.
    """

    __slots__ = ("dates", "mjd", "source", "x", "y")

    def __init__(self, mjd: Any, x: Any, y: Any, source: str) -> None:
        self.mjd: FloatArray = as_float_array(mjd, "mjd")
        self.x: FloatArray = as_float_array(x, "x")
        self.y: FloatArray = as_float_array(y, "y")
        if not (self.mjd.shape == self.x.shape == self.y.shape) or self.mjd.ndim != 1:
            raise PoinsotError(
                f"x: mjd, x and y must be 1-D of one length, got {self.mjd.shape}, "
                f"{self.x.shape}, {self.y.shape}"
            )
        self.dates: NDArray[np.datetime64] = _MJD0 + np.rint(self.mjd).astype("timedelta64[D]")
        self.source = str(source)

    @property
    def t(self) -> FloatArray:
        """Seconds since :data:`J2000` (2000-01-01 12:00 UTC): the times :func:`fit_wobble`
        takes (it makes the same from :attr:`dates`)."""
        return (self.mjd - 51_544.5) * _DAY

    def __len__(self) -> int:
        return int(self.mjd.size)

    def __repr__(self) -> str:
        span = f"{self.dates[0]} to {self.dates[-1]}" if len(self) else "empty"
        return f"PolarMotion({len(self)} samples, {span}, source={self.source!r})"

    def __reduce__(self) -> tuple[Any, ...]:
        return (PolarMotion, (self.mjd, self.x, self.y, self.source))


def _read_c04(path: Path) -> tuple[FloatArray, FloatArray, FloatArray, str]:
    """MJD, x, y (arcsec) and the series' name from an IERS C04 file (``eopc04.1962-now``):
    the columns found by the header line that names them (``# YR MM DD HH MJD x(") y(")``)."""
    names: list[str] = []
    series = "IERS EOP C04"
    with open(path, encoding="ascii", errors="replace") as f:
        for line in f:
            if not line.startswith("#"):
                break
            if "C04" in line and "TIME SERIES" in line.upper():
                series = line.strip("# \n").split("  ")[0].strip()
            tokens = line.strip("# \n").split()
            if tokens[:1] == ["YR"] and "MJD" in tokens:
                names = tokens
    if not names:
        raise PoinsotError(f"source: {path} has no header naming its MJD and x, y columns")
    i = names.index("MJD")
    data = np.loadtxt(path, comments="#", usecols=(i, i + 1, i + 2), ndmin=2)
    return data[:, 0], data[:, 1], data[:, 2], series


def _shipped() -> PolarMotion:
    text = resources.files("poinsot").joinpath("data", SHIPPED).read_text(encoding="utf-8")
    rows = [ln for ln in text.splitlines() if ln and not ln.startswith("#")]
    data = np.array([r.split(",") for r in rows[1:]], dtype=np.float64)
    return PolarMotion(
        data[:, 0],
        data[:, 1] * _ARCSEC,
        data[:, 2] * _ARCSEC,
        "IERS EOP 20 C04, every 5th day (shipped extract poinsot/data/" + SHIPPED + ")",
    )


def _iers() -> PolarMotion:
    try:
        import astropy_iers_data as aid
    except ImportError:
        raise PoinsotError(
            "source: 'iers' needs the astropy-iers-data package (pip install 'poinsot[earth]')"
        ) from None
    mjd, x, y, series = _read_c04(Path(aid.IERS_B_FILE))
    version = getattr(aid, "__version__", "?")
    return PolarMotion(
        mjd, x * _ARCSEC, y * _ARCSEC, f"{series} (astropy-iers-data {version}, eopc04.1962-now)"
    )


def polar_motion(source: str = _READ["source"]) -> PolarMotion:
    """The Earth's polar motion from the IERS EOP C04 series, 1962 to the data's last day.

    Parameters
    ----------
    source:
        ``"iers"``: the daily C04 file of the ``astropy-iers-data`` package (``pip install
        'poinsot[earth]'``; updated with that package); ``"shipped"``: the extract that ships
        with poinsot (the same series every 5th day, 1962-01-03 to 2026-09-29, attributed in its
        header); ``"auto"`` (default): the first when installed, else the second.

    Returns
    -------
    PolarMotion
        Dates (``datetime64[D]``), MJD (days), x and y (rad), the source.

    Examples
    --------
    >>> import poinsot as ps
    >>> pm = ps.polar_motion("shipped")
    >>> str(pm.dates[0]), len(pm) > 4000
    ('1962-01-03', True)
    """
    choice = as_choice(source, "source", ("auto", "shipped", "iers"))
    if choice == "shipped":
        return _shipped()
    if choice == "iers":
        return _iers()
    try:
        return _iers()
    except PoinsotError:
        return _shipped()


@dataclasses.dataclass(frozen=True)
class WobbleTerm:
    """One circle of the pole's motion, p = x − i y = A e^{i(±ωt + φ)}, with 1-σ uncertainties.

    ``period`` (s), ``amplitude`` (rad), ``phase`` (rad, at t = 0, i.e. at :data:`J2000` for
    dates); each ``*_sigma`` its 1-σ uncertainty (``period_sigma`` 0 for a period held fixed);
    ``prograde`` whether it turns with the Earth's rotation.
    """

    period: float
    period_sigma: float
    amplitude: float
    amplitude_sigma: float
    phase: float
    phase_sigma: float
    prograde: bool

    @property
    def period_days(self) -> float:
        """The period in days of 86400 s."""
        return self.period / _DAY


@dataclasses.dataclass(frozen=True)
class WobbleFit:
    """The fit of :func:`fit_wobble`: three circles, the trend and the fit's quality.

    Attributes
    ----------
    chandler, annual_prograde, annual_retrograde:
        The circles (:class:`WobbleTerm`).
    offset, offset_sigma:
        The trend's pole (x₀, y₀) at t = 0 (rad) and its 1-σ uncertainties.
    drift, drift_sigma:
        The trend's drift (ẋ, ẏ) (rad/s) and its 1-σ uncertainties.
    residual_rms:
        RMS of the residuals over x and y (rad).
    serial_correlation:
        ρ, the residuals' lag-1 autocorrelation (clamped to [0, 0.999]).
    sigma_inflation:
        √((1 + ρ)/(1 − ρ)), the factor by which the formal uncertainties were widened.
    chandler_false_alarm:
        The chance that noise alone, searched over the band's independent periods, gives a
        Chandler amplitude this large.
    chandler_significant:
        Whether that chance is below 0.0027 (the two-sided 3-σ level).
    samples:
        Number of samples fitted.
    """

    chandler: WobbleTerm
    annual_prograde: WobbleTerm
    annual_retrograde: WobbleTerm
    offset: tuple[float, float]
    offset_sigma: tuple[float, float]
    drift: tuple[float, float]
    drift_sigma: tuple[float, float]
    residual_rms: float
    serial_correlation: float
    sigma_inflation: float
    chandler_false_alarm: float
    chandler_significant: bool
    samples: int

    def __str__(self) -> str:
        c, a, r = self.chandler, self.annual_prograde, self.annual_retrograde
        mas = 1e3 / _ARCSEC
        return (
            f"Chandler wobble: period {c.period_days:.1f} ± {c.period_sigma / _DAY:.1f} days, "
            f"radius {c.amplitude * mas:.0f} ± {c.amplitude_sigma * mas:.0f} mas, prograde"
            f"{'' if self.chandler_significant else ' (not significant)'}; annual wobble "
            f"({a.period_days:.2f} days): prograde {a.amplitude * mas:.0f} ± "
            f"{a.amplitude_sigma * mas:.0f} mas, retrograde {r.amplitude * mas:.0f} ± "
            f"{r.amplitude_sigma * mas:.0f} mas; residual RMS {self.residual_rms * mas:.0f} mas "
            f"({self.samples} samples, uncertainties widened ×{self.sigma_inflation:.1f} for "
            f"serial correlation)."
        )


def _si(value: Any, name: str, like: str, what: str) -> Any:
    """A pint quantity ``value`` in the SI unit of the argument ``like`` (``"duration"``: s,
    ``"angle"``: rad), its error naming ``name``; anything else as it is."""
    if not is_quantity(value):
        return value
    try:
        return to_si(value, like)
    except PoinsotError:
        raise PoinsotError(f"{name}: expected {what}, got {value.units:~P}") from None


def _times(t: Any) -> FloatArray:
    """``t`` as seconds: dates (``datetime64``) from :data:`J2000`, pint times converted,
    plain numbers taken as seconds."""
    raw = t if isinstance(t, np.ndarray) else None
    if raw is None and not is_quantity(t):
        try:
            raw = np.asarray(t)
        except (TypeError, ValueError):
            raw = None
    if raw is not None and raw.dtype.kind == "M":
        if np.isnat(raw).any():
            raise PoinsotError("t: must be finite, got NaT")
        return ((raw - J2000) / np.timedelta64(1, "s")).astype(np.float64)
    return as_float_array(_si(t, "t", "duration", "a time"), "t")


def _angles(value: Any, name: str) -> FloatArray:
    """``value`` as radians: a pint angle converted, plain numbers taken as radians."""
    return as_float_array(_si(value, name, "angle", "an angle"), name)


def _period(value: Any, name: str = "chandler_period") -> float:
    return as_scalar(_si(value, name, "duration", "a time"), name)


def fit_wobble(
    t: Any,
    x: Any,
    y: Any,
    *,
    chandler_period: Any = None,
    annual_period: Any = _FIT["annual_period"],
) -> WobbleFit:
    """Fits the pole's motion to a trend, the prograde Chandler circle and the annual circles.

    The model, in p = x − i y (x towards Greenwich, y towards 90° W, so that prograde is
    anticlockwise seen from above the north pole): a linear trend of x and of y, the Chandler
    circle A_c e^{i(ω_c t + φ_c)} (prograde, ω_c searched), and the annual circles
    A₊ e^{i(ω_a t + φ₊)} and A₋ e^{i(−ω_a t + φ₋)} (ω_a = 2π/``annual_period``) — the
    decomposition the IERS use for the annual wobble. Least squares over x and y; the Chandler
    period minimises the residual over a grid finer than the record's resolution, refined by
    golden section. The record must span the two periods' beat (1/|1/P_a − 1/P_c|: 6.4 years at
    433 days, 25.7 years for the default band reaching 380 days); refused otherwise.

    Uncertainties (1 σ): from the covariance of all the parameters (the Chandler period
    included), scaled by the residual variance and widened by √((1 + ρ)/(1 − ρ)), ρ the
    residuals' lag-1 autocorrelation — a first-order (AR(1)) allowance for serial correlation.
    On white noise they are the formal errors; on the real pole the residuals (the irregular
    excitation) are correlated over months, longer than AR(1) allows for, so the stated σ are
    still lower bounds there.

    Parameters
    ----------
    t:
        Sampling times: ``datetime64`` dates (taken as seconds since :data:`J2000`, the epoch
        of the phases), or seconds (floats, or a pint time). MJD in days: pass
        ``(mjd - 51544.5) * 86400`` or :attr:`PolarMotion.t`. Strictly increasing.
    x, y:
        The pole's coordinates (rad, or a pint angle), finite, of the length of ``t``.
    chandler_period:
        ``None`` (default): searched over :data:`CHANDLER_SEARCH` (380 to 500 days); a pair
        ``(min, max)`` (s): searched over that band; one number (s): held fixed (its
        uncertainty 0), for a window too short to find it, as a sliding window.
    annual_period:
        The annual circles' period (s); default :data:`ANNUAL_PERIOD` (the tropical year).

    Returns
    -------
    WobbleFit

    Examples
    --------
    >>> import poinsot as ps
    >>> pm = ps.polar_motion("shipped")
    >>> fit = ps.fit_wobble(pm.dates, pm.x, pm.y)
    >>> 425 < fit.chandler.period_days < 440
    True
    """
    ts = _times(t)
    xs = _angles(x, "x")
    ys = _angles(y, "y")
    for name, arr in (("t", ts), ("x", xs), ("y", ys)):
        if arr.ndim != 1:
            raise PoinsotError(f"{name}: must be 1-D, got shape {arr.shape}")
    fixed: float | None = None
    band: tuple[float, float] | None = None
    if chandler_period is not None:
        if isinstance(chandler_period, (tuple, list)):
            if len(chandler_period) != 2:
                raise PoinsotError(
                    f"chandler_period: a band must be (min, max), got {chandler_period!r}"
                )
            band = (_period(chandler_period[0]), _period(chandler_period[1]))
        else:
            fixed = _period(chandler_period)
    pa = _period(annual_period, "annual_period")
    out = _core.fit_wobble(
        np.ascontiguousarray(ts),
        np.ascontiguousarray(xs),
        np.ascontiguousarray(ys),
        fixed,
        band,
        pa,
    )
    # The core's fields are the dataclass's, the three circles as dicts of WobbleTerm's fields.
    fields: dict[str, Any] = dict(out)
    for circle in ("chandler", "annual_prograde", "annual_retrograde"):
        fields[circle] = WobbleTerm(**out[circle])
    return WobbleFit(**fields)


def _write_extract(path: Path, every: int = 5) -> int:
    """Writes the shipped extract from ``astropy-iers-data``'s C04 file: every ``every``-th day
    counted back from the last, columns ``mjd,x_arcsec,y_arcsec``, with the attribution
    header. Returns the number of rows (the maintainers' tool: ``python -c "from
    poinsot.polar import _write_extract; _write_extract(...)"``)."""
    import astropy_iers_data as aid

    mjd, x, y, series = _read_c04(Path(aid.IERS_B_FILE))
    keep = (np.rint(mjd[-1] - mjd).astype(int) % every) == 0
    mjd, x, y = mjd[keep], x[keep], y[keep]

    def day(m: float) -> str:
        return str(_MJD0 + np.timedelta64(int(m), "D"))

    lines = [
        "# Polar motion of the Earth's rotation pole: IERS EOP 20 C04 series (consistent with ITRF 2020),",
        f"# sampled at 0h UTC, decimated here to every {every}th day (the last day of the series kept).",
        "# Source: IERS Earth Orientation Centre (EOP Product Center), Paris Observatory -",
        "#   International Earth Rotation and Reference Systems Service. Reference: IAU 2000 precession-nutation.",
        "#   Description of the series: https://hpiers.obspm.fr/eoppc/eop/eopc04/readme",
        f"# Taken from the file eopc04.1962-now (header: '{series}')",
        f"#   as shipped in the Python package astropy-iers-data {aid.__version__} (BSD-3-Clause, Astropy Developers),",
        f"#   extracted {datetime.date.today().isoformat()} by poinsot.polar._write_extract; values unchanged, columns MJD, x, y only.",
        "# Terms: IERS products are freely available; cite the IERS Earth Orientation Centre (Paris Observatory)",
        "#   and the IERS 20 C04 series when you use these numbers.",
        f"# Span: MJD {mjd[0]:.0f} ({day(mjd[0])}) to {mjd[-1]:.0f} ({day(mjd[-1])}), {len(mjd)} rows. "
        "Units: mjd in days (UTC), x and y in arcseconds",
        "#   (x towards Greenwich, y towards 90 deg W, the IERS convention).",
        "mjd,x_arcsec,y_arcsec",
    ]
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
        for m, a, b in zip(mjd, x, y):
            f.write(f"{m:.0f},{a:.6f},{b:.6f}\n")
    return len(mjd)
