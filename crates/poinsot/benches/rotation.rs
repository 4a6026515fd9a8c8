//! Criterion benchmarks of `poinsot::rotation`: the batch kernels on 10⁵ rotations (rayon) and
//! the single-rotation functions. Peer comparisons (scipy) live in `bench/rotation_vs_scipy.py`.
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use poinsot::rotation::*;
use poinsot::Vec3;
use std::hint::black_box;

const N: usize = 100_000;

/// Deterministic angles in the canonical ranges of intrinsic zxz.
fn angles(n: usize) -> Vec<f64> {
    (0..3 * n)
        .map(|i| ((i as f64) * 0.618_033_988_749_895).fract() * 6.0 - 3.0)
        .collect()
}

fn batches(c: &mut Criterion) {
    let mut g = c.benchmark_group("rotation_batch");
    g.throughput(Throughput::Elements(N as u64));
    for name in ["zxz", "xyz"] {
        let seq = EulerSequence::new(name, true).unwrap();
        let a = angles(N);
        let mut mats = vec![0.0; 9 * N];
        g.bench_with_input(BenchmarkId::new("euler_to_matrix", name), &a, |b, a| {
            b.iter(|| euler_to_matrix_batch(seq, black_box(a), &mut mats).unwrap())
        });
        let mut out = vec![0.0; 3 * N];
        let mut locked = vec![false; N];
        g.bench_function(BenchmarkId::new("matrix_to_euler", name), |b| {
            b.iter(|| matrix_to_euler_batch(seq, black_box(&mats), &mut out, &mut locked).unwrap())
        });
    }
    let seq = EulerSequence::UNIT;
    let mut mats = vec![0.0; 9 * N];
    euler_to_matrix_batch(seq, &angles(N), &mut mats).unwrap();
    let mut quats = vec![0.0; 4 * N];
    g.bench_function("matrix_to_quaternion", |b| {
        b.iter(|| matrix_to_quaternion_batch(black_box(&mats), &mut quats).unwrap())
    });
    g.bench_function("quaternion_to_matrix", |b| {
        b.iter(|| quaternion_to_matrix_batch(black_box(&quats), false, &mut mats).unwrap())
    });
    let mut axes = vec![0.0; 4 * N];
    g.bench_function("rotation_axis", |b| {
        b.iter(|| rotation_axis_batch(black_box(&mats), &mut axes).unwrap())
    });
    g.finish();
}

fn singles(c: &mut Criterion) {
    let r = euler_to_matrix([0.3, 1.1, -2.0], EulerSequence::UNIT).unwrap();
    c.bench_function("matrix_to_euler single", |b| {
        b.iter(|| matrix_to_euler(black_box(&r), EulerSequence::UNIT).unwrap())
    });
    c.bench_function("screw_axis single", |b| {
        b.iter(|| screw_axis(black_box(&r), &Vec3::new(1.0, 2.0, 3.0)).unwrap())
    });
    c.bench_function("euler_rates single", |b| {
        b.iter(|| {
            euler_rates(
                black_box([0.3, 1.1, -2.0]),
                &Vec3::new(1.0, 2.0, 3.0),
                EulerSequence::UNIT,
                Frame::Body,
            )
            .unwrap()
        })
    });
}

criterion_group!(benches, batches, singles);
criterion_main!(benches);
