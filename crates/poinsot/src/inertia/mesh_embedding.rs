//! Is a closed, consistently oriented triangle mesh the boundary of a solid? The two checks
//! that the edge topology cannot make (see [`crate::inertia::mesh`]):
//!
//! 1. **No self-intersection.** No two faces meet except in the vertex or edge they share
//!    by index. Broad phase: the non-degenerate faces, sorted along a Morton curve (one
//!    linear pass for boxes and keys, a three-pass radix sort), are grouped in leaves of
//!    [`LEAF`] consecutive faces under a complete binary hierarchy of `f32` boxes (a linear
//!    bounding-volume hierarchy, built bottom-up in parallel); a parallel self-join of the
//!    hierarchy yields the pairs of leaves whose boxes overlap, and within them the pairs of
//!    faces whose boxes overlap (within two leaves, only the faces that meet the common part
//!    of the leaves' boxes). A leaf stores its boxes coordinate by coordinate, so that one box
//!    is compared with all 32 of a leaf in a few vector instructions (AVX2 where the CPU has
//!    it, by [`crate::simd::dispatch`]), giving a bit mask of the candidates.
//!    Most pairs whose boxes meet are neighbours sharing a vertex (7.9 M pairs for a
//!    1.3 M-face sphere, against 49,680 that share none). They are skipped topologically when the **star** of a shared vertex
//!    (the faces around it) is proved embedded, exactly ([`star_embedded`]): along one axis
//!    every face of the star projects with the same orientation and the fan of their wedges
//!    winds once around the vertex, so two faces of the star meet only in the vertex or in
//!    the edge they share. A star that fails (a fold, a pinch, a fan winding twice, a face of
//!    zero area) leaves its pairs to the narrow phase, which handles faces sharing a vertex
//!    or an edge exactly as any others.
//!    Before all that, a mesh of one component is tried as **star-shaped** about its centre
//!    of mass ([`star_shaped_about`]): when every face faces away from that
//!    point and every vertex's fan winds once about it, the radial projection onto a sphere
//!    is one to one (a covering of the sphere), which proves the surface embedded in one pass
//!    over the faces, without the hierarchy or any pair (a convex or blobby solid; a torus or
//!    a cup is left to the pairwise tests).
//!    Narrow phase: exact triangle–triangle tests on Shewchuk's adaptive orientation
//!    predicates (`robust`), so a crossing by one ulp is found and neighbours that only share
//!    a vertex or an edge are never flagged. Faces of exactly zero area (collinear corners)
//!    are left out: their points belong to their neighbours. Two faces that touch without
//!    sharing a vertex index (a cube resting on another, an apex on a face) count as
//!    intersecting, as in CGAL's `does_self_intersect`.
//! 2. **Winding number 0 or 1 everywhere.** Without intersections each edge-connected
//!    component is an embedded closed surface. A component of positive volume must lie where
//!    the other components' winding number is 0 (else its inside would be counted twice: two
//!    nested shells of the same winding), one of negative volume (a cavity) where it is 1. The
//!    winding number of the others at a vertex of the component is counted exactly along a ray
//!    in `+x` with the same predicates, the ray symbolically perturbed (Simulation of
//!    Simplicity) so that it never grazes an edge or a vertex.
//!
//! Every phase checks the stop flag it is given ([`crate::control::Cancel`]) every few
//! thousand faces or vertices, and the join at every subtree of `2^PAR_LEVEL` leaves, so that
//! Ctrl-C stops a call on millions of faces within milliseconds.
//!
//! The predicates are exact as long as their products neither overflow nor underflow: the
//! points of each test are scaled by a power of two (exact) when their extent is outside
//! `[2^-60, 2^60]`, which keeps them exact for features down to about `1e-90` of the size of
//! their neighbours, at any absolute scale.

use std::sync::atomic::{AtomicBool, AtomicU32, AtomicU64, Ordering};

use rayon::prelude::*;
use robust::{Coord, Coord3D};

use crate::control::Cancel;
use crate::error::Result;

/// A point.
type P3 = [f64; 3];

/// The vertices, as rows (one bounds check per point read, not three), with their box when
/// the caller has it.
#[derive(Clone, Copy)]
pub(crate) struct Points<'a> {
    v: &'a [[f64; 3]],
    /// The box of all the points, when known ([`Points::with_bounds`]).
    known: Option<Bounds>,
}

impl<'a> Points<'a> {
    /// The points of flat coordinates (`3·n`; a trailing partial row is left out).
    pub(crate) fn new(v: &'a [f64]) -> Self {
        Self {
            v: v.as_chunks::<3>().0,
            known: None,
        }
    }

    /// [`Points::new`] with the box of all the points, `bounds` (the caller's, folded in a
    /// pass it made anyway: `mesh::checked_arrays`), so that [`Points::bounds`] makes no pass
    /// over the points.
    pub(crate) fn with_bounds(v: &'a [f64], bounds: Bounds) -> Self {
        Self {
            known: Some(bounds),
            ..Self::new(v)
        }
    }

    /// The box of all the points: the known one, else a parallel pass over them.
    pub(crate) fn bounds(&self) -> Bounds {
        self.known.unwrap_or_else(|| {
            self.v
                .par_chunks(FACE_CHUNK)
                .map(|c| Bounds::of(c.iter().copied()))
                .reduce(|| Bounds::EMPTY, Bounds::union)
        })
    }

    /// Vertex `i`.
    #[inline]
    pub(crate) fn point(&self, i: u32) -> P3 {
        self.p(i)
    }

    #[inline]
    fn p(&self, i: u32) -> P3 {
        self.v[i as usize]
    }

    #[inline]
    fn tri(&self, t: &[u32; 3]) -> [P3; 3] {
        [self.p(t[0]), self.p(t[1]), self.p(t[2])]
    }
}

// ---------------------------------------------------------------------------------------------
// Exact predicates.

#[inline]
fn c3(p: P3) -> Coord3D<f64> {
    Coord3D {
        x: p[0],
        y: p[1],
        z: p[2],
    }
}

#[inline]
fn sign(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

/// The sign of `det[b − a, c − a, d − a]`: `+1` when `d` is on the side of the normal
/// `(b − a) × (c − a)`, exactly.
#[inline]
fn o3(a: P3, b: P3, c: P3, d: P3) -> i8 {
    // robust::orient3d is positive when d is below (opposite the normal).
    -sign(robust::orient3d(c3(a), c3(b), c3(c), c3(d)))
}

/// The plane of a triangle for the float filters of [`o3_plane`] and [`off_plane`]: its first
/// corner `a`, the normal `n = (t₁ − a) × (t₂ − a)` and the permanent `na` of that product
/// (the sums of the absolute values of its terms).
struct Plane {
    a: P3,
    n: P3,
    na: P3,
}

impl Plane {
    #[inline]
    fn of(t: &[P3; 3]) -> Self {
        let a = t[0];
        let u = [t[1][0] - a[0], t[1][1] - a[1], t[1][2] - a[2]];
        let w = [t[2][0] - a[0], t[2][1] - a[1], t[2][2] - a[2]];
        let n = [
            u[1] * w[2] - u[2] * w[1],
            u[2] * w[0] - u[0] * w[2],
            u[0] * w[1] - u[1] * w[0],
        ];
        let na = [
            (u[1] * w[2]).abs() + (u[2] * w[1]).abs(),
            (u[2] * w[0]).abs() + (u[0] * w[2]).abs(),
            (u[0] * w[1]).abs() + (u[1] * w[0]).abs(),
        ];
        Self { a, n, na }
    }

    /// The float orientation determinant `n·(d − a)` of `d` against this plane, and its
    /// permanent (the bound the filter's error is relative to).
    #[inline]
    fn det(&self, d: P3) -> (f64, f64) {
        let (a, n, na) = (self.a, self.n, self.na);
        let v = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
        let det = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
        let perm = na[0] * v[0].abs() + na[1] * v[1].abs() + na[2] * v[2].abs();
        (det, perm)
    }
}

/// [`o3`]`(t[0], t[1], t[2], d)` for each `d`, with the plane of `t` computed once: a float
/// evaluation whose sign is certain beyond Shewchuk's error bound for this computation
/// (`(7 + 56ε) ε` times the permanent; 2e-15 here), else the exact predicate. For points of
/// extent in `[2^-60, 2^60]` (no overflow or underflow), as the callers ensure.
#[inline]
fn o3_plane<const N: usize>(t: &[P3; 3], ds: [P3; N]) -> [i8; N] {
    let plane = Plane::of(t);
    ds.map(|d| {
        let (det, perm) = plane.det(d);
        if det.abs() > O3_FILTER * perm {
            sign(det)
        } else {
            o3(t[0], t[1], t[2], d)
        }
    })
}

/// The relative error bound of the float filter of [`o3_plane`] (Shewchuk's o3derrboundA,
/// `(7 + 56ε) ε ≈ 1.554e-15`, rounded up).
const O3_FILTER: f64 = 2e-15;

/// The projection dropping axis `k` (cyclic, so orientations are the sign of the normal's `k`
/// component).
#[inline]
fn proj(p: P3, k: u8) -> Coord<f64> {
    match k {
        0 => Coord { x: p[1], y: p[2] },
        1 => Coord { x: p[2], y: p[0] },
        _ => Coord { x: p[0], y: p[1] },
    }
}

/// The sign of the 2-D orientation of `a, b, c` projected along axis `k`, exactly.
#[inline]
fn o2(a: P3, b: P3, c: P3, k: u8) -> i8 {
    sign(robust::orient2d(proj(a, k), proj(b, k), proj(c, k)))
}

/// The smaller of two numbers that are not NaN (one comparison and a select: `f64::min`'s
/// NaN handling cost a tenth of the face pass and the star proofs).
#[inline(always)]
fn min2(a: f64, b: f64) -> f64 {
    if b < a {
        b
    } else {
        a
    }
}

/// The larger of two numbers that are not NaN ([`min2`]).
#[inline(always)]
fn max2(a: f64, b: f64) -> f64 {
    if b > a {
        b
    } else {
        a
    }
}

/// The box of points (`lo`, `hi` per axis), for finite coordinates: the one fold of the vertex
/// boxes (the Morton grid of [`Index::new`], each component's centre in `mesh::integrate_parts`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Bounds {
    /// The least coordinate on each axis.
    pub(crate) lo: [f64; 3],
    /// The greatest coordinate on each axis.
    pub(crate) hi: [f64; 3],
}

impl Bounds {
    /// The box of nothing (the identity of [`Bounds::union`]).
    pub(crate) const EMPTY: Self = Self {
        lo: [f64::INFINITY; 3],
        hi: [f64::NEG_INFINITY; 3],
    };

    /// The box of `points`.
    pub(crate) fn of(points: impl IntoIterator<Item = [f64; 3]>) -> Self {
        Self::EMPTY.with(points)
    }

    /// The box of these and `points` (one comparison per coordinate and side: no box of the
    /// points alone to unite).
    #[inline]
    pub(crate) fn with(self, points: impl IntoIterator<Item = [f64; 3]>) -> Self {
        points.into_iter().fold(self, |mut b, p| {
            for (k, &x) in p.iter().enumerate() {
                b.lo[k] = min2(b.lo[k], x);
                b.hi[k] = max2(b.hi[k], x);
            }
            b
        })
    }

    /// The box of both.
    pub(crate) fn union(self, o: Self) -> Self {
        Self {
            lo: [0, 1, 2].map(|k| min2(self.lo[k], o.lo[k])),
            hi: [0, 1, 2].map(|k| max2(self.hi[k], o.hi[k])),
        }
    }
}

/// The extent of `pts` (the largest side of their box) is in `[2^-60, 2^60]`, where the
/// predicates' products cannot overflow or underflow.
#[inline]
fn well_scaled(extent: f64) -> bool {
    (EXTENT_LO..=EXTENT_HI).contains(&extent)
}

const EXTENT_LO: f64 = 8.673_617_379_884_035e-19; // 2^-60
const EXTENT_HI: f64 = 1.152_921_504_606_847e18; // 2^60

/// Scales `pts` by a power of two (exact) so that their extent is in `[1, 2)` when it is
/// outside `[2^-60, 2^60]` (halves first: no overflow near ±1.8e308).
fn fit(pts: &mut [P3]) {
    let mut half = 0.0f64;
    for k in 0..3 {
        let lo = pts.iter().fold(f64::INFINITY, |m, p| m.min(p[k]));
        let hi = pts.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p[k]));
        half = half.max(0.5 * hi - 0.5 * lo);
    }
    if half == 0.0 || well_scaled(2.0 * half) {
        return;
    }
    let e = crate::inertia::scaling::exponent(half) + 1;
    for p in pts.iter_mut() {
        *p = p.map(|x| crate::inertia::scaling::ldexp(x, -e));
    }
}

