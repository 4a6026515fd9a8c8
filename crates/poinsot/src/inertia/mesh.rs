//! Mass properties of a closed triangle mesh of uniform density, by exact polyhedral integrals,
//! after checking that the mesh bounds a solid.
//!
//! **Integrals.** A closed, outward-oriented triangle mesh is the signed sum of the tetrahedra
//! `(p₀, a, b, c)` spanned by a reference point `p₀` and each face `(a, b, c)`. With `a, b, c`
//! taken relative to `p₀` and `D = a·(b × c)` (six times the signed volume):
//!
//! ```text
//! ∫ dV      = D / 6
//! ∫ x dV    = D / 24  · (a + b + c)
//! ∫ x xᵀ dV = D / 120 · (a aᵀ + b bᵀ + c cᵀ + s sᵀ),   s = a + b + c
//! ```
//!
//! (exact for polynomials of degree ≤ 2; Tonon 2004). `p₀` is the centre of the bounding box,
//! which keeps the terms small and the sums accurate. The second moments about the centre of
//! mass give the inertia `I = tr(C) 1 − C` (the unit's 2.61–2.62 with uniform ρ).
//!
//! **Checks** (each refusal is an [`Error::mesh`] naming `faces` or `vertices` and saying what
//! is wrong and where): face indices in range; finite vertices; not every face degenerate;
//! closed (every edge shared by exactly two faces: the number of boundary edges is reported);
//! manifold (no edge shared by more than two faces); consistently oriented (each edge traversed
//! once in each direction); outward (positive total volume, else "faces are oriented inward;
//! reverse the winding"); non-zero volume. Faces with a repeated vertex index are degenerate
//! (they have no area) and are left out of the edge checks; faces of zero area with three
//! distinct indices take part in them as usual. Self-intersection is not checked.
//!
//! **Edge check without hashing.** Each use of an undirected edge `{a, b}` (`a < b`) by a face
//! is filed under its low vertex `a`, with `b` and a direction bit, by a counting sort into a
//! compressed (CSR) list; each vertex's short list is then sorted and its runs counted: one
//! use is a boundary edge, more than two a non-manifold edge, two in the same direction an
//! inconsistent orientation. `O(n · degree)`, parallel (rayon: each task owns a range of low
//! vertices, so no atomics and no `unsafe`).

use rayon::prelude::*;

use crate::error::{check_positive, Error, Result};
use crate::inertia::body::MassProperties;
use crate::inertia::tensor;
use crate::{Mat3, Vec3};

/// Faces per rayon task in the parallel passes (large enough to amortise scheduling).
const CHUNK: usize = 4096;

/// A type usable as a vertex index of a face (`u32`, `i32`, `i64`, `u64`, `usize`).
pub trait FaceIndex: Copy + Send + Sync + std::fmt::Display {
    /// The index as `usize`, or `None` when it is negative or does not fit.
    fn to_index(self) -> Option<usize>;
}

macro_rules! face_index {
    ($($t:ty),*) => {$(
        impl FaceIndex for $t {
            #[inline]
            fn to_index(self) -> Option<usize> {
                usize::try_from(self).ok()
            }
        }
    )*};
}
face_index!(u32, i32, i64, u64, usize);

/// Mass properties of the solid bounded by a closed triangle mesh of uniform `density` (kg/m³).
///
/// `vertices` holds `3·n_v` coordinates (m), row-major `(n_v, 3)`; `faces` holds `3·n_f` vertex
/// indices, row-major `(n_f, 3)`, each face counter-clockwise seen from outside (normals by the
/// right-hand rule point out of the solid). The mesh is checked first (see the module docs) and
/// refused with an [`Error::mesh`] naming `faces` or `vertices` when it does not bound a solid;
/// `density` must be finite and `> 0`.
pub fn mesh_mass_properties<I: FaceIndex>(
    vertices: &[f64],
    faces: &[I],
    density: f64,
) -> Result<MassProperties> {
    check_positive("density", density)?;
    let tris = checked_arrays(vertices, faces)?;
    check_topology(vertices.len() / 3, &tris)?;
    integrate(vertices, &tris, density)
}

/// [`mesh_mass_properties`] for vertices as `[x, y, z]` rows and faces as `[i, j, k]` rows.
pub fn mesh_mass_properties_rows(
    vertices: &[[f64; 3]],
    faces: &[[u32; 3]],
    density: f64,
) -> Result<MassProperties> {
    mesh_mass_properties(vertices.as_flattened(), faces.as_flattened(), density)
}

