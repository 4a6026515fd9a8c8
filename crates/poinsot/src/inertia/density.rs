//! Mass properties of a continuous density `ρ(r)` over a box, by adaptive cubature with an error
//! estimate (the unit's 2.61–2.62).
//!
//! **Rule.** Each box region is integrated with the Genz–Malik degree-7 rule (33 points in 3-D)
//! and the embedded degree-5 rule on the same points; `|R₇ − R₅|` is the region's error
//! estimate (Genz & Malik 1980; the same scheme as Steven G. Johnson's `hcubature`). All ten
//! moments `∫ρ, ∫ρx, ∫ρy, ∫ρz, ∫ρx², ∫ρy², ∫ρz², ∫ρxy, ∫ρyz, ∫ρzx` (coordinates relative to
//! the centre of the box) share the density values.
//!
//! **Adaptivity.** The box starts as a 4×4×4 grid of regions. Each round, the regions are sorted
//! by their (scaled) error estimate and the largest are bisected, along the axis where the
//! fourth divided difference of ρ is largest (the widest axis where ρ looks polynomial), until
//! the remaining error would be within the tolerance; all their children are evaluated in one
//! batch. The density is therefore called with **batches** of points (up to [`MAX_BATCH`]),
//! so a vectorised front end (numpy) pays its call overhead once per batch.
//!
//! **Discontinuities.** The rule's points stay within 0.95 of each half-width (0.69 along the
//! diagonals), so the boundary of a piecewise-constant density (the indicator of a shape) can
//! clip a corner of a region without touching any point, where `|R₇ − R₅| = 0` would hide the
//! error for ever. Each region is therefore also probed at its 8 corners (41 points in all):
//! when the 33 rule values are all equal but a corner value differs, the region's error is at
//! least the corner octant's share, `vol/8 · |Δρ| · |moment factor|`, and it is refined. The
//! error estimates are rigorous only for smooth densities; for indicators they were found
//! conservative by one to two orders of magnitude (tests), and convergence is slow (the error
//! falls like the region size near the boundary): prefer [`crate::inertia::mesh`] for uniform
//! solids.
//!
//! **Stopping.** Converged when the propagated error estimates satisfy
//! `δm ≤ rtol·m`, `δcom ≤ rtol·R` (R: the half-diagonal of the box) and
//! `δI ≤ max(rtol·tr(I)/2, atol)`. If `max_evals` would be exceeded first, the best estimate is
//! returned with its error estimate and `converged = false` (the Python layer warns).

use crate::error::{check_finite, Error, Result};
use crate::inertia::body::MassProperties;
use crate::{Mat3, Vec3};

/// The most points passed to the density in one call.
pub const MAX_BATCH: usize = 1 << 18;

/// Points per region: the 33 of the Genz–Malik rule in three dimensions (1 + 6 + 6 + 12 + 8)
/// and the 8 corners of the region (the discontinuity probe, see [`density_mass_properties`]).
pub const POINTS_PER_REGION: usize = 41;

/// Points of the Genz–Malik rule proper.
const RULE_POINTS: usize = 33;

/// Regions per axis of the initial grid.
const INITIAL_SPLITS: usize = 4;

/// Options of [`density_mass_properties`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CubatureOptions {
    /// Relative tolerance (see the module docs for what it is relative to). Default `1e-6`.
    pub rtol: f64,
    /// Absolute tolerance on the inertia tensor entries (kg·m²). Default `0`.
    pub atol: f64,
    /// The most density evaluations (points). Default `10_000_000`.
    pub max_evals: usize,
}

impl CubatureOptions {
    /// The defaults: rtol 1e-6, atol 0, 10⁷ evaluations (`crate::defaults::CUBATURE`).
    pub const DEFAULT: Self = Self {
        rtol: 1e-6,
        atol: 0.0,
        max_evals: 10_000_000,
    };
}

impl Default for CubatureOptions {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// The result of [`density_mass_properties`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DensityIntegral {
    /// The mass properties (best estimate).
    pub body: MassProperties,
    /// Error estimate of the mass (kg).
    pub mass_error: f64,
    /// Error estimate of each coordinate of the centre of mass (m), the largest of the three.
    pub center_of_mass_error: f64,
    /// Error estimate of each entry of the inertia tensor (kg·m²), the largest of the nine.
    pub inertia_error: f64,
    /// Number of density evaluations (points).
    pub evaluations: usize,
    /// Whether the tolerance was reached within `max_evals`.
    pub converged: bool,
}