/// The axis to drop for 2-D tests in the plane of the triangle (one along which its normal has
/// a non-zero component, preferably the largest), or `None` for a triangle of zero area.
fn drop_axis(t: &[P3; 3]) -> Option<u8> {
    let mut t = *t;
    let extent = (0..3).fold(0.0f64, |m, k| {
        m.max(t[0][k].max(t[1][k]).max(t[2][k]) - t[0][k].min(t[1][k]).min(t[2][k]))
    });
    if !well_scaled(extent) {
        fit(&mut t);
    }
    let [a, b, c] = t;
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        (u[1] * w[2] - u[2] * w[1]).abs(),
        (u[2] * w[0] - u[0] * w[2]).abs(),
        (u[0] * w[1] - u[1] * w[0]).abs(),
    ];
    let best = if n[0] >= n[1] && n[0] >= n[2] {
        0
    } else if n[1] >= n[2] {
        1
    } else {
        2
    };
    if o2(a, b, c, best) != 0 {
        return Some(best);
    }
    (0u8..3).find(|&k| k != best && o2(a, b, c, k) != 0)
}

/// `p` in the closed triangle `t` (all coplanar), in the projection along `k`.
fn in_triangle2(p: P3, t: &[P3; 3], k: u8) -> bool {
    let s = o2(t[0], t[1], t[2], k);
    (0..3).all(|i| {
        let o = o2(t[i], t[(i + 1) % 3], p, k);
        o == 0 || o == s
    })
}

/// `c` on the closed segment `ab`, given that the three are collinear.
fn on_segment(a: P3, b: P3, c: P3) -> bool {
    (0..3).all(|i| a[i].min(b[i]) <= c[i] && c[i] <= a[i].max(b[i]))
}

/// The closed segments `ab` and `cd` (coplanar) meet, in the projection along `k`.
fn segments_meet2(a: P3, b: P3, c: P3, d: P3, k: u8) -> bool {
    let (d1, d2) = (o2(a, b, c, k), o2(a, b, d, k));
    let (d3, d4) = (o2(c, d, a, k), o2(c, d, b, k));
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && on_segment(a, b, c))
        || (d2 == 0 && on_segment(a, b, d))
        || (d3 == 0 && on_segment(c, d, a))
        || (d4 == 0 && on_segment(c, d, b))
}

/// The closed coplanar triangles `p` and `q` meet (projection along `k`).
fn triangles_meet2(p: &[P3; 3], q: &[P3; 3], k: u8) -> bool {
    for i in 0..3 {
        for j in 0..3 {
            if segments_meet2(p[i], p[(i + 1) % 3], q[j], q[(j + 1) % 3], k) {
                return true;
            }
        }
    }
    in_triangle2(p[0], q, k) || in_triangle2(q[0], p, k)
}

/// The closed segment `st` meets the closed triangle `t` (whose drop axis is `k`).
fn segment_meets_triangle(s: P3, e: P3, t: &[P3; 3], k: u8) -> bool {
    let (os, oe) = (o3(t[0], t[1], t[2], s), o3(t[0], t[1], t[2], e));
    if os == oe && os != 0 {
        return false;
    }
    if os == 0 && oe == 0 {
        // In the plane of the triangle.
        return in_triangle2(s, t, k)
            || in_triangle2(e, t, k)
            || (0..3).any(|i| segments_meet2(s, e, t[i], t[(i + 1) % 3], k));
    }
    // The line through s, e crosses the plane at one point of the segment: inside the closed
    // triangle iff the three signed volumes agree (or vanish).
    let v = [
        o3(s, e, t[0], t[1]),
        o3(s, e, t[1], t[2]),
        o3(s, e, t[2], t[0]),
    ];
    !(v.contains(&1) && v.contains(&-1))
}

/// `x` in the closed wedge at `v` spanned by `p1, p2` (all coplanar; projection along `k`).
fn in_wedge2(v: P3, p1: P3, p2: P3, x: P3, k: u8) -> bool {
    let s = o2(v, p1, p2, k);
    let (a, b) = (o2(v, p1, x, k), o2(v, x, p2, k));
    (a == 0 || a == s) && (b == 0 || b == s)
}

/// Do the faces `p` and `q` (indices `pi`, `qi`, drop axes `kp`, `kq`) meet anywhere but in the
/// vertices they share by index?
fn faces_cross(p: &[P3; 3], q: &[P3; 3], pi: &[u32; 3], qi: &[u32; 3], kp: u8, kq: u8) -> bool {
    let mut shared = [(0usize, 0usize); 3];
    let mut n = 0;
    for (i, a) in pi.iter().enumerate() {
        for (j, b) in qi.iter().enumerate() {
            if a == b && n < 3 {
                shared[n] = (i, j);
                n += 1;
            }
        }
    }
    let shared = &shared[..n];
    // Cheap exits first, in the projection along p's drop axis (injective on p's plane, so
    // a point where the faces meet projects to a point of both projections; orient2d is fast
    // unless three projected points are collinear): flat regions, where the exact
    // orient3d would have to prove a zero, are settled here.
    match n {
        0 if separated2(p, q, kp) => return false,
        1 => {
            let (i, j) = shared[0];
            let (v, p1, p2) = (p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
            let (q1, q2) = (q[(j + 1) % 3], q[(j + 2) % 3]);
            let s = o2(v, p1, p2, kp);
            // Both q1, q2 strictly beyond the line v–p1, or strictly beyond the line v–p2: the
            // wedges at v touch only at v.
            if (o2(v, p1, q1, kp) == -s && o2(v, p1, q2, kp) == -s)
                || (o2(v, p2, q1, kp) == s && o2(v, p2, q2, kp) == s)
            {
                return false;
            }
        }
        2 => {
            // The third vertices strictly on opposite sides of the shared edge: not folded.
            let pk = (0..3)
                .find(|&i| !shared.iter().any(|s| s.0 == i))
                .unwrap_or(0);
            let qk = (0..3)
                .find(|&j| !shared.iter().any(|s| s.1 == j))
                .unwrap_or(0);
            let (a, b) = (p[shared[0].0], p[shared[1].0]);
            let (sp, sq) = (o2(a, b, p[pk], kp), o2(a, b, q[qk], kp));
            if sp != 0 && sq == -sp {
                return false;
            }
        }
        _ => {}
    }
    match n {
        0 => triangles_meet(p, q, kp, kq),
        1 => {
            // Rotate both so that the shared vertex comes first (windings kept).
            let (i, j) = shared[0];
            let p = [p[i], p[(i + 1) % 3], p[(i + 2) % 3]];
            let q = [q[j], q[(j + 1) % 3], q[(j + 2) % 3]];
            meet_beyond_vertex(&p, &q, kp, kq)
        }
        2 => {
            // The shared edge; p's third vertex and q's: they overlap only if folded flat
            // onto each other (coplanar, on the same side of the edge).
            let pk = (0..3)
                .find(|&i| !shared.iter().any(|s| s.0 == i))
                .unwrap_or(0);
            let qk = (0..3)
                .find(|&j| !shared.iter().any(|s| s.1 == j))
                .unwrap_or(0);
            let (a, b) = (p[shared[0].0], p[shared[1].0]);
            o3_plane(&[a, b, p[pk]], [q[qk]])[0] == 0 && o2(a, b, p[pk], kp) == o2(a, b, q[qk], kp)
        }
        // The same three vertices: the two sides of a flat, closed sliver of zero volume.
        _ => false,
    }
}

/// The projections along `k` (`p`'s drop axis) of `p` and `q` are strictly separated by a
/// line through an edge of one of them: then the triangles cannot meet.
fn separated2(p: &[P3; 3], q: &[P3; 3], k: u8) -> bool {
    let sp = o2(p[0], p[1], p[2], k);
    for i in 0..3 {
        let (a, b) = (p[i], p[(i + 1) % 3]);
        if q.iter().all(|x| o2(a, b, *x, k) == -sp) {
            return true;
        }
    }
    let sq = o2(q[0], q[1], q[2], k);
    if sq != 0 {
        for j in 0..3 {
            let (a, b) = (q[j], q[(j + 1) % 3]);
            if p.iter().all(|x| o2(a, b, *x, k) == -sq) {
                return true;
            }
        }
    }
    false
}

/// Closed triangles with no vertex in common meet.
fn triangles_meet(p: &[P3; 3], q: &[P3; 3], kp: u8, kq: u8) -> bool {
    let dq = o3_plane(p, *q);
    if dq[0] != 0 && dq[0] == dq[1] && dq[1] == dq[2] {
        return false;
    }
    if dq == [0, 0, 0] {
        return triangles_meet2(p, q, kp);
    }
    let dp = o3_plane(q, *p);
    if dp[0] != 0 && dp[0] == dp[1] && dp[1] == dp[2] {
        return false;
    }
    // Not coplanar: the intersection with the common line has an end on an edge of one.
    (0..3).any(|i| segment_meets_triangle(p[i], p[(i + 1) % 3], q, kq))
        || (0..3).any(|j| segment_meets_triangle(q[j], q[(j + 1) % 3], p, kp))
}

/// Triangles `p = (v, p1, p2)` and `q = (v, q1, q2)` sharing the vertex `v` meet elsewhere.
fn meet_beyond_vertex(p: &[P3; 3], q: &[P3; 3], kp: u8, kq: u8) -> bool {
    let v = p[0];
    let dq = o3_plane(p, [q[1], q[2]]);
    if dq[0] != 0 && dq[0] == dq[1] {
        return false;
    }
    let dp = o3_plane(q, [p[1], p[2]]);
    if dp[0] != 0 && dp[0] == dp[1] {
        return false;
    }
    if dq == [0, 0] {
        // Coplanar: the wedges at v overlap beyond v iff one holds an edge ray of the other.
        return in_wedge2(v, p[1], p[2], q[1], kp)
            || in_wedge2(v, p[1], p[2], q[2], kp)
            || in_wedge2(v, q[1], q[2], p[1], kp)
            || in_wedge2(v, q[1], q[2], p[2], kp);
    }
    // The intersection is a segment from v; its far end lies on the opposite edge of one of
    // them, or it runs along an edge from v that lies in the other's plane.
    segment_meets_triangle(p[1], p[2], q, kq)
        || segment_meets_triangle(q[1], q[2], p, kp)
        || (dq[0] == 0 && in_wedge2(v, p[1], p[2], q[1], kp))
        || (dq[1] == 0 && in_wedge2(v, p[1], p[2], q[2], kp))
        || (dp[0] == 0 && in_wedge2(v, q[1], q[2], p[1], kq))
        || (dp[1] == 0 && in_wedge2(v, q[1], q[2], p[2], kq))
}

// ---------------------------------------------------------------------------------------------
// Broad phase.

/// An axis-aligned box in `f32`, rounded outward from the `f64` corners it was made of (so it
/// contains their exact box), closed: boxes that touch meet.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Box3 {
    lo: [f32; 3],
    hi: [f32; 3],
}

impl Box3 {
    /// The box of nothing (the identity of [`Box3::merged`]).
    const EMPTY: Self = Self {
        lo: [f32::INFINITY; 3],
        hi: [f32::NEG_INFINITY; 3],
    };

    /// The closed boxes have a point in common (no branches: the six comparisons are cheaper
    /// than mispredicted jumps in the hot loops of the join).
    #[inline]
    fn meets(&self, o: &Self) -> bool {
        (self.lo[0] <= o.hi[0])
            & (o.lo[0] <= self.hi[0])
            & (self.lo[1] <= o.hi[1])
            & (o.lo[1] <= self.hi[1])
            & (self.lo[2] <= o.hi[2])
            & (o.lo[2] <= self.hi[2])
    }

    #[inline]
    fn merged(&self, o: &Self) -> Self {
        let (a, b) = (self, o);
        Self {
            lo: [
                a.lo[0].min(b.lo[0]),
                a.lo[1].min(b.lo[1]),
                a.lo[2].min(b.lo[2]),
            ],
            hi: [
                a.hi[0].max(b.hi[0]),
                a.hi[1].max(b.hi[1]),
                a.hi[2].max(b.hi[2]),
            ],
        }
    }

    /// The ray `{p + t e_x, t ≥ 0}` meets the closed box (so that the symbolically perturbed
    /// ray of [`Index::winding`] is covered too).
    #[inline]
    fn meets_ray(&self, p: P3) -> bool {
        f64::from(self.hi[0]) >= p[0]
            && f64::from(self.lo[1]) <= p[1]
            && p[1] <= f64::from(self.hi[1])
            && f64::from(self.lo[2]) <= p[2]
            && p[2] <= f64::from(self.hi[2])
    }
}

