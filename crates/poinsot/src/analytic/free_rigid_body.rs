//! The exact torque-free motion of any rigid body (Jacobi 1849; Landau & Lifshitz §37;
//! Celledoni, Fassò, Säfström & Zanna 2008): ω(t) by the Jacobi elliptic functions on both
//! sides of the separatrix, and the attitude by the elliptic integral of the third kind.
//!
//! With the principal moments sorted, `I₁ < I₂ < I₃`, the kinetic energy `T` and `L² = |L|²`
//! fix the motion's regime through the sign of `L² − 2TI₂ = I₁(I₁ − I₂)ω₁² + I₃(I₃ − I₂)ω₃²`:
//! above the separatrix ω circles the axis of the largest moment (the "pole" p = 3), below it
//! the axis of the smallest (p = 1); on it (`L² = 2TI₂`) ω leaves and approaches the
//! intermediate axis in infinite time — the unstable rotation whose neighbouring motions are the
//! Dzhanibekov flips. With `o` the other extreme axis,
//!
//! ```text
//! ω_o = ω_o,m cn(τ | m),  ω₂ = ±ω₂,m sn(τ | m),  ω_p = ±ω_p,m dn(τ | m),   τ = λ t + τ₀,
//! ```
//!
//! where (for p = 3; exchange 1 ↔ 3 for p = 1), with `d₃ = 2TI₃ − L²`, `d₁ = L² − 2TI₁` (both
//! ≥ 0 and computed as sums of positive terms):
//! `ω₁,m² = d₃ / (I₁(I₃ − I₁))`, `ω₂,m² = d₃ / (I₂(I₃ − I₂))`, `ω₃,m² = d₁ / (I₃(I₃ − I₁))`,
//! `λ² = (I₃ − I₂) d₁ / (I₁I₂I₃)`, `m = (I₂ − I₁) d₃ / ((I₃ − I₂) d₁)` and
//! `1 − m = (I₃ − I₁)(L² − 2TI₂) / ((I₃ − I₂) d₁)` (no cancellation near the separatrix).
//!
//! The attitude: with L along the Z axis of an inertial frame, the z-x-z Euler angles (θ, ψ)
//! follow from `L̂` in body components and the precession angle from
//! `φ̇ = |L| (2T − I_p ω_p²) / (L² − I_p² ω_p²)`, which integrates to
//! `φ = |L| t / I_p ± |L|(I₃ − I₁)/(I₁I₃λ) · [Π(n; am τ | m) − Π(n; am τ₀ | m)]`, with the
//! characteristic `n = −I₃(I₂ − I₁)/(I₁(I₃ − I₂))` for p = 3 (`−I₁(I₃ − I₂)/(I₃(I₂ − I₁))` for
//! p = 1) and `Π(n; am(τ + 2K)) = Π(n; am τ) + 2Π(n)`. The body frame is permuted cyclically
//! so that the pole is its third axis. Two equal moments, three, and a rotation about one
//! principal axis are solved by their own closed forms.

use super::free_symmetric_top::{check_omega, SymmetricMotion};
use super::rotations::{
    axis_angle_q, conj, coordinate_q, hamilton, matrix_to_quaternion_unchecked, normalized, rotate,
};
use crate::error::{check_finite, Error, Result};
use crate::rotation::{check_quaternion, Quaternion};
use crate::special::Jacobi;
use crate::{Mat3, Vec3};

/// Which motion a free rigid body performs.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FreeRegime {
    /// ω is constant: a spherical top, or a rotation about one principal axis (including the
    /// unstable rotation about the intermediate axis, which the exact solution keeps forever).
    Steady,
    /// Two equal moments: ω precesses uniformly about the symmetry axis (2.80–2.89).
    Symmetric,
    /// `L² > 2TI₂`: ω circles the axis of the largest moment.
    AboutMaxAxis,
    /// `L² < 2TI₂`: ω circles the axis of the smallest moment.
    AboutMinAxis,
    /// `L² = 2TI₂` exactly: the separatrix, ω tends to the intermediate axis as t → ±∞.
    Separatrix,
}

