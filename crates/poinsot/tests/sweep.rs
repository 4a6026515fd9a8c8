//! Sweeps against the scalar path they batch: every point of a grid equals the model built on
//! its own (bit for bit: the same code on the same numbers), blocks with offsets reproduce the
//! whole sweep, closed forms check the quantities, and bad points are refused by keyword and
//! index before any work.

use poinsot::analytic::{
    axis_stability, EulerState, FreeRegime, FreeRigidBody, HeavyTop, MotionClass, Stability,
};
use poinsot::dynamics::{simulate_batch, Method, SimulateOptions, Torque};
use poinsot::earth::{Earth, FallModel};
use poinsot::sweep::{self, Column, Dim, Grid, MOTION_CLASSES};
use poinsot::{ErrorKind, Vec3};
use proptest::prelude::*;

fn dim(name: &str, len: usize) -> Dim<'_> {
    Dim {
        name,
        len,
        offset: 0,
        argument: name,
    }
}

fn col<'a>(keyword: &'a str, values: &'a [f64], dim: Option<usize>) -> Column<'a> {
    Column {
        keyword,
        values,
        dim,
    }
}

fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![a];
    }
    (0..n)
        .map(|i| a + (b - a) * i as f64 / (n - 1) as f64)
        .collect()
}

/// The grid of the phase diagram, small: θ × ψ̇ with I₁ = 1, I₃ = 0.5, mgl = 1.
fn phase_grid<'a>(theta: &'a [f64], psi_dot: &'a [f64]) -> Grid<'a> {
    const I1: [f64; 1] = [1.0];
    const I3: [f64; 1] = [0.5];
    Grid::new(
        vec![dim("theta", theta.len()), dim("psi_dot", psi_dot.len())],
        vec![
            col("I1", &I1, None),
            col("I3", &I3, None),
            col("mgl", &I1, None),
            col("theta", theta, Some(0)),
            col("psi_dot", psi_dot, Some(1)),
        ],
    )
    .unwrap()
}

#[test]
fn heavy_top_sweep_equals_each_top_built_alone() {
    let theta = linspace(0.1, 1.5, 9);
    let psi_dot = linspace(-3.0, 25.0, 13);
    let out = sweep::heavy_top(&phase_grid(&theta, &psi_dot)).unwrap();
    assert_eq!(out.len(), theta.len() * psi_dot.len());
    let mut classes = std::collections::HashSet::new();
    for (i, &th) in theta.iter().enumerate() {
        for (j, &pd) in psi_dot.iter().enumerate() {
            let state = EulerState {
                theta: th,
                psi_dot: pd,
                ..Default::default()
            };
            let top = HeavyTop::new(1.0, 0.5, 1.0, state).unwrap();
            let got = &out[i * psi_dot.len() + j];
            assert_eq!(got.motion_class, top.motion_class());
            assert_eq!(got.turning_points, top.turning_points());
            assert_eq!(
                got.nutation_period,
                top.nutation_period().unwrap_or(f64::INFINITY)
            );
            assert_eq!(got.mean_precession_rate, top.mean_precession_rate());
            assert_eq!(got.mean_spin_rate, top.mean_spin_rate());
            assert_eq!(got.p_phi, top.p_phi());
            assert_eq!(got.energy, top.energy());
            assert_eq!(got.is_sleeping_stable, top.is_sleeping_stable());
            // Released at rest in φ: θ₀ is the upper turning point, and the path has cusps.
            assert!((got.turning_points.0 - th).abs() < 1e-12);
            classes.insert(got.motion_class);
        }
    }
    // Not trivial: released at rest in φ (φ̇ = 0) the axis makes cusps, or precesses steadily
    // at the one spin where θ₀ is the bottom of the potential well.
    assert!(classes.contains(&MotionClass::Cusps), "{classes:?}");
    // The layout is row-major θ × ψ̇: the transposed reading differs (a negative control for
    // the comparison above).
    let swapped = &out[psi_dot.len()];
    assert_ne!(swapped.turning_points, out[1].turning_points);
}

