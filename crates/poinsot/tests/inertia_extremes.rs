//! Mass properties at extreme magnitudes (issue 10, items 1.4 and 1.6): every returned number is
//! finite, or the call returns an error naming the user's argument; a result that is
//! representable is never refused (nor spoilt) because an intermediate product overflowed or
//! underflowed.
//!
//! The reference is scale invariance, which is exact in binary floating point: multiplying a
//! mass by 2^a and every length by 2^b multiplies a moment of inertia by exactly 2^(a + 2b), a
//! centre of mass by 2^b, and so on, as long as the results are normal numbers. So a body built
//! at an extreme scale must equal the same body built at unit scale, multiplied by the power of
//! two, **bit for bit**; a negative control checks that the naive formula really overflows or
//! underflows there.

use poinsot::inertia::{self, MassProperties};
use poinsot::{ErrorKind, Mat3, Vec3};
use proptest::prelude::*;

/// 2^k for k in [-1022, 1023].
fn p2(k: i32) -> f64 {
    assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}

/// x · 2^k in two exact steps (the test's own reference; x·2^k is a normal number here).
fn scaled(x: f64, k: i32) -> f64 {
    let h = k / 2;
    x * p2(h) * p2(k - h)
}

fn scaled_mat(m: &Mat3, k: i32) -> Mat3 {
    m.map(|x| scaled(x, k))
}

/// The nine solids as functions of (mass, one length scale `l`): the dimensions are fixed
/// multiples of `l`, so that the nine cover every formula.
type Solid = fn(f64, f64) -> poinsot::Result<MassProperties>;

fn solids() -> Vec<(&'static str, &'static str, Solid)> {
    vec![
        ("solid_sphere", "radius", |m, l| inertia::solid_sphere(m, l)),
        ("spherical_shell", "radius", |m, l| {
            inertia::spherical_shell(m, l)
        }),
        ("solid_cylinder", "height", |m, l| {
            inertia::solid_cylinder(m, l, 3.0 * l)
        }),
        ("solid_cone", "height", |m, l| {
            inertia::solid_cone(m, l, 1.5 * l)
        }),
        ("cuboid", "sides", |m, l| {
            inertia::cuboid(m, [l, 2.0 * l, 0.75 * l])
        }),
        ("ellipsoid", "semi_axes", |m, l| {
            inertia::ellipsoid(m, [l, 0.5 * l, 1.25 * l])
        }),
        ("thin_rod", "length", |m, l| inertia::thin_rod(m, l)),
        ("thin_disk", "radius", |m, l| inertia::thin_disk(m, l)),
        ("thin_ring", "radius", |m, l| inertia::thin_ring(m, l)),
    ]
}

/// The case: `solid_sphere(1.0, 1e308)` returned an infinite inertia.
#[test]
fn solid_sphere_of_radius_1e308_is_refused_naming_radius() {
    let e = inertia::solid_sphere(1.0, 1e308).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidArgument, "{e}");
    assert_eq!(e.argument, "radius", "{e}");
    assert!(e.message.contains("largest finite"), "{e}");
    // The mass is the extreme argument here.
    let e = inertia::solid_sphere(1e308, 10.0).unwrap_err();
    assert_eq!(e.argument, "mass", "{e}");
    // Every solid, both ways.
    for (name, length, f) in solids() {
        let e = f(1.0, 1e300).unwrap_err();
        assert_eq!(e.argument, length, "{name}: {e}");
        let e = f(1.0, 1e-300).unwrap_err();
        assert_eq!(e.argument, length, "{name}: {e}");
        assert!(e.message.contains("smallest normal"), "{name}: {e}");
    }
}

