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
//! (exact for polynomials of degree ≤ 2; Tonon 2004). The second moments about the centre of
//! mass give the inertia `I = tr(C) 1 − C` (the unit's 2.61–2.62 with uniform ρ).
//!
//! **Accuracy and range.** Each closed component (faces connected across edges) is summed about
//! its own `p₀`, the centre of the box of the vertices **it** uses, on coordinates scaled by a
//! power of two to `[-2, 2]`; the components are then composed about their common centre of
//! mass by the parallel-axis theorem on the moments (exact for the signed volumes of cavities),
//! lengths and volumes carried in separate power-of-two units. So unused vertices play no part,
//! components far apart (two unit cubes 1e7 apart) keep their accuracy, and a mesh of 1e±100 m
//! neither overflows nor underflows: a mass or inertia beyond `f64::MAX`, or whose largest
//! moment is below the smallest normal double, is an [`Error::invalid`] naming `vertices` or
//! `density`. The physical check of the tensor allows 16 ε of the magnitude of what was summed
//! ([`tensor::check_inertia_scaled`]; for a convex body that is the largest moment, Drake's
//! tolerance).
//!
//! **Checks** (each refusal is an [`Error::mesh`] naming `faces` or `vertices` and saying what
//! is wrong and where): face indices in range; finite vertices; not every face degenerate;
//! closed (every edge shared by exactly two faces: the number of boundary edges is reported);
//! manifold (no edge shared by more than two faces); consistently oriented (each edge traversed
//! once in each direction); outward (positive total volume, else "faces are oriented inward;
//! reverse the winding"); non-zero volume; no self-intersection (two faces meeting beyond the
//! vertex or edge they share by index: "faces i and j intersect"); components nested properly
//! (a shell inside another of the same winding would be counted twice; a cavity must be inside
//! a solid). Faces with a repeated vertex index are degenerate (they have no area) and are left
//! out of the edge checks; faces of zero area with three distinct indices take part in them as
//! usual. The last two checks, with their limits, are in `mesh_embedding.rs`; a mesh of one
//! component that is star-shaped about its centre of mass is proved free of self-intersection
//! there in one pass over the faces, the others by testing the pairs of faces whose boxes meet.
//!
//! **Merging** ([`mesh_mass_properties_merging`], for triangle soups and CAD exports): vertices
//! within [`MERGE_RTOL`] (2^-22) of the largest coordinate magnitude of each other, in every
//! coordinate, and chains of them, become the lowest-numbered vertex of their group, before
//! the checks; an open mesh is then refused with the distance used.
//!
//! **Edge check without hashing.** Each use of an undirected edge `{a, b}` (`a < b`) by a face
//! is filed under its low vertex `a`, with `b`, a direction bit and the face, by a counting
//! sort into a compressed (CSR) list; each vertex's short list is then sorted and its runs
//! counted: one use is a boundary edge, more than two a non-manifold edge, two in the same
//! direction an inconsistent orientation; the two faces of a manifold edge are joined in a
//! lock-free union-find (the components). `O(n · degree)`, parallel (rayon: each task owns a
//! range of low vertices; no `unsafe`).

use std::sync::atomic::{AtomicBool, Ordering};

use rayon::prelude::*;

use crate::control::Cancel;
use crate::error::{check_positive, Error, Result};
use crate::inertia::body::MassProperties;
use crate::inertia::mesh_embedding::{
    probe_vertices, star_shaped_about, vertex_owners, Bounds, Index, Points, UnionFind, UNUSED,
};
use crate::inertia::scaling::{
    check_margins, check_range, exponent, exponent_of_max, ldexp, ldexp_mat, ldexp_vec, magnitude,
    split,
};
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
    // On a helper thread while this one polls the monitor: Ctrl-C stops it between phases.
    crate::control::parallel((faces.len() / 3) as u64, |cancel| {
        let (tris, all) = checked_arrays(vertices, faces)?;
        cancel.check()?;
        solid(vertices, &tris, all, density, None, cancel)
    })
}

/// [`mesh_mass_properties`] after merging the vertices that lie within [`MERGE_RTOL`] of the
/// largest coordinate magnitude of each other ([`merge_close_vertices`]): for triangle soups
/// (STL files store each triangle with its own three corners) and CAD exports, whose shared
/// corners may differ in the last bits (SolidWorks' STL files: by ~1e-18 m near zero). When
/// the merged mesh is still open, the error says within which distance vertices were merged.
pub fn mesh_mass_properties_merging<I: FaceIndex>(
    vertices: &[f64],
    faces: &[I],
    density: f64,
) -> Result<MassProperties> {
    check_positive("density", density)?;
    crate::control::parallel((faces.len() / 3) as u64, |cancel| {
        let (mut tris, all) = checked_arrays(vertices, faces)?;
        let tolerance = merge_close_vertices(vertices, &mut tris, cancel)?;
        solid(vertices, &tris, all, density, Some(tolerance), cancel)
    })
}

/// The checks and integrals of a mesh whose arrays are checked; `all`: the box of every
/// vertex ([`checked_arrays`]); `merged`: the distance within which vertices were merged (for
/// the messages), if they were.
fn solid(
    vertices: &[f64],
    tris: &[[u32; 3]],
    all: Bounds,
    density: f64,
    merged: Option<f64>,
    cancel: &Cancel,
) -> Result<MassProperties> {
    let (comp, ncomp, every_vertex_used) =
        check_topology(vertices.len() / 3, tris, merged, cancel)?;
    cancel.check()?;
    // The box of the used vertices is that of all when every vertex is used.
    let used_box = every_vertex_used.then_some(all);
    let parts = integrate_parts(vertices, tris, &comp, ncomp, used_box, cancel)?;
    cancel.check()?;
    let whole = match assemble(&parts, tris.len()) {
        Ok(whole) => whole,
        Err(err) => {
            // Several shells of zero or negative total volume: a shell of the wrong winding
            // (a cavity outside any solid, say) is the cause the nesting check names.
            if parts.len() > 1 {
                check_embedding(vertices, all, tris, &comp, &parts, None, cancel)?;
            }
            return Err(err);
        }
    };
    // The centre of mass: the point the star-shaped certificate tries first.
    let centre = (Vec3::from(whole.g) + ldexp_vec(&whole.com, whole.e)).into();
    check_embedding(vertices, all, tris, &comp, &parts, Some(centre), cancel)?;
    cancel.check()?;
    finish(&whole, density)
}

