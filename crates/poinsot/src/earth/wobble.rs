//! The real pole: a least-squares fit of the Earth's polar motion (x, y) to a linear trend, the
//! prograde circular Chandler wobble (its period a nonlinear parameter) and the annual wobble
//! (a prograde and a retrograde circle of one tropical year).
//!
//! The pole is written as the complex number p = x − i y (x towards Greenwich, y towards 90° W,
//! the IERS convention), so that a prograde circle — anticlockwise seen from above the north
//! pole, in the sense of the Earth's rotation, as Euler's free nutation of the unit's 2.83 — is
//! p = A e^{i(ωt + φ)} and a retrograde one is p = A e^{i(−ωt + φ)}. The model is
//!
//! p(t) = (x₀ + ẋ t) − i (y₀ + ẏ t) + A_c e^{i(ω_c t + φ_c)} + A₊ e^{i(ω_a t + φ₊)}
//!        + A₋ e^{i(−ω_a t + φ₋)},
//!
//! ω_a = 2π / [`ANNUAL_PERIOD`] fixed, ω_c searched over a band of periods: the residual sum of
//! squares, minimised over the ten linear parameters, is scanned on a grid of frequencies finer
//! than the record's resolution 1/T and refined by golden-section search. The 1-σ
//! uncertainties come from the covariance of all eleven parameters (the Jacobian at the
//! optimum, ω_c included) scaled by the residual variance and by the AR(1) factor
//! (1 + ρ)/(1 − ρ) of the residuals' lag-1 autocorrelation ρ — a first-order allowance for
//! serial correlation; the real residuals (the wobble's irregular excitation) have longer
//! memory than AR(1), so even these uncertainties are lower bounds on the data.
use std::f64::consts::{PI, TAU};

use nalgebra::{SMatrix, SVector};

use crate::control;
use crate::error::{check_finite, check_result, Error, Result};

const DAY: f64 = 86_400.0;

/// The period of the annual wobble (s): the mean tropical year at J2000, 365.242190 days
/// (Laskar 1986; the seasons of the atmosphere and oceans that drive it).
pub const ANNUAL_PERIOD: f64 = 365.242_190 * DAY;

/// Where `polar_motion` reads the pole by default: `"auto"`, the daily IERS C04 file of the
/// `astropy-iers-data` package when it is installed, else the extract shipped with the package
/// (the other choices: `"iers"`, `"shipped"`).
pub const POLAR_MOTION_SOURCE: &str = "auto";

/// The default band of the Chandler period search (s): 380 to 500 days, around the observed
/// 433 days (and the 445 of an oceanless elastic Earth, [`crate::earth::RigidEarth`]), and
/// clear of the annual period by more than the resolution of a 30-year record.
pub const CHANDLER_SEARCH: (f64, f64) = (380.0 * DAY, 500.0 * DAY);

/// Number of linear parameters: x₀, ẋ, y₀, ẏ and (cos, sin) of three circles.
const NLIN: usize = 10;
/// Grid points per resolution element 1/T in the period scan.
const OVERSAMPLE: f64 = 8.0;

/// One circular term of the fit, with 1-σ uncertainties (0 for a quantity held fixed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WobbleTerm {
    /// Period (s).
    pub period: f64,
    /// Its 1-σ uncertainty (s); 0 when the period was held fixed.
    pub period_sigma: f64,
    /// Radius of the circle (rad).
    pub amplitude: f64,
    /// Its 1-σ uncertainty (rad).
    pub amplitude_sigma: f64,
    /// φ at t = 0 (rad, in (−π, π]): the term is A e^{i(±ωt + φ)} in p = x − i y.
    pub phase: f64,
    /// Its 1-σ uncertainty (rad).
    pub phase_sigma: f64,
    /// Whether the circle turns prograde (with the Earth's rotation).
    pub prograde: bool,
}