#[test]
fn heavy_top_with_spin_and_every_keyword_along_its_own_dimension() {
    let i1 = [1.0, 2.0];
    let i3 = [0.5];
    let mgl = [0.0, 1.0, 3.0];
    let theta = [0.4, 1.2, 2.0];
    let omega3 = [0.0, 7.0];
    let phi_dot = [-1.0, 0.3];
    let theta_dot = [0.2];
    let psi = [0.7];
    let grid = Grid::new(
        vec![
            dim("I1", 2),
            dim("mgl", 3),
            dim("theta", 3),
            dim("omega3", 2),
            dim("phi_dot", 2),
        ],
        vec![
            col("I1", &i1, Some(0)),
            col("I3", &i3, None),
            col("mgl", &mgl, Some(1)),
            col("theta", &theta, Some(2)),
            col("omega3", &omega3, Some(3)),
            col("phi_dot", &phi_dot, Some(4)),
            col("theta_dot", &theta_dot, None),
            col("psi", &psi, None),
        ],
    )
    .unwrap();
    let out = sweep::heavy_top(&grid).unwrap();
    let mut p = 0;
    for &a in &i1 {
        for &m in &mgl {
            for &th in &theta {
                for &w3 in &omega3 {
                    for &pd in &phi_dot {
                        let top =
                            HeavyTop::with_spin(a, 0.5, m, 0.0, th, 0.7, pd, 0.2, w3).unwrap();
                        assert_eq!(out[p].omega3, top.omega3());
                        assert_eq!(out[p].omega3, w3, "p_psi = I3 omega3 whatever phi_dot");
                        assert_eq!(out[p].turning_points, top.turning_points());
                        assert_eq!(out[p].mean_precession_rate, top.mean_precession_rate());
                        assert_eq!(out[p].reduced_energy, top.reduced_energy());
                        p += 1;
                    }
                }
            }
        }
    }
    assert_eq!(p, out.len());
    for c in MOTION_CLASSES {
        assert_eq!(MOTION_CLASSES[usize::from(sweep::motion_class_code(c))], c);
    }
}

