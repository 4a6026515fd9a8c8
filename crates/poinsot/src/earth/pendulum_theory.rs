//! The exact linear theory of the Foucault pendulum in the rotating frame (the model of
//! [`Earth::foucault`]: uniform gravity, the Coriolis force and the centrifugal force of
//! eq. 2.30 at the bob's own position): its rest position, its small swings about it in closed
//! form, and the mean rate at which their plane turns.
//!
//! **Rest.** The centrifugal force grows with the distance from the axis, so the bob, a length L
//! below the point of suspension, hangs a little off the plumb line of the suspension: tilted
//! towards the equator's side by φ in the meridian plane, where gravity and the centrifugal
//! force are along the string, g sin φ = ½ ω² L sin 2(λ − φ) (φ ≈ (ω²L/2g) sin 2λ: 1e-8 rad on
//! the Earth).
//!
//! **Small swings.** With ê the direction of the string at rest, up = −ê, and the tangent
//! basis e = x̂ (east), n = up × e (north, tilted by φ), the displacement q = (q_e, q_n) obeys
//!
//! q̈_e = 2w q̇_n − k_e q_e,   q̈_n = −2w q̇_e − k_n q_n,
//!
//! with w = ω·up = ω sin(λ − φ) the spin's component along the string (the Coriolis force),
//! k = (F·ê)/L = g cos φ / L + ω² cos²(λ − φ) the string's restoring stiffness (F: gravity plus
//! the centrifugal force at rest), and the centrifugal force's gradient −ω² (I − ω̂ω̂ᵀ) making
//! the stiffness anisotropic: k_e = k − ω², k_n = k − w². Its modes e^{iνt} have
//!
//! ν± ² = k̄ + 2w² ± D,  D = √(4w²(k̄ + w²) + κ²),  k̄ = (k_e + k_n)/2,  κ = (k_e − k_n)/2,
//!
//! one turning counterclockwise and one clockwise (seen from above). A swing is their sum: an
//! ellipse whose axis turns on average at
//!
//! **Δ = −sign(w) (ν₊ − ν₋)/2 = −sign(w) ½ √((√k_e − √k_n)² + 4w²)**,
//!
//! with a bounded wobble. At the pole (κ = 0) Δ = −ω exactly and ν± = √(g/L) ± ω: the swing is
//! the inertial frame's fixed swing seen from the turning Earth. Elsewhere Δ → −ω sin λ as
//! ω/√(g/L) → 0 (within 1e-7 relative on the Earth). Where |√k_e − √k_n| is not small
//! against 2|w| — near the equator, or on a planet spinning fast against the pendulum — the two
//! modes are nearly straight swings of different frequencies and the plane rocks instead of
//! turning: [`super::FoucaultRegime::Unsteady`].

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::{Complex, Matrix4, Vector4};

use super::planet::{check_latitude, Earth};
use crate::error::{check_finite, check_positive, Error, Result};
use crate::Vec3;

type C64 = Complex<f64>;

/// Scan resolution of [`LinearSwing::turning_points`]: samples per period of the faster mode
/// (the turning points are a quarter swing apart, so 32 samples put 8 or more between two).
const SCAN_PER_PERIOD: f64 = 32.0;

/// The rest position of a Foucault pendulum and its small swings (the module's theory).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoucaultTheory {
    /// L, the length of the string (m).
    pub length: f64,
    /// φ, the tilt of the string at rest from the plumb line of the suspension, in the
    /// meridian plane, positive when the bob hangs north of it (rad; ≈ (ω²L/2g) sin 2λ).
    pub tilt: f64,
    /// The bob's rest position (m, ENU, origin at the point of suspension): −L up.
    pub rest: Vec3,
    /// e, the unit east vector of the plane of small swings (ENU; x̂).
    pub east: Vec3,
    /// n = up × e, the unit "north" vector of that plane (ENU; (0, cos φ, sin φ)).
    pub north: Vec3,
    /// [k_e, k_n], the restoring stiffness per unit mass of east and north displacements
    /// (1/s²); both > 0 where the rest position is stable.
    pub stiffness: [f64; 2],
    /// w = ω · up = ω sin(λ − φ), the spin's component along the string at rest (rad/s).
    pub vertical_spin: f64,
    /// The small swings, where the rest position is stable (k_e > 0 and k_n > 0).
    pub modes: Option<FoucaultModes>,
}

