//! `free_body_states` (many free bodies at many times, on SIMD lanes) against
//! `FreeRigidBody::state` body by body and time by time, against itself (shared and per-body
//! times, a body alone, one thread or two), and its errors, limits and cancellation.

mod common;
use common::{sample_bodies, Bodies};
use poinsot::analytic::{free_body_states, FreeBodyStates, FreeRigidBody, StateTimes};
use poinsot::control::{self, Monitor};
use poinsot::{ErrorKind, Result, Vec3};
use proptest::prelude::*;

/// The attitude's tolerance against `FreeRigidBody::state` at time t for a body turning at
/// most at `rate` (rad/s): 1e-13, plus 8 ε per radian turned — the state's own error model
/// (its phase is known to a few ε times the angle turned; the batch sums Π by another formula
/// and takes its sines from the lanes, so the two roundings differ within it).
fn q_tol(rate: f64, t: f64) -> f64 {
    1e-13 + 8.0 * f64::EPSILON * rate * t.abs()
}

/// An upper bound of the rates of a free body's motion (λ and the precession rate):
/// |ω₀| I_max / I_min.
fn rate_bound(m: &[f64; 3], w: &[f64; 3]) -> f64 {
    let norm = w.iter().map(|x| x * x).sum::<f64>().sqrt();
    norm * m.iter().fold(0.0f64, |a, &b| a.max(b)) / m.iter().fold(f64::INFINITY, |a, &b| a.min(b))
}

/// The largest difference of ω (relative to |ω₀|), and of q (absolute) in units of
/// [`q_tol`], between the batch and `FreeRigidBody::sample` (the state at each time, the
/// quaternions' signs continuous) for every body at its times.
fn against_state((m, w, q): &Bodies, times: StateTimes<'_>, states: &FreeBodyStates) -> (f64, f64) {
    let (mut dw, mut dq): (f64, f64) = (0.0, 0.0);
    let mm = states.times;
    for i in 0..m.len() {
        let body = FreeRigidBody::new(m[i], Vec3::from(w[i]), Some(q[i])).unwrap();
        let scale = w[i].iter().fold(0.0f64, |a, b| a.max(b.abs()));
        let rate = rate_bound(&m[i], &w[i]);
        let ts = match times {
            StateTimes::Shared(ts) => ts,
            StateTimes::PerBody(ts) => &ts[i * mm..(i + 1) * mm],
        };
        let (we, qe) = body.sample(ts).unwrap();
        for k in 0..mm {
            let (wo, qo) = (states.omega[i * mm + k], states.attitude[i * mm + k]);
            for c in 0..3 {
                dw = dw.max((wo[c] - we[k][c]).abs() / scale);
            }
            for c in 0..4 {
                dq = dq.max((qo[c] - qe[k][c]).abs() / q_tol(rate, ts[k]));
            }
        }
    }
    (dw, dq)
}