/// Representable moments whose naive intermediates overflow (r² for r = 2^600) or underflow
/// (r² for r = 2^-600) are computed exactly: equal, bit for bit, to the unit-scale body times
/// the power of two.
#[test]
fn solids_with_representable_moments_are_exact_at_extreme_scales() {
    for (a, b) in [
        (-1000, 600),
        (1000, -600),
        (-300, 520),
        (900, -540),
        (-200, 530),
    ] {
        // Negative control: the naive m r² leaves the range of doubles in an intermediate.
        let (m, r) = (p2(a), p2(b));
        let naive = m * (r * r);
        assert!(
            naive == 0.0 || !naive.is_finite(),
            "({a}, {b}) is not an extreme case"
        );
        for (name, _, f) in solids() {
            let unit = f(1.5, 0.75).unwrap();
            let far = f(1.5 * m, 0.75 * r).unwrap_or_else(|e| panic!("{name} ({a}, {b}): {e}"));
            assert_eq!(far.mass(), scaled(unit.mass(), a), "{name}");
            assert_eq!(
                far.center_of_mass(),
                unit.center_of_mass().map(|x| scaled(x, b)),
                "{name}"
            );
            assert_eq!(
                far.inertia(),
                scaled_mat(&unit.inertia(), a + 2 * b),
                "{name} ({a}, {b})"
            );
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, rng_seed: proptest::test_runner::RngSeed::Fixed(20261110), ..ProptestConfig::default() })]

    /// Scale invariance of the nine solids across the whole double range: wherever every
    /// moment is a normal number the body is exact, elsewhere a named error.
    #[test]
    fn solids_are_exact_or_refused_everywhere(a in -1020i32..1020, b in -520i32..520, m in 0.5f64..2.0, l in 0.5f64..2.0) {
        for (name, length, f) in solids() {
            let unit = f(m, l).unwrap();
            let k = a + 2 * b;
            // The largest moment at unit scale is in [2^-5, 2^5]; whether it stays normal:
            let largest = unit.inertia().amax();
            let exp = largest.log2().floor() as i32 + k;
            match f(scaled(m, a), scaled(l, b)) {
                Ok(body) => {
                    prop_assert!((-1022..=1023).contains(&exp), "{} accepted out of range", name);
                    let expect = scaled_mat(&unit.inertia(), k);
                    for (x, y) in body.inertia().iter().zip(expect.iter()) {
                        // Bit for bit where normal; one rounding of a subnormal otherwise.
                        prop_assert!(x == y || (x - y).abs() <= f64::from_bits(1), "{}: {} vs {}", name, x, y);
                    }
                    prop_assert_eq!(body.mass(), scaled(m, a));
                }
                Err(e) => {
                    prop_assert!(!(-1021..=1022).contains(&exp), "{} refused in range: {}", name, e);
                    prop_assert!(e.argument == "mass" || e.argument == length, "{}: {}", name, e);
                }
            }
        }
    }
}

/// Point masses: the parallel-axis sums no longer square positions of 1e200 (|r|² = inf)
/// when m |r|² is representable, and the masses' sum is checked.
#[test]
fn point_masses_at_extreme_scales() {
    let pos = [[1.0, 0.5, -0.25], [-1.0, 0.25, 0.5], [0.5, -1.0, 0.0]];
    let masses = [1.0, 2.0, 0.5];
    let unit = MassProperties::from_point_masses(&masses, &pos).unwrap();
    for (a, b) in [(-1000, 650), (1000, -650), (0, 500), (0, -500)] {
        let m: Vec<f64> = masses.iter().map(|x| scaled(*x, a)).collect();
        let p: Vec<[f64; 3]> = pos.iter().map(|r| r.map(|x| scaled(x, b))).collect();
        let far = MassProperties::from_point_masses(&m, &p).unwrap();
        assert_eq!(far.mass(), scaled(unit.mass(), a));
        let d = (far.center_of_mass() - unit.center_of_mass().map(|x| scaled(x, b))).amax();
        assert!(
            d <= 4.0 * f64::EPSILON * scaled(1.0, b),
            "({a}, {b}) com off by {d}"
        );
        let expect = scaled_mat(&unit.inertia(), a + 2 * b);
        let err = (far.inertia() - expect).amax();
        assert!(
            err <= 16.0 * f64::EPSILON * expect.amax(),
            "({a}, {b}): {} vs {expect}",
            far.inertia()
        );
    }
    // Out of range: named errors.
    let e = MassProperties::from_point_masses(&[1e308, 1e308], &[[0.0; 3], [1.0; 3]]).unwrap_err();
    assert_eq!(e.argument, "masses", "{e}");
    let e =
        MassProperties::from_point_masses(&[1.0, 1.0], &[[1e300, 0.0, 0.0], [-1e300, 0.0, 0.0]])
            .unwrap_err();
    assert_eq!(e.argument, "positions", "{e}");
    let e = MassProperties::from_point_masses(&[1e-300, 1e-300], &[[1e-10, 0.0, 0.0], [0.0; 3]])
        .unwrap_err();
    assert!(e.message.contains("smallest normal"), "{e}");
}

