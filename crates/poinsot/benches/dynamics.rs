//! Criterion benchmarks of the exact free rigid body, the integrators and batches.
use criterion::{criterion_group, criterion_main, Criterion};
use poinsot::analytic::FreeRigidBody;
use poinsot::dynamics::{
    free_steps, simulate, simulate_batch, BodyInertia, Method, SimulateOptions, SplitState, Torque,
};
use poinsot::integrate::composition_coefficients;
use poinsot::special::Jacobi;
use poinsot::Vec3;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let body = FreeRigidBody::new([1.0, 2.0, 3.0], Vec3::new(1.0, 0.1, 1.0), None).unwrap();
    let mut t = 0.0;
    c.bench_function(
        "FreeRigidBody::state (ω and attitude) at an arbitrary t",
        |b| {
            b.iter(|| {
                t += 0.7316;
                body.state(black_box(t)).unwrap()
            })
        },
    );
    c.bench_function("FreeRigidBody::new, I = (1, 2, 3)", |b| {
        b.iter(|| {
            FreeRigidBody::new(black_box([1.0, 2.0, 3.0]), Vec3::new(1.0, 0.1, 1.0), None).unwrap()
        })
    });
    let j = Jacobi::new(0.7).unwrap();
    c.bench_function("Jacobi sn, cn, dn, am (m = 0.7)", |b| {
        b.iter(|| j.eval(black_box(12.345)))
    });
    let inertia = BodyInertia::from_moments([1.0, 2.0, 3.0]).unwrap();
    for (name, method) in [
        ("rk4", Method::Rk4),
        ("splitting2", Method::Splitting(2)),
        ("splitting6", Method::Splitting(6)),
    ] {
        let opts = SimulateOptions {
            method,
            dt: Some(1e-3),
            samples: 2,
            ..SimulateOptions::default()
        };
        c.bench_function(
            &format!("simulate {name}: 10⁴ steps of a free body"),
            |b| {
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
            },
        );
    }
    let g = composition_coefficients(6).unwrap();
    c.bench_function("free_steps splitting6: 10⁴ steps", |b| {
        b.iter(|| {
            let mut s = SplitState {
                l: Vec3::new(1.0, 0.2, 3.0),
                q: [1.0, 0.0, 0.0, 0.0],
                t: 0.0,
            };
            free_steps(&mut s, &[1.0, 2.0, 3.0], g, 1e-3, black_box(10_000));
            s
        })
    });
    let n = 1_000_000;
    let moments = vec![[1.0, 2.0, 3.0]; n];
    let omega = vec![[1.0, 0.1, 1.0]; n];
    let mut group = c.benchmark_group("batch");
    group.sample_size(10);
    group.bench_function("simulate_batch rk4: 10⁶ bodies × 20 steps", |b| {
        b.iter(|| {
            simulate_batch(
                &moments,
                &omega,
                None,
                0.02,
                &Torque::None,
                &SimulateOptions {
                    method: Method::Rk4,
                    dt: Some(1e-3),
                    ..SimulateOptions::default()
                },
            )
            .unwrap()
        })
    });
    group.bench_function("simulate_batch splitting2: 10⁶ bodies × 20 steps", |b| {
        b.iter(|| {
            simulate_batch(
                &moments,
                &omega,
                None,
                0.02,
                &Torque::None,
                &SimulateOptions {
                    method: Method::Splitting(2),
                    dt: Some(1e-3),
                    ..SimulateOptions::default()
                },
            )
            .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