#[test]
fn bad_points_are_refused_by_keyword_and_index_before_any_work() {
    let theta = [0.5, 1.0, 3.5, 4.0];
    let psi_dot = [1.0, f64::NAN];
    let grid = phase_grid(&theta, &psi_dot);
    // The first bad point in row-major order: psi_dot[1] at theta[0] (NaN), before theta[2].
    let e = sweep::check_heavy_top(&grid).unwrap_err();
    assert_eq!(
        e.to_string(),
        "psi_dot: must be finite, got NaN (at theta[0], psi_dot[1])"
    );
    assert_eq!(sweep::heavy_top(&grid).unwrap_err(), e);
    let psi_dot = [1.0, 2.0];
    let e = sweep::heavy_top(&phase_grid(&theta, &psi_dot)).unwrap_err();
    assert_eq!(e.argument, "theta");
    assert!(
        e.message.ends_with("got 3.5 (at theta[2], psi_dot[0])"),
        "{e}"
    );
    // I₃ ≤ 2 I₁ is a condition on two keywords: the point names both dimensions.
    let i1 = [1.0, 0.2];
    let i3 = [0.5];
    let th = [0.3];
    let g = Grid::new(
        vec![dim("I1", 2)],
        vec![
            col("I1", &i1, Some(0)),
            col("I3", &i3, None),
            col("mgl", &i3, None),
            col("theta", &th, None),
        ],
    )
    .unwrap();
    let e = sweep::heavy_top(&g).unwrap_err();
    assert_eq!(
        (e.kind, e.argument.as_str()),
        (ErrorKind::InvalidInertia, "I3")
    );
    assert!(e.message.ends_with("(at I1[1])"), "{e}");
    // A keyword that is not the model's, one missing, psi_dot with omega3.
    let g = Grid::new(vec![], vec![col("spin", &th, None)]).unwrap();
    let e = sweep::check_heavy_top(&g).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("spin: is not a keyword of heavy_top"),
        "{e}"
    );
    let g = Grid::new(vec![], vec![col("theta", &th, None)]).unwrap();
    assert_eq!(
        sweep::check_heavy_top(&g).unwrap_err().to_string(),
        "I1: must be given"
    );
    let g = Grid::new(
        vec![],
        vec![
            col("I1", &i1[..1], None),
            col("I3", &i3, None),
            col("mgl", &i3, None),
            col("theta", &th, None),
            col("psi_dot", &th, None),
            col("omega3", &th, None),
        ],
    )
    .unwrap();
    assert_eq!(sweep::check_heavy_top(&g).unwrap_err().argument, "omega3");
    // Negative control: the same grid without the bad values passes.
    assert!(sweep::check_heavy_top(&phase_grid(&[0.5, 1.0], &[1.0, 2.0])).is_ok());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]
    /// A sweep cut into blocks — each the grid of the keywords' slices, with each dimension's
    /// offset — gives the whole sweep's numbers bit for bit, and a bad point inside a block is
    /// named by its index in the whole sweep (what a chunk computed on a cluster relies on).
    #[test]
    fn blocks_reproduce_the_whole_sweep(
        nt in 1usize..7, np in 1usize..9, ct in 1usize..7, cp in 1usize..9, bad in 0usize..60,
    ) {
        let theta = linspace(0.2, 2.9, nt);
        let psi_dot = linspace(-5.0, 30.0, np);
        let whole = sweep::heavy_top(&phase_grid(&theta, &psi_dot)).unwrap();
        let mut seen = vec![0u32; whole.len()];
        for t0 in (0..nt).step_by(ct) {
            for p0 in (0..np).step_by(cp) {
                let (t1, p1) = ((t0 + ct).min(nt), (p0 + cp).min(np));
                let (ts, ps) = (&theta[t0..t1], &psi_dot[p0..p1]);
                let g = Grid::new(
                    vec![
                        Dim { name: "theta", len: ts.len(), offset: t0, argument: "theta" },
                        Dim { name: "psi_dot", len: ps.len(), offset: p0, argument: "psi_dot" },
                    ],
                    vec![
                        col("I1", &[1.0], None),
                        col("I3", &[0.5], None),
                        col("mgl", &[1.0], None),
                        col("theta", ts, Some(0)),
                        col("psi_dot", ps, Some(1)),
                    ],
                ).unwrap();
                let block = sweep::heavy_top(&g).unwrap();
                for (k, got) in block.iter().enumerate() {
                    let (i, j) = (t0 + k / ps.len(), p0 + k % ps.len());
                    let p = i * np + j;
                    prop_assert_eq!(got, &whole[p]);
                    seen[p] += 1;
                }
            }
        }
        // Every point once: none lost, none twice.
        prop_assert!(seen.iter().all(|&n| n == 1));
        // A bad value in a block is named by its index in the whole sweep.
        let j = bad % np;
        let mut bad_psi = psi_dot.clone();
        bad_psi[j] = f64::INFINITY;
        let p0 = (j / cp) * cp;
        let ps = &bad_psi[p0..(p0 + cp).min(np)];
        let g = Grid::new(
            vec![Dim { name: "theta", len: 1, offset: nt - 1, argument: "theta" }, Dim { name: "psi_dot", len: ps.len(), offset: p0, argument: "psi_dot" }],
            vec![
                col("I1", &[1.0], None),
                col("I3", &[0.5], None),
                col("mgl", &[1.0], None),
                col("theta", &theta[nt - 1..], Some(0)),
                col("psi_dot", ps, Some(1)),
            ],
        ).unwrap();
        let e = sweep::check_heavy_top(&g).unwrap_err();
        let wanted = format!("(at theta[{}], psi_dot[{j}])", nt - 1);
        prop_assert!(e.message.ends_with(&wanted), "{}", e);
    }
}