/// A tensor of the largest (or smallest normal) magnitudes passes the check and its principal
/// axes are finite: the eigen-decomposition no longer squares 1e300.
#[test]
fn inertia_tensors_of_extreme_magnitude_are_checked_exactly() {
    let base = Mat3::new(2.0, -0.5, 0.25, -0.5, 3.0, 0.125, 0.25, 0.125, 2.5);
    for k in [1000, 600, -600, -1015] {
        let i = scaled_mat(&base, k);
        let b = MassProperties::new(1.0, Vec3::zeros(), i).unwrap_or_else(|e| panic!("2^{k}: {e}"));
        let unit = inertia::principal(&base, 1e-9);
        let p = b.principal(1e-9);
        assert!(p.axes.iter().all(|x| x.is_finite()), "2^{k}: {}", p.axes);
        assert!((p.axes - unit.axes).amax() <= 1e-13, "2^{k}");
        for j in 0..3 {
            let expect = scaled(unit.moments[j], k);
            assert!((p.moments[j] - expect).abs() <= 1e-14 * expect, "2^{k}");
        }
        // A tensor that violates the triangle inequality is refused at every scale.
        let bad = scaled_mat(&Mat3::from_diagonal(&Vec3::new(1.0, 1.0, 2.5)), k);
        let e = MassProperties::new(1.0, Vec3::zeros(), bad).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidInertia, "2^{k}: {e}");
    }
}