/// Vertices within this fraction of the largest coordinate magnitude of a mesh are one vertex
/// when merging ([`mesh_mass_properties_merging`]): `2^-22`, two units in the last place of
/// single precision, the precision of binary STL files (so corners that an exporter computed
/// twice and rounded apart still meet), far below any feature of a mesh stored at that
/// precision.
pub const MERGE_RTOL: f64 = 2.384_185_791_015_625e-7; // 2^-22

/// Merges the vertices used by `tris` that lie within `MERGE_RTOL · max |coordinate|` (the
/// largest coordinate magnitude of the used vertices), in the max norm, of each other, and
/// chains of such vertices: each face corner is replaced by the lowest index of its group
/// (whose coordinates are kept; the others become unused and play no part). Returns the
/// distance used (m). The vertices are filed in a grid of cells of that size and each is
/// compared with those of the 27 cells around it; exactly equal coordinates (−0.0 and 0.0
/// included) are always merged. Stops with [`crate::control::interrupted`] once `cancel` is set
/// (checked around the sort and every 4,096 vertices of the comparison).
pub fn merge_close_vertices(
    vertices: &[f64],
    tris: &mut [[u32; 3]],
    cancel: &Cancel,
) -> Result<f64> {
    let nv = vertices.len() / 3;
    let mut used = vec![false; nv];
    for t in tris.iter() {
        for &v in t {
            used[v as usize] = true;
        }
    }
    let scale = (0..nv)
        .filter(|&i| used[i])
        .flat_map(|i| vertices[3 * i..3 * i + 3].iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    let tolerance = MERGE_RTOL * scale;
    let cell = |x: f64| {
        if tolerance > 0.0 {
            (x / tolerance).floor() as i64
        } else {
            0
        }
    };
    let key = |i: usize| [0, 1, 2].map(|k| cell(vertices[3 * i + k]));
    let mut sorted: Vec<([i64; 3], u32)> = (0..nv)
        .into_par_iter()
        .filter(|&i| used[i])
        .map(|i| (key(i), i as u32))
        .collect();
    cancel.check()?;
    sorted.par_sort_unstable();
    let groups = UnionFind::new(nv);
    sorted.par_chunks(CHUNK).try_for_each(|chunk| {
        cancel.check()?;
        for &(k, i) in chunk {
            let p = &vertices[3 * i as usize..3 * i as usize + 3];
            for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        let c = [k[0] + dx, k[1] + dy, k[2] + dz];
                        let from = sorted.partition_point(|e| e.0 < c);
                        for &(_, j) in sorted[from..].iter().take_while(|e| e.0 == c) {
                            if j != i {
                                let q = &vertices[3 * j as usize..3 * j as usize + 3];
                                if (0..3).all(|m| (p[m] - q[m]).abs() <= tolerance) {
                                    groups.union(i, j);
                                }
                            }
                        }
                    }
                }
            }
        }
        Ok(())
    })?;
    tris.par_iter_mut().with_min_len(CHUNK).for_each(|t| {
        for v in t.iter_mut() {
            *v = groups.find(*v);
        }
    });
    Ok(tolerance)
}

/// Peak memory (bytes) per triangle of `RigidBody.load_mesh` reading a binary STL file with
/// trimesh and checking it: measured 2026-11-28 with trimesh 5.2 (the peak resident size grew
/// by 716 bytes per triangle for 81,920 triangles, 676 for 327,680), rounded up.
pub const MESH_FILE_BYTES_PER_TRIANGLE: usize = 768;

/// Checks that reading and checking a mesh file of `triangles` triangles fits in the memory
/// budget ([`MESH_FILE_BYTES_PER_TRIANGLE`] each); the error names `path` and the budget.
pub fn check_mesh_file(triangles: f64) -> Result<()> {
    crate::limits::check_bytes(
        "path",
        &format!("a mesh file of {} triangles", crate::error::num(triangles)),
        triangles * MESH_FILE_BYTES_PER_TRIANGLE as f64,
    )
}

/// [`mesh_mass_properties`] for vertices as `[x, y, z]` rows and faces as `[i, j, k]` rows.
pub fn mesh_mass_properties_rows(
    vertices: &[[f64; 3]],
    faces: &[[u32; 3]],
    density: f64,
) -> Result<MassProperties> {
    mesh_mass_properties(vertices.as_flattened(), faces.as_flattened(), density)
}