// Genz–Malik weights for n = 3 (degree 7, then the embedded degree 5) and abscissae.
const W1: f64 = -10936.0 / 19683.0;
const W2: f64 = 980.0 / 6561.0;
const W3: f64 = 620.0 / 19683.0;
const W4: f64 = 200.0 / 19683.0;
const W5: f64 = 6859.0 / 19683.0 / 8.0;
const E1: f64 = -1671.0 / 729.0;
const E2: f64 = 245.0 / 486.0;
const E3: f64 = -35.0 / 1458.0;
const E4: f64 = 25.0 / 729.0;
/// sqrt(9/70), sqrt(9/10), sqrt(9/19).
fn lambdas() -> (f64, f64, f64) {
    (
        (9.0f64 / 70.0).sqrt(),
        (9.0f64 / 10.0).sqrt(),
        (9.0f64 / 19.0).sqrt(),
    )
}

/// One box region with its rule results.
#[derive(Debug, Clone, Copy)]
struct Region {
    center: [f64; 3],
    half: [f64; 3],
    value: [f64; 10],
    error: [f64; 10],
    split_axis: usize,
}

/// The 41 unit-cube offsets, in a fixed order: the rule's centre, ±λ2 eᵢ, ±λ4 eᵢ,
/// ±λ4 eᵢ ± λ4 eⱼ, (±λ5, ±λ5, ±λ5), then the corners (±1, ±1, ±1).
fn offsets() -> [[f64; 3]; POINTS_PER_REGION] {
    let (l2, l4, l5) = lambdas();
    let mut o = [[0.0; 3]; POINTS_PER_REGION];
    let mut k = 1;
    let units = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for l in [l2, l4] {
        for e in units {
            for s in [1.0, -1.0] {
                o[k] = e.map(|x: f64| s * l * x);
                k += 1;
            }
        }
    }
    for (i, j) in [(0, 1), (1, 2), (2, 0)] {
        for si in [1.0, -1.0] {
            for sj in [1.0, -1.0] {
                o[k][i] = si * l4;
                o[k][j] = sj * l4;
                k += 1;
            }
        }
    }
    for sx in [1.0, -1.0] {
        for sy in [1.0, -1.0] {
            for sz in [1.0, -1.0] {
                o[k] = [sx * l5, sy * l5, sz * l5];
                k += 1;
            }
        }
    }
    debug_assert_eq!(k, RULE_POINTS);
    for sx in [1.0, -1.0] {
        for sy in [1.0, -1.0] {
            for sz in [1.0, -1.0] {
                o[k] = [sx, sy, sz];
                k += 1;
            }
        }
    }
    debug_assert_eq!(k, POINTS_PER_REGION);
    o
}

