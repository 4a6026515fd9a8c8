//! Criterion benchmarks of `poinsot::inertia`: the closed triangle mesh path (topology checks
//! plus exact integrals) at 10⁵ and ~10⁶ triangles, the density cubature of a smooth density,
//! and the small per-body operations (principal axes, composition).
//!
//! `cargo bench -p poinsot --bench inertia`
use std::f64::consts::PI;
use std::hint::black_box;

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use poinsot::inertia::{self, CubatureOptions, MassProperties};
use poinsot::{Mat3, Vec3};

/// A closed UV sphere with `n` rings of `2n` vertices: 4n(n − 1) triangles.
fn uv_sphere(n: usize) -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let m = 2 * n;
    let mut v = vec![[0.0, 0.0, -1.0]];
    for i in 1..n {
        let t = PI * i as f64 / n as f64;
        for j in 0..m {
            let p = 2.0 * PI * j as f64 / m as f64;
            v.push([t.sin() * p.cos(), t.sin() * p.sin(), -t.cos()]);
        }
    }
    let top = v.len() as u32;
    v.push([0.0, 0.0, 1.0]);
    let at = |i: usize, j: usize| (1 + i * m + j % m) as u32;
    let mut f = Vec::new();
    for j in 0..m {
        f.push([0, at(0, j + 1), at(0, j)]);
    }
    for i in 0..n - 2 {
        for j in 0..m {
            f.push([at(i, j), at(i, j + 1), at(i + 1, j + 1)]);
            f.push([at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    for j in 0..m {
        f.push([top, at(n - 2, j), at(n - 2, j + 1)]);
    }
    (v, f)
}

fn mesh(c: &mut Criterion) {
    let mut g = c.benchmark_group("mesh_mass_properties");
    g.sample_size(20);
    for n in [160usize, 500] {
        let (v, f) = uv_sphere(n);
        g.throughput(Throughput::Elements(f.len() as u64));
        g.bench_with_input(
            BenchmarkId::from_parameter(f.len()),
            &(v, f),
            |b, (v, f)| {
                b.iter(|| {
                    inertia::mesh_mass_properties_rows(black_box(v), black_box(f), 1.0).unwrap()
                })
            },
        );
    }
    g.finish();
}

fn density(c: &mut Criterion) {
    let mut g = c.benchmark_group("density_mass_properties");
    g.sample_size(10);
    g.bench_function("gaussian_rtol_1e-6", |b| {
        b.iter(|| {
            inertia::density_mass_properties(
                |p: &[[f64; 3]], out: &mut [f64]| {
                    for (x, o) in p.iter().zip(out.iter_mut()) {
                        *o = (-(x[0] * x[0] + 2.0 * x[1] * x[1] + 3.0 * x[2] * x[2])).exp();
                    }
                    Ok(())
                },
                [[-6.0, 6.0], [-5.0, 5.0], [-4.0, 4.0]],
                &CubatureOptions::default(),
            )
            .unwrap()
        })
    });
    g.finish();
}

fn small(c: &mut Criterion) {
    let r = {
        let (s, co) = 0.7f64.sin_cos();
        Mat3::new(co, -s, 0.0, s, co, 0.0, 0.0, 0.0, 1.0)
    };
    let body = MassProperties::new(
        2.0,
        Vec3::new(0.1, 0.2, 0.3),
        r * Mat3::from_diagonal(&Vec3::new(1.0, 2.0, 2.5)) * r.transpose(),
    )
    .unwrap();
    c.bench_function("principal_axes", |b| {
        b.iter(|| black_box(&body).principal(1e-9))
    });
    let parts: Vec<MassProperties> = (0..8)
        .map(|k| body.translated(&Vec3::new(k as f64, 0.0, 0.0)).unwrap())
        .collect();
    c.bench_function("combine_8", |b| {
        b.iter(|| MassProperties::combine(black_box(&parts)).unwrap())
    });
    c.bench_function("holding_torque", |b| {
        b.iter(|| {
            black_box(&body)
                .holding_torque(&Vec3::new(0.1, 0.2, 3.0), None)
                .unwrap()
        })
    });
}

criterion_group!(benches, mesh, density, small);
criterion_main!(benches);