#[test]
fn free_body_sweep_equals_each_body_and_the_closed_forms() {
    // Two bodies (an asymmetric one, a symmetric prolate one) × directions of ω₀.
    let moments = [1.0, 2.0, 3.0, 1.0, 1.0, 0.4];
    let polar = linspace(0.05, std::f64::consts::PI - 0.05, 7);
    let azimuth = linspace(0.0, 3.0, 5);
    let size = [2.5];
    let grid = Grid::new(
        vec![
            dim("moments", 2),
            dim("omega_polar", 7),
            dim("omega_azimuth", 5),
        ],
        vec![
            col("moments", &moments, Some(0)),
            col("omega_magnitude", &size, None),
            col("omega_polar", &polar, Some(1)),
            col("omega_azimuth", &azimuth, Some(2)),
        ],
    )
    .unwrap();
    let out = sweep::free_body(&grid).unwrap();
    let mut p = 0;
    let mut regimes = vec![];
    for b in 0..2 {
        let m = [moments[3 * b], moments[3 * b + 1], moments[3 * b + 2]];
        for &th in &polar {
            for &ph in &azimuth {
                let w = [
                    2.5 * th.sin() * ph.cos(),
                    2.5 * th.sin() * ph.sin(),
                    2.5 * th.cos(),
                ];
                let got = &out[p];
                assert_eq!(got.omega0, w);
                let body = FreeRigidBody::new(m, Vec3::from(w), None).unwrap();
                assert_eq!(got.regime, body.regime());
                assert_eq!(got.period, body.period().unwrap());
                assert_eq!(got.flip_interval, body.flip_interval().unwrap());
                assert_eq!(got.parameter, body.parameter());
                assert_eq!(got.pole_axis, body.pole_axis());
                assert_eq!(got.energy, body.energy().unwrap());
                assert_eq!(got.axis_stability, axis_stability(m, 2.5).unwrap());
                regimes.push(sweep::regime_code(got.regime));
                if b == 1 {
                    // The symmetric top's closed form (2.83): the period of ω is 2π/|Ω|,
                    // Ω = (I₁ − I₃) ω₃ / I₁.
                    let big_omega = (1.0 - 0.4) * w[2] / 1.0;
                    let expected = 2.0 * std::f64::consts::PI / big_omega.abs();
                    assert!((got.period / expected - 1.0).abs() < 1e-13, "{p}");
                    assert_eq!(got.regime, FreeRegime::Symmetric);
                }
                p += 1;
            }
        }
    }
    assert!(regimes.contains(&sweep::regime_code(FreeRegime::AboutMaxAxis)));
    assert!(regimes.contains(&sweep::regime_code(FreeRegime::AboutMinAxis)));
    // The intermediate axis of (1, 2, 3) is the unstable one (the tennis-racket theorem).
    assert_eq!(out[0].axis_stability[1].stability, Stability::Unstable);
    assert_eq!(out[0].axis_stability[0].stability, Stability::Stable);
}

#[test]
fn free_body_refusals_name_the_keyword_and_point() {
    let moments = [1.0, 2.0, 3.0, 1.0, 1.0, 5.0];
    let omega = [0.0, 1.0, 0.0];
    let grid = Grid::new(
        vec![dim("moments_index", 2)],
        vec![
            col("moments", &moments, Some(0)),
            col("omega0", &omega, None),
        ],
    )
    .unwrap();
    let e = sweep::free_body(&grid).unwrap_err();
    assert_eq!(
        (e.kind, e.argument.as_str()),
        (ErrorKind::InvalidInertia, "moments")
    );
    assert!(e.message.ends_with("(at moments_index[1])"), "{e}");
    let polar = [0.5, 4.0];
    let g = Grid::new(
        vec![dim("omega_polar", 2)],
        vec![
            col("moments", &moments[..3], None),
            col("omega_magnitude", &[1.0], None),
            col("omega_polar", &polar, Some(0)),
            col("omega_azimuth", &[0.0], None),
        ],
    )
    .unwrap();
    let e = sweep::check_free_body(&g).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("omega_polar: must be finite and in [0, pi]"),
        "{e}"
    );
    assert!(e.message.ends_with("(at omega_polar[1])"));
    let g = Grid::new(
        vec![],
        vec![
            col("moments", &moments[..3], None),
            col("omega0", &[0.0; 3], None),
        ],
    )
    .unwrap();
    assert!(sweep::check_free_body(&g)
        .unwrap_err()
        .message
        .contains("nonzero"));
    let g = Grid::new(
        vec![],
        vec![
            col("moments", &moments[..3], None),
            col("omega0", &omega, None),
            col("omega_polar", &[0.1], None),
        ],
    )
    .unwrap();
    assert_eq!(
        sweep::check_free_body(&g).unwrap_err().argument,
        "omega_polar"
    );
}