/// A box rounded outward to `f32` (conservative: it contains the exact box). Written out per
/// axis: the array `map` here was not inlined (a profile showed it as its own function).
#[inline]
fn box32(t: &[P3; 3]) -> Box3 {
    let lo = |k: usize| down32(min2(min2(t[0][k], t[1][k]), t[2][k]));
    let hi = |k: usize| up32(max2(max2(t[0][k], t[1][k]), t[2][k]));
    Box3 {
        lo: [lo(0), lo(1), lo(2)],
        hi: [hi(0), hi(1), hi(2)],
    }
}

/// The largest `f32` at most `x` (not NaN): the rounded value, or its bits moved one step down
/// when the rounding went up. Both candidates are computed and one selected (no call, no
/// data-dependent jump: the face pass of [`Index::new`] took 99–128 ms instead of 150 ms on
/// one thread for 1.3 M faces).
#[inline]
fn down32(x: f64) -> f32 {
    let y = x as f32;
    let b = y.to_bits();
    // One step towards −∞: the bits of a positive number (or +∞) decrease, of a negative one
    // increase; below +0 and −0 comes the negative subnormal −2^-149.
    let below = if y == 0.0 {
        0x8000_0001
    } else if b >> 31 == 0 {
        b.wrapping_sub(1)
    } else {
        b.wrapping_add(1)
    };
    if f64::from(y) > x {
        f32::from_bits(below)
    } else {
        y
    }
}

/// The smallest `f32` at least `x` (not NaN), as [`down32`].
#[inline]
fn up32(x: f64) -> f32 {
    -down32(-x)
}

/// The next `f32` above `y` (`f32::next_up`, which needs Rust 1.86): the tests' reference for
/// [`down32`] and [`up32`].
#[cfg(test)]
fn step_up(y: f32) -> f32 {
    if y.is_nan() || y == f32::INFINITY {
        y
    } else if y == 0.0 {
        f32::from_bits(1)
    } else if y > 0.0 {
        f32::from_bits(y.to_bits() + 1)
    } else {
        f32::from_bits(y.to_bits() - 1)
    }
}

/// Spreads the low 21 bits of `x` to every third bit (Morton interleaving).
fn spread(x: u64) -> u64 {
    let mut x = x & 0x1f_ffff;
    x = (x | x << 32) & 0x1f_0000_0000_ffff;
    x = (x | x << 16) & 0x1f_0000_ff00_00ff;
    x = (x | x << 8) & 0x100f_00f0_0f00_f00f;
    x = (x | x << 4) & 0x10c3_0c30_c30c_30c3;
    x = (x | x << 2) & 0x1249_2492_4924_9249;
    x
}

/// The drop axis of a face, or `u8::MAX` when it takes no part (zero area, or left out).
const NO_AXIS: u8 = u8::MAX;

/// A face that takes part, at its position in Morton order (16 bytes: the join reads these
/// for every pair of boxes that meet, and the corners only for the pairs it must test).
#[derive(Clone, Copy)]
struct Face {
    indices: [u32; 3],
    /// The drop axis for 2-D tests in its plane ([`drop_axis`]).
    axis: u8,
    /// Bit `i` set: the star of corner `i` is proved embedded ([`star_embedded`]).
    proved: u8,
}

/// Every coordinate within [`FAST_COORD_MAX`]: the float filters of [`off_plane`] apply.
#[inline]
fn fast(t: &[P3; 3]) -> bool {
    t.iter()
        .all(|c| c.iter().all(|x| x.abs() <= FAST_COORD_MAX))
}

/// The boxes of the faces of one leaf, coordinate by coordinate (`lo[k][i]`, `hi[k][i]`: face
/// `i` of the leaf), so that one box is compared with all of a leaf's in a few vector
/// instructions ([`LeafBoxes::meeting`]). The lanes past the end of the last leaf hold empty
/// boxes and are masked out by [`Index::lanes`].
#[derive(Clone, Copy)]
struct LeafBoxes {
    lo: [[f32; LEAF]; 3],
    hi: [[f32; LEAF]; 3],
}

impl LeafBoxes {
    /// Box `i` of the leaf.
    #[inline(always)]
    fn get(&self, i: usize) -> Box3 {
        Box3 {
            lo: [self.lo[0][i], self.lo[1][i], self.lo[2][i]],
            hi: [self.hi[0][i], self.hi[1][i], self.hi[2][i]],
        }
    }

    /// Bit `i` set: box `i` of the leaf meets `b` ([`Box3::meets`], lane by lane; a loop the
    /// compiler turns into vector comparisons, of the width [`LeafWork`] dispatches to).
    #[inline(always)]
    fn meeting(&self, b: &Box3) -> u32 {
        let mut hit = [false; LEAF];
        for (i, h) in hit.iter_mut().enumerate() {
            *h = (self.lo[0][i] <= b.hi[0])
                & (b.lo[0] <= self.hi[0][i])
                & (self.lo[1][i] <= b.hi[1])
                & (b.lo[1] <= self.hi[1][i])
                & (self.lo[2][i] <= b.hi[2])
                & (b.lo[2] <= self.hi[2][i]);
        }
        hit.iter()
            .enumerate()
            .fold(0u32, |m, (i, &h)| m | u32::from(h) << i)
    }
}

/// The set bits of `m`, lowest first.
#[inline(always)]
fn bits(mut m: u32) -> impl Iterator<Item = usize> {
    std::iter::from_fn(move || {
        (m != 0).then(|| {
            let i = m.trailing_zeros() as usize;
            m &= m - 1;
            i
        })
    })
}

/// The faces that take part, in Morton order, with their boxes, and a bounding-volume
/// hierarchy over them: leaves of [`LEAF`] consecutive faces, and above them a complete binary
/// tree in Morton order (implicit: node `i` of level `l` has the children `2i` and `2i + 1`
/// of level `l − 1`), so that building it is one sort and a few linear passes.
pub(crate) struct Index<'a> {
    /// The vertices.
    pts: Points<'a>,
    /// Face indices in Morton order (faces that take part only).
    order: Vec<u32>,
    /// The boxes of the faces in Morton order, by leaf: position `k` is lane `k % LEAF` of
    /// `leaves[k / LEAF]`.
    leaves: Vec<LeafBoxes>,
    /// Vertex indices and drop axis of `order[k]`.
    faces: Vec<Face>,
    /// Whether face `f` takes part (non-degenerate), by face index.
    used: Vec<bool>,
    /// `levels[0][i]`: the box of leaf `i` (faces `LEAF·i .. LEAF·(i + 1)`); `levels[l][i]`:
    /// the union of `levels[l − 1][2i]` and `levels[l − 1][2i + 1]`; the last level is the root.
    levels: Vec<Vec<Box3>>,
    /// Every vertex is within [`FAST_COORD_MAX`] (from the vertices' box): the float filters
    /// of the narrow phase apply to every pair without checking its coordinates.
    inside: bool,
}

/// Faces per leaf of the tree (consecutive in Morton order), one bit each in a `u32` mask.
/// 32 rather than 8: a quarter of the nodes to traverse (1.7 M pairs of nodes visited instead
/// of 6.7 M on a 1.3 M-face sphere) for the same 7.9 M pairs of faces whose boxes meet.
const LEAF: usize = 32;

/// Subtrees from this level up (`2^PAR_LEVEL` leaves and more) are joined in parallel, and
/// check the stop flag.
const PAR_LEVEL: usize = 5;

/// Morton bits per axis of the sort keys (a grid of `2^30` cells over the vertices' box;
/// faces in one cell keep their index order).
const MORTON_BITS: u32 = 10;

/// Faces per parallel task of the face pass (and per check of the stop flag).
const FACE_CHUNK: usize = 4096;

/// The pairs within one leaf `(i, None)` or between two `(i, Some(j))`, run by
/// [`crate::simd::dispatch`] so that the box comparisons of [`LeafBoxes::meeting`] use the
/// widest vector instructions the CPU has (8 lanes of AVX2 instead of SSE2's 4).
struct LeafWork<'i, 'a> {
    index: &'i Index<'a>,
    leaves: (usize, Option<usize>),
}

impl crate::simd::WithSimd for LeafWork<'_, '_> {
    type Output = Found;

    #[inline(always)]
    fn with_simd<S: crate::simd::Simd>(self, _s: S) -> Found {
        match self.leaves {
            (i, None) => self.index.leaf_self(i),
            (i, Some(j)) => self.index.leaf_pair(i, j),
        }
    }
}

/// Intersecting pairs found: how many, and the first `(i, j)` (`i < j`) in index order.
#[derive(Clone, Copy, Default)]
struct Found {
    count: u64,
    first: Option<(u32, u32)>,
}

impl Found {
    fn merge(self, o: Self) -> Self {
        Self {
            count: self.count + o.count,
            first: match (self.first, o.first) {
                (Some(a), Some(b)) => Some(a.min(b)),
                (a, None) => a,
                (None, b) => b,
            },
        }
    }
}

/// The drop axis of the face `p` ([`drop_axis`], `NO_AXIS` for zero area), deciding the usual
/// case by a float filter: when the face's extent is in `[2^-60, 2^60]` (so [`drop_axis`]
/// would not rescale it and computes the same float normal) and the largest component of the
/// normal is certainly non-zero, that component's axis is the one [`drop_axis`] returns.
fn face_axis(p: &[P3; 3]) -> u8 {
    let extent = (0..3).fold(0.0f64, |m, k| {
        max2(
            m,
            max2(max2(p[0][k], p[1][k]), p[2][k]) - min2(min2(p[0][k], p[1][k]), p[2][k]),
        )
    });
    if well_scaled(extent) {
        let [a, b, c] = *p;
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let n = [
            u[1] * w[2] - u[2] * w[1],
            u[2] * w[0] - u[0] * w[2],
            u[0] * w[1] - u[1] * w[0],
        ];
        let na = [
            (u[1] * w[2]).abs() + (u[2] * w[1]).abs(),
            (u[2] * w[0]).abs() + (u[0] * w[2]).abs(),
            (u[0] * w[1]).abs() + (u[1] * w[0]).abs(),
        ];
        let m = n.map(f64::abs);
        // The same choice as drop_axis, ties included.
        let best = if m[0] >= m[1] && m[0] >= m[2] {
            0
        } else if m[1] >= m[2] {
            1
        } else {
            2
        };
        if m[best] > O2_FILTER * na[best] + FILTER_SLACK {
            return best as u8;
        }
    }
    drop_axis(p).unwrap_or(NO_AXIS)
}

/// Sorts `keys` by their bits 32–62 (stable: keys equal there keep their order), by three
/// passes of a least-significant-digit radix sort of 11 bits; linear, on this thread.
fn radix_sort_high(keys: &mut Vec<u64>, cancel: &Cancel) -> Result<()> {
    const DIGIT: u32 = 11;
    const BUCKETS: usize = 1 << DIGIT;
    let mut count = vec![[0usize; BUCKETS]; 3];
    for k in keys.iter() {
        for (d, c) in count.iter_mut().enumerate() {
            c[((k >> (32 + DIGIT * d as u32)) as usize) & (BUCKETS - 1)] += 1;
        }
    }
    let mut tmp = vec![0u64; keys.len()];
    for (d, c) in count.iter_mut().enumerate() {
        cancel.check()?;
        let mut acc = 0;
        for x in c.iter_mut() {
            let n = *x;
            *x = acc;
            acc += n;
        }
        let shift = 32 + DIGIT * d as u32;
        for &k in keys.iter() {
            let b = ((k >> shift) as usize) & (BUCKETS - 1);
            tmp[c[b]] = k;
            c[b] += 1;
        }
        std::mem::swap(keys, &mut tmp);
    }
    Ok(())
}

