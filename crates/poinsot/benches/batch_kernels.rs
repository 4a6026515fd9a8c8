//! Criterion benchmarks of the batch kernels on SIMD lanes (issue 15), each next to the peer its
//! target is a ratio against, measured in the same run: batch RK4 (10⁶ bodies × 20 steps) and
//! one core's single-body `simulate` (10⁴ RK4 steps); the splittings; the exact free-body states
//! (10³ bodies × 10³ times); the heavy top's exact angles at 10⁶ times — each with rayon's pool
//! of 1 and of 2 threads (`ThreadPoolBuilder::num_threads`). Throughputs are printed per element
//! (body-steps, states, output times): `cargo bench -p poinsot --bench batch_kernels`.
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use poinsot::analytic::{free_body_states, EulerState, HeavyTop, StateTimes};
use poinsot::dynamics::{simulate, simulate_batch, BodyInertia, Method, SimulateOptions, Torque};
use poinsot::Vec3;
use std::hint::black_box;

/// N bodies with different moments and initial states (none of the lanes alike).
fn bodies(n: usize) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let moments = (0..n)
        .map(|i| [1.0, 1.5 + 0.4 * ((i as f64) * 0.37).sin().abs(), 2.2])
        .collect();
    let omega = (0..n)
        .map(|i| {
            let a = i as f64;
            [
                (a * 0.7).cos(),
                0.1 + (a * 1.3).sin(),
                1.0 + 0.3 * (a * 0.11).cos(),
            ]
        })
        .collect();
    (moments, omega)
}

fn pool(threads: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap()
}

fn bench(c: &mut Criterion) {
    // One core's single-body rate (the peer of the batch's ratio): 10⁴ RK4 steps.
    let mut single = c.benchmark_group("single body");
    single.throughput(Throughput::Elements(10_000));
    let inertia = BodyInertia::from_moments([1.0, 2.0, 3.0]).unwrap();
    let opts = SimulateOptions {
        method: Method::Rk4,
        dt: Some(1e-3),
        samples: 2,
        ..SimulateOptions::default()
    };
    single.bench_function("simulate rk4: 10⁴ steps (body-steps)", |b| {
        b.iter(|| {
            simulate(
                &inertia,
                black_box(Vec3::new(1.0, 0.1, 1.0)),
                None,
                10.0,
                &mut Torque::None,
                &opts,
            )
            .unwrap()
        })
    });
    single.finish();

    let n = 1_000_000;
    let (moments, omega) = bodies(n);
    let mut group = c.benchmark_group("batch kernels");
    group.sample_size(10);
    for threads in [1, 2] {
        let pool = pool(threads);
        group.throughput(Throughput::Elements(20 * n as u64));
        for (name, method) in [
            ("rk4", Method::Rk4),
            ("splitting2", Method::Splitting(2)),
            ("splitting6", Method::Splitting(6)),
        ] {
            let opts = SimulateOptions {
                method,
                dt: Some(1e-3),
                ..SimulateOptions::default()
            };
            group.bench_function(
                format!("simulate_batch {name}: 10⁶ bodies × 20 steps, {threads} thread(s)"),
                |b| {
                    b.iter(|| {
                        pool.install(|| {
                            simulate_batch(&moments, &omega, None, 0.02, &Torque::None, &opts)
                                .unwrap()
                        })
                    })
                },
            );
        }
        let (m, w) = bodies(1000);
        let times: Vec<f64> = (0..1000).map(|k| 0.013 * k as f64 - 3.0).collect();
        group.throughput(Throughput::Elements(1_000_000));
        group.bench_function(
            format!("free_body_states: 10³ bodies × 10³ times, {threads} thread(s)"),
            |b| {
                b.iter(|| {
                    pool.install(|| {
                        free_body_states(&m, &w, None, StateTimes::Shared(black_box(&times)))
                            .unwrap()
                    })
                })
            },
        );
        let state = EulerState {
            theta: 0.8,
            theta_dot: 0.3,
            phi_dot: 0.6,
            psi_dot: 6.0,
            ..Default::default()
        };
        let top = HeavyTop::new(1.0, 0.5, 1.0, state).unwrap();
        let times: Vec<f64> = (0..n).map(|k| 1000.0 * k as f64 / n as f64).collect();
        let mut out = vec![0.0; 3 * n];
        group.throughput(Throughput::Elements(n as u64));
        group.bench_function(
            format!("HeavyTop::euler_angles_into: 10⁶ times, {threads} thread(s)"),
            |b| b.iter(|| pool.install(|| top.euler_angles_into(black_box(&times), &mut out))),
        );
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