/// Mass properties of the density `density` (kg/m³) over the box
/// `bounds = [[xmin, xmax], [ymin, ymax], [zmin, zmax]]` (m), by adaptive cubature
/// (module docs).
///
/// `density(points, values)` must fill `values[k]` with ρ at `points[k]` (m); it is called with
/// batches of up to [`MAX_BATCH`] points and may fail with its own error, which is passed on.
/// Errors: bounds not finite or `min >= max` (named `bounds`); bad options (`rtol`, `atol`,
/// `max_evals`); a density value that is negative or not finite, or a density that integrates
/// to zero mass (named `density`).
pub fn density_mass_properties<F>(
    mut density: F,
    bounds: [[f64; 2]; 3],
    options: &CubatureOptions,
) -> Result<DensityIntegral>
where
    F: FnMut(&[[f64; 3]], &mut [f64]) -> Result<()>,
{
    check_finite("bounds", bounds.as_flattened())?;
    for (i, b) in bounds.iter().enumerate() {
        if b[0] >= b[1] {
            return Err(Error::invalid(
                "bounds",
                format!(
                    "must have min < max on every axis, got [{}, {}] on axis {i}",
                    b[0], b[1]
                ),
            ));
        }
    }
    if !(options.rtol.is_finite() && options.rtol > 0.0) {
        return Err(Error::invalid(
            "rtol",
            format!("must be finite and > 0, got {}", options.rtol),
        ));
    }
    if !(options.atol.is_finite() && options.atol >= 0.0) {
        return Err(Error::invalid(
            "atol",
            format!("must be finite and >= 0, got {}", options.atol),
        ));
    }
    let initial = INITIAL_SPLITS.pow(3);
    if options.max_evals < initial * POINTS_PER_REGION {
        return Err(Error::invalid(
            "max_evals",
            format!(
                "must be at least {} (the initial {}x{}x{} grid of {}-point regions), got {}",
                initial * POINTS_PER_REGION,
                INITIAL_SPLITS,
                INITIAL_SPLITS,
                INITIAL_SPLITS,
                POINTS_PER_REGION,
                options.max_evals
            ),
        ));
    }
    // Halves first, so that bounds near ±1.8e308 do not overflow.
    let c0 = bounds.map(|b| 0.5 * b[0] + 0.5 * b[1]);
    let h0 = bounds.map(|b| 0.5 * b[1] - 0.5 * b[0]);
    let radius = (h0[0] * h0[0] + h0[1] * h0[1] + h0[2] * h0[2]).sqrt();
    let mut cub = Cubature {
        c0,
        offsets: offsets(),
        points: Vec::new(),
        values: Vec::new(),
        evaluations: 0,
    };

    // Initial grid.
    let n = INITIAL_SPLITS;
    let h = h0.map(|x| x / n as f64);
    let mut todo = Vec::with_capacity(initial);
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                let centre = [
                    bounds[0][0] + (2 * i + 1) as f64 * h[0],
                    bounds[1][0] + (2 * j + 1) as f64 * h[1],
                    bounds[2][0] + (2 * k + 1) as f64 * h[2],
                ];
                todo.push((centre, h));
            }
        }
    }
    let mut regions = cub.evaluate(&todo, &mut density)?;
    loop {
        let (total, err) = totals(&regions);
        check_representable(&total, &err)?;
        let est = Estimate::new(&total, &err, c0);
        let scales = Scales::new(&est, radius, options);
        let converged = est.mass > 0.0 && scales.within(&est);
        // Children of the split regions cost 2 regions each.
        let budget = options.max_evals.saturating_sub(cub.evaluations) / (2 * POINTS_PER_REGION);
        if converged || budget == 0 || est.mass.is_nan() || est.mass <= 0.0 {
            return finish(est, cub.evaluations, converged);
        }
        // Normalised error of each region, largest first.
        let norm = |r: &Region| scales.region_norm(&r.error);
        let mut order: Vec<(f64, usize)> = regions
            .iter()
            .enumerate()
            .map(|(i, r)| (norm(r), i))
            .collect();
        order.sort_by(|a, b| b.0.total_cmp(&a.0));
        let total_norm: f64 = order.iter().map(|x| x.0).sum();
        // Split the largest regions until what is left is within half the tolerance, or at
        // least half of the error is being refined; at most doubling the number of regions.
        let target = (0.5f64).min(0.5 * total_norm);
        let mut removed = 0.0;
        let mut count = 0;
        let cap = budget.min(regions.len()).max(1);
        while count < cap && total_norm - removed > target {
            removed += order[count].0;
            count += 1;
        }
        let count = count.max(1);
        let mut split = vec![false; regions.len()];
        let mut children = Vec::with_capacity(2 * count);
        for &(_, i) in &order[..count] {
            split[i] = true;
            let r = regions[i];
            let a = r.split_axis;
            let mut half = r.half;
            half[a] *= 0.5;
            let mut lo = r.center;
            let mut hi = r.center;
            lo[a] -= half[a];
            hi[a] += half[a];
            children.push((lo, half));
            children.push((hi, half));
        }
        let mut kept: Vec<Region> = regions
            .iter()
            .zip(&split)
            .filter(|(_, s)| !**s)
            .map(|(r, _)| *r)
            .collect();
        kept.extend(cub.evaluate(&children, &mut density)?);
        regions = kept;
    }
}

/// Evaluation state: the box centre, the rule's offsets and reusable buffers.
struct Cubature {
    c0: [f64; 3],
    offsets: [[f64; 3]; POINTS_PER_REGION],
    points: Vec<[f64; 3]>,
    values: Vec<f64>,
    evaluations: usize,
}