impl FreeRegime {
    /// "steady", "symmetric", "about max axis", "about min axis" or "separatrix".
    pub fn as_str(self) -> &'static str {
        match self {
            FreeRegime::Steady => "steady",
            FreeRegime::Symmetric => "symmetric",
            FreeRegime::AboutMaxAxis => "about max axis",
            FreeRegime::AboutMinAxis => "about min axis",
            FreeRegime::Separatrix => "separatrix",
        }
    }
}

/// The elliptic solution of the asymmetric top, in the sorted frame (`I₁ < I₂ < I₃`).
#[derive(Debug, Clone, PartialEq)]
struct Elliptic {
    /// User body components → sorted components (a signed permutation, det +1).
    to_sorted: Mat3,
    sorted: [f64; 3],
    /// The pole (dn) and the other extreme (cn) axes, sorted indices (2 and 0, or 0 and 2).
    pole: usize,
    other: usize,
    /// Signed amplitudes of cn (axis `other`), sn (axis 1) and dn (axis `pole`).
    amp_cn: f64,
    amp_sn: f64,
    amp_dn: f64,
    lambda: f64,
    tau0: f64,
    jacobi: Jacobi,
    separatrix: bool,
    /// The characteristic of Π, its complete value and Π(n; am τ₀).
    n: f64,
    pi_complete: f64,
    pi0: f64,
    /// φ = rate_p t + kappa (Π(τ) − Π(τ₀)).
    rate_p: f64,
    kappa: f64,
    /// The working frame W: its axis i is sorted axis `w_axes[i]`, the pole third.
    w_axes: [usize; 3],
    /// q₀ ⊗ q(M)* ⊗ q(C₀)*, and q(M), with M: user body → W.
    q_pre: Quaternion,
    q_post: Quaternion,
}

#[derive(Debug, Clone, PartialEq)]
enum Motion {
    Steady { omega: Vec3, axis: Vec3, rate: f64 },
    Symmetric(SymmetricMotion),
    Elliptic(Box<Elliptic>),
}

/// The exact torque-free motion of a rigid body with principal moments `moments` (any order,
/// body axes along the principal axes), from body angular velocity `omega0` and attitude
/// `attitude0` at t = 0.
///
/// ```
/// use poinsot::analytic::FreeRigidBody;
/// use poinsot::Vec3;
/// let body = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(1.0, 0.1, 1.0), None).unwrap();
/// let w = body.omega(1000.0);
/// // T and |L| are conserved exactly.
/// let t = 0.5 * (w.x * w.x + 2.0 * w.y * w.y + 3.0 * w.z * w.z);
/// assert!((t - body.energy()).abs() < 1e-13);
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct FreeRigidBody {
    moments: [f64; 3],
    omega0: Vec3,
    attitude0: Quaternion,
    energy: f64,
    l_space: Vec3,
    regime: FreeRegime,
    motion: Motion,
}

/// Checks principal moments: finite, > 0, and the triangle inequality `I₁ + I₂ ≥ I₃` of the
/// sorted moments within [`crate::inertia::tensor::PHYSICAL_RTOL`] of the largest (the same
/// rule as [`crate::inertia::check_inertia`], without its eigen-decomposition); errors name
/// `moments` ([`crate::ErrorKind::InvalidInertia`]).
pub fn check_moments(moments: &[f64; 3]) -> Result<()> {
    if let Err(e) = check_finite("moments", moments) {
        return Err(Error::inertia("moments", e.message));
    }
    if let Some(i) = moments.iter().position(|&v| v <= 0.0) {
        return Err(Error::inertia(
            "moments",
            format!(
                "principal moments must be > 0 for the body to turn, got {} at index {i}",
                moments[i]
            ),
        ));
    }
    let mut m = *moments;
    m.sort_by(f64::total_cmp);
    let excess = m[2] - (m[0] + m[1]);
    if excess > crate::inertia::tensor::PHYSICAL_RTOL * m[2] {
        return Err(Error::inertia(
            "moments",
            format!(
                "principal moments {m:?} violate the triangle inequality I1 + I2 >= I3: {} + {} < {} by {excess:.6e} \
                 ({:.3e} of the largest moment); no distribution of mass has these moments",
                m[0],
                m[1],
                m[2],
                excess / m[2]
            ),
        ));
    }
    Ok(())
}