/// The two modes of the small swings about a stable rest position.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FoucaultModes {
    /// [ν₋, ν₊], the mode frequencies (rad/s), ν₋ ≤ ν₊.
    pub frequencies: [f64; 2],
    /// σ = (ν₊ + ν₋)/2, the frequency of the swing (rad/s): a period of 2π/σ.
    pub swing_frequency: f64,
    /// Δ = −sign(w) (ν₊ − ν₋)/2, the mean rate at which the plane of a swing turns (rad/s,
    /// counterclockwise seen from above positive): exactly −ω at the poles, 0 at the equator.
    pub precession_rate: f64,
    /// |√k_e − √k_n|, the difference of the frequencies of east–west and north–south swings
    /// that the centrifugal force's gradient makes (rad/s): it rocks the plane (0 at the poles).
    pub splitting: f64,
    /// Unit mode vectors in (east, north) components, `[U₋, U₊]`: q = Re(c U e^{iνt}).
    vectors: [[C64; 2]; 2],
}

/// A small swing in closed form: q(t) = Re(c₋ U₋ e^{iν₋(t−t₀)} + c₊ U₊ e^{iν₊(t−t₀)}).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearSwing {
    t0: f64,
    /// q(t₀)·q̇(t₀) from the initial data themselves (0 for a release from rest), so that the
    /// start is not taken for a turning point by the modal sum's round-off.
    start_rate: f64,
    nu: [f64; 2],
    /// c_m U_m, per mode, in (east, north) components.
    terms: [[C64; 2]; 2],
}

