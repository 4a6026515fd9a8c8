//! `RigidEarth::simulate` (issue 25): the Earth's spin axis integrated under the instantaneous
//! gravity-gradient torques of the Sun and the Moon along their Kepler orbits, checked against
//! the orbit-averaged theory (`precession_rate`, `nutation_amplitudes`) and an independent
//! closed form written here; negative controls; bad input refused by name.
use std::f64::consts::PI;
use std::sync::OnceLock;

use poinsot::earth::{fit_pole, PoleRun, RigidEarth, SimulateOptions, MOON_ORBIT};

const YEAR: f64 = 365.25 * 86_400.0;
const ARCSEC: f64 = PI / 648_000.0;

/// 120 years (6.4 turns of the Moon's node) of the default Earth, shared by the tests.
fn century() -> &'static PoleRun {
    static RUN: OnceLock<PoleRun> = OnceLock::new();
    RUN.get_or_init(|| {
        let options = SimulateOptions {
            samples: 1201,
            ..SimulateOptions::default()
        };
        RigidEarth::default()
            .simulate(120.0 * YEAR, &options)
            .unwrap()
    })
}

#[test]
fn the_simulated_mean_rate_is_the_averaged_precession_rate() {
    let e = RigidEarth::default();
    let run = century();
    let fit = run.fit().unwrap();
    let rel = fit.precession_rate / e.precession_rate() - 1.0;
    // The issue asks for 1 %; the run gives 1e-5 (the second-order terms of the theory).
    assert!(rel.abs() < 0.01, "{rel}");
    assert!(rel.abs() < 2e-4, "{rel}");
    // An independent closed form, written out here: −(3/2)(H/ω) cos ε Σ GM/(a³(1−e²)^{3/2}),
    // the Moon's term with (1 − (3/2) sin² i) and GM_☾ = μ GM_⊕ (IERS 2010, Horizons).
    let (h, w, eps) = (3.273795e-3, 7.292115e-5, 84381.406 * ARCSEC);
    let sun =
        1.32712442099e20 / (1.495978707e11_f64.powi(3) * (1.0 - 0.0167086_f64.powi(2)).powf(1.5));
    let moon = 0.0123000371 * 3.986004418e14
        / (3.844e8_f64.powi(3) * (1.0 - 0.0549_f64.powi(2)).powf(1.5))
        * (1.0 - 1.5 * 5.145_f64.to_radians().sin().powi(2));
    let want = -1.5 * h / w * eps.cos() * (sun + moon);
    assert!((fit.precession_rate / want - 1.0).abs() < 2e-4);
    // About 50.39″ a year, westward.
    assert!((fit.precession_rate * YEAR / ARCSEC + 50.40).abs() < 0.02);
    // A fixed ecliptic: no secular change of the obliquity.
    assert!(fit.obliquity_rate.abs() * 100.0 * YEAR < 0.1 * ARCSEC);
    // The raw longitude falls by the rate over the run, to within the nutation's 17″.
    let end = *run.longitude.last().unwrap();
    assert!((end - e.precession_rate() * 120.0 * YEAR).abs() < 20.0 * ARCSEC);
    assert_eq!(run.t.len(), 1201);
    assert_eq!(run.t[0], 0.0);
}

#[test]
fn the_axis_nods_with_the_principal_nutation() {
    // The 18.6-year nod read off the run against the first-order amplitudes (Δψ₀, Δε₀) of
    // nutation_amplitudes: within 1 % (the run gives 0.1 %: the theory leaves out the
    // second-order terms, and the fortnightly and semi-annual nutations leak a little into
    // a fit of a few node periods).
    let e = RigidEarth::default();
    let fit = century().fit().unwrap();
    let (dpsi, deps) = e.nutation_amplitudes().unwrap();
    assert!(
        (fit.nutation_obliquity / deps - 1.0).abs() < 0.01,
        "{fit:?}"
    );
    assert!(
        (fit.nutation_longitude / dpsi - 1.0).abs() < 0.01,
        "{fit:?}"
    );
    // Started at ε₀ with the node at the equinox (Ω₀ = 0): the nod is about ε₀ − Δε₀.
    // Within 1″: the start also sets the mean of the semi-annual (0.57″) and fortnightly
    // (0.1″) nods, which the fit does not model.
    assert!((fit.mean_obliquity - (e.obliquity - deps)).abs() < 1.0 * ARCSEC);
    let range = century()
        .obliquity
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), &x| (lo.min(x), hi.max(x)));
    assert!(((range.1 - range.0) / (2.0 * deps) - 1.0).abs() < 0.1);
}