impl FreeRigidBody {
    /// The motion of a body with principal moments `moments` (kg·m², > 0, any order, obeying
    /// the triangle inequality), turning with body angular velocity `omega0` (rad/s, nonzero)
    /// in attitude `attitude0` (unit quaternion `[w, x, y, z]`, body → space; identity if
    /// `None`) at t = 0.
    ///
    /// Errors: `moments` ([`crate::ErrorKind::InvalidInertia`]), `omega0` (non-finite or zero),
    /// `attitude0` (non-finite, zero or not unit within 1e-6).
    pub fn new(moments: [f64; 3], omega0: Vec3, attitude0: Option<Quaternion>) -> Result<Self> {
        check_moments(&moments)?;
        check_omega("omega0", &omega0)?;
        let attitude0 = match attitude0 {
            Some(q) => check_quaternion("attitude0", &q, false)?,
            None => [1.0, 0.0, 0.0, 0.0],
        };
        let l_body = Vec3::new(
            moments[0] * omega0.x,
            moments[1] * omega0.y,
            moments[2] * omega0.z,
        );
        let energy = 0.5 * (l_body.x * omega0.x + l_body.y * omega0.y + l_body.z * omega0.z);
        let l_space = rotate(&attitude0, &l_body);
        // A component whose square underflows (|ω_i| < ~1e-162) adds nothing to T or L in
        // double precision, and would make the elliptic set-up divide 0 by 0: such a motion
        // is the steady rotation about the one remaining axis, to round-off.
        let nonzero = omega0.iter().filter(|w| **w * **w != 0.0).count();
        let (regime, motion) =
            if moments[0] == moments[1] && moments[1] == moments[2] || nonzero == 1 {
                let rate = omega0.norm();
                (
                    FreeRegime::Steady,
                    Motion::Steady {
                        omega: omega0,
                        axis: omega0 / rate,
                        rate,
                    },
                )
            } else if let Some(axis) = symmetry_axis(&moments) {
                (
                    FreeRegime::Symmetric,
                    Motion::Symmetric(SymmetricMotion::new(axis, moments, omega0, attitude0)),
                )
            } else {
                let (regime, e) = Elliptic::new(&moments, &omega0, &attitude0)?;
                (regime, Motion::Elliptic(Box::new(e)))
            };
        Ok(Self {
            moments,
            omega0,
            attitude0,
            energy,
            l_space,
            regime,
            motion,
        })
    }

    /// The principal moments, as given (kg·m²).
    pub fn moments(&self) -> [f64; 3] {
        self.moments
    }
    /// ω at t = 0 (body, rad/s).
    pub fn omega0(&self) -> Vec3 {
        self.omega0
    }
    /// The attitude at t = 0.
    pub fn attitude0(&self) -> Quaternion {
        self.attitude0
    }
    /// The kinetic energy T = ½ ω·I·ω, conserved (J).
    pub fn energy(&self) -> f64 {
        self.energy
    }
    /// The angular momentum in space components, conserved (kg·m²/s).
    pub fn angular_momentum(&self) -> Vec3 {
        self.l_space
    }
    /// Which motion this is.
    pub fn regime(&self) -> FreeRegime {
        self.regime
    }

    /// The parameter m = k² of the Jacobi functions (0 for the steady and symmetric motions,
    /// 1 on the separatrix).
    pub fn parameter(&self) -> f64 {
        match &self.motion {
            Motion::Elliptic(e) => e.jacobi.m(),
            _ => 0.0,
        }
    }

    /// λ, the rate of the Jacobi argument τ = λ t + τ₀ (rad/s; for the symmetric top |Ω|,
    /// 0 when ω is constant).
    pub fn frequency(&self) -> f64 {
        match &self.motion {
            Motion::Elliptic(e) => e.lambda,
            Motion::Symmetric(s) => s.big_omega.abs(),
            Motion::Steady { .. } => 0.0,
        }
    }