impl<'a> Index<'a> {
    /// Builds the index of the faces `tris` (`skip[f]`: left out, e.g. a repeated index);
    /// stops with [`crate::control::interrupted`] once `cancel` is set.
    pub(crate) fn new(
        pts: Points<'a>,
        tris: &[[u32; 3]],
        skip: impl Fn(usize) -> bool + Sync,
        cancel: &Cancel,
    ) -> Result<Self> {
        // The box of the vertices, for the Morton keys (a far vertex that no face uses only
        // coarsens the order: the speed of the join, not its result).
        let Bounds { lo, hi } = pts.bounds();
        let cells = f64::from(1u32 << MORTON_BITS);
        let scale = [0, 1, 2].map(|k| {
            let span = hi[k] - lo[k];
            if span > 0.0 && (cells / span).is_finite() {
                cells / span
            } else {
                0.0
            }
        });
        // One pass: drop axis (exact degeneracy), box and sort key (Morton code of the first
        // corner, bit 62 set for a face that takes no part, the face in the low 32 bits).
        let mut per_face = vec![(NO_AXIS, Box3::EMPTY); tris.len()];
        let mut keys = vec![0u64; tris.len()];
        per_face
            .par_chunks_mut(FACE_CHUNK)
            .zip(keys.par_chunks_mut(FACE_CHUNK))
            .enumerate()
            .for_each(|(c, (out, key))| {
                if cancel.check().is_err() {
                    return;
                }
                let f0 = c * FACE_CHUNK;
                for (i, (o, k)) in out.iter_mut().zip(key.iter_mut()).enumerate() {
                    let f = f0 + i;
                    let t = &tris[f];
                    if skip(f) {
                        *k = 1 << 62 | f as u64;
                        continue;
                    }
                    let p = pts.tri(t);
                    let axis = face_axis(&p);
                    *o = (axis, box32(&p));
                    let q = |k: usize| {
                        // Saturating: NaN (no span) and overflow map into the grid.
                        ((p[0][k] - lo[k]) * scale[k]).clamp(0.0, cells - 1.0) as u64
                    };
                    let morton = spread(q(0)) | spread(q(1)) << 1 | spread(q(2)) << 2;
                    *k = u64::from(axis == NO_AXIS) << 62 | morton << 32 | f as u64;
                }
            });
        cancel.check()?;
        radix_sort_high(&mut keys, cancel)?;
        let taking_part = keys.partition_point(|k| k >> 62 == 0);
        let order: Vec<u32> = keys[..taking_part].par_iter().map(|&k| k as u32).collect();
        drop(keys);
        let used: Vec<bool> = per_face.par_iter().map(|(a, _)| *a != NO_AXIS).collect();
        let star = stars(pts, tris, &used, cancel)?;
        let faces: Vec<Face> = order
            .par_iter()
            .with_min_len(FACE_CHUNK)
            .map(|&f| {
                let indices = tris[f as usize];
                let proved = (0..3).fold(0u8, |m, i| m | u8::from(star[indices[i] as usize]) << i);
                Face {
                    indices,
                    axis: per_face[f as usize].0,
                    proved,
                }
            })
            .collect();
        let (leaves, leaf_boxes): (Vec<LeafBoxes>, Vec<Box3>) = order
            .par_chunks(LEAF)
            .map(|c| {
                let mut l = LeafBoxes {
                    lo: [[f32::INFINITY; LEAF]; 3],
                    hi: [[f32::NEG_INFINITY; LEAF]; 3],
                };
                let mut all = Box3::EMPTY;
                for (i, &f) in c.iter().enumerate() {
                    let b = per_face[f as usize].1;
                    for k in 0..3 {
                        l.lo[k][i] = b.lo[k];
                        l.hi[k][i] = b.hi[k];
                    }
                    all = all.merged(&b);
                }
                (l, all)
            })
            .unzip();
        let merge_all = |c: &[Box3]| c.iter().fold(Box3::EMPTY, |e, x| e.merged(x));
        let mut levels = vec![leaf_boxes];
        while levels[levels.len() - 1].len() > 1 {
            let next = levels[levels.len() - 1]
                .par_chunks(2)
                .with_min_len(1024)
                .map(merge_all)
                .collect();
            levels.push(next);
        }
        cancel.check()?;
        let inside = (0..3).all(|k| max2(lo[k].abs(), hi[k].abs()) <= FAST_COORD_MAX);
        Ok(Self {
            pts,
            order,
            leaves,
            faces,
            used,
            levels,
            inside,
        })
    }

    /// Pairs of faces that meet anywhere but in what they share by index: how many, and the
    /// first pair `(i, j)`, `i < j`; stops once `cancel` is set.
    pub(crate) fn intersections(&self, cancel: &Cancel) -> Result<(u64, Option<(u32, u32)>)> {
        if self.faces.is_empty() {
            return Ok((0, None));
        }
        let f = self.self_join(self.levels.len() - 1, 0, cancel);
        cancel.check()?;
        Ok((f.count, f.first))
    }

    /// The faces of leaf `i` (positions in Morton order).
    #[inline(always)]
    fn leaf(&self, i: usize) -> std::ops::Range<usize> {
        LEAF * i..(LEAF * (i + 1)).min(self.faces.len())
    }

    /// The lanes of leaf `i` that hold faces.
    #[inline(always)]
    fn lanes(&self, i: usize) -> u32 {
        let n = self.leaf(i).len();
        if n >= LEAF {
            u32::MAX
        } else {
            (1u32 << n) - 1
        }
    }

    /// The box of the face at Morton position `k`.
    #[inline]
    fn face_box(&self, k: usize) -> Box3 {
        self.leaves[k / LEAF].get(k % LEAF)
    }

    /// The children of node `i` of level `l > 0`: node `2i` of level `l − 1`, and `2i + 1`
    /// when it exists.
    #[inline]
    fn children(&self, l: usize, i: usize) -> (usize, Option<usize>) {
        let a = 2 * i;
        (a, (a + 1 < self.levels[l - 1].len()).then_some(a + 1))
    }

    /// The pairs within the subtree of node `i` of level `l` (nothing once `cancel` is set:
    /// the caller checks it).
    fn self_join(&self, l: usize, i: usize, cancel: &Cancel) -> Found {
        if l == 0 {
            return crate::simd::dispatch(LeafWork {
                index: self,
                leaves: (i, None),
            });
        }
        let (a, b) = self.children(l, i);
        let Some(b) = b else {
            return self.self_join(l - 1, a, cancel);
        };
        let (x, (y, z)) = if l >= PAR_LEVEL {
            if cancel.check().is_err() {
                return Found::default();
            }
            rayon::join(
                || self.self_join(l - 1, a, cancel),
                || {
                    rayon::join(
                        || self.self_join(l - 1, b, cancel),
                        || self.pair_join((l - 1, a), (l - 1, b), cancel),
                    )
                },
            )
        } else {
            (
                self.self_join(l - 1, a, cancel),
                (
                    self.self_join(l - 1, b, cancel),
                    self.pair_join((l - 1, a), (l - 1, b), cancel),
                ),
            )
        };
        x.merge(y).merge(z)
    }

    /// The pairs between the subtrees of two distinct nodes `(level, index)`.
    fn pair_join(
        &self,
        (la, ia): (usize, usize),
        (lb, ib): (usize, usize),
        cancel: &Cancel,
    ) -> Found {
        if !self.levels[la][ia].meets(&self.levels[lb][ib]) {
            return Found::default();
        }
        if la == 0 && lb == 0 {
            return crate::simd::dispatch(LeafWork {
                index: self,
                leaves: (ia, Some(ib)),
            });
        }
        // Open the higher node; its children against the other.
        let (split_a, l) = if la >= lb { (true, la) } else { (false, lb) };
        let (c0, c1) = self.children(l, if split_a { ia } else { ib });
        let with = |c: usize| {
            if split_a {
                self.pair_join((l - 1, c), (lb, ib), cancel)
            } else {
                self.pair_join((la, ia), (l - 1, c), cancel)
            }
        };
        match c1 {
            None => with(c0),
            Some(c1) if l >= PAR_LEVEL => {
                if cancel.check().is_err() {
                    return Found::default();
                }
                let (x, y) = rayon::join(|| with(c0), || with(c1));
                x.merge(y)
            }
            Some(c1) => with(c0).merge(with(c1)),
        }
    }

    /// The pairs within leaf `i`: each face's box against the boxes after it, a leaf at once.
    #[inline(always)]
    fn leaf_self(&self, i: usize) -> Found {
        let mut f = Found::default();
        let (base, boxes, lanes) = (LEAF * i, &self.leaves[i], self.lanes(i));
        for a in bits(lanes) {
            let later = lanes & u32::MAX.checked_shl(a as u32 + 1).unwrap_or(0);
            let key = self.proved_corners(base + a);
            for b in bits(boxes.meeting(&boxes.get(a)) & later) {
                if !self.has_any(base + b, key) {
                    self.narrow(base + a, base + b, &mut f);
                }
            }
        }
        f
    }

    /// The pairs between two leaves whose boxes meet: only faces that meet the common part
    /// of the two leaves' boxes can meet a face of the other leaf.
    #[inline(always)]
    fn leaf_pair(&self, i: usize, j: usize) -> Found {
        let mut f = Found::default();
        let (bi, bj) = (self.levels[0][i], self.levels[0][j]);
        let common = Box3 {
            lo: [0, 1, 2].map(|k| bi.lo[k].max(bj.lo[k])),
            hi: [0, 1, 2].map(|k| bi.hi[k].min(bj.hi[k])),
        };
        let (li, lj) = (&self.leaves[i], &self.leaves[j]);
        let near_j = lj.meeting(&common) & self.lanes(j);
        if near_j == 0 {
            return f;
        }
        let near_i = li.meeting(&common) & self.lanes(i);
        // One leaf's near boxes against the other's, from the side with fewer.
        if near_i.count_ones() <= near_j.count_ones() {
            for a in bits(near_i) {
                let key = self.proved_corners(LEAF * i + a);
                for b in bits(lj.meeting(&li.get(a)) & near_j) {
                    if !self.has_any(LEAF * j + b, key) {
                        self.narrow(LEAF * i + a, LEAF * j + b, &mut f);
                    }
                }
            }
        } else {
            for b in bits(near_j) {
                let key = self.proved_corners(LEAF * j + b);
                for a in bits(li.meeting(&lj.get(b)) & near_i) {
                    if !self.has_any(LEAF * i + a, key) {
                        self.narrow(LEAF * i + a, LEAF * j + b, &mut f);
                    }
                }
            }
        }
        f
    }

    /// The corners of the face at Morton position `k` whose stars are proved embedded, and
    /// [`NOT_USED`] (no vertex index: indices are below [`super::mesh::MAX_VERTICES`]) for the
    /// others: the key of [`Index::has_any`], made once per face of an outer loop.
    #[inline(always)]
    fn proved_corners(&self, k: usize) -> [u32; 3] {
        let f = &self.faces[k];
        [0, 1, 2].map(|i| {
            if f.proved & (1 << i) != 0 {
                f.indices[i]
            } else {
                NOT_USED
            }
        })
    }

    /// The face at Morton position `k` has a corner in `key` ([`Index::proved_corners`] of
    /// another face): both faces are in the star of a shared vertex that is proved embedded,
    /// so they meet only in what they share, and the pair is skipped before [`Index::narrow`]
    /// (nine comparisons without branches; the neighbour pairs are most of the pairs whose
    /// boxes meet: 6.4 per face on a torus).
    #[inline(always)]
    fn has_any(&self, k: usize, key: [u32; 3]) -> bool {
        let q = self.faces[k].indices;
        let is = |x: u32| (x == key[0]) | (x == key[1]) | (x == key[2]);
        is(q[0]) | is(q[1]) | is(q[2])
    }

    /// Tests the faces at Morton positions `a` and `b`, whose boxes meet and that share no
    /// vertex whose star is proved embedded (the callers skip those pairs by
    /// [`Index::has_any`]): first the float filter of [`off_plane`] (the usual answer for near
    /// faces of a smooth surface: one face lies strictly on one side of the other's plane, but
    /// for the vertices they share), then the exact tests.
    #[inline]
    fn narrow(&self, a: usize, b: usize, found: &mut Found) {
        let (fp, fq) = (&self.faces[a], &self.faces[b]);
        let (pi, qi) = (&fp.indices, &fq.indices);
        // The corners of `t` that `o` has too (bit i: corner i), without branches.
        let shared = |t: &[u32; 3], o: &[u32; 3]| {
            let has = |x: u32| u8::from(x == o[0]) | u8::from(x == o[1]) | u8::from(x == o[2]);
            has(t[0]) | has(t[1]) << 1 | has(t[2]) << 2
        };
        let sp = shared(pi, qi);
        let sq = shared(qi, pi);
        let (p, q) = (self.pts.tri(pi), self.pts.tri(qi));
        if (self.inside || (fast(&p) && fast(&q)))
            && (off_plane(&p, &q, sq) || off_plane(&q, &p, sp))
        {
            return;
        }
        self.exact(a, b, found);
    }

    /// The exact test of the faces at Morton positions `a` and `b` ([`faces_cross`]).
    #[cold]
    #[inline(never)]
    fn exact(&self, a: usize, b: usize, found: &mut Found) {
        let (fp, fq) = (&self.faces[a], &self.faces[b]);
        let (mut p, mut q) = (self.pts.tri(&fp.indices), self.pts.tri(&fq.indices));
        let both = self.face_box(a).merged(&self.face_box(b));
        let extent = (0..3).fold(0.0f64, |m, k| {
            m.max(f64::from(both.hi[k]) - f64::from(both.lo[k]))
        });
        if !well_scaled(extent) {
            let mut all = [p[0], p[1], p[2], q[0], q[1], q[2]];
            fit(&mut all);
            p = [all[0], all[1], all[2]];
            q = [all[3], all[4], all[5]];
        }
        if faces_cross(&p, &q, &fp.indices, &fq.indices, fp.axis, fq.axis) {
            let (fi, fj) = (self.order[a], self.order[b]);
            found.count += 1;
            let pair = (fi.min(fj), fi.max(fj));
            found.first = Some(found.first.map_or(pair, |x| x.min(pair)));
        }
    }