fn bodies(max: usize) -> impl Strategy<Value = Bodies> {
    (1usize..max).prop_flat_map(|n| {
        (
            prop::collection::vec(
                // I₃ between |I₁ − I₂| and I₁ + I₂: the triangle inequalities hold.
                (0.5f64..2.0, 0.5f64..2.0, 0.02f64..0.98).prop_map(|(a, b, t)| {
                    let lo = (a - b).abs();
                    [a, b, lo + t * (a + b - lo)]
                }),
                n,
            ),
            prop::collection::vec(
                (-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0).prop_map(|(x, y, z)| [x, y, z + 0.05]),
                n,
            ),
            prop::collection::vec(
                (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, 0.1f64..1.0).prop_map(|(x, y, z, w)| {
                    let n = (w * w + x * x + y * y + z * z).sqrt();
                    [w / n, x / n, y / n, z / n]
                }),
                n,
            ),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Random bodies at shared times: ω bit for bit as `FreeRigidBody::state` (the same
    /// reduction and duplication on every lane), the attitude within `q_tol` of `sample`'s (its
    /// Π by the Fourier series, its sines by the lanes'; the signs continuous).
    #[test]
    fn shared_times_equal_the_single_body_states(
        b in bodies(12),
        times in prop::collection::vec(-200.0f64..200.0, 1..40),
    ) {
        let s = free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::Shared(&times)).unwrap();
        let (dw, dq) = against_state(&b, StateTimes::Shared(&times), &s);
        prop_assert_eq!(dw, 0.0);
        prop_assert!(dq <= 1.0, "{:e} of the tolerance", dq);
    }

    /// Each body at its own times: the same.
    #[test]
    fn per_body_times_equal_the_single_body_states(
        b in bodies(6),
        per in 1usize..30,
        seed in 0.0f64..1.0,
    ) {
        let n = b.0.len();
        let times: Vec<f64> = (0..n * per)
            .map(|k| 300.0 * ((k as f64 * 0.618 + seed).fract() - 0.5))
            .collect();
        let s = free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::PerBody(&times)).unwrap();
        prop_assert_eq!((s.bodies, s.times), (n, per));
        let (dw, dq) = against_state(&b, StateTimes::PerBody(&times), &s);
        prop_assert_eq!(dw, 0.0);
        prop_assert!(dq <= 1.0, "{:e} of the tolerance", dq);
    }
}

#[test]
fn every_kind_of_motion_and_many_times_per_body() {
    // Steady, symmetric, both sides of the separatrix, next to it (the Π series too slow: the
    // scalar path), a body at rest, and a body nearly symmetric about its pole; 10⁴ times each
    // (split over several tasks).
    let m = vec![
        [1.0, 2.0, 3.0],
        [1.0, 1.0, 2.0],
        [1.0, 2.0, 3.0],
        [1.0, 2.0, 3.0],
        [1.0, 2.0, 3.0],
        [1.0, 2.0, 3.0],
        [1.0, 2.0, 2.0 + 1e-9],
    ];
    let w = vec![
        [0.0, 0.0, 2.0],
        [0.3, 0.1, 1.0],
        [1.0, 0.1, 1.0],
        [1.0, 0.1, 0.1],
        [1e-3, 2.0, 1e-3],
        [0.0, 0.0, 0.0],
        [0.1, 0.2, 1.0],
    ];
    let q = vec![[1.0, 0.0, 0.0, 0.0]; 7];
    let times: Vec<f64> = (0..10_000).map(|k| 0.037 * k as f64 - 20.0).collect();
    let s = free_body_states(&m, &w, Some(&q), StateTimes::Shared(&times)).unwrap();
    let moving = (m[..5].to_vec(), w[..5].to_vec(), q[..5].to_vec());
    let five = free_body_states(
        &moving.0,
        &moving.1,
        Some(&moving.2),
        StateTimes::Shared(&times),
    )
    .unwrap();
    let (dw, dq) = against_state(&moving, StateTimes::Shared(&times), &five);
    assert_eq!(dw, 0.0);
    assert!(dq <= 1.0, "{dq:e} of the tolerance");
    assert_eq!(&s.omega[..5 * 10_000], &five.omega[..]);
    // At rest: ω = 0 and the attitude kept.
    assert!(s.omega[5 * 10_000..6 * 10_000]
        .iter()
        .all(|v| *v == [0.0; 3]));
    assert!(s.attitude[5 * 10_000..6 * 10_000]
        .iter()
        .all(|v| *v == [1.0, 0.0, 0.0, 0.0]));
    let last = (m[6..].to_vec(), w[6..].to_vec(), q[6..].to_vec());
    let one =
        free_body_states(&last.0, &last.1, Some(&last.2), StateTimes::Shared(&times)).unwrap();
    let (dw, dq) = against_state(&last, StateTimes::Shared(&times), &one);
    assert_eq!(dw, 0.0);
    assert!(dq <= 1.0, "{dq:e} of the tolerance");
}

#[test]
fn a_state_does_not_depend_on_the_batch_or_the_threads() {
    let b = sample_bodies(23);
    let times: Vec<f64> = (0..301).map(|k| 0.1 * k as f64 - 15.0).collect();
    let all = free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::Shared(&times)).unwrap();
    // Per-body times equal to the shared ones, a single body, a single time, 1 or 2 threads.
    let tiled: Vec<f64> = (0..23).flat_map(|_| times.iter().copied()).collect();
    let per = free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::PerBody(&tiled)).unwrap();
    assert_eq!(per, all);
    let alone = free_body_states(
        &b.0[7..8],
        &b.1[7..8],
        Some(&b.2[7..8]),
        StateTimes::Shared(&times),
    )
    .unwrap();
    assert_eq!(alone.omega[..], all.omega[7 * 301..8 * 301]);
    assert_eq!(alone.attitude[..], all.attitude[7 * 301..8 * 301]);
    let single =
        free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::Shared(&times[41..42])).unwrap();
    // One time per body takes the scalar path: ω bit for bit, q within round-off.
    for i in 0..23 {
        assert_eq!(single.omega[i], all.omega[i * 301 + 41]);
    }
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let again = pool.install(|| {
            free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::Shared(&times)).unwrap()
        });
        assert_eq!(again, all, "{threads} threads");
    }
}