    /// The period of ω(t) in the body (s): 4K(m)/λ for the asymmetric top, 2π/|Ω| for the
    /// symmetric top; infinite when ω is constant or on the separatrix.
    pub fn period(&self) -> f64 {
        match &self.motion {
            Motion::Elliptic(e) if !e.separatrix => 4.0 * e.jacobi.quarter_period() / e.lambda,
            Motion::Symmetric(s) if s.big_omega != 0.0 => {
                2.0 * std::f64::consts::PI / s.big_omega.abs()
            }
            _ => f64::INFINITY,
        }
    }

    /// The time between two successive reversals of the intermediate-axis component ω₂ (half
    /// the period, 2K/λ): near the separatrix, the interval between Dzhanibekov flips (s).
    pub fn flip_interval(&self) -> f64 {
        0.5 * self.period()
    }

    /// The principal axis (index into `moments`) that ω circles: the largest-moment axis above
    /// the separatrix, the smallest below; the symmetry axis of a symmetric top; `None` when ω
    /// is constant or on the separatrix.
    pub fn pole_axis(&self) -> Option<usize> {
        match &self.motion {
            Motion::Elliptic(e) if !e.separatrix => {
                let row = e.to_sorted.row(e.pole);
                (0..3).find(|&k| row[k] != 0.0)
            }
            Motion::Symmetric(s) => Some(s.axis),
            _ => None,
        }
    }

    /// ω(t) in body components (rad/s).
    pub fn omega(&self, t: f64) -> Vec3 {
        match &self.motion {
            Motion::Steady { omega, .. } => *omega,
            Motion::Symmetric(s) => s.omega(t),
            Motion::Elliptic(e) => e.to_sorted.transpose() * e.omega_sorted(e.tau(t)).0,
        }
    }

    /// The attitude at t (`[w, x, y, z]`, body → space).
    pub fn attitude(&self, t: f64) -> Quaternion {
        self.state(t).1
    }

    /// ω(t) (body) and the attitude at t together (cheaper than separately).
    pub fn state(&self, t: f64) -> (Vec3, Quaternion) {
        match &self.motion {
            Motion::Steady { omega, axis, rate } => (
                *omega,
                hamilton(&self.attitude0, &axis_angle_q(axis, rate * t)),
            ),
            Motion::Symmetric(s) => (s.omega(t), s.attitude(t)),
            Motion::Elliptic(e) => {
                let (w_sorted, q) = e.state(t);
                (e.to_sorted.transpose() * w_sorted, q)
            }
        }
    }

    /// ω (body) and the attitude at each of `times`, the quaternions' signs made continuous
    /// from one time to the next (`q` and `−q` are the same attitude).
    pub fn sample(&self, times: &[f64]) -> (Vec<[f64; 3]>, Vec<Quaternion>) {
        let mut omega = Vec::with_capacity(times.len());
        let mut attitude: Vec<Quaternion> = Vec::with_capacity(times.len());
        for &t in times {
            let (w, q) = self.state(t);
            let q = match attitude.last() {
                Some(prev) => super::rotations::same_hemisphere(q, prev),
                None => q,
            };
            omega.push([w.x, w.y, w.z]);
            attitude.push(q);
        }
        (omega, attitude)
    }

    /// L(t) in body components (kg·m²/s).
    pub fn angular_momentum_body(&self, t: f64) -> Vec3 {
        let w = self.omega(t);
        Vec3::new(
            self.moments[0] * w.x,
            self.moments[1] * w.y,
            self.moments[2] * w.z,
        )
    }

    /// ω(t) in space components: its tip traces the herpolhode on the invariable plane
    /// `ω·L̂ = 2T/|L|` (rad/s).
    pub fn omega_space(&self, t: f64) -> Vec3 {
        let (w, q) = self.state(t);
        rotate(&q, &w)
    }
}

/// The reduction τ = 2Kj + r and the Jacobi functions at r.
#[derive(Debug, Clone, Copy)]
struct Reduced {
    j: f64,
    sn: f64,
    cn: f64,
    dn: f64,
}