    /// The winding number at `p` (a vertex of the scaled mesh) of the faces `f` with
    /// `keep(f)`, counted exactly along the ray from `p` in `+x`, symbolically perturbed to
    /// `p + (0, δ, δ²)` so that it never meets an edge or a vertex. `None` if `p` lies on one of
    /// those faces (the callers' checks rule that out).
    pub(crate) fn winding(&self, p: P3, keep: impl Fn(usize) -> bool) -> Option<i64> {
        let mut w = 0i64;
        if self.faces.is_empty() {
            return Some(w);
        }
        let mut stack = vec![(self.levels.len() - 1, 0usize)];
        while let Some((l, i)) = stack.pop() {
            if !self.levels[l][i].meets_ray(p) {
                continue;
            }
            if l > 0 {
                let (a, b) = self.children(l, i);
                stack.push((l - 1, a));
                stack.extend(b.map(|b| (l - 1, b)));
                continue;
            }
            for k in self.leaf(i) {
                if !keep(self.order[k] as usize) {
                    continue;
                }
                match crossing(&self.pts.tri(&self.faces[k].indices), p) {
                    Some(c) => w += i64::from(c),
                    None => return None,
                }
            }
        }
        Some(w)
    }
}

/// Every corner of `q` outside the bit mask `shared` (the corners it shares with `t` by index)
/// lies strictly on one side of the plane of `t`, certainly: then `q` meets that plane only in
/// the shared corners (a vertex, or an edge, of `t`), so `q` and `t` meet nowhere else. A float
/// evaluation of [`o3`] with Shewchuk's error bound ([`O3_FILTER`], as in [`o3_plane`]) plus
/// [`FILTER_SLACK`] for underflow; `false` when that cannot decide (the exact tests then do).
/// For coordinates of magnitude at most [`FAST_COORD_MAX`] (no overflow).
#[inline]
fn off_plane(t: &[P3; 3], q: &[P3; 3], shared: u8) -> bool {
    let plane = Plane::of(t);
    let mut side = 0.0f64;
    for (j, d) in q.iter().enumerate() {
        if shared & (1 << j) != 0 {
            continue;
        }
        let (det, perm) = plane.det(*d);
        if det.abs() <= O3_FILTER * perm + FILTER_SLACK || det * side < 0.0 {
            return false;
        }
        side = det;
    }
    true
}

/// The largest coordinate magnitude for the float filters of [`off_plane`]: differences are
/// at most `2^257`, the filter's products at most `2^775`, far from overflow.
const FAST_COORD_MAX: f64 = 1.157_920_892_373_162e77; // 2^256

/// Absolute slack of the float filters for underflow: a product that underflows is off by at
/// most `2^-1075`; through the filter's later products (factors at most `2^257`) and sums
/// that is below `2^-810` in all. `2^-800`, with margin.
const FILTER_SLACK: f64 = 1.499_696_813_895_631e-241; // 2^-800

/// The relative error bound of a float 2-D orientation (Shewchuk's ccwerrboundA,
/// `(3 + 16ε) ε ≈ 3.33e-16` with `ε = 2^-53`), rounded up with margin.
const O2_FILTER: f64 = 1e-15;

/// How the perturbed ray from `p` along `+x` crosses the triangle `t`: `+1` or `−1` (the sign
/// of the normal's x component) or `0`; `None` when `p` lies in the plane of `t` within it.
fn crossing(t: &[P3; 3], p: P3) -> Option<i8> {
    let mut all = [t[0], t[1], t[2], p];
    fit(&mut all);
    let (t, p) = (&[all[0], all[1], all[2]], all[3]);
    // The sign of the normal's x component: the yz-projection's orientation.
    let s = o2(t[0], t[1], t[2], 0);
    if s == 0 {
        // Parallel to the ray: the perturbed ray never meets it.
        return Some(0);
    }
    // The perturbed point strictly inside the projected triangle.
    for i in 0..3 {
        let (u, w) = (t[i], t[(i + 1) % 3]);
        let mut o = o2(u, w, p, 0);
        if o == 0 {
            // d/dδ of orient2d((u_y,u_z), (w_y,w_z), (p_y + δ, p_z + δ²)): −(w_z − u_z), then
            // (w_y − u_y).
            o = if w[2] != u[2] {
                if u[2] > w[2] {
                    1
                } else {
                    -1
                }
            } else if w[1] > u[1] {
                1
            } else {
                -1
            };
        }
        if o != s {
            return Some(0);
        }
    }
    // In front of p: the plane is met at t > 0 iff p is on the side opposite the normal's x
    // component, i.e. sign(det[b − a, c − a, p − a]) = −s.
    match o3(t[0], t[1], t[2], p) {
        0 => None,
        d if d == -s => Some(s),
        _ => Some(0),
    }
}

// ---------------------------------------------------------------------------------------------
// Stars: the faces around a vertex.

/// For each vertex `v`, whether the faces around it are proved to meet each other only in `v`
/// and the edges they share ([`star_embedded`]). Faces are filed under their vertices by the
/// edge check's counting sort ([`super::mesh::file_by_vertex`]); then each vertex is tested
/// on its own. Stops once `cancel` is set.
fn stars(pts: Points<'_>, tris: &[[u32; 3]], used: &[bool], cancel: &Cancel) -> Result<Vec<bool>> {
    let nv = pts.v.len();
    // Each face's wedge (the next two corners, in its orientation) under each of its corners;
    // a face that takes no part files `NOT_USED`.
    let (start, list) = super::mesh::file_by_vertex(nv, tris, cancel, |f, t| {
        let w = |i: usize| {
            if used[f] {
                [t[(i + 1) % 3], t[(i + 2) % 3]]
            } else {
                [NOT_USED; 2]
            }
        };
        ([(t[0], w(0)), (t[1], w(1)), (t[2], w(2))], 3)
    })?;
    cancel.check()?;
    let mut proved = vec![false; nv];
    proved
        .par_chunks_mut(FACE_CHUNK)
        .enumerate()
        .for_each(|(c, out)| {
            if cancel.check().is_err() {
                return;
            }
            for (i, o) in out.iter_mut().enumerate() {
                let v = c * FACE_CHUNK + i;
                *o = star_embedded(pts, v as u32, &list[start[v]..start[v + 1]]);
            }
        });
    cancel.check()?;
    Ok(proved)
}

/// The wedge filed by a face that takes no part ([`stars`]).
const NOT_USED: u32 = u32::MAX;

/// The sign of the 2-D orientation `o2(c, a, b, k)`, from the differences `da = a − c`,
/// `db = b − c` already projected along `k` (`[x, y]`): the float determinant when its sign is
/// certain beyond Shewchuk's bound ([`O2_FILTER`], which covers the rounding of the
/// differences, plus [`FILTER_SLACK`] for underflow), else the exact predicate.
#[inline]
fn o2_diff(da: [f64; 2], db: [f64; 2], exact: impl FnOnce() -> i8) -> i8 {
    let (l, r) = (da[0] * db[1], da[1] * db[0]);
    let det = l - r;
    if det.abs() > O2_FILTER * (l.abs() + r.abs()) + FILTER_SLACK {
        sign(det)
    } else {
        exact()
    }
}

/// The faces `star` around the vertex `v` meet each other only in `v` and the edges they
/// share, proved exactly: along one coordinate axis `k` every face projects with the same
/// orientation `s ≠ 0`, and their wedges at `v` wind around `v` exactly once. Then every
/// face projects one to one, the projected wedges (each under π) tile the plane around `v`
/// once, two wedges meet only in `v` or in the ray of the edge they share, and so two faces
/// meet only in `v` or in that edge. The winding is counted without ordering the fan: in a
/// closed, consistently oriented mesh the faces around `v` form closed fans (each edge at `v`
/// is left by one face and entered by the next), each winding at least once, and the number
/// of wedges `[a, b)` (half-open) that hold the ray from `v` through a fixed corner `r` is
/// their total winding. `false` (the pairs are then tested one by one) for a vertex with a
/// face that takes no part (zero area, repeated index),
/// whose neighbourhood is badly scaled for the predicates, or whose fan is folded, pinched or
/// winds twice. The orientations are float-filtered ([`o2_diff`]) on the corners' differences
/// from `v`, computed once.
fn star_embedded(pts: Points<'_>, v: u32, star: &[[u32; 2]]) -> bool {
    if star.len() < 3 || star.iter().any(|w| w[0] == NOT_USED) {
        return false;
    }
    let c = pts.p(v);
    // The wedges (a, b) of the faces, in face order (the lowest face index first), are read
    // from the points at each use (no copy: a buffer per vertex cost a tenth of the pairwise
    // path in zeroing alone), with their differences from v (float; the filter accounts for
    // their rounding).
    let wedge = |&[a, b]: &[u32; 2]| (pts.p(a), pts.p(b));
    let diff = |p: P3| [p[0] - c[0], p[1] - c[1], p[2] - c[2]];
    let (mut lo, mut hi) = (c, c);
    for w in star {
        let (a, b) = wedge(w);
        for p in [a, b] {
            for k in 0..3 {
                lo[k] = min2(lo[k], p[k]);
                hi[k] = max2(hi[k], p[k]);
            }
        }
    }
    if !well_scaled((0..3).fold(0.0f64, |m, k| max2(m, hi[k] - lo[k]))) {
        return false;
    }
    // The reference corner r (the first face's a) and the axes to try, the largest normal
    // component of the first face's first.
    let (r, b0) = wedge(&star[0]);
    let (u, w) = (diff(r), diff(b0));
    let nrm = [
        (u[1] * w[2] - u[2] * w[1]).abs(),
        (u[2] * w[0] - u[0] * w[2]).abs(),
        (u[0] * w[1] - u[1] * w[0]).abs(),
    ];
    let first = if nrm[0] >= nrm[1] && nrm[0] >= nrm[2] {
        0
    } else if nrm[1] >= nrm[2] {
        1
    } else {
        2
    };
    // The projection dropping axis k, as [`proj`].
    let pj = |p: [f64; 3], k: u8| match k {
        0 => [p[1], p[2]],
        1 => [p[2], p[0]],
        _ => [p[0], p[1]],
    };
    for k in [first, (first + 1) % 3, (first + 2) % 3] {
        let dr = pj(u, k);
        let s = o2_diff(dr, pj(w, k), || o2(c, r, b0, k));
        if s == 0 {
            continue;
        }
        let mut winding = 0u32;
        let mut same = true;
        for w in star {
            let (a, b) = wedge(w);
            let (da, db) = (pj(diff(a), k), pj(diff(b), k));
            if o2_diff(da, db, || o2(c, a, b, k)) != s {
                same = false;
                break;
            }
            let oa = o2_diff(da, dr, || o2(c, a, r, k));
            let holds = if oa == 0 {
                // r on the line of a: on its ray iff each projected coordinate of r − c has
                // the sign of a − c's (float differences have exact signs).
                sign(da[0]) == sign(dr[0]) && sign(da[1]) == sign(dr[1])
            } else {
                oa == s && o2_diff(dr, db, || o2(c, r, b, k)) == s
            };
            winding += u32::from(holds);
        }
        if same {
            return winding == 1;
        }
    }
    false
}

// ---------------------------------------------------------------------------------------------
// A certificate for a whole component: star-shaped about a point.