/// Shapes, index ranges and finiteness; returns the faces as `u32` rows.
fn checked_arrays<I: FaceIndex>(vertices: &[f64], faces: &[I]) -> Result<Vec<[u32; 3]>> {
    if vertices.len() % 3 != 0 {
        return Err(Error::mesh(
            "vertices",
            format!("must have shape (N, 3), got {} values", vertices.len()),
        ));
    }
    if faces.len() % 3 != 0 {
        return Err(Error::mesh(
            "faces",
            format!("must have shape (M, 3), got {} values", faces.len()),
        ));
    }
    let nv = vertices.len() / 3;
    let nf = faces.len() / 3;
    if nf < 4 || nv < 4 {
        return Err(Error::mesh(
            "faces",
            format!(
                "a closed triangle mesh needs at least 4 faces and 4 vertices, got {nf} faces and \
                 {nv} vertices"
            ),
        ));
    }
    if nv > MAX_VERTICES {
        return Err(Error::mesh(
            "vertices",
            format!("at most {MAX_VERTICES} vertices are supported, got {nv}"),
        ));
    }
    // Indices: u32::MAX marks an index out of range (or negative).
    let tris: Vec<[u32; 3]> = faces
        .par_chunks_exact(3)
        .with_min_len(CHUNK)
        .map(|f| {
            let ix = |v: I| match v.to_index() {
                Some(i) if i < nv => i as u32,
                _ => u32::MAX,
            };
            [ix(f[0]), ix(f[1]), ix(f[2])]
        })
        .collect();
    let any_bad = tris
        .par_iter()
        .with_min_len(CHUNK)
        .any(|t| t.contains(&u32::MAX));
    if let Some(k) = any_bad
        .then(|| tris.iter().position(|t| t.contains(&u32::MAX)))
        .flatten()
    {
        let j = (0..3).find(|&j| tris[k][j] == u32::MAX).unwrap_or(0);
        return Err(Error::mesh(
            "faces",
            format!(
                "index {} at face {k} (corner {j}) is out of range: indices must be in [0, {nv}) \
                 for {nv} vertices",
                faces[3 * k + j]
            ),
        ));
    }
    // Non-finite coordinates: find the block, then the vertex.
    let block = 3 * CHUNK;
    if let Some(c) = vertices
        .par_chunks(block)
        .position_first(|c| !c.iter().all(|x| x.is_finite()))
    {
        let k = c * block
            + vertices[c * block..]
                .iter()
                .position(|x| !x.is_finite())
                .unwrap_or(0);
        let i = k / 3;
        return Err(Error::mesh(
            "vertices",
            format!(
                "must be finite, got {:?} at vertex {i}",
                [vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]]
            ),
        ));
    }
    Ok(tris)
}

/// The most vertices: the edge check packs a vertex index and a direction bit in a `u32`.
pub const MAX_VERTICES: usize = (u32::MAX >> 1) as usize;

/// A face with a repeated vertex index: no area, left out of the edge checks.
#[inline]
fn index_degenerate(t: &[u32; 3]) -> bool {
    t[0] == t[1] || t[1] == t[2] || t[2] == t[0]
}

/// The undirected edges of a face as `(low vertex, high vertex << 1 | direction)`, where the
/// direction bit is 1 when the face runs the edge from low to high.
#[inline]
fn half_edges(t: &[u32; 3]) -> [(u32, u32); 3] {
    let e = |a: u32, b: u32| {
        if a < b {
            (a, (b << 1) | 1)
        } else {
            (b, a << 1)
        }
    };
    [e(t[0], t[1]), e(t[1], t[2]), e(t[2], t[0])]
}

/// Counts of edge defects (each undirected edge counted once), with the lowest offending edge.
#[derive(Default, Clone, Copy)]
struct EdgeDefects {
    /// Edges used by one face only.
    boundary: u64,
    /// Edges used by more than two faces.
    non_manifold: u64,
    /// Edges used by two faces in the same direction.
    flipped: u64,
    first_boundary: Option<(u32, u32)>,
    first_non_manifold: Option<(u32, u32, u32)>,
    first_flipped: Option<(u32, u32)>,
}

fn min_opt<T: Copy + PartialOrd>(a: Option<T>, b: Option<T>) -> Option<T> {
    match (a, b) {
        (Some(x), Some(y)) => Some(if y < x { y } else { x }),
        (x, None) => x,
        (None, y) => y,
    }
}

impl EdgeDefects {
    fn merge(self, o: Self) -> Self {
        Self {
            boundary: self.boundary + o.boundary,
            non_manifold: self.non_manifold + o.non_manifold,
            flipped: self.flipped + o.flipped,
            first_boundary: min_opt(self.first_boundary, o.first_boundary),
            first_non_manifold: min_opt(self.first_non_manifold, o.first_non_manifold),
            first_flipped: min_opt(self.first_flipped, o.first_flipped),
        }
    }
}

