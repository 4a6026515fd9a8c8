//! Criterion benchmarks of moving frames, the Earth and the integrator.
use criterion::{criterion_group, criterion_main, Criterion};
use poinsot::earth::{Earth, FallModel};
use poinsot::frames::{simulate_particle_at, MovingFrame, SteadyMotion};
use poinsot::integrate::Options;
use poinsot::Vec3;
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let e = Earth::default();
    let lat = 45f64.to_radians();
    let w = e.omega_enu(lat).unwrap();
    let t_fall = e.drop(100.0, lat, &FallModel::default()).unwrap().time;
    let motion = SteadyMotion::new(MovingFrame::rotating(w).unwrap()).unwrap();
    let opts = Options {
        dense: false,
        ..Options::with_tolerances(1e-12, 1e-12)
    };
    let g = Vec3::new(0.0, 0.0, -e.g);
    c.bench_function("simulate_particle: 100 m drop at 45°, rtol 1e-12", |b| {
        b.iter(|| {
            simulate_particle_at(
                &motion,
                1.0,
                black_box(Vec3::new(0.0, 0.0, 100.0)),
                Vec3::zeros(),
                t_fall,
                &[t_fall],
                |_t, _r, _v| g,
                &opts,
            )
            .unwrap()
        })
    });
    c.bench_function("Earth::drop: 100 m at 45° with landing event", |b| {
        b.iter(|| {
            e.drop(black_box(100.0), lat, &FallModel::default())
                .unwrap()
        })
    });
    let frame = MovingFrame::new(
        Vec3::new(1.0, 2.0, 3.0),
        Vec3::x(),
        Vec3::y(),
        Vec3::new(0.1, 0.2, 0.3),
        Vec3::z(),
    )
    .unwrap();
    c.bench_function("MovingFrame::to_fixed", |b| {
        b.iter(|| frame.to_fixed(black_box(&Vec3::new(1.0, 0.5, 0.2)), &Vec3::x(), &Vec3::y()))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