/// Is the closed surface of the faces `tris` (those with `skip(f)` left out) proved embedded
/// by being **star-shaped about `c`**? The theorem: let `M` be a connected, closed,
/// consistently oriented triangle mesh (the edge checks of `mesh::check_topology`, one
/// component) and `c` a point such that
///
/// 1. every face `(p₀, p₁, p₂)` is positively oriented seen from `c`:
///    `det[p₀ − c, p₁ − c, p₂ − c] > 0` (`c` strictly on the inner side of its plane), and
/// 2. at every vertex `v` the faces around it, seen from `c`, wind once around `v`: their
///    wedges `[a, b)` at `v` (tangent directions of the arcs `v → a`, `v → b` of the radial
///    projection onto the unit sphere about `c`) hold one fixed tangent direction `t` exactly
///    once.
///
/// Then the radial projection `x ↦ (x − c)/|x − c|` is a local homeomorphism from `M` onto the
/// sphere (inside a face by 1; across an edge because 1 puts the two faces on opposite sides
/// of the plane through `c` and the edge; at a vertex by 2: the wedges, each turning by less
/// than π, tile its neighbourhood once, and a pinched vertex, two fans, would hold `t` twice).
/// A local homeomorphism from a compact connected surface onto the sphere is a covering, and
/// the sphere is simply connected, so it is one to one: no two points of `M` lie in one
/// direction from `c`, so two faces meet only where they share a vertex or an edge by index,
/// which is the self-intersection check's answer without testing any pair. It holds for any
/// mesh star-shaped about `c` (a convex body about any interior point, most blobby or
/// sculpted solids about their centre of mass), not for a torus, a cup or a double-wound
/// fan; `false` then (the pairwise check decides), as for any zero test the proof cannot
/// settle.
///
/// One pass over the faces, no sorting: per face the sign of condition 1, and per corner `v`
/// whether its wedge holds `t = e_k − (e_k·u) u` (`u` the direction of `v − c`, `e_k` the
/// axis along which `v − c` is shortest, decided from `v` and `c` alone so that every face
/// around `v` uses the same `t`): `det[v − c, a − c, e_k]` and `det[v − c, e_k, b − c]`, the
/// `k` components of `(v − c) × (a − c)` and `(b − c) × (v − c)`, i.e. 2-D orientations (`t`
/// on the ray of `a` is held, on that of `b` not: the wedges of a closed fan, half-open, hold
/// each direction as often as the fan winds). Every used vertex holds `t` at least once (its
/// fans are closed by the edge checks, and a closed fan of wedges each turning by less than π
/// winds at least once), so a flag per vertex, set atomically, finds any second hold (the
/// same answer in any order). All signs are float-filtered (Shewchuk's bounds on the
/// differences from `c`, plus [`FILTER_SLACK`]) with the exact predicates behind, for
/// coordinates within [`FAST_COORD_MAX`] and faces of extent in `[2^-60, 2^60]` (the caller's
/// envelope of the pairwise tests); outside it `false`. Stops once `cancel` is set.
pub(crate) fn star_shaped_about(
    pts: Points<'_>,
    tris: &[[u32; 3]],
    skip: impl Fn(usize) -> bool + Sync,
    c: P3,
    cancel: &Cancel,
) -> Result<bool> {
    let Some(proof) = StarProof::new(pts, c) else {
        return Ok(false);
    };
    let ok = tris
        .par_chunks(FACE_CHUNK)
        .enumerate()
        .try_for_each(|(chunk, ts)| {
            if cancel.check().is_err() {
                return Err(());
            }
            let f0 = chunk * FACE_CHUNK;
            for (i, t) in ts.iter().enumerate() {
                if !skip(f0 + i) && !proof.face(t, pts.tri(t)) {
                    return Err(());
                }
            }
            Ok(())
        });
    cancel.check()?;
    Ok(ok.is_ok() && proof.proved())
}

/// The state of [`star_shaped_about`]: [`StarProof::face`] for each face, in any order and on
/// any thread (the per-vertex flags are set atomically; any second hold fails the proof), then
/// [`StarProof::proved`].
struct StarProof {
    /// Per vertex: a wedge around it holds the reference direction.
    held: Vec<AtomicBool>,
    /// Set once a face fails: the proof is refused and later faces are not examined.
    failed: AtomicBool,
    c: P3,
    /// Every vertex is within [`FAST_COORD_MAX`] and their box is at most [`EXTENT_HI`] on
    /// each axis: the per-face envelope checks of [`radial_wedges`] hold but for a face's
    /// least extent (decided once per mesh).
    inside: bool,
}

impl StarProof {
    /// A proof about `c` for the mesh of the vertices `pts`; `None` when `c` is outside the
    /// envelope of the float filters ([`FAST_COORD_MAX`]).
    fn new(pts: Points<'_>, c: P3) -> Option<Self> {
        let b = pts.bounds();
        let inside = (0..3).all(|k| {
            max2(b.lo[k].abs(), b.hi[k].abs()) <= FAST_COORD_MAX && b.hi[k] - b.lo[k] <= EXTENT_HI
        });
        c.iter().all(|x| x.abs() <= FAST_COORD_MAX).then(|| Self {
            held: (0..pts.v.len()).map(|_| AtomicBool::new(false)).collect(),
            failed: AtomicBool::new(false),
            c,
            inside,
        })
    }

    /// Takes the face `t` with corners `p` (the points of `t`) into the proof; `false` once
    /// the proof has failed (by this face or an earlier one).
    #[inline]
    fn face(&self, t: &[u32; 3], p: [P3; 3]) -> bool {
        if self.failed.load(Ordering::Relaxed) {
            return false;
        }
        let ok = match radial_wedges(p, self.c, self.inside) {
            Some(holds) => t
                .iter()
                .zip(holds)
                .all(|(&v, h)| !(h && self.held[v as usize].swap(true, Ordering::Relaxed))),
            None => false,
        };
        if !ok {
            self.failed.store(true, Ordering::Relaxed);
        }
        ok
    }

    /// Whether every face taken in passed: the surface they form is embedded.
    fn proved(&self) -> bool {
        !self.failed.load(Ordering::Relaxed)
    }
}

/// For the face `t` seen from `c` ([`star_shaped_about`]): `None` unless it is positively
/// oriented (and within the envelope of the predicates); else, for each corner, whether its
/// wedge holds the corner's reference tangent direction.
///
/// The float filters bound each product's permanent by the corners' largest differences from
/// `c` (`m_i = max_k |p_i,k − c_k|`: `|u_j w_l| + |u_l w_j| ≤ 2 m_u m_w`, and rounding is
/// monotone, so the bound is at least the permanent the filter was derived for): a coarser
/// filter, never a wrong sign, without the nine absolute permanents per face; and only the
/// components of the cross products that a corner's test reads are computed (the corners
/// unrolled), about half of the instructions of the proof.
///
/// `inside`: every vertex of the mesh is within [`FAST_COORD_MAX`] and the vertices' box is at
/// most [`EXTENT_HI`] on each axis ([`StarProof`]); then only the face's least extent is
/// checked, first by one edge (`extent ≥ |p₁ − p₀|_∞`, both rounded alike), with the same
/// answer as the checks of every coordinate and the whole extent.
#[inline]
fn radial_wedges(p: [P3; 3], c: P3, inside: bool) -> Option<[bool; 3]> {
    if !inside && !fast(&p) {
        return None;
    }
    let edge = |k: usize| (p[1][k] - p[0][k]).abs();
    if !(inside && max2(max2(edge(0), edge(1)), edge(2)) >= EXTENT_LO) {
        let extent = (0..3).fold(0.0f64, |m, k| {
            max2(
                m,
                max2(max2(p[0][k], p[1][k]), p[2][k]) - min2(min2(p[0][k], p[1][k]), p[2][k]),
            )
        });
        if !well_scaled(extent) {
            return None;
        }
    }
    let d = p.map(|x| [x[0] - c[0], x[1] - c[1], x[2] - c[2]]);
    let a = d.map(|x| x.map(f64::abs));
    let m = a.map(|x| max2(max2(x[0], x[1]), x[2]));
    // Component k of d[i] × d[j].
    let cross = |i: usize, j: usize, k: usize| cross_k(&d[i], &d[j], k);
    // Condition 1: det[d₀, d₁, d₂] = d₀ · (d₁ × d₂) > 0; the permanent is at most
    // 3 · m₀ · 2 m₁ m₂ (8: a power of two above 6, exact).
    let det = d[0][0] * cross(1, 2, 0) + d[0][1] * cross(1, 2, 1) + d[0][2] * cross(1, 2, 2);
    let perm = 8.0 * (m[0] * (m[1] * m[2]));
    let positive = if det.abs() > O3_FILTER * perm + FILTER_SLACK {
        det > 0.0
    } else {
        robust::orient3d(c3(p[0]), c3(p[1]), c3(p[2]), c3(c)) > 0.0
    };
    if !positive {
        return None;
    }
    // The sign of component k of (p[i] − c) × (p[j] − c).
    let comp = |i: usize, j: usize, k: usize| {
        let n = cross(i, j, k);
        if n.abs() > O2_FILTER * (2.0 * (m[i] * m[j])) + FILTER_SLACK {
            sign(n)
        } else {
            o2_cold(c, p[i], p[j], k as u8)
        }
    };
    #[inline(always)]
    fn corner(
        i: usize,
        a: usize,
        b: usize,
        abs: P3,
        comp: &impl Fn(usize, usize, usize) -> i8,
        tie: impl FnOnce(usize) -> bool,
    ) -> bool {
        // The axis along which v − c is shortest (ties: the lowest); v − c ≠ 0 by condition
        // 1, so e_k is not along it.
        let k = if abs[0] <= min2(abs[1], abs[2]) {
            0
        } else if abs[1] <= abs[2] {
            1
        } else {
            2
        };
        // det[v − c, a − c, e_k] = ((v − c) × (a − c))_k.
        let sa = comp(i, a, k);
        if sa == 0 {
            // t along ±(tangent towards a): held iff the same ray, i.e. (v − c) × e_k and
            // (v − c) × (a − c) (parallel: e_k lies in their plane) point the same way.
            tie(k)
        } else {
            // det[v − c, e_k, b − c] = ((b − c) × (v − c))_k.
            sa == 1 && comp(b, i, k) == 1
        }
    }
    Some([
        corner(0, 1, 2, a[0], &comp, |k| same_ray(c, p[0], p[1], d[0], k)),
        corner(1, 2, 0, a[1], &comp, |k| same_ray(c, p[1], p[2], d[1], k)),
        corner(2, 0, 1, a[2], &comp, |k| same_ray(c, p[2], p[0], d[2], k)),
    ])
}

/// [`o2`] out of line (the rare fall-back of a float filter in a hot loop).
#[cold]
#[inline(never)]
fn o2_cold(a: P3, b: P3, c: P3, k: u8) -> i8 {
    o2(a, b, c, k)
}

/// Component `k` of `u × w`.
#[inline(always)]
fn cross_k(u: &P3, w: &P3, k: usize) -> f64 {
    match k {
        0 => u[1] * w[2] - u[2] * w[1],
        1 => u[2] * w[0] - u[0] * w[2],
        _ => u[0] * w[1] - u[1] * w[0],
    }
}

/// For `det[v − c, a − c, e_k] = 0` ([`radial_wedges`]): do `(v − c) × e_k` and
/// `(v − c) × (a − c)` point the same way? Compared on a component where the second is not
/// zero (exact: [`o2`]); the first's components are `±` coordinates of `dv = v − c`, whose
/// float signs are exact.
#[cold]
fn same_ray(c: P3, v: P3, a: P3, dv: P3, k: usize) -> bool {
    for j in 0..3 {
        let n = o2(c, v, a, j as u8);
        if n != 0 {
            // ((v − c) × e_k)_j = dv[j+1]·[k = j+2] − dv[j+2]·[k = j+1] (indices mod 3).
            let w = if k == (j + 2) % 3 {
                sign(dv[(j + 1) % 3])
            } else if k == (j + 1) % 3 {
                -sign(dv[(j + 2) % 3])
            } else {
                0
            };
            return w == n;
        }
    }
    false
}

// ---------------------------------------------------------------------------------------------
// Connected components.

/// A lock-free union-find over `0..n` (links the larger root under the smaller, so parents
/// only decrease and no cycle can form; roots linked by compare-and-swap, paths split by plain
/// stores: a locked compare-and-swap per step of every find cost about a tenth of the whole
/// call on a 1.3 M-face sphere, one thread).
pub(crate) struct UnionFind(Vec<AtomicU32>);

impl UnionFind {
    pub(crate) fn new(n: usize) -> Self {
        Self((0..n as u32).map(AtomicU32::new).collect())
    }

    pub(crate) fn find(&self, mut x: u32) -> u32 {
        loop {
            let p = self.0[x as usize].load(Ordering::Acquire);
            if p == x {
                return x;
            }
            let g = self.0[p as usize].load(Ordering::Acquire);
            if g != p {
                // Path halving by a plain store: `x` is not a root (its parent `p ≠ x`), and
                // only roots are linked (by `union`'s compare-and-swap), so nothing but
                // another halving writes here, and any ancestor of `x` is a valid parent
                // (`g` is one: parents only ever point to ancestors).
                self.0[x as usize].store(g, Ordering::Release);
            }
            x = p;
        }
    }

    pub(crate) fn union(&self, a: u32, b: u32) {
        loop {
            let (ra, rb) = (self.find(a), self.find(b));
            if ra == rb {
                return;
            }
            let (lo, hi) = (ra.min(rb), ra.max(rb));
            if self.0[hi as usize]
                .compare_exchange(hi, lo, Ordering::AcqRel, Ordering::Acquire)
                .is_ok()
            {
                return;
            }
        }
    }
}