/// The fitted wobble ([`fit_wobble`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WobbleFit {
    /// The prograde Chandler circle.
    pub chandler: WobbleTerm,
    /// The prograde annual circle.
    pub annual_prograde: WobbleTerm,
    /// The retrograde annual circle.
    pub annual_retrograde: WobbleTerm,
    /// (x₀, y₀), the trend's pole at t = 0 (rad).
    pub offset: [f64; 2],
    /// Their 1-σ uncertainties (rad).
    pub offset_sigma: [f64; 2],
    /// (ẋ, ẏ), the trend's drift (rad/s).
    pub drift: [f64; 2],
    /// Their 1-σ uncertainties (rad/s).
    pub drift_sigma: [f64; 2],
    /// RMS of the residuals over x and y (rad).
    pub residual_rms: f64,
    /// ρ, the lag-1 autocorrelation of the residuals (clamped to [0, 0.999]).
    pub serial_correlation: f64,
    /// √((1 + ρ)/(1 − ρ)), the factor by which the formal uncertainties were widened.
    pub sigma_inflation: f64,
    /// The chance that noise alone, searched over the band's independent periods, gives a
    /// Chandler amplitude this large (1 for a fit held at a fixed period with no amplitude).
    pub chandler_false_alarm: f64,
    /// Number of samples.
    pub samples: usize,
}

impl WobbleFit {
    /// Whether the Chandler term stands above the noise: false-alarm probability below 0.0027
    /// (the two-sided 3-σ level of a Gaussian).
    pub fn chandler_significant(&self) -> bool {
        self.chandler_false_alarm < 0.0027
    }
}

/// How the Chandler period is found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ChandlerPeriod {
    /// Searched over the band (min, max) (s).
    Search(f64, f64),
    /// Held at this period (s).
    Fixed(f64),
}

impl Default for ChandlerPeriod {
    fn default() -> Self {
        ChandlerPeriod::Search(CHANDLER_SEARCH.0, CHANDLER_SEARCH.1)
    }
}

/// The sampled series, its time measured from the record's middle.
struct Series<'a> {
    tm: f64,
    half: f64,
    t: &'a [f64],
    x: &'a [f64],
    y: &'a [f64],
}

impl Series<'_> {
    /// The two model rows (x, y) at sample `i` for frequencies (ω_c, ω_a) (rad/s).
    fn rows(&self, i: usize, wc: f64, wa: f64) -> ([f64; NLIN], [f64; NLIN]) {
        let s = self.t[i] - self.tm;
        let tau = s / self.half;
        let (sc, cc) = (wc * s).sin_cos();
        let (sa, ca) = (wa * s).sin_cos();
        (
            [1.0, tau, 0.0, 0.0, cc, -sc, ca, -sa, ca, sa],
            [0.0, 0.0, 1.0, tau, -sc, -cc, -sa, -ca, sa, -ca],
        )
    }

    /// The linear least squares at fixed ω_c: the coefficients and the residual sum of squares.
    fn solve(&self, wc: f64, wa: f64) -> Result<(SVector<f64, NLIN>, f64)> {
        let mut n = SMatrix::<f64, NLIN, NLIN>::zeros();
        let mut b = SVector::<f64, NLIN>::zeros();
        for i in 0..self.t.len() {
            let (rx, ry) = self.rows(i, wc, wa);
            for (row, v) in [(rx, self.x[i]), (ry, self.y[i])] {
                let r = SVector::<f64, NLIN>::from(row);
                n += r * r.transpose();
                b += r * v;
            }
        }
        control::tick_by(u32::try_from(self.t.len() / 64 + 1).unwrap_or(u32::MAX))?;
        let chol = n.cholesky().ok_or_else(|| {
            Error::invalid(
                "t",
                "the samples do not determine the trend and the circles (too few distinct times)",
            )
        })?;
        let c = chol.solve(&b);
        // The residuals summed directly (y·y − cᵀb loses digits when the fit is close).
        let mut rss = 0.0;
        for i in 0..self.t.len() {
            let (rx, ry) = self.rows(i, wc, wa);
            let r = SVector::<f64, NLIN>::from(rx);
            let q = SVector::<f64, NLIN>::from(ry);
            rss += (self.x[i] - r.dot(&c)).powi(2) + (self.y[i] - q.dot(&c)).powi(2);
        }
        Ok((c, rss))
    }
}

fn days(s: f64) -> f64 {
    s / DAY
}

