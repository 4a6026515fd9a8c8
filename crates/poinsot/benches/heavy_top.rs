//! Criterion benchmarks of the heavy top: construction (roots, elliptic constants, Fourier
//! coefficients), one exact evaluation by the Fourier fast path and by Carlson's R_J, and a
//! batch of 10⁶ times (the figure bench/heavy_top_vs_scipy.py compares with scipy).
use criterion::{criterion_group, criterion_main, Criterion};
use poinsot::analytic::{EulerState, HeavyTop};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let state = EulerState {
        theta: 0.8,
        theta_dot: 0.3,
        phi_dot: 0.6,
        psi_dot: 6.0,
        ..Default::default()
    };
    c.bench_function("HeavyTop::new (loops)", |b| {
        b.iter(|| HeavyTop::new(1.0, 0.5, 1.0, black_box(state)).unwrap())
    });
    let top = HeavyTop::new(1.0, 0.5, 1.0, state).unwrap();
    c.bench_function("HeavyTop::euler_angles (Fourier)", |b| {
        b.iter(|| top.euler_angles(black_box(12.345)).unwrap())
    });
    c.bench_function("HeavyTop::euler_angles_carlson (sn, R_J)", |b| {
        b.iter(|| top.euler_angles_carlson(black_box(12.345)).unwrap())
    });
    let n = 1_000_000;
    let times: Vec<f64> = (0..n).map(|k| 1000.0 * k as f64 / n as f64).collect();
    let mut out = vec![0.0; 3 * n];
    let mut group = c.benchmark_group("batch");
    group.sample_size(10);
    group.bench_function("HeavyTop::euler_angles_into, 10^6 times", |b| {
        b.iter(|| top.euler_angles_into(black_box(&times), &mut out).unwrap())
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