/// For each vertex, the one component that uses it, or [`SHARED`] (several) / [`UNUSED`].
pub(crate) fn vertex_owners(nv: usize, tris: &[[u32; 3]], comp: &[u32]) -> Vec<u32> {
    let owner: Vec<AtomicU32> = (0..nv).map(|_| AtomicU32::new(UNUSED)).collect();
    tris.par_iter()
        .zip(comp)
        .with_min_len(1024)
        .filter(|(_, c)| **c != UNUSED)
        .for_each(|(t, &c)| {
            for &v in t {
                let _ = owner[v as usize].fetch_update(Ordering::AcqRel, Ordering::Acquire, |o| {
                    if o == UNUSED {
                        Some(c)
                    } else if o == c || o == SHARED {
                        None
                    } else {
                        Some(SHARED)
                    }
                });
            }
        });
    owner.into_iter().map(AtomicU32::into_inner).collect()
}

/// A vertex used by no face (or a face in no component).
pub(crate) const UNUSED: u32 = u32::MAX;
/// A vertex used by faces of several components.
pub(crate) const SHARED: u32 = u32::MAX - 1;

/// For each component, the lowest face index with a vertex that belongs to it alone and that
/// takes part in the index (non-degenerate), and that vertex; `None` if it has none.
pub(crate) fn probe_vertices(
    index: &Index<'_>,
    tris: &[[u32; 3]],
    comp: &[u32],
    owner: &[u32],
    ncomp: usize,
) -> Vec<Option<(u32, u32)>> {
    let best: Vec<AtomicU64> = (0..ncomp).map(|_| AtomicU64::new(u64::MAX)).collect();
    tris.par_iter()
        .enumerate()
        .with_min_len(1024)
        .for_each(|(f, t)| {
            let c = comp[f];
            if c == UNUSED || !index.used[f] {
                return;
            }
            if let Some(&v) = t.iter().find(|&&v| owner[v as usize] == c) {
                best[c as usize].fetch_min((f as u64) << 32 | u64::from(v), Ordering::AcqRel);
            }
        });
    best.into_iter()
        .map(|b| {
            let b = b.into_inner();
            (b != u64::MAX).then_some(((b >> 32) as u32, b as u32))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    const A: P3 = [0.0, 0.0, 0.0];
    const B: P3 = [1.0, 0.0, 0.0];
    const C: P3 = [0.0, 1.0, 0.0];

    #[test]
    fn orientation_signs() {
        assert_eq!(o3(A, B, C, [0.0, 0.0, 1.0]), 1);
        assert_eq!(o3(A, B, C, [0.3, 0.3, 0.0]), 0);
        assert_eq!(o2(A, B, C, 2), 1);
        assert_eq!(drop_axis(&[A, B, C]), Some(2));
        assert_eq!(drop_axis(&[A, B, [2.0, 0.0, 0.0]]), None);
    }

    #[test]
    fn pairs_of_triangles() {
        let t = [A, B, C];
        let ti = [0, 1, 2];
        let k = 2;
        // Disjoint, above.
        let q = [[0.0, 0.0, 1.0], [1.0, 0.0, 1.0], [0.0, 1.0, 1.0]];
        assert!(!faces_cross(&t, &q, &ti, &[3, 4, 5], k, 2));
        // Piercing.
        let q = [[0.2, 0.2, -1.0], [0.2, 0.2, 1.0], [0.9, 0.9, 1.0]];
        let kq = drop_axis(&q).unwrap();
        assert!(faces_cross(&t, &q, &ti, &[3, 4, 5], k, kq));
        // Sharing an edge, folded onto each other (coplanar, same side) and unfolded.
        let q = [B, A, [0.2, 0.5, 0.0]];
        assert!(faces_cross(&t, &q, &ti, &[1, 0, 6], k, 2));
        let q = [B, A, [0.2, -0.5, 0.0]];
        assert!(!faces_cross(&t, &q, &ti, &[1, 0, 6], k, 2));
        // Sharing a vertex: touching only there, crossing beyond it, coplanar overlap.
        let q = [A, [-1.0, 0.0, 0.5], [0.0, -1.0, 0.5]];
        let kq = drop_axis(&q).unwrap();
        assert!(!faces_cross(&t, &q, &ti, &[0, 7, 8], k, kq));
        let q = [A, [0.5, 0.2, 1.0], [0.2, 0.5, -1.0]];
        let kq = drop_axis(&q).unwrap();
        assert!(faces_cross(&t, &q, &ti, &[0, 7, 8], k, kq));
        let q = [A, [0.5, 0.1, 0.0], [0.1, 0.5, 0.0]];
        assert!(faces_cross(&t, &q, &ti, &[0, 7, 8], k, 2));
        let q = [A, [-0.5, 0.1, 0.0], [-0.1, -0.5, 0.0]];
        assert!(!faces_cross(&t, &q, &ti, &[0, 7, 8], k, 2));
        // Sharing a vertex, an edge of q lying in t's plane inside t's angle.
        let q = [A, [0.3, 0.3, 0.0], [0.0, 0.0, 1.0]];
        let kq = drop_axis(&q).unwrap();
        assert!(faces_cross(&t, &q, &ti, &[0, 7, 8], k, kq));
        // Coplanar, no shared index: overlapping and apart.
        let q = [[0.2, 0.2, 0.0], [2.0, 0.2, 0.0], [0.2, 2.0, 0.0]];
        assert!(faces_cross(&t, &q, &ti, &[3, 4, 5], k, 2));
        let q = [[0.6, 0.6, 0.0], [2.0, 0.6, 0.0], [0.6, 2.0, 0.0]];
        assert!(!faces_cross(&t, &q, &ti, &[3, 4, 5], k, 2));
    }

    #[test]
    fn ray_crossings() {
        // The triangle x = 1 facing +x; from the origin the ray crosses it leaving (+1).
        let t = [[1.0, -1.0, -1.0], [1.0, 1.0, -1.0], [1.0, 0.0, 1.0]];
        let s = crossing(&t, [0.0, 0.0, 0.0]);
        let n = o2(t[0], t[1], t[2], 0);
        assert_eq!(s, Some(n));
        assert_eq!(crossing(&t, [2.0, 0.0, 0.0]), Some(0));
        // Two triangles sharing the edge x = 1, y = 0: the ray through the edge counts once.
        let a = [[1.0, 0.0, -1.0], [1.0, 0.0, 1.0], [1.0, -1.0, 0.0]];
        let b = [[1.0, 0.0, 1.0], [1.0, 0.0, -1.0], [1.0, 1.0, 0.0]];
        let sum = crossing(&a, [0.0; 3]).unwrap() + crossing(&b, [0.0; 3]).unwrap();
        assert_eq!(sum.abs(), 1);
    }

    use proptest::prelude::*;

    fn small_point() -> impl Strategy<Value = P3> {
        proptest::array::uniform3(-3i32..=3).prop_map(|a| a.map(f64::from))
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 4000, rng_seed: proptest::test_runner::RngSeed::Fixed(20261123), ..ProptestConfig::default() })]

        /// On small integer coordinates (coplanar, collinear and touching configurations are
        /// frequent) the cheap exits of `faces_cross` agree with the full tests, and the
        /// answer does not depend on the order of the faces or the rotation of their corners.
        #[test]
        fn narrow_phase_is_consistent(a in small_point(), b in small_point(), c in small_point(),
                                      d in small_point(), e in small_point(), f in small_point(),
                                      share in 0usize..3, rot in 0usize..3) {
            let p = [a, b, c];
            let Some(kp) = drop_axis(&p) else { return Ok(()) };
            // q shares `share` leading corners of p (reversed, as a consistent neighbour would).
            let (q, qi): ([P3; 3], [u32; 3]) = match share {
                0 => ([d, e, f], [3, 4, 5]),
                1 => ([a, e, f], [0, 4, 5]),
                _ => ([b, a, f], [1, 0, 5]),
            };
            let Some(kq) = drop_axis(&q) else { return Ok(()) };
            let pi = [0u32, 1, 2];
            let got = faces_cross(&p, &q, &pi, &qi, kp, kq);
            let full = match share {
                0 => triangles_meet(&p, &q, kp, kq),
                1 => meet_beyond_vertex(&p, &q, kp, kq),
                _ => o3(a, b, c, f) == 0 && o2(a, b, c, kp) == o2(a, b, f, kp),
            };
            prop_assert_eq!(got, full);
            prop_assert_eq!(faces_cross(&q, &p, &qi, &pi, kq, kp), got);
            let r = |t: [P3; 3]| [t[rot], t[(rot + 1) % 3], t[(rot + 2) % 3]];
            let ri = |t: [u32; 3]| [t[rot], t[(rot + 1) % 3], t[(rot + 2) % 3]];
            prop_assert_eq!(faces_cross(&r(p), &q, &ri(pi), &qi, kp, kq), got);
        }
    }

    #[test]
    fn plane_filter_agrees_with_the_exact_predicate() {
        // Points on, one ulp off, and far from a tilted plane.
        let t = [[0.1, 0.2, 0.3], [1.7, 0.4, 0.9], [0.3, 1.9, 1.3]];
        let mut ds = Vec::new();
        for k in 0..200 {
            let s = k as f64 / 199.0;
            let on =
                [0, 1, 2].map(|i| t[0][i] + s * (t[1][i] - t[0][i]) + 0.3 * (t[2][i] - t[0][i]));
            ds.push(on);
            ds.push([on[0], on[1], on[2] + f64::EPSILON]);
            ds.push([on[0], on[1] + 1e-3, on[2]]);
        }
        for d in ds {
            assert_eq!(o3_plane(&t, [d])[0], o3(t[0], t[1], t[2], d), "{d:?}");
        }
    }

    /// A closed, consistently oriented UV sphere (`n` rings, `m` vertices each, and two
    /// poles) whose vertices are moved by up to `amp` in each coordinate (a fixed pseudo-random
    /// sequence from `seed`): for large `amp` fans fold, pinch and wind twice.
    fn bumpy_sphere(n: usize, m: usize, seed: u64, amp: f64) -> (Vec<f64>, Vec<[u32; 3]>) {
        let mut state = seed
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        let mut rnd = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        let mut v = vec![0.0, 0.0, 1.0];
        for k in 1..=n {
            let th = std::f64::consts::PI * k as f64 / (n + 1) as f64;
            for j in 0..m {
                let ph = 2.0 * std::f64::consts::PI * j as f64 / m as f64;
                v.extend([th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]);
            }
        }
        v.extend([0.0, 0.0, -1.0]);
        for x in v.iter_mut() {
            *x += amp * rnd();
        }
        let ring = |k: usize, j: usize| (1 + (k - 1) * m + j % m) as u32;
        let south = (1 + n * m) as u32;
        let mut f = Vec::new();
        for j in 0..m {
            f.push([0, ring(1, j + 1), ring(1, j)]);
            for k in 1..n {
                let (a, b) = (ring(k, j), ring(k, j + 1));
                let (c, d) = (ring(k + 1, j + 1), ring(k + 1, j));
                f.push([a, b, c]);
                f.push([a, c, d]);
            }
            f.push([south, ring(n, j), ring(n, j + 1)]);
        }
        (v, f)
    }

    /// Issue 21, item 17: the join skips the pairs of faces around a vertex whose star is
    /// proved embedded; on bumpy spheres (smooth to folded) it finds exactly the pairs that
    /// testing every pair of faces finds, the first pair included.
    #[test]
    fn star_shortcut_agrees_with_testing_every_pair() {
        let mut skipped_some = false;
        let mut found_some = false;
        for seed in 0..60u64 {
            let amp = [0.0, 0.02, 0.08, 0.2, 0.5][seed as usize % 5];
            let (v, f) = bumpy_sphere(6, 9, seed, amp);
            let pts = Points::new(&v);
            let cancel = Cancel::new(0);
            let index = Index::new(pts, &f, |_| false, &cancel).unwrap();
            skipped_some |= index.faces.iter().any(|f| f.proved != 0);
            let got = index.intersections(&cancel).unwrap();
            let (count, first) = all_pairs(&v, &f);
            found_some |= count > 0;
            assert_eq!(got, (count, first), "seed {seed}, amplitude {amp}");
        }
        assert!(skipped_some && found_some);
    }

    /// `bumpy_sphere` with its faces reversed: outward, as the star-shaped certificate needs.
    fn outward_sphere(n: usize, m: usize, seed: u64, amp: f64) -> (Vec<f64>, Vec<[u32; 3]>) {
        let (v, f) = bumpy_sphere(n, m, seed, amp);
        (v, f.iter().map(|t| [t[0], t[2], t[1]]).collect())
    }

    /// Every pair of faces by the exact test: how many meet, and the first pair.
    fn all_pairs(v: &[f64], f: &[[u32; 3]]) -> (u64, Option<(u32, u32)>) {
        let pts = Points::new(v);
        let mut count = 0u64;
        let mut first = None;
        for i in 0..f.len() {
            for j in i + 1..f.len() {
                let (p, q) = (pts.tri(&f[i]), pts.tri(&f[j]));
                let (Some(kp), Some(kq)) = (drop_axis(&p), drop_axis(&q)) else {
                    continue;
                };
                if faces_cross(&p, &q, &f[i], &f[j], kp, kq) {
                    count += 1;
                    first.get_or_insert((i as u32, j as u32));
                }
            }
        }
        (count, first)
    }

    /// Issue 21, item 17: the star-shaped certificate passes only meshes in which testing
    /// every pair of faces finds no intersection, on bumpy spheres from smooth to folded and
    /// self-intersecting, about points inside, off-centre and outside; it passes the smooth
    /// ones about an inside point, and refuses any point outside.
    #[test]
    fn star_shaped_certificate_implies_no_intersection() {
        let (mut certified, mut crossing, mut refused_embedded) = (0, 0, 0);
        let cancel = Cancel::new(0);
        for seed in 0..80u64 {
            let amp = [0.0, 0.01, 0.05, 0.2, 0.5][seed as usize % 5];
            let (n, m) = if seed % 2 == 0 { (6, 9) } else { (10, 17) };
            let (v, f) = outward_sphere(n, m, seed, amp);
            let pts = Points::new(&v);
            let (count, _) = all_pairs(&v, &f);
            crossing += usize::from(count > 0);
            for c in [
                [0.0; 3],
                [0.21, -0.13, 0.07],
                [0.0, 0.0, 0.93],
                [2.5, 0.0, 0.0],
            ] {
                let ok = star_shaped_about(pts, &f, |_| false, c, &cancel).unwrap();
                if ok {
                    assert_eq!(count, 0, "seed {seed}, amplitude {amp}, centre {c:?}");
                    certified += 1;
                } else if count == 0 {
                    refused_embedded += 1;
                }
                if amp <= 0.01 && c == [0.0; 3] {
                    assert!(ok, "seed {seed}: a smooth sphere about its centre");
                }
                if c[0] > 2.0 {
                    assert!(!ok, "seed {seed}: a point outside");
                }
            }
        }
        assert!(certified > 0 && crossing > 0 && refused_embedded > 0);
    }

    /// Negative controls: a sphere whose meridians wind twice around the axis (each face
    /// seen from the centre is positively oriented, but the fans at the poles wind twice and
    /// the sheets overlap) and a sphere with one vertex pushed through the opposite side are
    /// refused by the certificate, and the pairwise check finds their intersections.
    #[test]
    fn star_shaped_certificate_refuses_self_intersecting_meshes() {
        let cancel = Cancel::new(0);
        let (n, m) = (8, 11);
        let (mut v, f) = outward_sphere(n, m, 0, 0.0);
        for k in 1..=n {
            let th = std::f64::consts::PI * k as f64 / (n + 1) as f64;
            for j in 0..m {
                let ph = 4.0 * std::f64::consts::PI * j as f64 / m as f64;
                let i = 3 * (1 + (k - 1) * m + j);
                v[i..i + 3].copy_from_slice(&[th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]);
            }
        }
        let pts = Points::new(&v);
        assert!(!star_shaped_about(pts, &f, |_| false, [0.0; 3], &cancel).unwrap());
        assert!(all_pairs(&v, &f).0 > 0);
        let index = Index::new(pts, &f, |_| false, &cancel).unwrap();
        assert_eq!(index.intersections(&cancel).unwrap(), all_pairs(&v, &f));
        // One ring vertex pushed through to the far side: faces around it turn inside out.
        let (mut v, f) = outward_sphere(n, 2 * m, 0, 0.0);
        let i = 3 * (1 + 3 * 2 * m);
        let p = [v[i], v[i + 1], v[i + 2]];
        v[i..i + 3].copy_from_slice(&p.map(|x| -1.3 * x));
        let pts = Points::new(&v);
        assert!(!star_shaped_about(pts, &f, |_| false, [0.0; 3], &cancel).unwrap());
        assert!(all_pairs(&v, &f).0 > 0);
        // A stopped call stops.
        let stopped = Cancel::new(0);
        stopped.cancel();
        let (v, f) = outward_sphere(n, m, 0, 0.0);
        assert!(star_shaped_about(Points::new(&v), &f, |_| false, [0.0; 3], &stopped).is_err());
    }

    /// [`radial_wedges`] with every sign by the exact predicates (no float filter): the
    /// reference for its filters.
    fn radial_wedges_exact(p: [P3; 3], c: P3) -> Option<[bool; 3]> {
        let extent = (0..3).fold(0.0f64, |m, k| {
            let (lo, hi) = (
                p[0][k].min(p[1][k]).min(p[2][k]),
                p[0][k].max(p[1][k]).max(p[2][k]),
            );
            m.max(hi - lo)
        });
        if !fast(&p) || !well_scaled(extent) {
            return None;
        }
        if robust::orient3d(c3(p[0]), c3(p[1]), c3(p[2]), c3(c)) <= 0.0 {
            return None;
        }
        Some([0, 1, 2].map(|i| {
            let (a, b) = ((i + 1) % 3, (i + 2) % 3);
            let dv = [p[i][0] - c[0], p[i][1] - c[1], p[i][2] - c[2]];
            let m = dv.map(f64::abs);
            let k = if m[0] <= m[1] && m[0] <= m[2] {
                0
            } else if m[1] <= m[2] {
                1
            } else {
                2
            };
            match o2(c, p[i], p[a], k as u8) {
                0 => same_ray(c, p[i], p[a], dv, k),
                sa => sa == 1 && o2(c, p[b], p[i], k as u8) == 1,
            }
        }))
    }

    /// The filtered [`radial_wedges`] (coarse permanents from the corners' largest
    /// differences, only the components it reads) answers as the exact predicates do, on
    /// random faces about random points, faces nearly through the point or along its axes
    /// (ties of the shortest axis, zero components, the exact fall-backs), tiny and huge
    /// scales (products that overflow: the exact path), and faces outside the envelope.
    #[test]
    fn radial_wedges_filters_agree_with_exact_signs() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut rnd = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        let (mut some, mut none, mut held) = (0, 0, 0);
        for n in 0..40_000 {
            let scale = [1.0, 1e-9, 1e9, 1e40, 1e70, 1e-70, 3e-17][n % 7];
            let c = [rnd(), rnd(), rnd()].map(|x| x * scale);
            let mut p = [[0.0; 3]; 3];
            for q in p.iter_mut() {
                *q = [rnd(), rnd(), rnd()].map(|x| x * scale);
            }
            match n % 5 {
                // Corners snapped to grid values: equal coordinates, ties of |v − c|.
                1 => {
                    for q in p.iter_mut() {
                        for (x, y) in q.iter_mut().zip(c) {
                            *x = y + (4.0 * (*x - y) / scale).round() * 0.25 * scale;
                        }
                    }
                }
                // The third corner in the plane through c and the first two, up to rounding.
                2 => {
                    let t = rnd();
                    p[2] = [0, 1, 2].map(|k| c[k] + t * (p[0][k] - c[k]) + 0.7 * (p[1][k] - c[k]));
                }
                // A corner on the ray from c through another (a tie of the wedge).
                3 => p[1] = [0, 1, 2].map(|k| c[k] + 2.0 * (p[0][k] - c[k])),
                _ => {}
            }
            for q in [p, [p[0], p[2], p[1]]] {
                let got = radial_wedges(q, c, false);
                assert_eq!(got, radial_wedges_exact(q, c), "{q:?} about {c:?}");
                // The envelope decided once per mesh: the same answer for a mesh of this face
                // alone, when its box is inside that envelope.
                let b = Bounds::of(q);
                if (0..3).all(|k| {
                    b.lo[k].abs().max(b.hi[k].abs()) <= FAST_COORD_MAX
                        && b.hi[k] - b.lo[k] <= EXTENT_HI
                }) {
                    assert_eq!(radial_wedges(q, c, true), got, "{q:?} about {c:?}");
                }
                match got {
                    Some(h) => {
                        some += 1;
                        held += h.iter().filter(|&&x| x).count();
                    }
                    None => none += 1,
                }
            }
        }
        assert!(
            some > 10_000 && none > 10_000 && held > 1_000,
            "{some} {none} {held}"
        );
    }

    /// A fan of many faces (the poles of a UV sphere of 100 meridians) is proved too (it was
    /// left to the pairwise tests when the proof copied a fan into a stack buffer of 32).
    #[test]
    fn large_fans_are_proved() {
        let (v, f) = bumpy_sphere(6, 100, 1, 0.0);
        let cancel = Cancel::new(0);
        let index = Index::new(Points::new(&v), &f, |_| false, &cancel).unwrap();
        let south = (1 + 6 * 100) as u32;
        for pole in [0u32, south] {
            let around: Vec<&Face> = index
                .faces
                .iter()
                .filter(|g| g.indices.contains(&pole))
                .collect();
            assert_eq!(around.len(), 100);
            for g in around {
                let i = g.indices.iter().position(|&x| x == pole).unwrap();
                assert!(g.proved & (1 << i) != 0, "pole {pole}");
            }
        }
        assert_eq!(index.intersections(&cancel).unwrap(), (0, None));
    }

    #[test]
    fn outward_rounding_to_f32() {
        for x in [0.1, -0.1, 1e-50, -1e-50, 1e300, -1e300, 0.0, 3.0] {
            assert!(f64::from(down32(x)) <= x && x <= f64::from(up32(x)), "{x}");
        }
        assert_eq!(step_up(1.0), 1.0 + f32::EPSILON);
        assert_eq!(-step_up(-1.0), 1.0 - f32::EPSILON / 2.0);
        // The branch-free rounding is the tightest: against step_up on values either side of
        // f32 numbers, zeros, subnormals and beyond f32::MAX.
        let mut xs = vec![
            0.0, -0.0, 1e-45, -1e-45, 1e-46, -1e-46, 3.5e38, -3.5e38, 1e300,
        ];
        for k in -40..40 {
            let y = 1.37f64 * 2f64.powi(k);
            xs.extend([y, -y, f64::from(y as f32), -f64::from(y as f32)]);
        }
        for x in xs {
            let (d, u) = (down32(x), up32(x));
            assert!(f64::from(d) <= x && x <= f64::from(u), "{x}");
            // Nothing strictly between: the next f32 above d exceeds x, the one below u is
            // under x.
            assert!(f64::from(step_up(d)) > x || d == f32::MAX, "{x}: {d}");
            assert!(f64::from(-step_up(-u)) < x || u == f32::MIN, "{x}: {u}");
        }
    }

    #[test]
    fn union_find_links_components() {
        let u = UnionFind::new(6);
        u.union(4, 2);
        u.union(2, 5);
        u.union(0, 1);
        assert_eq!(u.find(5), 2);
        assert_eq!(u.find(1), 0);
        assert_eq!(u.find(3), 3);
    }

    /// Unions from several threads at once (roots linked by compare-and-swap, paths split by
    /// plain stores, finds racing with both) give the partition of the same unions made on one
    /// thread, and every element's root is the least element of its class, on long chains
    /// (pairs `(i, i + 1)` and `(i, i + 7)` interleaved) and random pairs.
    #[test]
    fn union_find_is_exact_under_concurrent_unions() {
        let n = 40_000u32;
        let mut seed = 0x9E37_79B9_7F4A_7C15u64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed
        };
        let mut pairs: Vec<(u32, u32)> = (0..n - 7)
            .flat_map(|i| [(i + 1, i), (i, i + 7)])
            .filter(|&(a, b)| a % 97 != 3 && b % 97 != 3)
            .collect();
        pairs.extend((0..30_000).map(|_| {
            let a = (next() % u64::from(n)) as u32;
            (a, (next() % u64::from(n)) as u32)
        }));
        for k in (1..pairs.len()).rev() {
            pairs.swap(k, (next() % (k as u64 + 1)) as usize);
        }
        let serial = UnionFind::new(n as usize);
        for &(a, b) in &pairs {
            serial.union(a, b);
        }
        for threads in [2, 4] {
            let shared = UnionFind::new(n as usize);
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| {
                    pairs.par_iter().with_max_len(64).for_each(|&(a, b)| {
                        shared.union(a, b);
                        shared.find(a);
                    });
                });
            let mut least = vec![u32::MAX; n as usize];
            for x in 0..n {
                let r = serial.find(x) as usize;
                least[r] = least[r].min(x);
            }
            for x in 0..n {
                assert_eq!(shared.find(x), serial.find(x), "{x} on {threads} threads");
                assert_eq!(serial.find(x), least[serial.find(x) as usize]);
            }
        }
    }
}