#[test]
fn started_on_the_true_pole_the_run_nods_about_the_mean_pole() {
    let e = RigidEarth::default();
    let options = SimulateOptions {
        samples: 401,
        moon_node: 1.0,
        mean_pole: true,
        ..SimulateOptions::default()
    };
    let run = e.simulate(40.0 * YEAR, &options).unwrap();
    // Sample by sample, the run is the averaged pole (RigidEarth::averaged_pole) of the same
    // Ω₀, to within the semi-annual (1.3″ in ψ, 0.55″ in ε, about a mean the start shifts by as
    // much) and fortnightly nods it leaves out and the second-order terms (1.8″ and 1.25″
    // seen); without the nutation (scale 0) it is 17″ off.
    let pole = e.averaged_pole(&run.t, 1.0, 1.0).unwrap();
    let worst = |pole: &poinsot::earth::AveragedPole| {
        let mut w = (0.0_f64, 0.0_f64);
        for k in 0..run.t.len() {
            w.0 = w.0.max((pole.psi[k] + run.longitude[k]).abs() / ARCSEC);
            w.1 =
                w.1.max((pole.obliquity[k] - run.obliquity[k]).abs() / ARCSEC);
        }
        w
    };
    let (dpsi_max, deps_max) = worst(&pole);
    assert!(dpsi_max < 2.5 && deps_max < 1.5, "{dpsi_max}″ {deps_max}″");
    let (mean_only, _) = worst(&e.averaged_pole(&run.t, 1.0, 0.0).unwrap());
    assert!(mean_only > 10.0, "{mean_only}″");
    let fit = run.fit().unwrap();
    // Within 1″ (the semi-annual and fortnightly nods' means, as above), against the 9.2″ × cos 1
    // = 5″ the default start is off by.
    assert!(
        (fit.mean_obliquity - e.obliquity).abs() < 1.0 * ARCSEC,
        "{fit:?}"
    );
    let (dpsi, _) = e.nutation_amplitudes().unwrap();
    assert!((fit.nutation_longitude / dpsi - 1.0).abs() < 0.01);
}

#[test]
fn negative_controls_no_inclination_no_nod_no_bulge_no_precession() {
    let options = SimulateOptions {
        samples: 401,
        ..SimulateOptions::default()
    };
    // The Moon in the ecliptic: the node means nothing, the 18.6-year nod is gone, and the
    // Moon's part of the precession loses its (1 − (3/2) sin² i).
    let flat = RigidEarth {
        moon: poinsot::earth::MeanOrbit {
            inclination: 0.0,
            ..MOON_ORBIT
        },
        ..RigidEarth::default()
    };
    let fit = flat.simulate(40.0 * YEAR, &options).unwrap().fit().unwrap();
    let (_, deps) = RigidEarth::default().nutation_amplitudes().unwrap();
    // (0.16 % is left: the fortnightly and semi-annual terms over only two node periods.)
    assert!(fit.nutation_obliquity.abs() < 0.01 * deps, "{fit:?}");
    assert!((fit.precession_rate / flat.precession_rate() - 1.0).abs() < 1e-3);
    // A nearly round Earth: no torque worth the name, no precession.
    let round = RigidEarth::new(1e-9, 7.292115e-5, 0.4).unwrap();
    let fit = round
        .simulate(40.0 * YEAR, &options)
        .unwrap()
        .fit()
        .unwrap();
    assert!(fit.precession_rate.abs() < 1e-6 * RigidEarth::default().precession_rate().abs());
}

#[test]
fn bad_input_is_refused_by_name() {
    let e = RigidEarth::default();
    let o = SimulateOptions::default();
    for d in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(e.simulate(d, &o).unwrap_err().argument, "duration", "{d}");
    }
    let few = SimulateOptions { samples: 1, ..o };
    assert_eq!(e.simulate(YEAR, &few).unwrap_err().argument, "samples");
    let huge = SimulateOptions {
        samples: usize::MAX / 2,
        ..o
    };
    assert_eq!(e.simulate(YEAR, &huge).unwrap_err().argument, "samples");
    // A thousand years need 1.5 million steps of a quarter day.
    let short = SimulateOptions {
        max_steps: 1_000_000,
        ..o
    };
    let err = e.simulate(1000.0 * YEAR, &short).unwrap_err();
    assert_eq!(err.argument, "max_steps");
    assert!(err.message.contains("1.4698e6 steps"), "{err}");
    let node = SimulateOptions {
        moon_node: f64::NAN,
        ..o
    };
    assert_eq!(e.simulate(YEAR, &node).unwrap_err().argument, "moon_node");
    let mut bad = e;
    bad.moon.eccentricity = 1.0;
    assert_eq!(
        bad.simulate(YEAR, &o).unwrap_err().argument,
        "moon.eccentricity"
    );
    let mut bad = e;
    bad.sun.node_period = 0.0;
    assert_eq!(
        bad.simulate(YEAR, &o).unwrap_err().argument,
        "sun.node_period"
    );
    let flat = RigidEarth::new(0.003, 7e-5, 0.0).unwrap();
    let pole = SimulateOptions {
        mean_pole: true,
        ..o
    };
    assert_eq!(
        flat.simulate(YEAR, &pole).unwrap_err().argument,
        "obliquity"
    );
    // The fit: a run shorter than a node period, mismatched lengths, non-finite values.
    let t: Vec<f64> = (0..10).map(|i| i as f64 * YEAR).collect();
    let z = vec![0.0; 10];
    let rate = -2.0 * PI / MOON_ORBIT.node_period;
    assert_eq!(fit_pole(&t, &z, &z, 0.0, rate).unwrap_err().argument, "t");
    assert_eq!(
        fit_pole(&t, &z[..9], &z, 0.0, rate).unwrap_err().argument,
        "longitude"
    );
    let mut nan = z.clone();
    nan[3] = f64::NAN;
    assert_eq!(
        fit_pole(&t, &z, &nan, 0.0, 0.0).unwrap_err().argument,
        "obliquity"
    );
    assert!(fit_pole(&t, &z, &z, 0.0, 0.0).is_ok());
}