/// Closed, manifold and consistently oriented, or an [`Error::mesh`] naming `faces`.
///
/// Each use of an undirected edge `{a, b}` (a < b) by a face is filed under `a` with `b` and
/// the direction bit ([`half_edges`]): a counting sort by low vertex into a compressed (CSR)
/// list, built in parallel without atomics by giving each rayon task its own range of low
/// vertices (each task scans all faces and files only its own edges). Then each vertex's short
/// list is sorted and its runs classified: one use is a boundary edge, more than two a
/// non-manifold edge, two uses in the same direction an inconsistent orientation.
fn check_topology(nv: usize, tris: &[[u32; 3]]) -> Result<()> {
    let tasks = rayon::current_num_threads().clamp(1, 64);
    let span = nv.div_ceil(tasks).max(1);
    // Per-vertex counts, each task filling its own range.
    let mut count = vec![0u32; nv];
    count.par_chunks_mut(span).enumerate().for_each(|(k, own)| {
        let lo = (k * span) as u32;
        let hi = lo + own.len() as u32;
        for t in tris {
            if index_degenerate(t) {
                continue;
            }
            for (a, _) in half_edges(t) {
                if a >= lo && a < hi {
                    own[(a - lo) as usize] += 1;
                }
            }
        }
    });
    // Offsets (exclusive prefix sums).
    let mut start = Vec::with_capacity(nv + 1);
    let mut acc = 0usize;
    for c in &count {
        start.push(acc);
        acc += *c as usize;
    }
    start.push(acc);
    drop(count);
    // Fill: the ranges of vertices map to disjoint ranges of the list.
    let mut list = vec![0u32; acc];
    let mut pieces = Vec::with_capacity(tasks);
    let mut rest = list.as_mut_slice();
    for k in 0..nv.div_ceil(span) {
        let (v0, v1) = (k * span, ((k + 1) * span).min(nv));
        let (piece, tail) = rest.split_at_mut(start[v1] - start[v0]);
        pieces.push((v0, v1, piece));
        rest = tail;
    }
    pieces.par_iter_mut().for_each(|(v0, v1, piece)| {
        let base = start[*v0];
        let mut cursor: Vec<usize> = start[*v0..*v1].iter().map(|s| s - base).collect();
        let (lo, hi) = (*v0 as u32, *v1 as u32);
        for t in tris {
            if index_degenerate(t) {
                continue;
            }
            for (a, entry) in half_edges(t) {
                if a >= lo && a < hi {
                    let c = &mut cursor[(a - lo) as usize];
                    piece[*c] = entry;
                    *c += 1;
                }
            }
        }
    });
    drop(pieces);
    // Classify, vertex by vertex, in parallel blocks of vertices.
    let mut blocks = Vec::new();
    let mut rest = list.as_mut_slice();
    let block = CHUNK;
    for v0 in (0..nv).step_by(block) {
        let v1 = (v0 + block).min(nv);
        let (piece, tail) = rest.split_at_mut(start[v1] - start[v0]);
        blocks.push((v0, v1, piece));
        rest = tail;
    }
    let defects = blocks
        .into_par_iter()
        .map(|(v0, v1, piece)| {
            let mut d = EdgeDefects::default();
            let base = start[v0];
            for a in v0..v1 {
                let edges = &mut piece[start[a] - base..start[a + 1] - base];
                edges.sort_unstable();
                let mut i = 0;
                while i < edges.len() {
                    let b = edges[i] >> 1;
                    let mut j = i;
                    let mut up = 0u32;
                    while j < edges.len() && edges[j] >> 1 == b {
                        up += edges[j] & 1;
                        j += 1;
                    }
                    let uses = (j - i) as u32;
                    let a = a as u32;
                    if uses == 1 {
                        d.boundary += 1;
                        d.first_boundary = min_opt(d.first_boundary, Some((a, b)));
                    } else if uses > 2 {
                        d.non_manifold += 1;
                        d.first_non_manifold = min_opt(d.first_non_manifold, Some((a, b, uses)));
                    } else if up != 1 {
                        d.flipped += 1;
                        d.first_flipped = min_opt(d.first_flipped, Some((a, b)));
                    }
                    i = j;
                }
            }
            d
        })
        .reduce(EdgeDefects::default, EdgeDefects::merge);
    // The first face using an edge (for the message; only on failure).
    let face_of = |a: u32, b: u32| {
        tris.par_iter()
            .position_first(|t| !index_degenerate(t) && t.contains(&a) && t.contains(&b))
            .map_or(String::new(), |k| format!(" of face {k}"))
    };
    let mut problems = Vec::new();
    if let Some((a, b)) = defects.first_boundary {
        problems.push(format!(
            "the mesh is open: {} boundary edge(s) are used by only one face (e.g. edge ({a}, {b}){}); \
             a mesh must be closed (watertight) to bound a solid",
            defects.boundary,
            face_of(a, b)
        ));
    }
    if let Some((a, b, uses)) = defects.first_non_manifold {
        problems.push(format!(
            "the mesh is non-manifold: {} edge(s) are shared by more than two faces (e.g. edge \
             ({a}, {b}) is used by {uses} faces)",
            defects.non_manifold
        ));
    }
    if let Some((a, b)) = defects.first_flipped {
        problems.push(format!(
            "faces are inconsistently oriented: {} edge(s) are traversed twice in the same \
             direction (e.g. edge ({a}, {b}){}); neighbouring faces must list a shared edge in \
             opposite directions",
            defects.flipped,
            face_of(a, b)
        ));
    }
    if problems.is_empty() {
        Ok(())
    } else {
        Err(Error::mesh("faces", problems.join("; ")))
    }
}