#[test]
fn simulate_sweep_equals_the_batch_and_the_exact_flow() {
    let moments = [1.0, 2.0, 3.0];
    let omega0 = [1.0, 0.1, 1.0, 0.1, 3.0, 0.1, -0.5, 0.2, 2.0];
    let attitude0 = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0];
    let grid = Grid::new(
        vec![dim("omega0_index", 3), dim("attitude0_index", 2)],
        vec![
            col("moments", &moments, None),
            col("omega0", &omega0, Some(0)),
            col("attitude0", &attitude0, Some(1)),
        ],
    )
    .unwrap();
    let opts = SimulateOptions {
        method: Method::Rk4,
        dt: Some(1e-3),
        ..SimulateOptions::default()
    };
    let out = sweep::simulate(&grid, 2.0, &Torque::None, &opts).unwrap();
    // The batch of the same rows, built by hand.
    let mut m = vec![];
    let mut w = vec![];
    let mut q = vec![];
    for i in 0..3 {
        for k in 0..2 {
            m.push(moments);
            w.push([omega0[3 * i], omega0[3 * i + 1], omega0[3 * i + 2]]);
            q.push([
                attitude0[4 * k],
                attitude0[4 * k + 1],
                attitude0[4 * k + 2],
                attitude0[4 * k + 3],
            ]);
        }
    }
    let batch = simulate_batch(&m, &w, Some(&q), 2.0, &Torque::None, &opts).unwrap();
    for p in 0..6 {
        assert_eq!(out[p].omega, batch.omega[p]);
        assert_eq!(out[p].attitude, batch.attitude[p]);
        // RK4 with dt = 1e-3 against the exact flow: O(dt⁴) · t.
        let exact = FreeRigidBody::new(moments, Vec3::from(w[p]), Some(q[p])).unwrap();
        let (we, _) = exact.state(2.0).unwrap();
        let err = (Vec3::from(out[p].omega) - we).norm() / we.norm();
        assert!(err < 1e-10, "{p}: {err}");
    }
    // A torque changes the result (negative control of the torque's path).
    let torqued =
        sweep::simulate(&grid, 2.0, &Torque::Body(Vec3::new(0.0, 0.0, 1.0)), &opts).unwrap();
    assert!((torqued[0].omega[2] - out[0].omega[2]).abs() > 0.1);
}

#[test]
fn simulate_errors_of_one_body_are_located() {
    let moments = [1.0, 2.0, 3.0];
    let omega0 = [1.0, 0.0, 0.0, 1e4, 0.0, 0.0];
    let grid = Grid::new(
        vec![dim("omega0_index", 2)],
        vec![
            col("moments", &moments, None),
            col("omega0", &omega0, Some(0)),
        ],
    )
    .unwrap();
    // The default step resolves the fastest rate: the fast body needs more than 10⁴ steps.
    let opts = SimulateOptions {
        method: Method::Rk4,
        max_steps: 10_000,
        ..SimulateOptions::default()
    };
    let e = sweep::simulate(&grid, 10.0, &Torque::None, &opts).unwrap_err();
    assert_eq!(e.argument, "max_steps");
    assert!(e.message.ends_with("(at omega0_index[1])"), "{e}");
    let bad_q = [1.0, 1.0, 0.0, 0.0];
    let grid = Grid::new(
        vec![dim("omega0_index", 2)],
        vec![
            col("moments", &moments, None),
            col("omega0", &omega0, Some(0)),
            col("attitude0", &bad_q, None),
        ],
    )
    .unwrap();
    let e = sweep::check_simulate(&grid, 1.0, &Torque::None, &opts).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidRotation);
    assert!(e.message.ends_with("(at omega0_index[0])"), "{e}");
    let e = sweep::check_simulate(&grid, -1.0, &Torque::None, &opts).unwrap_err();
    assert_eq!(e.argument, "duration");
}