/// Carlson's R_F(x, y, 1), checked. For `x, y < 1e-24` (next to the separatrix, where
/// `ellip`'s duplication does not converge over 300 decades) the asymptotic form
/// `R_F(x, y, 1) = ln(4 / (√x + √y)) + O(max(x, y) ln)` (Carlson & Gustafson 1994), exact to
/// round-off there.
fn carlson_f(x: f64, y: f64) -> Result<f64> {
    if x.max(y) < 1e-24 {
        return Ok((4.0 / (x.sqrt() + y.sqrt())).ln());
    }
    ellip::elliprf(x, y, 1.0)
        .map_err(|e| Error::invalid("omega0", format!("R_F({x}, {y}, 1): {e}")))
}

/// Carlson's R_J(x, y, 1, p), checked.
fn carlson_j(x: f64, y: f64, p: f64) -> Result<f64> {
    ellip::elliprj(x, y, 1.0, p)
        .map_err(|e| Error::invalid("omega0", format!("R_J({x}, {y}, 1, {p}): {e}")))
}

/// The index of the distinct moment when exactly two are equal.
fn symmetry_axis(m: &[f64; 3]) -> Option<usize> {
    if m[0] == m[1] && m[1] != m[2] {
        Some(2)
    } else if m[1] == m[2] && m[0] != m[1] {
        Some(0)
    } else if m[0] == m[2] && m[0] != m[1] {
        Some(1)
    } else {
        None
    }
}

/// A signed permutation matrix (det +1) whose row i picks axis `axes[i]`.
fn permutation(axes: [usize; 3]) -> Mat3 {
    let mut p = Mat3::zeros();
    for (i, &a) in axes.iter().enumerate() {
        p[(i, a)] = 1.0;
    }
    if p.determinant() < 0.0 {
        for k in 0..3 {
            p[(2, k)] = -p[(2, k)];
        }
    }
    p
}

fn row_major(m: &Mat3) -> [f64; 9] {
    [
        m[(0, 0)],
        m[(0, 1)],
        m[(0, 2)],
        m[(1, 0)],
        m[(1, 1)],
        m[(1, 2)],
        m[(2, 0)],
        m[(2, 1)],
        m[(2, 2)],
    ]
}

/// The rotation C with third row `l` (a unit vector), C = R_x(θ) R_z(ψ) with
/// (sin θ sin ψ, sin θ cos ψ, cos θ) = l: the z-x-z Euler angles (θ, ψ) of the direction of L.
fn euler_tilt(l: &Vec3) -> Quaternion {
    let rho = l.x.hypot(l.y);
    let (a, b) = (l.y / rho, l.x / rho);
    let c = [a, -b, 0.0, l.z * b, l.z * a, -rho, l.x, l.y, l.z];
    matrix_to_quaternion_unchecked(&c)
}