impl Cubature {
    /// Applies the rule to each region `(centre, half-widths)`, calling the density in batches.
    fn evaluate<F>(&mut self, todo: &[([f64; 3], [f64; 3])], density: &mut F) -> Result<Vec<Region>>
    where
        F: FnMut(&[[f64; 3]], &mut [f64]) -> Result<()>,
    {
        let per_batch = MAX_BATCH / POINTS_PER_REGION;
        let mut out = Vec::with_capacity(todo.len());
        for chunk in todo.chunks(per_batch) {
            self.points.clear();
            for (c, h) in chunk {
                for o in &self.offsets {
                    self.points
                        .push([c[0] + h[0] * o[0], c[1] + h[1] * o[1], c[2] + h[2] * o[2]]);
                }
            }
            self.values.clear();
            self.values.resize(self.points.len(), 0.0);
            density(&self.points, &mut self.values)?;
            self.evaluations += self.points.len();
            if let Some(k) = self
                .values
                .iter()
                .position(|v| !(v.is_finite() && *v >= 0.0))
            {
                return Err(Error::invalid(
                    "density",
                    format!(
                        "must be finite and >= 0 (kg/m³), got {} at the point {:?}",
                        self.values[k], self.points[k]
                    ),
                ));
            }
            for (r, (c, h)) in chunk.iter().enumerate() {
                let span = r * POINTS_PER_REGION..(r + 1) * POINTS_PER_REGION;
                out.push(self.rule(c, h, &self.points[span.clone()], &self.values[span]));
            }
        }
        Ok(out)
    }

    /// The degree-7 and degree-5 results of the ten moments on one region, and its split axis.
    fn rule(&self, c: &[f64; 3], h: &[f64; 3], pts: &[[f64; 3]], f: &[f64]) -> Region {
        // Moment factors (1, x, y, z, x², y², z², xy, yz, zx) at each point, coordinates
        // relative to the box centre; the integrands are ρ times these.
        let poly = |k: usize| -> [f64; 10] {
            let p = [
                pts[k][0] - self.c0[0],
                pts[k][1] - self.c0[1],
                pts[k][2] - self.c0[2],
            ];
            [
                1.0,
                p[0],
                p[1],
                p[2],
                p[0] * p[0],
                p[1] * p[1],
                p[2] * p[2],
                p[0] * p[1],
                p[1] * p[2],
                p[2] * p[0],
            ]
        };
        let m = |k: usize| -> [f64; 10] { poly(k).map(|x| f[k] * x) };
        let mut s = [[0.0f64; 10]; 5];
        let groups = [0..1, 1..7, 7..13, 13..25, 25..33];
        for (g, range) in groups.iter().enumerate() {
            // (Points RULE_POINTS.. are the corners, outside the rule.)
            for k in range.clone() {
                let v = m(k);
                for (acc, x) in s[g].iter_mut().zip(v) {
                    *acc += x;
                }
            }
        }
        let vol = 8.0 * h[0] * h[1] * h[2];
        let mut value = [0.0; 10];
        let mut error = [0.0; 10];
        for i in 0..10 {
            let r7 = W1 * s[0][i] + W2 * s[1][i] + W3 * s[2][i] + W4 * s[3][i] + W5 * s[4][i];
            let r5 = E1 * s[0][i] + E2 * s[1][i] + E3 * s[2][i] + E4 * s[3][i];
            value[i] = vol * r7;
            error[i] = vol * (r7 - r5).abs();
        }
        // Discontinuity probe: the rule's points stay inside 0.95 of the half-widths (0.69 on
        // the diagonals), so a boundary of a piecewise-constant density can clip a corner of the
        // region unseen, and |R7 − R5| = 0 there. If the 33 rule values are all equal but a
        // corner value differs, the clipped part is bounded by the corner's octant: take
        // vol/8 · |Δρ| · |moment factor at that corner| as the error.
        let f0 = f[0];
        if f[..RULE_POINTS].iter().all(|&v| v == f0) {
            for (k, fk) in f.iter().enumerate().skip(RULE_POINTS) {
                let jump = fk - f0;
                if jump != 0.0 {
                    for (e, factor) in error.iter_mut().zip(poly(k)) {
                        *e = e.max(vol / 8.0 * (jump * factor).abs());
                    }
                }
            }
        }
        // Fourth divided difference of ρ along each axis (points 1..7 at ±λ2, 7..13 at ±λ4).
        let ratio = 9.0 / 70.0 / (9.0 / 10.0);
        let mut diff = [0.0; 3];
        for (i, d) in diff.iter_mut().enumerate() {
            let d2 = f[1 + 2 * i] + f[2 + 2 * i] - 2.0 * f[0];
            let d4 = f[7 + 2 * i] + f[8 + 2 * i] - 2.0 * f[0];
            *d = (d2 - ratio * d4).abs();
        }
        let widest = (0..3).fold(0, |b, i| if h[i] > h[b] { i } else { b });
        let best = (0..3).fold(0, |b, i| if diff[i] > diff[b] { i } else { b });
        let spread = diff[best] - diff.iter().cloned().fold(f64::INFINITY, f64::min);
        let fscale = f.iter().fold(0.0f64, |a, v| a.max(v.abs()));
        // No clear winner (ρ locally polynomial of degree ≤ 3, or flat): the widest axis.
        let split_axis = if spread <= 1e-10 * fscale {
            widest
        } else {
            best
        };
        Region {
            center: *c,
            half: *h,
            value,
            error,
            split_axis,
        }
    }
}