/// Shapes, index ranges and finiteness; returns the faces as `u32` rows and the box of all the
/// vertices (folded in the finiteness pass: no pass of its own).
fn checked_arrays<I: FaceIndex>(vertices: &[f64], faces: &[I]) -> Result<(Vec<[u32; 3]>, Bounds)> {
    if !vertices.len().is_multiple_of(3) {
        return Err(Error::mesh(
            "vertices",
            format!("must have shape (N, 3), got {} values", vertices.len()),
        ));
    }
    if !faces.len().is_multiple_of(3) {
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
    // Indices, converted and checked in one pass: u32::MAX marks an index out of range (or
    // negative).
    let mut tris = vec![[0u32; 3]; nf];
    let any_bad = tris
        .par_chunks_mut(CHUNK)
        .zip(faces.par_chunks(3 * CHUNK))
        .map(|(out, fs)| {
            let ix = |v: I| match v.to_index() {
                Some(i) if i < nv => i as u32,
                _ => u32::MAX,
            };
            let mut bad = false;
            for (t, f) in out.iter_mut().zip(fs.chunks_exact(3)) {
                *t = [ix(f[0]), ix(f[1]), ix(f[2])];
                bad |= t.contains(&u32::MAX);
            }
            bad
        })
        .reduce(|| false, |a, b| a || b);
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
    // Non-finite coordinates: find the block, then the vertex; the box of the vertices on the
    // way (order-independent where it is used: see integrate_parts).
    let block = 3 * CHUNK;
    let (finite, all) = vertices
        .par_chunks(block)
        .map(|c| {
            let rows = c.as_chunks::<3>().0;
            (
                c.iter().all(|x| x.is_finite()),
                Bounds::of(rows.iter().copied()),
            )
        })
        .reduce(
            || (true, Bounds::EMPTY),
            |(f1, b1), (f2, b2)| (f1 && f2, b1.union(b2)),
        );
    if let Some(c) = (!finite)
        .then(|| {
            vertices
                .chunks(block)
                .position(|c| !c.iter().all(|x| x.is_finite()))
        })
        .flatten()
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
    Ok((tris, all))
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

/// Entries filed by vertex, as a compressed (CSR) list: `file(f, t)` gives the face `f`'s up
/// to three `(vertex, entry)` pairs (the first `n` of the array it returns); the entries of
/// vertex `v` are `list[start[v]..start[v + 1]]`, in face order. A counting sort built in
/// parallel without atomics: each rayon task owns a range of vertices and scans every face,
/// filing only its own (the edge check files half-edges by their low vertex, the star proofs
/// faces by their corners).
pub(super) fn file_by_vertex<T, F>(
    nv: usize,
    tris: &[[u32; 3]],
    cancel: &Cancel,
    file: F,
) -> Result<(Vec<usize>, Vec<T>)>
where
    T: Copy + Default + Send + Sync,
    F: Fn(usize, &[u32; 3]) -> ([(u32, T); 3], usize) + Sync,
{
    let tasks = rayon::current_num_threads().clamp(1, 64);
    let span = nv.div_ceil(tasks).max(1);
    // Per-vertex counts, each task filling its own range.
    let mut count = vec![0u32; nv];
    count.par_chunks_mut(span).enumerate().for_each(|(k, own)| {
        let lo = (k * span) as u32;
        let hi = lo + own.len() as u32;
        for (f, t) in tris.iter().enumerate() {
            if f % POLL_FACES == 0 && cancel.check().is_err() {
                return;
            }
            let (entries, n) = file(f, t);
            for &(v, _) in &entries[..n] {
                if v >= lo && v < hi {
                    own[(v - lo) as usize] += 1;
                }
            }
        }
    });
    cancel.check()?;
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
    let mut list = vec![T::default(); acc];
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
        for (f, t) in tris.iter().enumerate() {
            if f % POLL_FACES == 0 && cancel.check().is_err() {
                return;
            }
            let (entries, n) = file(f, t);
            for &(v, entry) in &entries[..n] {
                if v >= lo && v < hi {
                    let c = &mut cursor[(v - lo) as usize];
                    piece[*c] = entry;
                    *c += 1;
                }
            }
        }
    });
    drop(pieces);
    cancel.check()?;
    Ok((start, list))
}

/// Faces scanned between two checks of the stop flag in the loops over every face.
const POLL_FACES: usize = 1 << 16;