/// `inertia_about`, `from_inertia_about`, `angular_momentum`, `kinetic_energy`,
/// `holding_torque`: finite and exact where representable, else an error naming the argument.
#[test]
fn derived_quantities_are_finite_or_refused() {
    // A light body far from the point: m d² = 2^-1000 · 2^1300 is representable, d² is not.
    let light = inertia::solid_sphere(p2(-1000), 1.0).unwrap();
    let p = Vec3::new(-p2(650), 0.0, 0.0);
    let i_p = light.inertia_about(&p).unwrap();
    assert_eq!(i_p[(1, 1)], scaled(1.0, 300) + 0.4 * p2(-1000));
    assert_eq!(i_p[(0, 0)], 0.4 * p2(-1000));
    let back = MassProperties::from_inertia_about(light.mass(), Vec3::zeros(), i_p, p).unwrap();
    assert_eq!(back.mass(), light.mass());
    // Unrepresentable: the unit body about a point 1e200 away.
    let unit = inertia::solid_sphere(1.0, 1.0).unwrap();
    let e = unit.inertia_about(&Vec3::new(1e200, 0.0, 0.0)).unwrap_err();
    assert_eq!(e.argument, "point", "{e}");
    let e = unit
        .angular_momentum(&Vec3::new(0.0, 1.0, 0.0), Some(&Vec3::new(1e200, 0.0, 0.0)))
        .unwrap_err();
    assert_eq!(e.argument, "about", "{e}");
    // ω of 1e200 on a unit body: L = 4e199 is fine, T = ½ ω·L = 2e399 is not.
    let w = Vec3::new(1e200, 0.0, 0.0);
    let l = unit.angular_momentum(&w, None).unwrap();
    assert_eq!(l, Vec3::new(0.4 * 1e200, 0.0, 0.0));
    let e = unit.kinetic_energy(&w, None).unwrap_err();
    assert_eq!(e.argument, "omega", "{e}");
    let ten = inertia::cuboid(10.0, [1.0, 2.0, 3.0]).unwrap();
    let e = ten
        .angular_momentum(&Vec3::new(1e308, 1e308, 0.0), None)
        .unwrap_err();
    assert_eq!(e.argument, "omega", "{e}");
    // The holding torque ω × L of an asymmetric body: |ω|² |I| overflows at |ω| = 1e155.
    let brick = inertia::cuboid(1.0, [1.0, 2.0, 3.0]).unwrap();
    let e = brick
        .holding_torque(&Vec3::new(1e155, 1e155, 0.0), None)
        .unwrap_err();
    assert_eq!(e.argument, "omega", "{e}");
    // Exact at extreme scales (scaling by powers of two commutes with rounding): a body of
    // 2^-1000 kg turning at 2^-100 rad/s has L ~ 2^-1100, below the normal range, but the
    // angle between L and ω is the unit body's; before, L underflowed to zero and the angle
    // was refused as undefined.
    let unit_brick = brick;
    let unit_w = Vec3::new(1.0, -0.5, 0.25);
    let light = inertia::cuboid(p2(-1000), [1.0, 2.0, 3.0]).unwrap();
    let slow = unit_w.map(|x| scaled(x, -100));
    let a = light
        .momentum_angle(&slow, None)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(a, unit_brick.momentum_angle(&unit_w, None).unwrap());
    // Heavy and slow: I ~ 2^900, ω ~ 2^-600, T ~ 2^-300.
    let heavy = inertia::cuboid(p2(900), [1.0, 2.0, 3.0]).unwrap();
    let small = unit_w.map(|x| scaled(x, -600));
    assert_eq!(
        heavy.kinetic_energy(&small, None).unwrap(),
        scaled(
            unit_brick.kinetic_energy(&unit_w, None).unwrap(),
            900 - 1200
        )
    );
    assert_eq!(
        heavy.holding_torque(&small, None).unwrap(),
        unit_brick
            .holding_torque(&unit_w, None)
            .unwrap()
            .map(|x| scaled(x, 900 - 1200))
    );
}

/// Composition, translation and rotation at extreme scales.
#[test]
fn composition_translation_rotation_at_extreme_scales() {
    // Two light spheres 2^651 apart: the parallel-axis term m d² is representable, d² is not.
    let s = inertia::solid_sphere(p2(-1000), 1.0).unwrap();
    let a = s.translated(&Vec3::new(p2(650), 0.0, 0.0)).unwrap();
    let b = s.translated(&Vec3::new(-p2(650), 0.0, 0.0)).unwrap();
    let ab = MassProperties::combine(&[a, b]).unwrap();
    assert_eq!(ab.mass(), p2(-999));
    assert_eq!(ab.center_of_mass(), Vec3::zeros());
    assert_eq!(ab.inertia()[(1, 1)], p2(301) + 0.8 * p2(-1000));
    // Out of range: named.
    let big = inertia::solid_sphere(1e308, 1e-100).unwrap();
    let e = MassProperties::combine(&[big, big]).unwrap_err();
    assert_eq!(e.argument, "bodies", "{e}");
    let unit = inertia::solid_sphere(1.0, 1.0).unwrap();
    let far = unit.translated(&Vec3::new(1e200, 0.0, 0.0)).unwrap();
    let e = MassProperties::combine(&[unit, far]).unwrap_err();
    assert_eq!(e.argument, "bodies", "{e}");
    let edge = unit.translated(&Vec3::new(1.5e308, 0.0, 0.0)).unwrap();
    let e = edge.translated(&Vec3::new(1.5e308, 0.0, 0.0)).unwrap_err();
    assert_eq!(e.argument, "offset", "{e}");
    // Rotating a tensor at the top of the range: R I Rᵀ without overflow in the products.
    let top = MassProperties::new(
        1.0,
        Vec3::zeros(),
        Mat3::from_diagonal(&Vec3::new(1.5e308, 1.0e308, 1.2e308)),
    )
    .unwrap();
    // Stored as given: the symmetrisation (I + Iᵀ)/2 overflowed to inf before.
    assert_eq!(top.inertia()[(0, 0)], 1.5e308);
    let (c, sn) = (0.6, 0.8);
    let r = Mat3::new(c, -sn, 0.0, sn, c, 0.0, 0.0, 0.0, 1.0);
    let turned = top.rotated(&r).unwrap();
    assert!(
        turned.inertia().iter().all(|x| x.is_finite()),
        "{}",
        turned.inertia()
    );
    let p = turned.principal(1e-9).moments;
    assert!((p[2] - 1.5e308).abs() <= 1e-14 * 1.5e308, "{p:?}");
}