fn totals(regions: &[Region]) -> ([f64; 10], [f64; 10]) {
    let mut t = [0.0; 10];
    let mut e = [0.0; 10];
    for r in regions {
        for i in 0..10 {
            t[i] += r.value[i];
            e[i] += r.error[i];
        }
    }
    (t, e)
}

/// Mass properties and propagated error bounds from the moment totals.
struct Estimate {
    mass: f64,
    com: Vec3,
    inertia: Mat3,
    mass_error: f64,
    com_error: f64,
    inertia_error: f64,
    moments_scale: [f64; 3],
}

impl Estimate {
    fn new(t: &[f64; 10], e: &[f64; 10], c0: [f64; 3]) -> Self {
        let mass = t[0];
        let d = if mass > 0.0 {
            Vec3::new(t[1], t[2], t[3]) / mass
        } else {
            Vec3::zeros()
        };
        let q = Mat3::new(t[4], t[7], t[9], t[7], t[5], t[8], t[9], t[8], t[6]);
        let second = q - d * d.transpose() * mass;
        let inertia = Mat3::identity() * second.trace() - second;
        // Linearised error propagation, all terms taken with absolute values (a bound).
        let m = mass.max(f64::MIN_POSITIVE);
        let d_abs = d.abs();
        let e1 = Vec3::new(e[1], e[2], e[3]);
        let com_err = (e1 + d_abs * e[0]) / m;
        let eq = Mat3::new(e[4], e[7], e[9], e[7], e[5], e[8], e[9], e[8], e[6]);
        // δ(M d dᵀ) = δ(S₁ S₁ᵀ / M) ≤ d δS₁ᵀ + δS₁ dᵀ + d dᵀ δM.
        let ec =
            eq + d_abs * e1.transpose() + e1 * d_abs.transpose() + d_abs * d_abs.transpose() * e[0];
        let mut ei = ec;
        for i in 0..3 {
            ei[(i, i)] = (0..3).filter(|&k| k != i).map(|k| ec[(k, k)]).sum();
        }
        Self {
            mass,
            com: d + Vec3::from(c0),
            inertia,
            mass_error: e[0],
            com_error: com_err.max(),
            inertia_error: ei.max(),
            moments_scale: [mass.abs(), mass.abs(), q.trace().abs()],
        }
    }
}

/// Tolerances in absolute units and the normalisation of region errors.
struct Scales {
    mass: f64,
    com: f64,
    inertia: f64,
    first: f64,
    second: f64,
}

impl Scales {
    fn new(est: &Estimate, radius: f64, o: &CubatureOptions) -> Self {
        let inertia = (o.rtol * 0.5 * est.inertia.trace().abs()).max(o.atol);
        Self {
            mass: o.rtol * est.mass.abs(),
            com: o.rtol * radius,
            inertia,
            first: o.rtol * est.moments_scale[1] * radius,
            second: (o.rtol * est.moments_scale[2]).max(o.atol),
        }
    }
    fn within(&self, est: &Estimate) -> bool {
        est.mass_error <= self.mass
            && est.com_error <= self.com
            && est.inertia_error <= self.inertia
    }
    /// A region's error in units of the tolerance (summing to ≤ 1 roughly means converged).
    fn region_norm(&self, e: &[f64; 10]) -> f64 {
        let tiny = f64::MIN_POSITIVE;
        let a = e[0] / self.mass.max(tiny);
        let b = e[1].max(e[2]).max(e[3]) / self.first.max(tiny);
        let c = e[4..].iter().cloned().fold(0.0, f64::max) / self.second.max(tiny);
        a.max(b).max(c)
    }
}

/// An error naming `density` when a moment or its error estimate overflowed: the mass,
/// first or second moments of this density over these bounds exceed the range of doubles.
/// (Without it the refinement would chase infinite errors one region at a time.)
fn check_representable(total: &[f64; 10], err: &[f64; 10]) -> Result<()> {
    if total.iter().chain(err).all(|x| x.is_finite()) {
        return Ok(());
    }
    Err(Error::invalid(
        "density",
        format!(
            "its integrals over the bounds exceed the largest finite double (1.8e+308): mass \
             {:e} kg, second moments up to {:e} kg·m²; no finite answer exists, express the \
             density and the bounds in other units",
            total[0],
            total[4..].iter().fold(0.0f64, |a, x| a.max(x.abs()))
        ),
    ))
}