#[test]
fn a_wrong_time_or_body_is_seen_negative_control() {
    // The comparison can fail: states one step of 1e-9 s late, or of another body, differ
    // from the reference by far more than its tolerance.
    let b = sample_bodies(5);
    let times: Vec<f64> = (0..50).map(|k| 0.3 * k as f64).collect();
    let late: Vec<f64> = times.iter().map(|t| t + 1e-9).collect();
    let s = free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::Shared(&late)).unwrap();
    let (dw, dq) = against_state(&b, StateTimes::Shared(&times), &s);
    assert!(dw > 1e-12 && dq > 10.0, "{dw:e} {dq:e}");
    let mut other = b.clone();
    other.1[3][1] += 1e-9;
    let s = free_body_states(
        &other.0,
        &other.1,
        Some(&other.2),
        StateTimes::Shared(&times),
    )
    .unwrap();
    let (dw, _) = against_state(&b, StateTimes::Shared(&times), &s);
    assert!(dw > 1e-12, "{dw:e}");
}

#[test]
fn errors_name_the_argument_and_the_first_row_or_body() {
    let (m, mut w, q) = sample_bodies(30);
    let ts = [0.0, 1.0];
    let shared = StateTimes::Shared(&ts);
    let e = free_body_states(&m, &w[..29], None, shared).unwrap_err();
    assert_eq!(e.argument, "omega0");
    let e = free_body_states(&m, &w, Some(&q[..3]), shared).unwrap_err();
    assert_eq!(e.argument, "attitude0");
    let mut bad = m.clone();
    bad[17] = [1.0, 1.0, 3.0];
    bad[21] = [-1.0, 1.0, 1.0];
    let e = free_body_states(&bad, &w, None, shared).unwrap_err();
    assert_eq!(
        (e.argument.as_str(), e.kind),
        ("moments", ErrorKind::InvalidInertia)
    );
    assert!(e.message.starts_with("row 17: "), "{e}");
    let mut tilted = q.clone();
    tilted[4] = [0.9, 0.0, 0.0, 0.0];
    let e = free_body_states(&m, &w, Some(&tilted), shared).unwrap_err();
    assert_eq!(e.argument, "attitude0");
    assert!(e.message.starts_with("row 4: "), "{e}");
    let e = free_body_states(&m, &w, None, StateTimes::Shared(&[0.0, f64::NAN])).unwrap_err();
    assert_eq!(e.argument, "t");
    let e = free_body_states(&m, &w, None, StateTimes::PerBody(&[0.0; 31])).unwrap_err();
    assert_eq!(e.argument, "t");
    // Beyond a body's time limit (2⁴² rad of turning): the first such body is named.
    w[12] = [1e3, 1e3, 1e3];
    w[25] = [1e3, 1e3, 1e3];
    let e = free_body_states(&m, &w, None, StateTimes::Shared(&[0.0, 1e10])).unwrap_err();
    assert_eq!(e.argument, "t");
    assert!(e.message.starts_with("body 12: "), "{e}");
    // The output is checked against the memory budget before anything is computed.
    let huge = vec![0.0; 1];
    let many = vec![[1.0, 2.0, 3.0]; 1 << 16];
    let spin = vec![[1.0, 0.1, 1.0]; 1 << 16];
    assert!(free_body_states(&many, &spin, None, StateTimes::Shared(&huge)).is_ok());
    let lots: Vec<f64> = vec![0.0; 1 << 14];
    let e = free_body_states(&many, &spin, None, StateTimes::Shared(&lots)).unwrap_err();
    assert_eq!(e.argument, "t");
    assert!(e.message.contains("memory budget"), "{e}");
}

/// Stops at the first poll.
struct StopNow;

impl Monitor for StopNow {
    fn poll(&mut self, _progress: f64) -> Result<()> {
        Err(control::interrupted())
    }
}

#[test]
fn a_monitor_stops_the_run() {
    // 2000 bodies × 10⁴ times (2·10⁷ states): stopped at the monitor's first poll.
    let b = sample_bodies(2000);
    let times: Vec<f64> = (0..10_000).map(|k| 0.01 * k as f64).collect();
    let (result, _) = control::watched(StopNow, || {
        free_body_states(&b.0, &b.1, Some(&b.2), StateTimes::Shared(&times))
    });
    assert_eq!(result.unwrap_err().kind, ErrorKind::Interrupted);
}