/// A density whose integrals overflow names `density` (before: the internal `mass`), and one
/// that is representable throughout is integrated.
#[test]
fn density_integrals_that_overflow_name_density() {
    let opts = inertia::CubatureOptions::default();
    let uniform = |rho: f64| {
        move |p: &[[f64; 3]], v: &mut [f64]| -> poinsot::Result<()> {
            v[..p.len()].fill(rho);
            Ok(())
        }
    };
    let e =
        inertia::density_mass_properties(uniform(1e308), [[-10.0, 10.0]; 3], &opts).unwrap_err();
    assert_eq!(e.argument, "density", "{e}");
    assert!(e.message.contains("largest finite"), "{e}");
    let r = inertia::density_mass_properties(uniform(1e300), [[-0.5, 0.5]; 3], &opts).unwrap();
    assert!((r.body.mass() - 1e300).abs() <= 1e-12 * 1e300);
    assert!((r.body.inertia()[(0, 0)] - 1e300 / 6.0).abs() <= 1e-12 * 1e300);
}

/// A body reports its triangle margins (`I₂ + I₃ − I₁, ...`, up to twice the largest moment):
/// where they would overflow although every moment is finite (a rod of 1.7e308 kg), the body is
/// refused where it is made, naming the argument, instead of reporting an infinite margin.
#[test]
fn bodies_whose_triangle_margins_overflow_are_refused() {
    let e = inertia::thin_rod(1.7e308, 3.4).unwrap_err();
    assert!(e.argument == "mass" || e.argument == "length", "{e}");
    let big = Mat3::from_diagonal(&Vec3::new(0.0, 1.5e308, 1.5e308));
    let e = MassProperties::new(1.0, Vec3::zeros(), big).unwrap_err();
    assert_eq!(e.argument, "inertia", "{e}");
    // Just inside: the margins are finite.
    let rod = inertia::thin_rod(0.8e308, 3.4).unwrap();
    let margins = rod.principal(1e-9).triangle_margins();
    assert!(margins.iter().all(|m| m.is_finite()), "{margins:?}");
    let ok = MassProperties::new(1.0, Vec3::zeros(), big / 2.0).unwrap();
    assert!(ok.principal(1e-9).triangle_margins()[0].is_finite());
    // Margins that are finite although the sum I2 + I3 is not: computed without that sum.
    let top = Mat3::from_diagonal(&Vec3::new(1.5e308, 1.0e308, 1.2e308));
    let m = MassProperties::new(1.0, Vec3::zeros(), top)
        .unwrap()
        .principal(1e-9)
        .triangle_margins();
    for (x, want) in m.iter().zip([1.7e308, 1.3e308, 0.7e308]) {
        assert!((x / want - 1.0).abs() < 1e-15, "{m:?}");
    }
}