fn finish(est: Estimate, evaluations: usize, converged: bool) -> Result<DensityIntegral> {
    let finite = est.mass.is_finite()
        && est.com.iter().all(|x| x.is_finite())
        && est.inertia.iter().all(|x| x.is_finite());
    if !finite {
        return Err(Error::invalid(
            "density",
            format!(
                "its mass properties over the bounds exceed the largest finite double \
                 (1.8e+308): mass {:e} kg, centre of mass {:?} m; express the density and the \
                 bounds in other units",
                est.mass,
                est.com.as_slice()
            ),
        ));
    }
    if est.mass.is_nan() || est.mass <= 0.0 {
        return Err(Error::invalid(
            "density",
            format!(
                "integrates to zero mass over the bounds (got {:e} kg after {evaluations} \
                 evaluations); is the body inside the bounds?",
                est.mass
            ),
        ));
    }
    let body = MassProperties::new(est.mass, est.com, est.inertia).map_err(|e| {
        Error::inertia(
            "density",
            format!(
                "the integrated inertia is not physical within the integration error \
                 ({:.3e} kg·m²): {}; tighten rtol or raise max_evals",
                est.inertia_error, e.message
            ),
        )
    })?;
    Ok(DensityIntegral {
        body,
        mass_error: est.mass_error,
        center_of_mass_error: est.com_error,
        inertia_error: est.inertia_error,
        evaluations,
        converged,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_box_is_exact() {
        let r = density_mass_properties(
            |_p: &[[f64; 3]], v: &mut [f64]| {
                v.fill(3.0);
                Ok(())
            },
            [[0.0, 1.0], [0.0, 2.0], [0.0, 3.0]],
            &CubatureOptions::default(),
        )
        .unwrap();
        let m = 18.0;
        assert!(r.converged);
        assert!((r.body.mass() - m).abs() < 1e-12);
        assert!((r.body.center_of_mass() - Vec3::new(0.5, 1.0, 1.5)).amax() < 1e-13);
        let expect =
            Mat3::from_diagonal(&Vec3::new(m * 13.0 / 12.0, m * 10.0 / 12.0, m * 5.0 / 12.0));
        assert!((r.body.inertia() - expect).amax() < 1e-12);
    }

    #[test]
    fn weights_integrate_degree_seven() {
        // x⁴ y² z on [0, 1]³ (degree 7): ∫ = 1/5 · 1/3 · 1/2 = 1/30; mass only.
        let mut calls = 0;
        let r = density_mass_properties(
            |p: &[[f64; 3]], v: &mut [f64]| {
                calls += 1;
                for (x, o) in p.iter().zip(v.iter_mut()) {
                    *o = x[0].powi(4) * x[1] * x[1] * x[2] + 1.0;
                }
                Ok(())
            },
            [[0.0, 1.0], [0.0, 1.0], [0.0, 1.0]],
            &CubatureOptions {
                rtol: 1e-10,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(
            (r.body.mass() - (1.0 + 1.0 / 30.0)).abs() < 1e-13,
            "{}",
            r.body.mass()
        );
        assert!(calls >= 1);
    }

    #[test]
    fn refusals() {
        let ones = |_p: &[[f64; 3]], v: &mut [f64]| {
            v.fill(1.0);
            Ok(())
        };
        let o = CubatureOptions::default();
        let e =
            density_mass_properties(ones, [[1.0, 0.0], [0.0, 1.0], [0.0, 1.0]], &o).unwrap_err();
        assert!(e.to_string().starts_with("bounds:"), "{e}");
        let neg = |_p: &[[f64; 3]], v: &mut [f64]| {
            v.fill(-1.0);
            Ok(())
        };
        let e = density_mass_properties(neg, [[0.0, 1.0]; 3], &o).unwrap_err();
        assert!(
            e.to_string().starts_with("density:") && e.message.contains(">= 0"),
            "{e}"
        );
        let zero = |_p: &[[f64; 3]], v: &mut [f64]| {
            v.fill(0.0);
            Ok(())
        };
        let e = density_mass_properties(zero, [[0.0, 1.0]; 3], &o).unwrap_err();
        assert!(e.message.contains("zero mass"), "{e}");
    }
}