/// The tilt φ of the string at rest: the root of g sin φ = ½ ω² L sin 2(λ − φ) between 0 and λ,
/// in units where `w_hat = ω/s` and `w0_hat = √(g/L)/s` (s = max of the two), so that nothing
/// overflows. Bisection: f(0) ≤ 0 ≤ f(λ) for λ in [0, π/2]; odd in λ.
fn rest_tilt(latitude: f64, w_hat: f64, w0_hat: f64) -> f64 {
    let lat = latitude.abs();
    // No spin, the equator and the poles: the string hangs along the plumb line (symmetry).
    if w_hat == 0.0 || lat == 0.0 || lat == FRAC_PI_2 {
        return 0.0;
    }
    let f = |p: f64| w0_hat * w0_hat * p.sin() - 0.5 * w_hat * w_hat * (2.0 * (lat - p)).sin();
    let (mut lo, mut hi) = (0.0_f64, lat);
    // Halving down to adjacent doubles: at most ~1100 rounds (a root near the subnormals).
    for _ in 0..2000 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if f(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let tilt = if f(hi).abs() < f(lo).abs() { hi } else { lo };
    tilt.copysign(latitude)
}

impl Earth {
    /// The exact linear theory of a Foucault pendulum of `length` (m) at `latitude` (rad): the
    /// rest position and the small swings about it (see the module documentation).
    ///
    /// Errors name `latitude` or `length` out of their domains, and `rotation_rate` or
    /// `length` where a frequency of the pendulum does not fit in a double (above ~1e150 rad/s).
    pub fn foucault_theory(&self, latitude: f64, length: f64) -> Result<FoucaultTheory> {
        check_latitude(latitude)?;
        check_positive("length", length)?;
        let omega = self.rotation_rate;
        let w0 = self.g.sqrt() / length.sqrt();
        if !w0.is_finite() {
            return Err(Error::invalid(
                "length",
                format!("the pendulum's frequency sqrt(g/length) overflows for length = {length} m and g = {} m/s^2", self.g),
            ));
        }
        // Dimensionless: frequencies in units of s, stiffnesses in units of s².
        let s = omega.max(w0);
        if !(s * s).is_finite() {
            // The larger of the two frequencies overflows when squared: blame its source.
            let (argument, what) = if w0 >= omega {
                ("length", format!("the pendulum's frequency squared g/length overflows a double for length = {length} m"))
            } else {
                ("rotation_rate", format!("the spin's square overflows a double: rotation_rate = {omega} rad/s is beyond any pendulum"))
            };
            return Err(Error::invalid(argument, what));
        }
        let (wh, w0h) = (omega / s, w0 / s);
        let tilt = rest_tilt(latitude, wh, w0h);
        let (sp, cp) = tilt.sin_cos();
        // a = ω̂·up and b = ω̂·n, the spin's direction against the string and the plane.
        let (a, b) = (latitude - tilt).sin_cos();
        let up = Vec3::new(0.0, -sp, cp);
        let gravity = w0h * w0h * cp;
        let k_e = gravity - wh * wh * a * a;
        let k_n = gravity + wh * wh * (b - a) * (b + a);
        let w = wh * a;
        let modes = (k_e > 0.0 && k_n > 0.0).then(|| {
            let kappa = -0.5 * wh * wh * b * b;
            let kbar = k_e - kappa;
            let d = (4.0 * w * w * (kbar + w * w) + kappa * kappa).sqrt();
            let nu_p = (kbar + 2.0 * w * w + d).sqrt();
            // ν₋ = √(k_e k_n)/ν₊ (the product of the roots), free of cancellation.
            let nu_m = (k_e.sqrt() * k_n.sqrt()) / nu_p;
            let half = d / (nu_p + nu_m);
            let rate = if w > 0.0 {
                -half
            } else if w < 0.0 {
                half
            } else {
                0.0
            };
            // Null vectors of the mode equations, each from the row that has no cancellation:
            // (k_e − ν₊²) = −(D + 2w² − κ) and (k_n − ν₋²) = D − 2w² − κ (κ ≤ 0, D ≥ 2w²).
            let vectors = if d == 0.0 {
                // No spin: any two independent swings (east, north).
                [
                    [C64::new(1.0, 0.0), C64::new(0.0, 0.0)],
                    [C64::new(0.0, 0.0), C64::new(1.0, 0.0)],
                ]
            } else {
                let um = [
                    C64::new(d - 2.0 * w * w - kappa, 0.0),
                    C64::new(0.0, -2.0 * w * nu_m),
                ];
                let up = [
                    C64::new(0.0, 2.0 * w * nu_p),
                    C64::new(-(d + 2.0 * w * w - kappa), 0.0),
                ];
                let unit = |u: [C64; 2]| {
                    let n = u[0].norm().hypot(u[1].norm());
                    [u[0] / n, u[1] / n]
                };
                [unit(um), unit(up)]
            };
            let splitting = (k_n - k_e) / (k_e.sqrt() + k_n.sqrt());
            FoucaultModes {
                frequencies: [nu_m * s, nu_p * s],
                swing_frequency: 0.5 * (nu_p + nu_m) * s,
                precession_rate: rate * s,
                splitting: splitting.abs() * s,
                vectors,
            }
        });
        Ok(FoucaultTheory {
            length,
            tilt,
            rest: -length * up,
            east: Vec3::x(),
            north: Vec3::new(0.0, cp, sp),
            stiffness: [k_e * s * s, k_n * s * s],
            vertical_spin: w * s,
            modes,
        })
    }
}

impl FoucaultTheory {
    /// The upward unit vector along the string at rest (ENU).
    pub fn up(&self) -> Vec3 {
        -self.rest / self.length
    }

    /// The bob's displacement from rest in the plane of small swings, `[east, north]` (m), of
    /// a position `r` (m, ENU, from the point of suspension).
    pub fn displacement_of(&self, r: &Vec3) -> [f64; 2] {
        let d = r - self.rest;
        [d.dot(&self.east), d.dot(&self.north)]
    }

    /// The direction of the bob's displacement from rest, counterclockwise from east seen from
    /// above (rad, in (−π, π]), of a position `r` (m, ENU).
    pub fn swing_angle(&self, r: &Vec3) -> f64 {
        let [e, n] = self.displacement_of(r);
        n.atan2(e)
    }
}

impl FoucaultModes {
    /// The small swing through displacement `q0` (m) and velocity `v0` (m/s), both `[east,
    /// north]` in the plane of small swings, at time `t0` (s). Errors name `q0`/`v0`/`t0` if
    /// they are not finite.
    pub fn swing(&self, q0: [f64; 2], v0: [f64; 2], t0: f64) -> Result<LinearSwing> {
        check_finite("q0", &q0)?;
        check_finite("v0", &v0)?;
        check_finite("t0", &[t0])?;
        let [u_m, u_p] = self.vectors;
        let [nu_m, nu_p] = self.frequencies;
        // Unknowns (Re c₋, Im c₋, Re c₊, Im c₊): q = Re(cU), q̇ = Re(iν c U) = −ν Im(cU).
        let mut m = Matrix4::zeros();
        for j in 0..2 {
            for (k, (u, nu)) in [(u_m, nu_m), (u_p, nu_p)].into_iter().enumerate() {
                m[(j, 2 * k)] = u[j].re;
                m[(j, 2 * k + 1)] = -u[j].im;
                m[(2 + j, 2 * k)] = -nu * u[j].im;
                m[(2 + j, 2 * k + 1)] = -nu * u[j].re;
            }
        }
        let rhs = Vector4::new(q0[0], q0[1], v0[0], v0[1]);
        let c = m
            .lu()
            .solve(&rhs)
            .filter(|c| c.iter().all(|x| x.is_finite()))
            .ok_or_else(|| {
                Error::diverged(
                    "q0",
                    "the small-swing modes are degenerate; report it as a bug",
                )
            })?;
        let (c_m, c_p) = (C64::new(c[0], c[1]), C64::new(c[2], c[3]));
        Ok(LinearSwing {
            t0,
            start_rate: q0[0] * v0[0] + q0[1] * v0[1],
            nu: [nu_m, nu_p],
            terms: [[c_m * u_m[0], c_m * u_m[1]], [c_p * u_p[0], c_p * u_p[1]]],
        })
    }
}

impl LinearSwing {
    /// The displacement `[east, north]` (m) at time `t` (s).
    pub fn displacement(&self, t: f64) -> [f64; 2] {
        let mut q = [0.0; 2];
        for (terms, nu) in self.terms.iter().zip(self.nu) {
            let phase = C64::from_polar(1.0, nu * (t - self.t0));
            q[0] += (terms[0] * phase).re;
            q[1] += (terms[1] * phase).re;
        }
        q
    }

    /// The velocity `[east, north]` (m/s) at time `t` (s).
    pub fn velocity(&self, t: f64) -> [f64; 2] {
        let mut v = [0.0; 2];
        for (terms, nu) in self.terms.iter().zip(self.nu) {
            let phase = C64::from_polar(nu, nu * (t - self.t0)) * C64::i();
            v[0] += (terms[0] * phase).re;
            v[1] += (terms[1] * phase).re;
        }
        v
    }

    /// The four circular terms of the swing, u = q_e + i q_n = Σ α e^{iνt} + β e^{−iνt}:
    /// `[[|α₋|, |β₋|], [|α₊|, |β₊|]]` (m), the radii of the counterclockwise and clockwise
    /// circles of each mode.
    pub fn circles(&self) -> [[f64; 2]; 2] {
        self.terms.map(|[x, y]| {
            [
                0.5 * (x + C64::i() * y).norm(),
                0.5 * (x.conj() + C64::i() * y.conj()).norm(),
            ]
        })
    }

    /// The long-run wobble of the swing plane about its steady turn (rad, roughly): the radii
    /// of the two minor circles over those of the two major ones (which circles are major
    /// depends on the sense of the spin, `vertical_spin`). Small when the swing turns steadily.
    pub fn wobble(&self, vertical_spin: f64) -> f64 {
        let [[a_m, b_m], [a_p, b_p]] = self.circles();
        // w > 0: the slow mode turns counterclockwise, the fast one clockwise; w < 0: mirrored.
        let (major, minor) = if vertical_spin >= 0.0 {
            (a_m + b_p, a_p + b_m)
        } else {
            (a_p + b_m, a_m + b_p)
        };
        if major > 0.0 {
            minor / major
        } else {
            f64::INFINITY
        }
    }

    /// The turning points of the swing (the maxima of |q|) in `[t_start, t_end]`, fed to
    /// `visit(t, angle)` in order with the direction of q there (rad, counterclockwise from east);
    /// stops after `max_count` of them. Located by a scan of d|q|²/dt at 32 samples per period
    /// of the faster mode and bisection to round-off. Returns the number visited.
    pub fn turning_points<F: FnMut(f64, f64)>(
        &self,
        t_start: f64,
        t_end: f64,
        max_count: usize,
        mut visit: F,
    ) -> usize {
        let rate = |t: f64| {
            let (q, v) = (self.displacement(t), self.velocity(t));
            q[0] * v[0] + q[1] * v[1]
        };
        let nu_max = self.nu[1].max(self.nu[0]);
        if t_end <= t_start || t_end.is_nan() || t_start.is_nan() || nu_max <= 0.0 {
            return 0;
        }
        let h = 2.0 * PI / (nu_max * SCAN_PER_PERIOD);
        let steps = ((t_end - t_start) / h).ceil();
        let mut count = 0;
        let g_start = if t_start == self.t0 {
            self.start_rate
        } else {
            rate(t_start)
        };
        let (mut t_prev, mut g_prev) = (t_start, g_start);
        let mut i = 1.0;
        while i <= steps && count < max_count {
            let t = (t_start + i * h).min(t_end);
            let g = rate(t);
            if g_prev > 0.0 && g <= 0.0 {
                let (mut lo, mut hi) = (t_prev, t);
                for _ in 0..200 {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    if rate(mid) > 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                let q = self.displacement(hi);
                visit(hi, q[1].atan2(q[0]));
                count += 1;
            }
            (t_prev, g_prev) = (t, g);
            i += 1.0;
        }
        count
    }
}