/// Closed, manifold and consistently oriented, or an [`Error::mesh`] naming `faces`.
///
/// Each use of an undirected edge `{a, b}` (a < b) by a face is filed under `a` with `b` and
/// the direction bit ([`half_edges`]): a counting sort by low vertex into a compressed (CSR)
/// list, built in parallel without atomics by giving each rayon task its own range of low
/// vertices (each task scans all faces and files only its own edges). Then each vertex's short
/// list is sorted and its runs classified: one use is a boundary edge, more than two a
/// non-manifold edge, two uses in the same direction an inconsistent orientation.
/// On success, returns each face's component (faces connected across shared edges; `UNUSED`
/// for faces with a repeated index), the number of components, and whether every vertex is
/// used by a face with three distinct indices (an end of an edge filed: the low ends have a
/// list, the high ends are marked as the lists are read).
fn check_topology(
    nv: usize,
    tris: &[[u32; 3]],
    merged: Option<f64>,
    cancel: &Cancel,
) -> Result<(Vec<u32>, usize, bool)> {
    // Entries: (high vertex << 1 | direction) << 32 | face.
    let (start, mut list) = file_by_vertex(nv, tris, cancel, |f, t| {
        if index_degenerate(t) {
            return ([(0, 0); 3], 0);
        }
        let e = half_edges(t);
        let entry = |(a, d): (u32, u32)| (a, u64::from(d) << 32 | f as u64);
        ([entry(e[0]), entry(e[1]), entry(e[2])], 3)
    })?;
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
    let components = UnionFind::new(tris.len());
    let high_end: Vec<AtomicBool> = (0..nv).map(|_| AtomicBool::new(false)).collect();
    let defects = blocks
        .into_par_iter()
        .map(|(v0, v1, piece)| {
            let mut d = EdgeDefects::default();
            if cancel.check().is_err() {
                return d;
            }
            let base = start[v0];
            for a in v0..v1 {
                let edges = &mut piece[start[a] - base..start[a + 1] - base];
                edges.sort_unstable();
                let mut i = 0;
                while i < edges.len() {
                    let b = (edges[i] >> 33) as u32;
                    let mut j = i;
                    let mut up = 0u32;
                    while j < edges.len() && (edges[j] >> 33) as u32 == b {
                        up += ((edges[j] >> 32) & 1) as u32;
                        j += 1;
                    }
                    let uses = (j - i) as u32;
                    let a = a as u32;
                    high_end[b as usize].store(true, Ordering::Relaxed);
                    if uses == 2 {
                        // The two faces of a manifold edge are in one component.
                        components.union(edges[i] as u32, edges[i + 1] as u32);
                    }
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
    cancel.check()?;
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
             a mesh must be closed (watertight) to bound a solid{}",
            defects.boundary,
            face_of(a, b),
            merged.map_or(String::new(), |tol| format!(
                " (vertices were merged within {} m, {} of the largest coordinate magnitude; \
                 its gaps are wider)",
                crate::error::num(tol),
                crate::error::num(MERGE_RTOL)
            ))
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
    if !problems.is_empty() {
        return Err(Error::mesh("faces", problems.join("; ")));
    }
    let every_vertex_used = high_end
        .par_iter()
        .enumerate()
        .with_min_len(CHUNK)
        .all(|(v, h)| start[v + 1] > start[v] || h.load(Ordering::Relaxed));
    // Compact component labels, in order of each component's lowest face.
    let roots: Vec<u32> = (0..tris.len() as u32)
        .into_par_iter()
        .with_min_len(CHUNK)
        .map(|f| {
            if index_degenerate(&tris[f as usize]) {
                UNUSED
            } else {
                components.find(f)
            }
        })
        .collect();
    let mut label = vec![UNUSED; tris.len()];
    let mut n = 0u32;
    for (f, r) in roots.iter().enumerate() {
        if *r == f as u32 {
            label[f] = n;
            n += 1;
        }
    }
    let comp = roots
        .par_iter()
        .with_min_len(CHUNK)
        .map(|&r| {
            if r == UNUSED {
                UNUSED
            } else {
                label[r as usize]
            }
        })
        .collect();
    Ok((comp, n as usize, every_vertex_used))
}

/// The face sums of one component, on coordinates relative to its reference point `p` (the
/// centre of the box of its vertices) scaled by `2^-e` (its half-extent in `[1, 2)`):
/// `[Σ D, Σ D s (3), Σ D (a aᵀ + b bᵀ + c cᵀ + s sᵀ) (6: xx yy zz xy yz zx), Σ |D|,
/// Σ |D| (|a|² + |b|² + |c|² + |s|²)]`, and its number of zero-area faces.
#[derive(Clone, Copy)]
struct Part {
    p: [f64; 3],
    e: i32,
    s: [f64; 12],
    degenerate: u64,
}

/// The faces of one component, in fixed chunks of [`CHUNK`] (the chunks, and so the order of
/// the sums, depend on the mesh only).
#[derive(Clone, Copy)]
enum Faces<'a> {
    /// The only component: every face whose label is not `UNUSED`, chunked by face index
    /// (no list of members to build).
    All(&'a [u32]),
    /// The listed faces.
    Members(&'a [u32]),
}

impl Faces<'_> {
    fn chunks(self) -> usize {
        match self {
            Faces::All(comp) => comp.len().div_ceil(CHUNK),
            Faces::Members(m) => m.len().div_ceil(CHUNK),
        }
    }

    /// Calls `f` on each face of chunk `k`, in order.
    #[inline]
    fn each(self, k: usize, mut f: impl FnMut(usize)) {
        match self {
            Faces::All(comp) => {
                let hi = ((k + 1) * CHUNK).min(comp.len());
                for (i, &c) in comp[k * CHUNK..hi].iter().enumerate() {
                    if c != UNUSED {
                        f(k * CHUNK + i);
                    }
                }
            }
            Faces::Members(m) => {
                let hi = ((k + 1) * CHUNK).min(m.len());
                for &g in &m[k * CHUNK..hi] {
                    f(g as usize);
                }
            }
        }
    }
}

/// Integrates each component about a point of its own (module docs). (The star-shaped proof
/// of the embedding is a pass of its own: fused into this one it made the pass slower than
/// both apart on a 1.3 M-face sphere, 165–180 ms against 65–77 + 63–80 ms on one thread.)
/// `used_box`: the box of the vertices that faces outside `UNUSED` use, when it is known (the
/// box of all the vertices, when every one is used): a single component's box is then not
/// folded again from its faces' corners.
fn integrate_parts(
    vertices: &[f64],
    tris: &[[u32; 3]],
    comp: &[u32],
    ncomp: usize,
    used_box: Option<Bounds>,
    cancel: &Cancel,
) -> Result<Vec<Part>> {
    // Faces grouped by component (a counting sort), unless there is one.
    let mut start = vec![0usize; ncomp + 1];
    let mut members = Vec::new();
    if ncomp > 1 {
        for &c in comp {
            if c != UNUSED {
                start[c as usize + 1] += 1;
            }
        }
        for k in 0..ncomp {
            start[k + 1] += start[k];
        }
        members = vec![0u32; start[ncomp]];
        let mut cursor = start.clone();
        for (f, &c) in comp.iter().enumerate() {
            if c != UNUSED {
                members[cursor[c as usize]] = f as u32;
                cursor[c as usize] += 1;
            }
        }
    }
    // As rows: one bounds check per vertex read.
    let rows = vertices.as_chunks::<3>().0;
    let vertex = |i: u32| rows[i as usize];
    let parts = (0..ncomp)
        .into_par_iter()
        .map(|k| {
            let faces = if ncomp == 1 {
                Faces::All(comp)
            } else {
                Faces::Members(&members[start[k]..start[k + 1]])
            };
            // The box of the component's vertices (unused vertices play no part): the box of
            // the used vertices when there is one component, else a pass over its faces.
            let Bounds { lo, hi } = match used_box.filter(|b| ncomp == 1 && same_centre(b)) {
                Some(b) => b,
                None => (0..faces.chunks())
                    .into_par_iter()
                    .map(|c| {
                        let mut b = Bounds::EMPTY;
                        faces.each(c, |f| b = b.with(tris[f].map(vertex)));
                        b
                    })
                    .reduce(|| Bounds::EMPTY, Bounds::union),
            };
            // Halves first: no overflow for coordinates near ±1.8e308.
            let p = [0, 1, 2].map(|j| 0.5 * lo[j] + 0.5 * hi[j]);
            let half = (0..3).fold(0.0f64, |m, j| m.max(0.5 * hi[j] - 0.5 * lo[j]));
            let e = exponent(half);
            let ps = p.map(|x| ldexp(x, -e));
            // `x · 2^-e` is `ldexp(x, -e)`, bit for bit, whenever `2^-e` is a normal double
            // (a product by a power of two is exact, or rounds once in the subnormal range
            // as ldexp does): one multiplication instead of ldexp's branches, per coordinate.
            let unit = (-1022..=1023).contains(&-e).then(|| ldexp(1.0, -e));
            // Fixed chunks summed in order: the same sums (bit for bit) on any number of
            // threads (a rayon fold's pieces depend on which thread steals what).
            let sums: Vec<([f64; 12], u64)> = (0..faces.chunks())
                .into_par_iter()
                .map(|chunk| {
                    let (mut m, mut degenerate) = ([0.0; 12], 0u64);
                    if cancel.check().is_err() {
                        return (m, degenerate);
                    }
                    faces.each(chunk, |f| {
                        let raw = tris[f].map(vertex);
                        let q = |v: [f64; 3]| match unit {
                            Some(u) => [v[0] * u - ps[0], v[1] * u - ps[1], v[2] * u - ps[2]],
                            None => [0, 1, 2].map(|j| ldexp(v[j], -e) - ps[j]),
                        };
                        let (a, b, c) = (q(raw[0]), q(raw[1]), q(raw[2]));
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
                            degenerate += 1;
                            return;
                        }
                        let bc = [
                            b[1] * c[2] - b[2] * c[1],
                            b[2] * c[0] - b[0] * c[2],
                            b[0] * c[1] - b[1] * c[0],
                        ];
                        let d = a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2];
                        let sv = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
                        m[0] += d;
                        m[1] += d * sv[0];
                        m[2] += d * sv[1];
                        m[3] += d * sv[2];
                        let sq = |i: usize, j: usize| {
                            a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + sv[i] * sv[j]
                        };
                        m[4] += d * sq(0, 0);
                        m[5] += d * sq(1, 1);
                        m[6] += d * sq(2, 2);
                        m[7] += d * sq(0, 1);
                        m[8] += d * sq(1, 2);
                        m[9] += d * sq(2, 0);
                        m[10] += d.abs();
                        m[11] += d.abs() * (sq(0, 0) + sq(1, 1) + sq(2, 2));
                    });
                    (m, degenerate)
                })
                .collect();
            let (s, degenerate) = sums.iter().fold(([0.0; 12], 0u64), |(mut x, d1), (y, d2)| {
                for (a, b) in x.iter_mut().zip(y) {
                    *a += b;
                }
                (x, d1 + d2)
            });
            Part {
                p,
                e,
                s,
                degenerate,
            }
        })
        .collect();
    cancel.check()?;
    Ok(parts)
}

/// A box folded in another order (the vertices' instead of the faces' corners) has the same
/// bounds but for the sign of a zero bound (`min2` keeps the first of `−0.0` and `0.0`): `true`
/// when that sign cannot change the part's centre `½ lo + ½ hi` or half-extent, i.e. on each
/// axis a zero bound is met by a non-zero half of the other (`½ x ± 0 = ½ x` for `½ x ≠ 0`), so
/// that the sums are the same, bit for bit, whichever fold gave the box.
fn same_centre(b: &Bounds) -> bool {
    (0..3).all(|k| {
        (b.lo[k] != 0.0 || 0.5 * b.hi[k] != 0.0) && (b.hi[k] != 0.0 || 0.5 * b.lo[k] != 0.0)
    })
}

/// The signed volume of a part relative to the tetrahedra it was summed from: `+1`, `−1`, or
/// `0` for a component that encloses no volume (within round-off, as for the whole mesh).
fn part_sign(part: &Part) -> i8 {
    let (v, a) = (part.s[0], part.s[10]);
    if v.abs() <= ZERO_VOLUME_RTOL * a || v == 0.0 {
        0
    } else if v > 0.0 {
        1
    } else {
        -1
    }
}

/// A signed volume within this fraction of the volume of the tetrahedra summed is zero (the
/// round-off of the sum of `|D|`, with a wide margin: a real solid is far from it).
const ZERO_VOLUME_RTOL: f64 = 1e-12;

/// What to do when the mass properties leave the range of doubles.
const HINT: &str = "express the mesh and the density in other units (e.g. mm and g/mm³, or km)";

/// The whole mesh about the point `g`, with lengths in units of `2^e` and volumes in units of
/// `2^(3 ev)` (the largest component's scale: a tiny component far away neither underflows
/// nor spoils the others): volume, centre of mass, inertia per unit density (units
/// `2^(3 ev + 2 e)`), and the magnitude of what was summed into the inertia (its round-off
/// scale).
struct Whole {
    g: [f64; 3],
    e: i32,
    ev: i32,
    volume: f64,
    com: Vec3,
    inertia: Mat3,
    roundoff: f64,
}

/// Composes the parts about their common centre of mass (the parallel-axis theorem on the
/// moments, exact for signed volumes), after the volume checks.
fn assemble(parts: &[Part], nf: usize) -> Result<Whole> {
    let degenerate: u64 = parts.iter().map(|p| p.degenerate).sum();
    if parts.is_empty() || degenerate as usize == nf {
        return Err(Error::mesh(
            "faces",
            format!("all {nf} faces are degenerate (zero area)"),
        ));
    }
    // The common reference point and scales.
    let g = [0, 1, 2].map(|j| {
        let lo = parts.iter().fold(f64::INFINITY, |m, p| m.min(p.p[j]));
        let hi = parts.iter().fold(f64::NEG_INFINITY, |m, p| m.max(p.p[j]));
        0.5 * lo + 0.5 * hi
    });
    let half_offset = |p: &Part| [0, 1, 2].map(|j| 0.5 * p.p[j] - 0.5 * g[j]);
    let ev = parts.iter().map(|p| p.e).max().unwrap_or(0);
    let e = parts
        .iter()
        .map(|p| {
            let d = half_offset(p);
            if d == [0.0; 3] {
                p.e
            } else {
                p.e.max(exponent_of_max(&d) + 1)
            }
        })
        .max()
        .unwrap_or(0);
    // Per part: volume (2^3ev), offset from g (2^e), first moment about its point (2^(3ev+e)),
    // second moments about it and their round-off scale (2^(3ev+2e)).
    let scaled = |p: &Part| {
        let v = ldexp(p.s[0] / 6.0, 3 * (p.e - ev));
        let at = Vec3::from(half_offset(p).map(|x| ldexp(x, 1 - e)));
        let m1 = Vec3::new(p.s[1], p.s[2], p.s[3]).map(|x| ldexp(x / 24.0, 4 * p.e - 3 * ev - e));
        let s = p.s.map(|x| ldexp(x / 120.0, 5 * p.e - 3 * ev - 2 * e));
        let m2 = Mat3::new(s[4], s[7], s[9], s[7], s[5], s[8], s[9], s[8], s[6]);
        (v, at, m1, m2, s[11])
    };
    let mut volume = 0.0;
    let mut tetrahedra = 0.0;
    let mut first = Vec3::zeros();
    for p in parts {
        let (v, at, m1, _, _) = scaled(p);
        volume += v;
        tetrahedra += ldexp(p.s[10] / 6.0, 3 * (p.e - ev));
        first += at * v + m1;
    }
    if volume.abs() <= ZERO_VOLUME_RTOL * tetrahedra || volume == 0.0 {
        return Err(Error::mesh(
            "vertices",
            format!(
                "the mesh encloses zero volume (signed volume {} m³ against {} m³ of \
                 tetrahedra); a flat or collapsed mesh does not bound a solid",
                magnitude(volume, 3 * ev),
                magnitude(tetrahedra, 3 * ev)
            ),
        ));
    }
    if volume < 0.0 {
        return Err(Error::mesh(
            "faces",
            format!(
                "faces are oriented inward; reverse the winding (e.g. faces[:, ::-1]) so that \
                 face normals point out of the solid (the total signed volume is {} m³ < 0)",
                magnitude(volume, 3 * ev)
            ),
        ));
    }
    let com = first / volume;
    let mut second = Mat3::zeros();
    let mut roundoff = 0.0;
    for p in parts {
        let (v, at, m1, m2, r) = scaled(p);
        let d = at - com;
        second += m2 + m1 * d.transpose() + d * m1.transpose() + d * d.transpose() * v;
        roundoff += r + 2.0 * m1.norm() * d.norm() + v.abs() * d.norm_squared();
    }
    let inertia = Mat3::identity() * second.trace() - second;
    Ok(Whole {
        g,
        e,
        ev,
        volume,
        com,
        inertia,
        roundoff: 2.0 * roundoff,
    })
}

/// No self-intersection, and winding numbers 0 or 1 ([`mesh_embedding`]). A single component
/// that is star-shaped about `centre` is embedded by a theorem
/// ([`star_shaped_about`]: one pass over the faces); otherwise, or when that
/// proof fails, every pair of faces whose boxes meet is tested. `all`: the box of every
/// vertex ([`checked_arrays`]).
fn check_embedding(
    vertices: &[f64],
    all: Bounds,
    tris: &[[u32; 3]],
    comp: &[u32],
    parts: &[Part],
    centre: Option<[f64; 3]>,
    cancel: &Cancel,
) -> Result<()> {
    let pts = Points::with_bounds(vertices, all);
    if let (1, Some(c)) = (parts.len(), centre) {
        if star_shaped_about(pts, tris, |f| comp[f] == UNUSED, c, cancel)? {
            return Ok(());
        }
    }
    let index = Index::new(pts, tris, |f| comp[f] == UNUSED, cancel)?;
    let (count, first) = index.intersections(cancel)?;
    if let Some((i, j)) = first {
        return Err(Error::mesh(
            "faces",
            format!(
                "the mesh intersects itself: faces {i} and {j} intersect ({count} pair(s) of \
                 faces meet beyond a vertex or edge they share); a self-intersecting surface \
                 does not bound a solid, and where it overlaps the volume would be counted \
                 twice: repair it (e.g. a boolean union of the overlapping parts), or build the \
                 parts as separate bodies and combine them"
            ),
        ));
    }
    if parts.len() < 2 {
        return Ok(());
    }
    let owner = vertex_owners(vertices.len() / 3, tris, comp);
    let probes = probe_vertices(&index, tris, comp, &owner, parts.len());
    let bad = (0..parts.len()).into_par_iter().find_map_first(|k| {
        let sigma = part_sign(&parts[k]);
        if sigma == 0 {
            return None;
        }
        let Some((f, v)) = probes[k] else {
            return Some(format!(
                "the closed component that includes face {} shares every vertex with other \
                 components, so which side of them it lies on cannot be decided; separate it",
                comp.iter().position(|&c| c == k as u32).unwrap_or(0)
            ));
        };
        let k32 = k as u32;
        let w = match index.winding(pts_at(pts, v), |g| comp[g] != k32) {
            Some(w) => w,
            None => {
                return Some(format!(
                    "the closed component that includes face {f} touches another component at \
                     vertex {v}"
                ))
            }
        };
        match (sigma, w) {
            (1, 0) | (-1, 1) => None,
            (1, 1) => Some(format!(
                "the closed component that includes face {f} lies inside another component \
                 of the same orientation, so its volume would be counted twice; if it is \
                 meant as a cavity, reverse its winding (normals pointing into the cavity)"
            )),
            (-1, 0) => Some(format!(
                "the closed component that includes face {f} is oriented inward (a cavity) \
                 but is not inside any solid; reverse its winding"
            )),
            (s, w) => Some(format!(
                "the closed component that includes face {f} lies where the other components \
                 already have winding number {w}, so the solid would be counted {} times \
                 there",
                w + i64::from(s)
            )),
        }
    });
    match bad {
        Some(message) => Err(Error::mesh("faces", message)),
        None => Ok(()),
    }
}

/// Vertex `v` of the scaled mesh.
fn pts_at(pts: Points<'_>, v: u32) -> [f64; 3] {
    pts.point(v)
}

/// Mass, centre of mass and inertia in SI units from the composed mesh, checked against the
/// range of doubles and (allowing for the round-off of the sums) physically.
fn finish(whole: &Whole, density: f64) -> Result<MassProperties> {
    let (rho, er) = split(density);
    let (km, ki) = (3 * whole.ev, 3 * whole.ev + 2 * whole.e);
    let blame = |k: i32| {
        if er.abs() > k.abs() {
            "density"
        } else {
            "vertices"
        }
    };
    let m = rho * whole.volume;
    check_range(blame(km), "the mass (kg)", m, er + km, HINT)?;
    let i = whole.inertia * rho;
    check_range(
        blame(ki),
        "the largest moment of inertia (kg·m²)",
        i.amax(),
        er + ki,
        HINT,
    )?;
    check_margins(blame(ki), tensor::moments_of(&i), er + ki, HINT)?;
    let checked =
        tensor::check_inertia_scaled("inertia", &whole.inertia, whole.roundoff).map_err(|err| {
            Error::mesh(
                "faces",
                format!(
                    "the mesh integrals give a non-physical inertia tensor even allowing for \
                     their round-off ({}); the mesh is too thin or too detailed for double \
                     precision",
                    err.message
                ),
            )
        })?;
    let inertia = ldexp_mat(&(checked * rho), er + ki);
    let com = Vec3::from(whole.g) + ldexp_vec(&whole.com, whole.e);
    Ok(MassProperties::from_parts(ldexp(m, er + km), com, inertia))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The merge (a grid of cells of the tolerance) groups exactly the vertices that a comparison of
    /// every pair groups (chains included), on clustered random points at scales from 1e-300
    /// to 1e300; and it stops when cancelled.
    #[test]
    fn merging_matches_all_pairs_and_stops_when_cancelled() {
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for scale in [1e-300, 1.0, 1e300] {
            // 2000 points about 60 centres: a third spread over ~4 tolerances (some pairs merge,
            // some only through chains, some not), the others within a twentieth of one.
            let mut v = Vec::new();
            let centres: Vec<[f64; 3]> = (0..60)
                .map(|_| [next() - 0.5, next() - 0.5, next() - 0.5])
                .collect();
            for k in 0..2000 {
                let c = centres[k % 60];
                let spread = if k % 3 == 0 { 1e-6 } else { 1e-8 };
                for x in c {
                    v.push(scale * (x + spread * (next() - 0.5)));
                }
            }
            let n = v.len() / 3;
            let tris: Vec<[u32; 3]> = (0..n as u32 - 2).map(|i| [i, i + 1, i + 2]).collect();
            let mut merged = tris.clone();
            let tol = merge_close_vertices(&v, &mut merged, &Cancel::new(1)).unwrap();
            let all = UnionFind::new(n);
            for i in 0..n {
                for j in i + 1..n {
                    if (0..3).all(|m| (v[3 * i + m] - v[3 * j + m]).abs() <= tol) {
                        all.union(i as u32, j as u32);
                    }
                }
            }
            let want: Vec<[u32; 3]> = tris.iter().map(|t| t.map(|x| all.find(x))).collect();
            assert_eq!(merged, want, "scale {scale}");
            // Negative controls: some merged, and not all of a cluster's points into one.
            assert_ne!(merged, tris, "nothing merged at scale {scale}");
            let roots: std::collections::BTreeSet<u32> = merged.iter().flatten().copied().collect();
            assert!(roots.len() > 120, "{} groups at scale {scale}", roots.len());
            let cancel = Cancel::new(1);
            cancel.cancel();
            assert!(merge_close_vertices(&v, &mut tris.clone(), &cancel).is_err());
        }
    }

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

    /// The sums are taken in fixed chunks and added in order: the same mass properties, bit
    /// for bit, on 1, 2 and 3 threads (a rayon fold's pieces depend on which thread steals
    /// what; the 1.3 M-face icosphere's mass differed in its last digits between two calls).
    #[test]
    fn same_bits_on_any_number_of_threads() {
        // A UV sphere of 100 × 200 quads split in two: 39,800 faces, ten chunks.
        let (v, f) = wound_sphere(100, 200, 1.0);
        assert!(f.len() > 8 * CHUNK);
        let on = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| mesh_mass_properties_rows(&v, &f, 1.0).unwrap())
        };
        let one = on(1);
        // A sphere's volume, as a check that the mesh is the intended one.
        assert!((one.mass() - 4.0 / 3.0 * std::f64::consts::PI).abs() < 2e-3);
        for threads in [2, 3] {
            for _ in 0..5 {
                let other = on(threads);
                assert_eq!(other.mass().to_bits(), one.mass().to_bits());
                assert_eq!(other.center_of_mass(), one.center_of_mass());
                assert_eq!(other.inertia(), one.inertia());
            }
        }
    }

    /// A UV sphere of radius 1 (`n − 1` rings of `m` vertices and two poles) whose meridians
    /// wind `turns` times around the axis, outward.
    fn wound_sphere(n: usize, m: usize, turns: f64) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
        let mut v = vec![[0.0, 0.0, 1.0]];
        for k in 1..n {
            let th = std::f64::consts::PI * k as f64 / n as f64;
            for j in 0..m {
                let ph = turns * 2.0 * std::f64::consts::PI * j as f64 / m as f64;
                v.push([th.sin() * ph.cos(), th.sin() * ph.sin(), th.cos()]);
            }
        }
        v.push([0.0, 0.0, -1.0]);
        let ring = |k: usize, j: usize| (1 + (k - 1) * m + j % m) as u32;
        let south = (1 + (n - 1) * m) as u32;
        let mut f = Vec::new();
        for j in 0..m {
            f.push([0, ring(1, j), ring(1, j + 1)]);
            for k in 1..n - 1 {
                let (a, b) = (ring(k, j), ring(k, j + 1));
                let (c, d) = (ring(k + 1, j + 1), ring(k + 1, j));
                f.push([a, d, c]);
                f.push([a, c, b]);
            }
            f.push([south, ring(n - 1, j + 1), ring(n - 1, j)]);
        }
        (v, f)
    }

    /// Issue 21, item 17: the star-shaped certificate (a single component, every face facing
    /// away from the centre of mass, every vertex's fan winding once about it) stands in for
    /// the pairwise self-intersection check only where it is a proof: a sphere is accepted
    /// with its volume; a sphere wound twice (every face facing away from the centre, but
    /// covering the sphere twice) and a torus (not star-shaped: the pairwise check decides)
    /// are judged as by the pairwise check, refused and accepted.
    #[test]
    fn star_shaped_certificate_in_the_checks() {
        let (v, f) = wound_sphere(40, 60, 1.0);
        let pts = Points::new(v.as_flattened());
        assert!(star_shaped_about(pts, &f, |_| false, [0.0; 3], &Cancel::new(0)).unwrap());
        let b = mesh_mass_properties_rows(&v, &f, 1.0).unwrap();
        assert!((b.mass() - 4.0 / 3.0 * std::f64::consts::PI).abs() < 0.02);
        let (v, f) = wound_sphere(40, 61, 2.0);
        let pts = Points::new(v.as_flattened());
        assert!(!star_shaped_about(pts, &f, |_| false, [0.0; 3], &Cancel::new(0)).unwrap());
        let e = mesh_mass_properties_rows(&v, &f, 1.0).unwrap_err();
        assert!(e.message.contains("intersects itself"), "{e}");
        // A torus of radii 1 and 0.3: volume 2π² R r².
        let (nu, nw) = (48usize, 24usize);
        let mut v = Vec::new();
        for i in 0..nu {
            let u = 2.0 * std::f64::consts::PI * i as f64 / nu as f64;
            for j in 0..nw {
                let w = 2.0 * std::f64::consts::PI * j as f64 / nw as f64;
                let r = 1.0 + 0.3 * w.cos();
                v.push([r * u.cos(), r * u.sin(), 0.3 * w.sin()]);
            }
        }
        let at = |i: usize, j: usize| ((i % nu) * nw + j % nw) as u32;
        let mut f = Vec::new();
        for i in 0..nu {
            for j in 0..nw {
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                f.push([a, b, c]);
                f.push([a, c, d]);
            }
        }
        let pts = Points::new(v.as_flattened());
        assert!(!star_shaped_about(pts, &f, |_| false, [0.0; 3], &Cancel::new(0)).unwrap());
        let b = mesh_mass_properties_rows(&v, &f, 1.0).unwrap();
        let exact = 2.0 * std::f64::consts::PI.powi(2) * 0.3 * 0.3;
        assert!((b.mass() - exact).abs() < 0.02 * exact, "{}", b.mass());
    }

    /// Issue 21 item 17: a single component's box comes from the vertices' box (folded in the
    /// finiteness pass) when the edge check finds every vertex used, and the sums are then the
    /// same, bit for bit, as from the box of the faces' corners; a vertex that no face uses, or
    /// only a face with a repeated index, is seen (the box is then folded from the faces), and
    /// signed zeros on the box are harmless (`same_centre`).
    #[test]
    fn vertex_box_stands_in_for_the_faces_box() {
        let run = |v: &[[f64; 3]], f: &[[u32; 3]]| {
            let cancel = Cancel::new(0);
            let (tris, all) = checked_arrays(v.as_flattened(), f.as_flattened()).unwrap();
            let (comp, ncomp, used) = check_topology(v.len(), &tris, None, &cancel).unwrap();
            let slow = integrate_parts(v.as_flattened(), &tris, &comp, ncomp, None, &cancel);
            let fast = integrate_parts(v.as_flattened(), &tris, &comp, ncomp, Some(all), &cancel);
            let bits = |parts: Vec<Part>| -> Vec<(Vec<u64>, i32, u64)> {
                parts
                    .iter()
                    .map(|p| {
                        let mut x: Vec<u64> = p.p.iter().map(|y| y.to_bits()).collect();
                        x.extend(p.s.iter().map(|y| y.to_bits()));
                        (x, p.e, p.degenerate)
                    })
                    .collect()
            };
            let same = bits(slow.unwrap()) == bits(fast.unwrap());
            (used, all, same)
        };
        // A sphere: every vertex used, the two boxes' sums agree.
        let (v, f) = wound_sphere(30, 40, 1.0);
        let (used, _, same) = run(&v, &f);
        assert!(used && same);
        // A cube with −0.0 and 0.0 on its lower bounds (in both orders).
        let (mut v, f) = cube();
        for (i, p) in v.iter_mut().enumerate() {
            for x in p.iter_mut() {
                if *x == 0.0 && i % 2 == 1 {
                    *x = -0.0;
                }
            }
        }
        let (used, all, same) = run(&v, &f);
        assert!(used && same && same_centre(&all));
        // A far vertex that no face uses: not every vertex is used, and its box is not the
        // component's.
        let (mut v, f) = cube();
        v.push([1e6, 0.0, 0.0]);
        let (used, all, _) = run(&v, &f);
        assert!(!used && all.hi[0] == 1e6);
        // A vertex only in a face with a repeated index: not used either.
        let (mut v, mut f) = cube();
        v.push([-5.0, 0.0, 0.0]);
        f.push([8, 8, 0]);
        let (used, _, _) = run(&v, &f);
        assert!(!used);
        // Zero bounds whose sign would matter: the faces' fold decides.
        let flat = Bounds {
            lo: [-0.0, 0.0, -1.0],
            hi: [0.0, 1.0, 1.0],
        };
        assert!(!same_centre(&flat));
        let tiny = Bounds {
            lo: [-f64::from_bits(1), 0.0, -1.0],
            hi: [0.0, 1.0, 1.0],
        };
        assert!(!same_centre(&tiny));
    }

    /// The indices are converted and checked in one pass by chunks: the first index out of
    /// range (or negative) is named with its face and corner wherever it lies, also in a
    /// later chunk and in the last, partial one.
    #[test]
    fn bad_indices_are_named_in_any_chunk() {
        let (v, f) = wound_sphere(60, 80, 1.0);
        assert!(f.len() > 2 * CHUNK);
        let nv = v.len() as i64;
        let flat: Vec<i64> = f.as_flattened().iter().map(|&i| i64::from(i)).collect();
        for (k, j, bad) in [(2 * CHUNK + 5, 1, nv), (f.len() - 1, 2, -1), (0, 0, nv + 7)] {
            let mut g = flat.clone();
            g[3 * k + j] = bad;
            let later = (k + 1..f.len()).next().map(|m| 3 * m);
            if let Some(m) = later {
                g[m] = -5; // a later bad index: the first is named
            }
            let e = mesh_mass_properties(v.as_flattened(), &g, 1.0).unwrap_err();
            assert_eq!(e.argument, "faces");
            let want = format!("index {bad} at face {k} (corner {j}) is out of range");
            assert!(e.message.contains(&want), "{}", e.message);
        }
        assert!(mesh_mass_properties(v.as_flattened(), &flat, 1.0).is_ok());
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