fn wrap(phase: f64) -> f64 {
    let p = phase.rem_euclid(TAU);
    if p > PI {
        p - TAU
    } else {
        p
    }
}

/// Fits the wobble model of this module to the pole (x, y) (rad) sampled at times `t` (s,
/// strictly increasing; phases refer to t = 0), the annual circles at `annual_period` (s) and
/// the Chandler circle per `chandler`. Errors name `t`, `x`, `y`, `annual_period` or
/// `chandler_period`: an empty or mismatched series, times not strictly increasing, a NaN,
/// a band of periods that holds the annual one, and a record too short to separate the two
/// periods (its span must reach 1/|1/P_a − 1/P_c| for every Chandler period P_c tried: the
/// beat of the two, 6.4 years at 433 days).
pub fn fit_wobble(
    t: &[f64],
    x: &[f64],
    y: &[f64],
    chandler: ChandlerPeriod,
    annual_period: f64,
) -> Result<WobbleFit> {
    if t.is_empty() {
        return Err(Error::invalid("t", "must not be empty"));
    }
    for (name, v) in [("x", x), ("y", y)] {
        if v.len() != t.len() {
            return Err(Error::invalid(
                name,
                format!("must have the length of t ({}), got {}", t.len(), v.len()),
            ));
        }
    }
    check_finite("t", t)?;
    check_finite("x", x)?;
    check_finite("y", y)?;
    if let Some(i) = t.windows(2).position(|w| w[1] <= w[0]) {
        return Err(Error::invalid(
            "t",
            format!(
                "must be strictly increasing, got t[{}] = {} after t[{}] = {}",
                i + 1,
                t[i + 1],
                i,
                t[i]
            ),
        ));
    }
    crate::error::check_positive("annual_period", annual_period)?;
    let (lo, hi) = match chandler {
        ChandlerPeriod::Search(lo, hi) => {
            crate::error::check_positive("chandler_period", lo)?;
            crate::error::check_positive("chandler_period", hi)?;
            if lo >= hi {
                return Err(Error::invalid(
                    "chandler_period",
                    format!(
                        "the band (min, max) must have min < max, got ({} d, {} d)",
                        days(lo),
                        days(hi)
                    ),
                ));
            }
            (lo, hi)
        }
        ChandlerPeriod::Fixed(p) => {
            crate::error::check_positive("chandler_period", p)?;
            (p, p)
        }
    };
    if lo <= annual_period && annual_period <= hi {
        return Err(Error::invalid(
            "chandler_period",
            format!(
                "the band {} d to {} d holds the annual period ({} d): the two terms cannot be told apart",
                days(lo),
                days(hi),
                days(annual_period)
            ),
        ));
    }
    let n = t.len();
    if 2 * n < NLIN + 3 {
        return Err(Error::invalid(
            "t",
            format!("need at least 7 samples to fit the trend and three circles, got {n}"),
        ));
    }
    let span = t[n - 1] - t[0];
    let fa = 1.0 / annual_period;
    // The Chandler frequency nearest the annual one.
    let nearest = if hi < annual_period { hi } else { lo };
    let beat = 1.0 / (fa - 1.0 / nearest).abs();
    if span < beat {
        return Err(Error::invalid(
            "t",
            format!(
                "spans {:.1} d, too short to separate the Chandler term (period {} d) from the \
                 annual one ({} d): need at least their beat, {:.1} d",
                days(span),
                days(nearest),
                days(annual_period),
                days(beat)
            ),
        ));
    }
    let s = Series {
        tm: 0.5 * (t[0] + t[n - 1]),
        half: 0.5 * span,
        t,
        x,
        y,
    };
    let wa = TAU * fa;
    let rss_at = |f: f64| s.solve(TAU * f, wa).map(|(_, r)| r);
    // The frequency of least RSS: a grid finer than 1/T, then golden section about its best.
    let (flo, fhi) = (1.0 / hi, 1.0 / lo);
    let f_best = if hi > lo {
        let steps = (((fhi - flo) * span * OVERSAMPLE).ceil() as usize).max(2);
        let df = (fhi - flo) / steps as f64;
        let mut best = (flo, f64::INFINITY);
        for k in 0..=steps {
            let f = flo + df * k as f64;
            let r = rss_at(f)?;
            if r < best.1 {
                best = (f, r);
            }
        }
        let (mut a, mut b) = ((best.0 - df).max(flo), (best.0 + df).min(fhi));
        let g = 0.5 * (5f64.sqrt() - 1.0);
        let (mut c, mut d) = (b - g * (b - a), a + g * (b - a));
        let (mut rc, mut rd) = (rss_at(c)?, rss_at(d)?);
        while (b - a) > 1e-7 * df.max(f64::MIN_POSITIVE) {
            if rc < rd {
                b = d;
                d = c;
                rd = rc;
                c = b - g * (b - a);
                rc = rss_at(c)?;
            } else {
                a = c;
                c = d;
                rc = rd;
                d = a + g * (b - a);
                rd = rss_at(d)?;
            }
        }
        0.5 * (a + b)
    } else {
        flo
    };
    let wc = TAU * f_best;
    let (c, rss) = s.solve(wc, wa)?;
    let search = hi > lo;
    let npar = NLIN + usize::from(search);
    let dof = (2 * n - npar) as f64;
    // Residuals, their lag-1 autocorrelation, and the Jacobian's normal matrix (ω_c last).
    let mut jtj = SMatrix::<f64, 11, 11>::zeros();
    let (mut r0, mut r1) = (0.0, 0.0);
    let mut prev: Option<(f64, f64)> = None;
    for i in 0..n {
        let (rx, ry) = s.rows(i, wc, wa);
        let ts = t[i] - s.tm;
        let (sn, cs) = (wc * ts).sin_cos();
        // ∂x/∂ω_c and ∂y/∂ω_c of c cos ωt − s sin ωt and −(c sin ωt + s cos ωt).
        let dx = -ts * (c[4] * sn + c[5] * cs);
        let dy = -ts * (c[4] * cs - c[5] * sn);
        let mut jx = SVector::<f64, 11>::zeros();
        let mut jy = SVector::<f64, 11>::zeros();
        for k in 0..NLIN {
            jx[k] = rx[k];
            jy[k] = ry[k];
        }
        jx[NLIN] = dx;
        jy[NLIN] = dy;
        jtj += jx * jx.transpose() + jy * jy.transpose();
        let ex = x[i] - jx.rows(0, NLIN).dot(&c);
        let ey = y[i] - jy.rows(0, NLIN).dot(&c);
        r0 += ex * ex + ey * ey;
        if let Some((px, py)) = prev {
            r1 += ex * px + ey * py;
        }
        prev = Some((ex, ey));
    }
    let rho = if r0 > 0.0 {
        (r1 / r0).clamp(0.0, 0.999)
    } else {
        0.0
    };
    let inflation = ((1.0 + rho) / (1.0 - rho)).sqrt();
    let var = rss / dof * inflation * inflation;
    // Covariance of the parameters: the inverse of JᵀJ (scaled to unit diagonal first), ω_c's
    // row left out when the period was held fixed.
    let np = npar;
    let mut scale = [0.0; 11];
    for k in 0..np {
        scale[k] = 1.0 / jtj[(k, k)].sqrt().max(f64::MIN_POSITIVE);
    }
    let mut m = nalgebra::DMatrix::<f64>::zeros(np, np);
    for i in 0..np {
        for j in 0..np {
            m[(i, j)] = jtj[(i, j)] * scale[i] * scale[j];
        }
    }
    let inv = m.cholesky().map(|ch| ch.inverse()).ok_or_else(|| {
        Error::invalid(
            "t",
            "the samples do not determine the Chandler period (too few distinct times)",
        )
    })?;
    let cov = |i: usize, j: usize| -> f64 {
        if i < np && j < np {
            inv[(i, j)] * scale[i] * scale[j] * var
        } else {
            0.0
        }
    };
    let sd = |g: &[(usize, f64)]| -> f64 {
        let mut v = 0.0;
        for &(i, a) in g {
            for &(j, b) in g {
                v += a * b * cov(i, j);
            }
        }
        v.max(0.0).sqrt()
    };
    // A circle from its coefficients (k, k+1) at the middle time, its phase moved to t = 0.
    let circle = |k: usize, w: f64, sign: f64, period_sigma: f64| -> WobbleTerm {
        let (cc, ss) = (c[k], c[k + 1]);
        let a2 = (cc * cc + ss * ss).max(f64::MIN_POSITIVE);
        let a = a2.sqrt();
        let mut phase_grad = vec![(k, -ss / a2), (k + 1, cc / a2)];
        if search && k == 4 {
            phase_grad.push((NLIN, -sign * s.tm));
        }
        WobbleTerm {
            period: TAU / w,
            period_sigma,
            amplitude: a,
            amplitude_sigma: sd(&[(k, cc / a), (k + 1, ss / a)]),
            phase: wrap(ss.atan2(cc) - sign * w * s.tm),
            phase_sigma: sd(&phase_grad),
            prograde: sign > 0.0,
        }
    };
    let period_sigma = if search {
        TAU / (wc * wc) * cov(NLIN, NLIN).max(0.0).sqrt()
    } else {
        0.0
    };
    let chandler = circle(4, wc, 1.0, period_sigma);
    let annual_prograde = circle(6, wa, 1.0, 0.0);
    let annual_retrograde = circle(8, wa, -1.0, 0.0);
    // The trend a + b (t − t_m)/h at t = 0.
    let r = s.tm / s.half;
    let offset = [c[0] - c[1] * r, c[2] - c[3] * r];
    let offset_sigma = [sd(&[(0, 1.0), (1, -r)]), sd(&[(2, 1.0), (3, -r)])];
    let drift = [c[1] / s.half, c[3] / s.half];
    let drift_sigma = [sd(&[(1, 1.0 / s.half)]), sd(&[(3, 1.0 / s.half)])];
    // Look-elsewhere: |C|²/(2σ²) of noise is exponential at each period tried, and a continuous
    // search over the band Δf counts as M = 2 Δf T + 1 independent ones (checked on 300 draws
    // of white noise: the chance of a false alarm then falls below 1, 5, 10 and 50 % in 1.3,
    // 5.3, 11 and 47 % of the draws; with M = Δf T, in 1.7, 11, 19 and 71 %).
    let sigma_c = (0.5 * (cov(4, 4) + cov(5, 5))).sqrt();
    let z = if sigma_c > 0.0 {
        chandler.amplitude.powi(2) / (2.0 * sigma_c * sigma_c)
    } else {
        f64::INFINITY
    };
    let trials = 2.0 * (fhi - flo) * span + 1.0;
    let p1 = (-z).exp();
    let chandler_false_alarm = (-(trials * (-p1).ln_1p()).exp_m1()).clamp(0.0, 1.0);
    let out = WobbleFit {
        chandler,
        annual_prograde,
        annual_retrograde,
        offset,
        offset_sigma,
        drift,
        drift_sigma,
        residual_rms: (r0 / (2 * n) as f64).sqrt(),
        serial_correlation: rho,
        sigma_inflation: inflation,
        chandler_false_alarm,
        samples: n,
    };
    let mut all = vec![
        out.residual_rms,
        out.offset[0],
        out.offset[1],
        out.drift[0],
        out.drift[1],
    ];
    for term in [chandler, annual_prograde, annual_retrograde] {
        all.extend([
            term.period,
            term.period_sigma,
            term.amplitude,
            term.amplitude_sigma,
            term.phase,
            term.phase_sigma,
        ]);
    }
    check_result("x", "the wobble fit", &all)?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A small deterministic generator (xorshift) and Box–Muller normals.
    struct Rng(u64);
    impl Rng {
        fn uniform(&mut self) -> f64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        }
        fn normal(&mut self) -> f64 {
            (-2.0 * self.uniform().ln()).sqrt() * (TAU * self.uniform()).cos()
        }
    }

    const MAS: f64 = 4.848_136_811_095_36e-9;

    fn series(chandler: f64, noise: f64, seed: u64) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let mut rng = Rng(seed);
        let (pc, wa) = (433.0 * DAY, TAU / ANNUAL_PERIOD);
        let (mut t, mut x, mut y) = (vec![], vec![], vec![]);
        for k in 0..1500 {
            let tk = (k as f64 * 10.0 - 7000.0) * DAY;
            let ac = TAU / pc * tk + 1.0;
            let ap = wa * tk - 0.5;
            let am = -wa * tk + 2.0;
            let px =
                40.0 * MAS + chandler * ac.cos() + 90.0 * MAS * ap.cos() + 5.0 * MAS * am.cos();
            let py = 300.0 * MAS + 1e-16 * tk
                - chandler * ac.sin()
                - 90.0 * MAS * ap.sin()
                - 5.0 * MAS * am.sin();
            t.push(tk);
            x.push(px + noise * rng.normal());
            y.push(py + noise * rng.normal());
        }
        (t, x, y)
    }

    #[test]
    fn recovers_a_synthetic_wobble_within_its_uncertainties() {
        let (t, x, y) = series(170.0 * MAS, 20.0 * MAS, 7);
        let f = fit_wobble(&t, &x, &y, ChandlerPeriod::default(), ANNUAL_PERIOD).unwrap();
        let c = f.chandler;
        assert!(c.prograde && f.chandler_significant());
        assert!(
            (c.period - 433.0 * DAY).abs() < 3.0 * c.period_sigma,
            "{c:?}"
        );
        assert!(c.period_sigma > 0.0 && c.period_sigma < 0.5 * DAY);
        assert!(
            (c.amplitude - 170.0 * MAS).abs() < 3.0 * c.amplitude_sigma,
            "{c:?}"
        );
        assert!(wrap(c.phase - 1.0).abs() < 3.0 * c.phase_sigma, "{c:?}");
        let a = f.annual_prograde;
        assert!((a.amplitude - 90.0 * MAS).abs() < 3.0 * a.amplitude_sigma);
        assert!(wrap(a.phase + 0.5).abs() < 3.0 * a.phase_sigma);
        let r = f.annual_retrograde;
        assert!(!r.prograde && (r.amplitude - 5.0 * MAS).abs() < 3.0 * r.amplitude_sigma);
        assert!((f.drift[1] - 1e-16).abs() < 3.0 * f.drift_sigma[1]);
        assert!((f.residual_rms / (20.0 * MAS) - 1.0).abs() < 0.05);
    }

    #[test]
    fn finds_no_chandler_term_where_there_is_none() {
        let (t, x, y) = series(0.0, 20.0 * MAS, 11);
        let f = fit_wobble(&t, &x, &y, ChandlerPeriod::default(), ANNUAL_PERIOD).unwrap();
        assert!(!f.chandler_significant(), "{f:?}");
        assert!(f.chandler.amplitude < 4.0 * f.chandler.amplitude_sigma);
    }

    #[test]
    fn refuses_bad_input_by_name() {
        let (t, x, y) = series(170.0 * MAS, 20.0 * MAS, 3);
        let fit = |t: &[f64], x: &[f64], y: &[f64], c| fit_wobble(t, x, y, c, ANNUAL_PERIOD);
        let d = ChandlerPeriod::default();
        assert_eq!(fit(&[], &[], &[], d).unwrap_err().argument, "t");
        assert_eq!(fit(&t, &x[1..], &y, d).unwrap_err().argument, "x");
        let mut bad = t.clone();
        bad.swap(3, 4);
        assert_eq!(fit(&bad, &x, &y, d).unwrap_err().argument, "t");
        let mut nan = y.clone();
        nan[5] = f64::NAN;
        assert_eq!(fit(&t, &x, &nan, d).unwrap_err().argument, "y");
        let e = fit(&t[..300], &x[..300], &y[..300], d).unwrap_err();
        assert!(
            e.argument == "t" && e.message.contains("too short"),
            "{e:?}"
        );
        let band = ChandlerPeriod::Search(300.0 * DAY, 400.0 * DAY);
        assert_eq!(
            fit(&t, &x, &y, band).unwrap_err().argument,
            "chandler_period"
        );
        // A fixed period needs only the beat at that period: 6.4 years at 433 days.
        let f = fit(
            &t[..300],
            &x[..300],
            &y[..300],
            ChandlerPeriod::Fixed(433.0 * DAY),
        )
        .unwrap();
        assert_eq!(f.chandler.period_sigma, 0.0);
    }
}