impl Elliptic {
    fn new(
        moments: &[f64; 3],
        omega0: &Vec3,
        attitude0: &Quaternion,
    ) -> Result<(FreeRegime, Self)> {
        let mut order = [0usize, 1, 2];
        order.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
        let to_sorted = permutation(order);
        let [i1, i2, i3] = [moments[order[0]], moments[order[1]], moments[order[2]]];
        let w = to_sorted * omega0;
        let (w1, w2, w3) = (w.x * w.x, w.y * w.y, w.z * w.z);
        // d₃ = 2TI₃ − L², d₁ = L² − 2TI₁, s₂ = L² − 2TI₂: sums without cancellation.
        let d3 = i1 * (i3 - i1) * w1 + i2 * (i3 - i2) * w2;
        let d1 = i2 * (i2 - i1) * w2 + i3 * (i3 - i1) * w3;
        let s2 = i1 * (i1 - i2) * w1 + i3 * (i3 - i2) * w3;
        let l2 = i1 * i1 * w1 + i2 * i2 * w2 + i3 * i3 * w3;
        let l_norm = l2.sqrt();
        let (pole, other, regime) = if s2 > 0.0 {
            (2, 0, FreeRegime::AboutMaxAxis)
        } else if s2 < 0.0 {
            (0, 2, FreeRegime::AboutMinAxis)
        } else {
            (2, 0, FreeRegime::Separatrix)
        };
        let separatrix = regime == FreeRegime::Separatrix;
        // Amplitudes, λ, m and 1 − m (see the module docs; p = 1 exchanges 1 ↔ 3).
        let (amp_o2, amp_22, amp_p2, lambda2, m, mc) = if pole == 2 {
            (
                d3 / (i1 * (i3 - i1)),
                d3 / (i2 * (i3 - i2)),
                d1 / (i3 * (i3 - i1)),
                (i3 - i2) * d1 / (i1 * i2 * i3),
                (i2 - i1) * d3 / ((i3 - i2) * d1),
                (i3 - i1) * s2 / ((i3 - i2) * d1),
            )
        } else {
            (
                d1 / (i3 * (i3 - i1)),
                d1 / (i2 * (i2 - i1)),
                d3 / (i1 * (i3 - i1)),
                (i2 - i1) * d3 / (i1 * i2 * i3),
                (i3 - i2) * d1 / ((i2 - i1) * d3),
                (i3 - i1) * (-s2) / ((i2 - i1) * d3),
            )
        };
        let lambda = lambda2.sqrt();
        let jacobi = if separatrix {
            Jacobi::new(1.0)?
        } else {
            Jacobi::with_complement(m.min(1.0), mc.clamp(0.0, 1.0))?
        };
        // Signs: ω_p never vanishes (dn > 0); ω₂ = sign(ω_o ω_p) ω₂,m sn with ω_o ∝ +cn
        // (off the separatrix; on it cn > 0, so ω_o keeps the sign of ω_o(0)).
        let sign = |v: f64| if v < 0.0 { -1.0 } else { 1.0 };
        let s_p = sign(w[pole]);
        let s_o = if separatrix { sign(w[other]) } else { 1.0 };
        let amp_cn = s_o * amp_o2.sqrt();
        let amp_sn = s_o * s_p * amp_22.sqrt();
        let amp_dn = s_p * amp_p2.sqrt();
        // τ₀ from sn τ₀ and cn τ₀ (ratios of ω₀'s components, accurate even where the amplitude
        // φ₀ is within round-off of ±π/2, as it is next to the separatrix).
        let (sn0, cn0) = {
            let (a, b) = (w.y / amp_sn, w[other] / amp_cn);
            let h = a.hypot(b);
            (a / h, b / h)
        };
        let tau0 = if separatrix {
            sn0.atanh()
        } else {
            let k = jacobi.quarter_period();
            let f = sn0.abs() * carlson_f(cn0 * cn0, cn0 * cn0 + jacobi.complement() * sn0 * sn0)?;
            let f = if cn0 >= 0.0 { f } else { 2.0 * k - f };
            if sn0 < 0.0 {
                -f
            } else {
                f
            }
        };
        // The precession angle φ (module docs).
        let n = if pole == 2 {
            -i3 * (i2 - i1) / (i1 * (i3 - i2))
        } else {
            -i1 * (i3 - i2) / (i3 * (i2 - i1))
        };
        let kappa_sign = if pole == 2 { 1.0 } else { -1.0 };
        let kappa = kappa_sign * l_norm * (i3 - i1) / (i1 * i3 * lambda);
        let sorted = [i1, i2, i3];
        let rate_p = l_norm / sorted[pole];
        let w_axes = if pole == 2 { [0, 1, 2] } else { [1, 2, 0] };
        let to_w = permutation(w_axes) * to_sorted;
        let mut e = Self {
            to_sorted,
            sorted,
            pole,
            other,
            amp_cn,
            amp_sn,
            amp_dn,
            lambda,
            tau0,
            jacobi,
            separatrix,
            n,
            pi_complete: 0.0,
            pi0: 0.0,
            rate_p,
            kappa,
            w_axes,
            q_pre: [1.0, 0.0, 0.0, 0.0],
            q_post: matrix_to_quaternion_unchecked(&row_major(&to_w)),
        };
        if !separatrix {
            // Π(n | m) = R_F(0, m₁, 1) + (n/3) R_J(0, m₁, 1, 1 − n) (DLMF 19.25.2).
            let mc = jacobi.complement();
            e.pi_complete = carlson_f(0.0, mc)? + n / 3.0 * carlson_j(0.0, mc, 1.0 - n)?;
        }
        let (w_s0, red0) = e.omega_sorted(tau0);
        e.pi0 = e.pi_of(tau0, red0)?;
        let c0 = euler_tilt(&e.l_hat_w(&w_s0));
        e.q_pre = hamilton(&hamilton(attitude0, &conj(&e.q_post)), &conj(&c0));
        check_finite("omega0", &[e.lambda, e.tau0, e.kappa, e.pi0, e.pi_complete]).map_err(
            |_| {
                Error::invalid(
                    "omega0",
                    "the elliptic solution is not finite for this state (report it as a bug)",
                )
            },
        )?;
        Ok((regime, e))
    }

