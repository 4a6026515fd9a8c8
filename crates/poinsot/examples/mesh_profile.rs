//! A fixed workload for instruction counts of `mesh_mass_properties` (the whole call, checks
//! included): an icosphere (the star-shaped proof) and a torus (the pairwise tests).
//!
//! `RAYON_NUM_THREADS=1 valgrind --tool=callgrind target/release/examples/mesh_profile
//! [ico|torus] [size] [repeat]`. Sizes: icosphere subdivisions (6: 81,920 faces), torus
//! meridians (256: 256 × 128 × 2 = 65,536 faces).

use std::collections::HashMap;

use poinsot::inertia::mesh_mass_properties_rows;

type P3 = [f64; 3];

/// The icosahedron subdivided `sub` times, projected onto the unit sphere (outward).
fn icosphere(sub: usize) -> (Vec<P3>, Vec<[u32; 3]>) {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let norm = |p: P3| {
        let n = (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
        [p[0] / n, p[1] / n, p[2] / n]
    };
    let mut v: Vec<P3> = [
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ]
    .map(norm)
    .to_vec();
    let mut f: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..sub {
        let mut mid = HashMap::new();
        let mut nf = Vec::with_capacity(f.len() * 4);
        for t in &f {
            let mut m = [0u32; 3];
            for i in 0..3 {
                let (a, b) = (t[i].min(t[(i + 1) % 3]), t[i].max(t[(i + 1) % 3]));
                m[i] = *mid.entry((a, b)).or_insert_with(|| {
                    let (pa, pb) = (v[a as usize], v[b as usize]);
                    v.push(norm([
                        (pa[0] + pb[0]) / 2.0,
                        (pa[1] + pb[1]) / 2.0,
                        (pa[2] + pb[2]) / 2.0,
                    ]));
                    (v.len() - 1) as u32
                });
            }
            nf.extend([
                [t[0], m[0], m[2]],
                [t[1], m[1], m[0]],
                [t[2], m[2], m[1]],
                [m[0], m[1], m[2]],
            ]);
        }
        f = nf;
    }
    (v, f)
}

/// A torus of radii 1 and 0.35, `n` meridians of `n / 2` points, split into triangles.
fn torus(n: usize) -> (Vec<P3>, Vec<[u32; 3]>) {
    let m = n / 2;
    let (big, small) = (1.0, 0.35);
    let mut v = Vec::with_capacity(n * m);
    for i in 0..n {
        let u = std::f64::consts::TAU * i as f64 / n as f64;
        for j in 0..m {
            let w = std::f64::consts::TAU * j as f64 / m as f64;
            let r = big + small * w.cos();
            v.push([r * u.cos(), r * u.sin(), small * w.sin()]);
        }
    }
    let id = |i: usize, j: usize| ((i % n) * m + j % m) as u32;
    let mut f = Vec::with_capacity(2 * n * m);
    for i in 0..n {
        for j in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            f.push([a, b, c]);
            f.push([a, c, d]);
        }
    }
    (v, f)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map_or("ico", String::as_str);
    let size = args.get(2).and_then(|s| s.parse().ok());
    let (v, f) = match which {
        "torus" => torus(size.unwrap_or(256)),
        _ => icosphere(size.unwrap_or(6)),
    };
    let repeat: usize = args.get(3).and_then(|s| s.parse().ok()).unwrap_or(1);
    for _ in 0..repeat {
        let t0 = std::time::Instant::now();
        let mp = mesh_mass_properties_rows(&v, &f, 1.0).expect("a solid");
        eprintln!(
            "{which}: {} faces, mass {:.12}, {:?}",
            f.len(),
            mp.mass(),
            t0.elapsed()
        );
    }
}
