//! Helpers shared by the integration tests (each test file includes this module and uses what
//! it needs): heavy tops and their references, batches of free bodies.
#![allow(dead_code)]

use poinsot::analytic::{EulerState, HeavyTop};
use std::collections::BTreeMap;

/// The top with moments `i1`, `i3` (kg·m²) and `mgl` (N·m), started at `theta` (rad) with the
/// rates `theta_dot`, `phi_dot`, `psi_dot` (rad/s) and φ = ψ = 0; panics if the core refuses it.
pub fn top(
    i1: f64,
    i3: f64,
    mgl: f64,
    theta: f64,
    theta_dot: f64,
    phi_dot: f64,
    psi_dot: f64,
) -> HeavyTop {
    HeavyTop::new(
        i1,
        i3,
        mgl,
        EulerState::with_rates(theta, theta_dot, phi_dot, psi_dot),
    )
    .unwrap()
}

/// One row of a heavy-top mpmath reference: the case's class, `[I1, I3, mgl]`, the initial
/// `[θ, θ̇, φ̇, ψ̇]`, the time `t` (s) and `[φ, θ, ψ, φ̇, θ̇, ψ̇]` there.
pub struct Row {
    pub class: String,
    pub params: [f64; 3],
    pub initial: [f64; 4],
    pub t: f64,
    pub values: [f64; 6],
}

/// The rows of `python/tests/reference/<file>`, by case name (written by `generator`).
pub fn load_reference(file: &str, generator: &str) -> BTreeMap<String, Vec<Row>> {
    let path = format!(
        "{}/../../python/tests/reference/{file}",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("reference data {path} (run {generator}): {e}"));
    let mut cases: BTreeMap<String, Vec<Row>> = BTreeMap::new();
    for line in text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("name,"))
    {
        let f: Vec<&str> = line.split(',').collect();
        let num = |i: usize| f[i].parse::<f64>().unwrap();
        cases.entry(f[0].to_string()).or_default().push(Row {
            class: f[1].to_string(),
            params: [num(2), num(3), num(4)],
            initial: [num(5), num(6), num(7), num(8)],
            t: num(9),
            values: [num(10), num(11), num(12), num(13), num(14), num(15)],
        });
    }
    cases
}

/// A batch: moments (kg m²), initial angular velocities (rad/s), attitudes (scalar first).
pub type Bodies = (Vec<[f64; 3]>, Vec<[f64; 3]>, Vec<[f64; 4]>);

/// `n` free bodies for the batch kernels: moments, ω₀ (rad/s) and attitudes, none of the lanes
/// alike.
pub fn sample_bodies(n: usize) -> Bodies {
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
    let attitude = (0..n)
        .map(|i| {
            let h = 0.5 * (i as f64 * 0.21);
            [h.cos(), 0.0, h.sin(), 0.0]
        })
        .collect();
    (moments, omega, attitude)
}