    #[inline]
    fn tau(&self, t: f64) -> f64 {
        self.lambda.mul_add(t, self.tau0)
    }

    /// ω in sorted components at τ, and (j, sn r, cn r, dn r) of the reduction τ = 2Kj + r.
    #[inline]
    fn omega_sorted(&self, tau: f64) -> (Vec3, Reduced) {
        let (j, r) = self.jacobi.reduce(tau);
        let v = self.jacobi.eval_reduced(r);
        let flip = if j.rem_euclid(2.0) == 1.0 { -1.0 } else { 1.0 };
        let mut w = Vec3::zeros();
        w[self.other] = self.amp_cn * flip * v.cn;
        w[1] = self.amp_sn * flip * v.sn;
        w[self.pole] = self.amp_dn * v.dn;
        (
            w,
            Reduced {
                j,
                sn: v.sn,
                cn: v.cn,
                dn: v.dn,
            },
        )
    }

    /// Π(n; am τ | m) = 2jΠ(n) + Π(n; am r), the last in Carlson's form from sn r, cn r and
    /// dn r themselves (no amplitude angle, which near m = 1 sits within round-off of ±π/2):
    /// `Π = s R_F(c², d², 1) + (n/3) s³ R_J(c², d², 1, 1 − n s²)` (DLMF 19.25.14); the
    /// closed form on the separatrix.
    #[inline]
    fn pi_of(&self, tau: f64, red: Reduced) -> Result<f64> {
        if self.separatrix {
            // ∫₀^τ dτ / (1 − n tanh²τ) = [τ + √(−n) atan(√(−n) tanh τ)] / (1 − n).
            let r = (-self.n).sqrt();
            return Ok((tau + r * (r * tau.tanh()).atan()) / (1.0 - self.n));
        }
        let (s, c2, d2) = (red.sn, red.cn * red.cn, red.dn * red.dn);
        let p = s * carlson_f(c2, d2)?
            + self.n / 3.0 * s * s * s * carlson_j(c2, d2, 1.0 - self.n * s * s)?;
        Ok(2.0 * red.j * self.pi_complete + p)
    }

    /// L̂ in the working frame W (pole third) from ω in sorted components.
    #[inline]
    fn l_hat_w(&self, w: &Vec3) -> Vec3 {
        let l = Vec3::new(
            self.sorted[0] * w.x,
            self.sorted[1] * w.y,
            self.sorted[2] * w.z,
        );
        let lw = Vec3::new(l[self.w_axes[0]], l[self.w_axes[1]], l[self.w_axes[2]]);
        lw / lw.norm()
    }

    fn state(&self, t: f64) -> (Vec3, Quaternion) {
        let tau = self.tau(t);
        let (w, red) = self.omega_sorted(tau);
        // The reduced Π cannot fail for n < 1 and 0 < m_c ≤ 1, checked at construction.
        let pi = self.pi_of(tau, red).unwrap_or(f64::NAN);
        let phi = self.rate_p.mul_add(t, self.kappa * (pi - self.pi0));
        let c = euler_tilt(&self.l_hat_w(&w));
        let q = hamilton(
            &hamilton(&self.q_pre, &coordinate_q(2, phi)),
            &hamilton(&c, &self.q_post),
        );
        (w, normalized(&q))
    }
}
