"""The real pole (issue 25): :func:`poinsot.polar_motion` (the IERS EOP C04 series, from
``astropy-iers-data`` or the shipped extract) and :func:`poinsot.fit_wobble` (the Chandler and
annual wobbles, fitted in the core).

On the shipped extract (1962-01-03 to 2026-09-29, every 5th day) the Chandler period comes out
432.6 days (the daily series: the same to 0.1 d), its 1-σ 0.6 d after the AR(1) widening; the
test holds it to 430–436 d. A synthetic pole of known period, radius and phase in white noise is
recovered within 3 σ, and a pole without the Chandler term is found to have none (the fit's
false-alarm chance, calibrated on noise, above 0.27 %).
"""

from __future__ import annotations

import math
import pickle

import numpy as np
import poinsot as ps
import pytest

DAY = 86_400.0
MAS = math.pi / 648_000.0 / 1000.0  # one milliarcsecond (rad)


def synthetic(
    chandler: float,
    *,
    noise: float = 20 * MAS,
    seed: int = 1,
    years: float = 40.0,
    step: float = 7.0,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A pole p = x − i y of trend, a prograde 433-day circle of radius ``chandler`` (rad,
    phase 0.7 at t = 0), a prograde 90 mas and a retrograde 10 mas annual circle, white noise of
    ``noise`` (rad) on x and y; t in s from J2000, sampled every ``step`` days."""
    rng = np.random.default_rng(seed)
    t = np.arange(-0.5 * years * 365.25, 0.5 * years * 365.25, step) * DAY
    wc, wa = 2 * math.pi / (433.0 * DAY), 2 * math.pi / ps.ANNUAL_PERIOD
    p = (
        (40 - 300j) * MAS
        + 3e-17 * t
        + chandler * np.exp(1j * (wc * t + 0.7))
        + 90 * MAS * np.exp(1j * (wa * t - 1.2))
        + 10 * MAS * np.exp(1j * (-wa * t + 2.0))
    )
    x = p.real + noise * rng.standard_normal(t.size)
    y = -p.imag + noise * rng.standard_normal(t.size)
    return t, x, y


def wrapped(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


@pytest.fixture(scope="module")
def shipped() -> ps.PolarMotion:
    return ps.polar_motion("shipped")


def test_the_shipped_extract(shipped: ps.PolarMotion) -> None:
    pm = shipped
    assert len(pm) == 4730 and str(pm.dates[0]) == "1962-01-03"
    assert str(pm.dates[-1]) == "2026-09-29" and "C04" in pm.source
    assert np.all(np.diff(pm.mjd) == 5.0)
    # the pole stays within a second of arc of the IERS reference pole
    assert np.all(np.abs(pm.x) < 1.0 * 1000 * MAS) and np.all(np.abs(pm.y) < 1.0 * 1000 * MAS)
    assert pm.t[0] == pytest.approx((pm.mjd[0] - 51544.5) * DAY)
    assert repr(pm).startswith("PolarMotion(4730 samples, 1962-01-03 to 2026-09-29")
    twin = pickle.loads(pickle.dumps(pm))
    assert twin.source == pm.source and np.array_equal(twin.dates, pm.dates)


def test_the_chandler_period_on_the_shipped_data(shipped: ps.PolarMotion) -> None:
    fit = ps.fit_wobble(shipped.dates, shipped.x, shipped.y)
    c = fit.chandler
    assert 430.0 < c.period_days < 436.0, fit
    assert c.prograde and fit.chandler_significant
    assert 0 < c.period_sigma < 3 * DAY
    assert 80 * MAS < c.amplitude < 200 * MAS  # its mean radius over 64 years
    assert 60 * MAS < fit.annual_prograde.amplitude < 120 * MAS
    assert fit.annual_retrograde.amplitude < fit.annual_prograde.amplitude
    assert fit.sigma_inflation > 5  # the real residuals are correlated, and the fit says so
    # the same from the seconds since J2000 and from the dates
    again = ps.fit_wobble(shipped.t, shipped.x, shipped.y)
    assert again.chandler.period == pytest.approx(c.period, rel=1e-9)
    assert again.chandler.phase == pytest.approx(c.phase, abs=1e-9)
    assert "Chandler wobble: period 43" in str(fit)
    assert repr(fit).startswith("WobbleFit(chandler=WobbleTerm(period=")
    assert pickle.loads(pickle.dumps(fit)) == fit


def test_a_synthetic_wobble_is_recovered_within_its_uncertainties() -> None:
    t, x, y = synthetic(150 * MAS, seed=2)
    fit = ps.fit_wobble(t, x, y)
    c, a, r = fit.chandler, fit.annual_prograde, fit.annual_retrograde
    assert fit.chandler_significant and c.prograde and not r.prograde
    assert abs(c.period - 433.0 * DAY) < 3 * c.period_sigma, c
    assert abs(c.amplitude - 150 * MAS) < 3 * c.amplitude_sigma, c
    assert abs(wrapped(c.phase - 0.7)) < 3 * c.phase_sigma, c
    assert abs(a.amplitude - 90 * MAS) < 3 * a.amplitude_sigma, a
    assert abs(wrapped(a.phase + 1.2)) < 3 * a.phase_sigma, a
    assert abs(r.amplitude - 10 * MAS) < 3 * r.amplitude_sigma, r
    assert abs(wrapped(r.phase - 2.0)) < 3 * r.phase_sigma, r
    assert a.period == ps.ANNUAL_PERIOD and a.period_sigma == 0.0
    assert abs(fit.drift[0] - 3e-17) < 3 * fit.drift_sigma[0]
    assert abs(fit.offset[0] - 40 * MAS) < 3 * fit.offset_sigma[0]
    assert abs(fit.offset[1] - 300 * MAS) < 3 * fit.offset_sigma[1]
    # white noise: ρ near 0, the σ left as they are, the noise's level found
    assert fit.sigma_inflation < 1.2
    assert fit.residual_rms == pytest.approx(20 * MAS, rel=0.05)
    # the period is found to a fraction of a day: the σ is no empty promise
    assert c.period_sigma < 1.0 * DAY


def test_the_uncertainties_are_honest_over_many_noise_draws() -> None:
    # The stated σ of the period describes its scatter over independent noise draws.
    pulls = []
    for seed in range(12):
        t, x, y = synthetic(60 * MAS, noise=40 * MAS, seed=100 + seed, step=14.0)
        c = ps.fit_wobble(t, x, y).chandler
        pulls.append((c.period - 433.0 * DAY) / c.period_sigma)
    assert 0.5 < np.std(pulls) < 1.6, pulls
    assert max(abs(p) for p in pulls) < 4.0, pulls


def test_no_chandler_term_is_found_where_there_is_none() -> None:
    # Negative control: the same poles without the Chandler circle, then with a small one.
    for seed in (3, 4, 5):
        fit = ps.fit_wobble(*synthetic(0.0, seed=seed))
        assert not fit.chandler_significant, fit
        assert "(not significant)" in str(fit)
        # the annual circles are still found in it
        a = fit.annual_prograde
        assert abs(a.amplitude - 90 * MAS) < 3 * a.amplitude_sigma
        with_term = ps.fit_wobble(*synthetic(15 * MAS, seed=seed))
        assert with_term.chandler_significant, with_term
        assert with_term.chandler_false_alarm < 1e-6 < fit.chandler_false_alarm


def test_the_false_alarm_chance_is_calibrated() -> None:
    # On noise alone the chance the fit states is uniform: below 20 % in about 20 % of draws
    # (40 draws: 8 expected, 2 to 16 allowed, a 99.8 % binomial interval).
    chances = [
        ps.fit_wobble(*synthetic(0.0, seed=200 + k, years=30.0, step=20.0)).chandler_false_alarm
        for k in range(40)
    ]
    assert 2 <= sum(c < 0.2 for c in chances) <= 16, sorted(chances)


def test_a_fixed_chandler_period_fits_a_short_window() -> None:
    t, x, y = synthetic(150 * MAS, seed=6)
    window = (t >= 0) & (t < 7 * 365.25 * DAY)  # 7 years: past the beat, 6.4 years
    with pytest.raises(ps.PoinsotError, match="^t: spans .* too short"):
        ps.fit_wobble(t[window], x[window], y[window])
    fit = ps.fit_wobble(t[window], x[window], y[window], chandler_period=433.0 * DAY)
    assert fit.chandler.period_sigma == 0.0
    assert abs(fit.chandler.amplitude - 150 * MAS) < 3 * fit.chandler.amplitude_sigma
    band = ps.fit_wobble(t, x, y, chandler_period=(420 * DAY, 450 * DAY))
    assert abs(band.chandler.period - 433.0 * DAY) < 3 * band.chandler.period_sigma


def test_units_at_the_door() -> None:
    pint = pytest.importorskip("pint")
    u = pint.UnitRegistry()
    t, x, y = synthetic(150 * MAS, seed=7, years=30.0, step=10.0)
    plain = ps.fit_wobble(t, x, y)
    with_units = ps.fit_wobble((t / DAY) * u.day, (x / MAS) * u.milliarcsecond, y * u.radian)
    assert with_units.chandler.period == pytest.approx(plain.chandler.period, rel=1e-9)
    with pytest.raises(ps.PoinsotError, match="^x: expected an angle"):
        ps.fit_wobble(t, x * u.meter, y)
    with pytest.raises(ps.PoinsotError, match="^t: "):
        ps.fit_wobble(t * u.meter, x, y)


def test_bad_input_is_refused_by_name() -> None:
    t, x, y = synthetic(150 * MAS, seed=8, years=30.0, step=10.0)
    bad = [
        (([], [], []), "t", "must not be empty"),
        ((t, x[:-1], y), "x", "length of t"),
        ((t, x, y[:-1]), "y", "length of t"),
        ((t[::-1], x, y), "t", "strictly increasing"),
        ((np.where(np.arange(t.size) == 5, t[4], t), x, y), "t", "strictly increasing"),
        ((t, np.where(np.arange(t.size) == 9, np.nan, x), y), "x", "finite"),
        ((t, x, np.where(np.arange(t.size) == 9, np.inf, y)), "y", "finite"),
        ((np.where(np.arange(t.size) == 3, np.nan, t), x, y), "t", "finite"),
        ((t[:200], x[:200], y[:200]), "t", "too short to separate"),
    ]
    for args, name, words in bad:
        with pytest.raises(ps.PoinsotError, match=f"^{name}: .*{words}"):
            ps.fit_wobble(*args)
    dates = np.datetime64("2000-01-01") + np.arange(t.size).astype("timedelta64[D]") * 10
    dates[4] = np.datetime64("NaT")
    with pytest.raises(ps.PoinsotError, match="^t: must be finite"):
        ps.fit_wobble(dates, x, y)
    with pytest.raises(ps.PoinsotError, match="^chandler_period: .*holds the annual period"):
        ps.fit_wobble(t, x, y, chandler_period=(300 * DAY, 400 * DAY))
    with pytest.raises(ps.PoinsotError, match="^chandler_period: .*min < max"):
        ps.fit_wobble(t, x, y, chandler_period=(450 * DAY, 420 * DAY))
    with pytest.raises(ps.PoinsotError, match="^chandler_period: "):
        ps.fit_wobble(t, x, y, chandler_period=-433 * DAY)
    with pytest.raises(ps.PoinsotError, match="^annual_period: "):
        ps.fit_wobble(t, x, y, annual_period=0.0)
    with pytest.raises(ps.PoinsotError, match="^source: must be one of"):
        ps.polar_motion("bulletin-a")


def test_the_iers_series_agrees_with_the_extract(shipped: ps.PolarMotion) -> None:
    pytest.importorskip("astropy_iers_data")
    daily = ps.polar_motion("iers")
    assert "astropy-iers-data" in daily.source and "C04" in daily.source
    assert ps.polar_motion().source == daily.source  # "auto" takes it when installed
    assert np.all(np.diff(daily.mjd) == 1.0) and daily.dates[0] == np.datetime64("1962-01-01")
    both, i, j = np.intersect1d(daily.mjd, shipped.mjd, return_indices=True)
    assert both.size > 4000
    # the same numbers where they overlap (a later C04 may revise the last days a little)
    assert np.max(np.abs(daily.x[i] - shipped.x[j])) < 2 * MAS
    assert np.max(np.abs(daily.y[i] - shipped.y[j])) < 2 * MAS
    assert np.median(np.abs(daily.x[i] - shipped.x[j])) < 1e-3 * MAS
    fit = ps.fit_wobble(daily.dates, daily.x, daily.y)
    ref = ps.fit_wobble(shipped.dates, shipped.x, shipped.y)
    assert abs(fit.chandler.period - ref.chandler.period) < 1.0 * DAY


def test_auto_falls_back_to_the_extract(monkeypatch: pytest.MonkeyPatch) -> None:
    import sys

    monkeypatch.setitem(sys.modules, "astropy_iers_data", None)  # as if not installed
    assert "shipped extract" in ps.polar_motion().source
    with pytest.raises(ps.PoinsotError, match=r"^source: 'iers' needs .*poinsot\[earth\]"):
        ps.polar_motion("iers")