#[test]
fn drops_and_projectiles_equal_each_run_alone() {
    let earth = Earth::default();
    let model = FallModel::default();
    let height = [10.0, 100.0, 1000.0];
    let latitude = [-0.7, 0.0, 0.3, 1.2];
    let grid = Grid::new(
        vec![dim("latitude", 4), dim("height", 3)],
        vec![
            col("height", &height, Some(1)),
            col("latitude", &latitude, Some(0)),
        ],
    )
    .unwrap();
    let out = sweep::drop(&earth, &grid, &model).unwrap();
    for (i, &lat) in latitude.iter().enumerate() {
        for (j, &h) in height.iter().enumerate() {
            let f = earth.drop(h, lat, &model).unwrap();
            let got = &out[i * 3 + j];
            assert_eq!((got.time, got.east, got.north), (f.time, f.east, f.north));
            // The unit's 2.42 to first order in ω.
            let rel = (got.east - got.first_order_east).abs() / got.first_order_east;
            assert!(rel < 1e-3, "{rel}");
        }
    }
    // Negative control: on a non-rotating Earth the body lands at the foot of the plumb line.
    let still = FallModel {
        rotation: false,
        ..model
    };
    let out = sweep::drop(&earth, &grid, &still).unwrap();
    assert!(out
        .iter()
        .all(|d| d.east.abs() < 1e-12 && d.north.abs() < 1e-12));
    let speed = [50.0, 300.0];
    let elevation = [0.3, 0.8];
    let azimuth = [0.0, 1.5];
    let lat = [0.8];
    let h0 = [0.0];
    let grid = Grid::new(
        vec![dim("speed", 2), dim("elevation", 2), dim("azimuth", 2)],
        vec![
            col("speed", &speed, Some(0)),
            col("elevation", &elevation, Some(1)),
            col("azimuth", &azimuth, Some(2)),
            col("latitude", &lat, None),
            col("height", &h0, None),
        ],
    )
    .unwrap();
    let out = sweep::projectile(&earth, &grid, &model).unwrap();
    let mut p = 0;
    for &s in &speed {
        for &el in &elevation {
            for &az in &azimuth {
                let f = earth.projectile(s, el, az, 0.8, 0.0, &model).unwrap();
                assert_eq!(
                    (out[p].time, out[p].range, out[p].drift),
                    (f.time, f.range, f.drift)
                );
                // In the north a projectile drifts to the right.
                assert!(out[p].drift > 0.0);
                p += 1;
            }
        }
    }
    let bad = [0.3, -0.1];
    let grid = Grid::new(
        vec![dim("elevation", 2)],
        vec![
            col("speed", &speed[..1], None),
            col("elevation", &bad, Some(0)),
            col("azimuth", &azimuth[..1], None),
            col("latitude", &lat, None),
            col("height", &h0, None),
        ],
    )
    .unwrap();
    let e = sweep::check_projectile(&grid, &model).unwrap_err();
    assert_eq!(e.argument, "elevation");
    assert!(e.message.ends_with("(at elevation[1])"), "{e}");
}

#[test]
fn a_failed_integration_names_the_users_argument_at_its_point() {
    // The integrator names its own variables (t, y0); the run names what the user gave, and so
    // does the sweep: the height of a drop, the speed of a projectile.
    let earth = Earth::default();
    let model = FallModel::default();
    let height = [100.0, 1e308];
    let lat = [0.5];
    let grid = Grid::new(
        vec![dim("height", 2)],
        vec![col("height", &height, Some(0)), col("latitude", &lat, None)],
    )
    .unwrap();
    let e = sweep::drop(&earth, &grid, &model).unwrap_err();
    assert_eq!(
        (e.kind, e.argument.as_str()),
        (ErrorKind::Diverged, "height")
    );
    assert!(e.message.ends_with("(at height[1])"), "{e}");
    // The run alone names the height too (issue 22: the core names the caller's arguments, so
    // the sweep renames nothing).
    assert_eq!(
        earth.drop(1e308, 0.5, &model).unwrap_err().argument,
        "height"
    );
    let speed = [50.0, 1e308];
    let one = [0.5];
    let h0 = [0.0];
    let grid = Grid::new(
        vec![dim("speed", 2)],
        vec![
            col("speed", &speed, Some(0)),
            col("elevation", &one, None),
            col("azimuth", &one, None),
            col("latitude", &one, None),
            col("height", &h0, None),
        ],
    )
    .unwrap();
    let e = sweep::projectile(&earth, &grid, &model).unwrap_err();
    assert_eq!(e.argument, "speed");
    assert!(e.message.ends_with("(at speed[1])"), "{e}");
}

#[test]
fn a_stopped_sweep_returns_the_interrupt() {
    use poinsot::control::{interrupted, watched, Monitor};
    struct StopNow;
    impl Monitor for StopNow {
        fn poll(&mut self, _: f64) -> poinsot::Result<()> {
            Err(interrupted())
        }
    }
    let theta = linspace(0.1, 1.5, 200);
    let psi_dot = linspace(0.5, 20.0, 200);
    let grid = phase_grid(&theta, &psi_dot);
    let (r, _) = watched(StopNow, || sweep::heavy_top(&grid));
    assert_eq!(r.unwrap_err().kind, ErrorKind::Interrupted);
    // Negative control: the same sweep unwatched runs to the end.
    assert_eq!(sweep::heavy_top(&grid).unwrap().len(), 40_000);
}