/// Sums over faces: `[Σ D, Σ D s (3), Σ D (a aᵀ + b bᵀ + c cᵀ + s sᵀ) (6: xx yy zz xy yz zx),
/// Σ |D|]` and the number of zero-area faces.
#[derive(Clone, Copy)]
struct Sums([f64; 11], u64);

impl Sums {
    fn zero() -> Self {
        Sums([0.0; 11], 0)
    }
    fn merge(mut self, o: Self) -> Self {
        for (x, y) in self.0.iter_mut().zip(o.0) {
            *x += y;
        }
        self.1 += o.1;
        self
    }
}

/// The exact polyhedral integrals (module docs), then mass, centre of mass and inertia.
fn integrate(vertices: &[f64], tris: &[[u32; 3]], density: f64) -> Result<MassProperties> {
    // Reference point: the centre of the bounding box.
    let (lo, hi) = vertices
        .par_chunks_exact(3)
        .with_min_len(CHUNK)
        .fold(
            || ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]),
            |(mut lo, mut hi), v| {
                for i in 0..3 {
                    lo[i] = lo[i].min(v[i]);
                    hi[i] = hi[i].max(v[i]);
                }
                (lo, hi)
            },
        )
        .reduce(
            || ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]),
            |(l1, h1), (l2, h2)| {
                (
                    [l1[0].min(l2[0]), l1[1].min(l2[1]), l1[2].min(l2[2])],
                    [h1[0].max(h2[0]), h1[1].max(h2[1]), h1[2].max(h2[2])],
                )
            },
        );
    let p0 = [
        0.5 * (lo[0] + hi[0]),
        0.5 * (lo[1] + hi[1]),
        0.5 * (lo[2] + hi[2]),
    ];
    let Sums(s, degenerate) = tris
        .par_iter()
        .with_min_len(CHUNK)
        .fold(Sums::zero, |mut acc, t| {
            let p = |i: u32| {
                let k = 3 * i as usize;
                let v = &vertices[k..k + 3];
                [v[0] - p0[0], v[1] - p0[1], v[2] - p0[2]]
            };
            let (a, b, c) = (p(t[0]), p(t[1]), p(t[2]));
            // Zero area: (b − a) × (c − a) = 0.
            let (u, w) = (
                [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
                [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            );
            let n = [
                u[1] * w[2] - u[2] * w[1],
                u[2] * w[0] - u[0] * w[2],
                u[0] * w[1] - u[1] * w[0],
            ];
            if n == [0.0; 3] {
                acc.1 += 1;
                return acc;
            }
            let bc = [
                b[1] * c[2] - b[2] * c[1],
                b[2] * c[0] - b[0] * c[2],
                b[0] * c[1] - b[1] * c[0],
            ];
            let d = a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2];
            let sv = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
            let m = &mut acc.0;
            m[0] += d;
            m[1] += d * sv[0];
            m[2] += d * sv[1];
            m[3] += d * sv[2];
            let q = |i: usize, j: usize| a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + sv[i] * sv[j];
            m[4] += d * q(0, 0);
            m[5] += d * q(1, 1);
            m[6] += d * q(2, 2);
            m[7] += d * q(0, 1);
            m[8] += d * q(1, 2);
            m[9] += d * q(2, 0);
            m[10] += d.abs();
            acc
        })
        .reduce(Sums::zero, Sums::merge);
    if degenerate as usize == tris.len() {
        return Err(Error::mesh(
            "faces",
            format!("all {} faces are degenerate (zero area)", tris.len()),
        ));
    }
    let six_volume = s[0];
    if six_volume.abs() <= 1e-12 * s[10] || six_volume == 0.0 {
        return Err(Error::mesh(
            "vertices",
            format!(
                "the mesh encloses zero volume (signed volume {:.3e} m³ against {:.3e} m³ of \
                 tetrahedra); a flat or collapsed mesh does not bound a solid",
                six_volume / 6.0,
                s[10] / 6.0
            ),
        ));
    }
    if six_volume < 0.0 {
        return Err(Error::mesh(
            "faces",
            format!(
                "faces are oriented inward; reverse the winding (e.g. faces[:, ::-1]) so that \
                 face normals point out of the solid (the total signed volume is {:.6e} m³ < 0)",
                six_volume / 6.0
            ),
        ));
    }
    let volume = six_volume / 6.0;
    // Centre of mass relative to p0, and second moments about it.
    let c = Vec3::new(s[1], s[2], s[3]) / (24.0 * volume);
    let second = Mat3::new(s[4], s[7], s[9], s[7], s[5], s[8], s[9], s[8], s[6]) / 120.0
        - c * c.transpose() * volume;
    let inertia = (Mat3::identity() * second.trace() - second) * density;
    let com = c + Vec3::from(p0);
    let mass = density * volume;
    if let Err(e) = tensor::check_inertia("inertia", &inertia) {
        return Err(Error::mesh(
            "faces",
            format!(
                "the mesh integrals give a non-physical inertia tensor ({}); is the mesh \
                 self-intersecting?",
                e.message
            ),
        ));
    }
    MassProperties::new(mass, com, inertia).map_err(|e| Error::mesh("faces", e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let v: Vec<[f64; 3]> = (0..8)
            .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64])
            .collect();
        let f = vec![
            [0, 2, 1],
            [1, 2, 3], // z = 0, normal −z
            [4, 5, 6],
            [5, 7, 6], // z = 1
            [0, 1, 4],
            [1, 5, 4], // y = 0
            [2, 6, 3],
            [3, 6, 7], // y = 1
            [0, 4, 2],
            [2, 4, 6], // x = 0
            [1, 3, 5],
            [3, 7, 5], // x = 1
        ];
        (v, f)
    }

    #[test]
    fn unit_cube() {
        let (v, f) = cube();
        let b = mesh_mass_properties_rows(&v, &f, 2.0).unwrap();
        assert!((b.mass() - 2.0).abs() < 1e-15);
        assert!((b.center_of_mass() - Vec3::new(0.5, 0.5, 0.5)).amax() < 1e-15);
        let expect = Mat3::identity() * (2.0 * 2.0 / 12.0);
        assert!((b.inertia() - expect).amax() < 1e-15, "{}", b.inertia());
    }

    #[test]
    fn refusals() {
        let (v, mut f) = cube();
        let open = &f[..11];
        let e = mesh_mass_properties_rows(&v, open, 1.0).unwrap_err();
        assert!(
            e.message.contains("open") && e.message.contains("3 boundary"),
            "{e}"
        );
        f[0] = [0, 1, 2];
        let e = mesh_mass_properties_rows(&v, &f, 1.0).unwrap_err();
        assert!(e.message.contains("inconsistently oriented"), "{e}");
        let inward: Vec<[u32; 3]> = cube().1.iter().map(|t| [t[0], t[2], t[1]]).collect();
        let e = mesh_mass_properties_rows(&v, &inward, 1.0).unwrap_err();
        assert!(e.message.contains("reverse the winding"), "{e}");
        let mut nm = cube().1;
        nm.push([0, 2, 1]);
        nm.push([0, 1, 2]);
        let e = mesh_mass_properties_rows(&v, &nm, 1.0).unwrap_err();
        assert!(e.message.contains("non-manifold"), "{e}");
        let mut bad = cube().1;
        bad[3] = [0, 1, 8];
        let e = mesh_mass_properties_rows(&v, &bad, 1.0).unwrap_err();
        assert!(
            e.message.contains("out of range") && e.argument == "faces",
            "{e}"
        );
        let e = mesh_mass_properties(
            v.as_flattened(),
            &[0i64, 1, -2, 3, 4, 5, 0, 2, 4, 1, 3, 5],
            1.0,
        )
        .unwrap_err();
        assert!(e.message.contains("-2"), "{e}");
        let mut nan = v.clone();
        nan[3][1] = f64::NAN;
        let e = mesh_mass_properties_rows(&nan, &cube().1, 1.0).unwrap_err();
        assert_eq!(e.argument, "vertices");
    }
}
