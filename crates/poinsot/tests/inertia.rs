//! Integration tests of `poinsot::inertia` against independent references: textbook formulas
//! written out here, exact polygon/prism formulas for meshes, direct sums over particles,
//! finite differences, and invariants (proptest).

use std::f64::consts::PI;

use poinsot::inertia::{self, CubatureOptions, MassProperties, TopKind, DEFAULT_KIND_RTOL};
use poinsot::{ErrorKind, Mat3, Vec3};
use proptest::prelude::*;

/// Round-off tolerance of closed forms and exact integrals (a few ulps of O(1) sums).
const EXACT: f64 = 1e-12;

fn diag(a: f64, b: f64, c: f64) -> Mat3 {
    Mat3::from_diagonal(&Vec3::new(a, b, c))
}

fn close(a: &Mat3, b: &Mat3, rtol: f64) -> bool {
    (a - b).amax() <= rtol * b.amax().max(1e-300)
}

/// A rotation matrix from a (non-zero) quaternion, normalised.
fn rot(q: [f64; 4]) -> Mat3 {
    let n = (q.iter().map(|x| x * x).sum::<f64>()).sqrt();
    let [w, x, y, z] = q.map(|c| c / n);
    Mat3::new(
        1.0 - 2.0 * (y * y + z * z),
        2.0 * (x * y - w * z),
        2.0 * (x * z + w * y),
        2.0 * (x * y + w * z),
        1.0 - 2.0 * (x * x + z * z),
        2.0 * (y * z - w * x),
        2.0 * (x * z - w * y),
        2.0 * (y * z + w * x),
        1.0 - 2.0 * (x * x + y * y),
    )
}

// ---------------------------------------------------------------------------------------------
// Mesh builders (outward faces).

struct Mesh {
    v: Vec<[f64; 3]>,
    f: Vec<[u32; 3]>,
}

/// An axis-aligned box [0,a]×[0,b]×[0,c], 12 outward triangles.
fn box_mesh(a: f64, b: f64, c: f64) -> Mesh {
    let v = (0..8)
        .map(|i| {
            [
                a * (i & 1) as f64,
                b * ((i >> 1) & 1) as f64,
                c * ((i >> 2) & 1) as f64,
            ]
        })
        .collect();
    let f = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    Mesh { v, f }
}

/// A closed surface of revolution about z: `profile` runs from a pole (r = 0) to a pole,
/// `n` vertices per ring (a regular n-gon of circumradius r).
fn revolve(profile: &[(f64, f64)], n: usize) -> Mesh {
    let rings = &profile[1..profile.len() - 1];
    let mut v = vec![[0.0, 0.0, profile[0].1]];
    for &(r, z) in rings {
        for j in 0..n {
            let phi = 2.0 * PI * j as f64 / n as f64;
            v.push([r * phi.cos(), r * phi.sin(), z]);
        }
    }
    let top = v.len() as u32;
    v.push([0.0, 0.0, profile[profile.len() - 1].1]);
    let at = |ring: usize, j: usize| (1 + ring * n + j % n) as u32;
    let mut f = Vec::new();
    for j in 0..n {
        f.push([0, at(0, j + 1), at(0, j)]);
    }
    for i in 0..rings.len() - 1 {
        for j in 0..n {
            let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
            f.push([a, b, c]);
            f.push([a, c, d]);
        }
    }
    let last = rings.len() - 1;
    for j in 0..n {
        f.push([top, at(last, j), at(last, j + 1)]);
    }
    Mesh { v, f }
}

fn mesh_body(m: &Mesh, density: f64) -> poinsot::Result<MassProperties> {
    inertia::mesh_mass_properties_rows(&m.v, &m.f, density)
}

/// Area and polar second moment (about the centre, per unit surface density) of a regular
/// n-gon of circumradius r: A = n r² sin α / 2, J = n r⁴ sin α (2 + cos α) / 12, α = 2π/n.
fn ngon(n: usize, r: f64) -> (f64, f64) {
    let a = 2.0 * PI / n as f64;
    (
        n as f64 * r * r * a.sin() / 2.0,
        n as f64 * r.powi(4) * a.sin() * (2.0 + a.cos()) / 12.0,
    )
}

// ---------------------------------------------------------------------------------------------
// Standard solids against their textbook formulas (written out again here).

#[test]
fn solids_match_textbook_formulas() {
    let (m, r, h) = (2.5, 0.4, 1.3);
    let cases: Vec<(MassProperties, Vec3, Mat3, TopKind)> = vec![
        (
            inertia::solid_sphere(m, r).unwrap(),
            Vec3::zeros(),
            Mat3::identity() * (2.0 / 5.0 * m * r * r),
            TopKind::SphericalTop,
        ),
        (
            inertia::spherical_shell(m, r).unwrap(),
            Vec3::zeros(),
            Mat3::identity() * (2.0 / 3.0 * m * r * r),
            TopKind::SphericalTop,
        ),
        (
            inertia::solid_cylinder(m, r, h).unwrap(),
            Vec3::zeros(),
            diag(
                m * (r * r / 4.0 + h * h / 12.0),
                m * (r * r / 4.0 + h * h / 12.0),
                m * r * r / 2.0,
            ),
            TopKind::SymmetricTop,
        ),
        (
            inertia::solid_cone(m, r, h).unwrap(),
            Vec3::new(0.0, 0.0, 0.75 * h),
            diag(
                m * (3.0 * r * r / 20.0 + 3.0 * h * h / 80.0),
                m * (3.0 * r * r / 20.0 + 3.0 * h * h / 80.0),
                3.0 * m * r * r / 10.0,
            ),
            TopKind::SymmetricTop,
        ),
        (
            inertia::cuboid(m, [1.0, 2.0, 3.0]).unwrap(),
            Vec3::zeros(),
            diag(m * 13.0 / 12.0, m * 10.0 / 12.0, m * 5.0 / 12.0),
            TopKind::AsymmetricTop,
        ),
        (
            inertia::ellipsoid(m, [1.0, 2.0, 3.0]).unwrap(),
            Vec3::zeros(),
            diag(m * 13.0 / 5.0, m * 10.0 / 5.0, m * 5.0 / 5.0),
            TopKind::AsymmetricTop,
        ),
        (
            inertia::thin_rod(m, h).unwrap(),
            Vec3::zeros(),
            diag(m * h * h / 12.0, m * h * h / 12.0, 0.0),
            TopKind::Rotor,
        ),
        (
            inertia::thin_disk(m, r).unwrap(),
            Vec3::zeros(),
            diag(m * r * r / 4.0, m * r * r / 4.0, m * r * r / 2.0),
            TopKind::SymmetricTop,
        ),
        (
            inertia::thin_ring(m, r).unwrap(),
            Vec3::zeros(),
            diag(m * r * r / 2.0, m * r * r / 2.0, m * r * r),
            TopKind::SymmetricTop,
        ),
    ];
    for (i, (b, com, expect, kind)) in cases.iter().enumerate() {
        assert_eq!(b.mass(), m, "case {i}");
        assert!((b.center_of_mass() - com).amax() <= EXACT, "case {i}");
        assert!(
            close(&b.inertia(), expect, EXACT),
            "case {i}: {} vs {}",
            b.inertia(),
            expect
        );
        assert_eq!(b.kind(DEFAULT_KIND_RTOL).unwrap(), *kind, "case {i}");
    }
    // Dimensions are checked and named.
    for (e, arg) in [
        (inertia::solid_sphere(-1.0, 1.0).unwrap_err(), "mass"),
        (
            inertia::solid_cylinder(1.0, 1.0, 0.0).unwrap_err(),
            "height",
        ),
        (
            inertia::cuboid(1.0, [1.0, f64::NAN, 1.0]).unwrap_err(),
            "sides",
        ),
        (
            inertia::ellipsoid(1.0, [1.0, -1.0, 1.0]).unwrap_err(),
            "semi_axes",
        ),
        (inertia::thin_rod(1.0, f64::INFINITY).unwrap_err(), "length"),
    ] {
        assert_eq!(e.argument, arg, "{e}");
    }
}

// ---------------------------------------------------------------------------------------------
// Composition: the parry parallel-axis bug.

#[test]
fn three_stacked_unit_cubes_equal_one_cuboid() {
    // Along z (1×1×3) and along y (1×3×1: parry's case).
    for axis in [2usize, 1] {
        let cubes: Vec<MassProperties> = (0..3)
            .map(|k| {
                let mut off = Vec3::zeros();
                off[axis] = k as f64;
                inertia::cuboid(1.0, [1.0; 3])
                    .unwrap()
                    .translated(&off)
                    .unwrap()
            })
            .collect();
        let compound = MassProperties::combine(&cubes).unwrap();
        let mut sides = [1.0; 3];
        sides[axis] = 3.0;
        let mut com = Vec3::zeros();
        com[axis] = 1.0;
        let monolith = inertia::cuboid(3.0, sides)
            .unwrap()
            .translated(&com)
            .unwrap();
        assert!((compound.mass() - 3.0).abs() <= EXACT);
        assert!((compound.center_of_mass() - com).amax() <= EXACT);
        assert!(
            close(&compound.inertia(), &monolith.inertia(), EXACT),
            "{} vs {}",
            compound.inertia(),
            monolith.inertia()
        );
        // Negative control: summing the cubes' own tensors without the shift is wrong.
        let unshifted: Mat3 = cubes.iter().map(|c| c.inertia()).sum();
        assert!(!close(&unshifted, &monolith.inertia(), 1e-3));
    }
}

#[test]
fn cone_mesh_about_apex_vs_formula() {
    // The cone's apex is at the origin: I about the apex = I_cm + m (3h/4)² on the x axis.
    let (m, r, h) = (1.0, 0.5, 2.0);
    let c = inertia::solid_cone(m, r, h).unwrap();
    let i0 = c.inertia_about(&Vec3::zeros()).unwrap();
    assert!((i0[(0, 0)] - m * (3.0 * r * r / 20.0 + 3.0 * h * h / 5.0)).abs() <= EXACT);
    assert!((i0[(2, 2)] - 0.3 * m * r * r).abs() <= EXACT);
}

// ---------------------------------------------------------------------------------------------
// Meshes against exact formulas.

#[test]
fn box_mesh_matches_cuboid() {
    let (a, b, c, rho) = (0.3, 1.7, 2.2, 7850.0);
    let body = mesh_body(&box_mesh(a, b, c), rho).unwrap();
    let m = rho * a * b * c;
    let reference = inertia::cuboid(m, [a, b, c]).unwrap();
    assert!((body.mass() - m).abs() <= EXACT * m);
    assert!((body.center_of_mass() - Vec3::new(a / 2.0, b / 2.0, c / 2.0)).amax() <= EXACT);
    assert!(close(&body.inertia(), &reference.inertia(), EXACT));
    // Far from the origin: the reference point at the mesh's centre keeps the accuracy.
    let far = Mesh {
        v: box_mesh(a, b, c)
            .v
            .iter()
            .map(|p| [p[0] + 1e4, p[1] - 3e4, p[2] + 2e4])
            .collect(),
        f: box_mesh(a, b, c).f,
    };
    let body = mesh_body(&far, rho).unwrap();
    assert!(
        close(&body.inertia(), &reference.inertia(), 1e-9),
        "{}",
        body.inertia()
    );
}

#[test]
fn prism_and_pyramid_meshes_are_exact() {
    // Regular n-gon prism (a faceted cylinder) and pyramid (a faceted cone, apex at origin):
    // exact polygon formulas, and the circular limit as n grows.
    let (r, h, rho) = (0.5, 1.5, 2.0);
    for n in [3usize, 7, 64] {
        let (area, j) = ngon(n, r);
        let prism = mesh_body(
            &revolve(
                &[(0.0, -h / 2.0), (r, -h / 2.0), (r, h / 2.0), (0.0, h / 2.0)],
                n,
            ),
            rho,
        )
        .unwrap();
        let m = rho * area * h;
        let expect = diag(
            rho * h * j / 2.0 + m * h * h / 12.0,
            rho * h * j / 2.0 + m * h * h / 12.0,
            rho * h * j,
        );
        assert!((prism.mass() - m).abs() <= EXACT * m, "n={n}");
        assert!(
            close(&prism.inertia(), &expect, EXACT),
            "n={n}: {} vs {}",
            prism.inertia(),
            expect
        );
        let pyramid = mesh_body(&revolve(&[(0.0, 0.0), (r, h), (0.0, h)], n), rho).unwrap();
        let m = rho * area * h / 3.0;
        let ixx_apex = rho * (j * h / 10.0 + area * h * h * h / 5.0);
        let expect = diag(
            ixx_apex - m * (0.75 * h).powi(2),
            ixx_apex - m * (0.75 * h).powi(2),
            rho * j * h / 5.0,
        );
        assert!((pyramid.mass() - m).abs() <= EXACT * m, "n={n}");
        assert!((pyramid.center_of_mass() - Vec3::new(0.0, 0.0, 0.75 * h)).amax() <= EXACT);
        assert!(
            close(&pyramid.inertia(), &expect, EXACT),
            "n={n}: {} vs {}",
            pyramid.inertia(),
            expect
        );
    }
    // Circular limit: the faceting error of the n-gon is O((2π/n)²).
    let n = 512;
    let err_tol = 2.0 * (2.0 * PI / n as f64).powi(2);
    let cone = mesh_body(&revolve(&[(0.0, 0.0), (r, h), (0.0, h)], n), rho).unwrap();
    let reference = inertia::solid_cone(cone.mass(), r, h).unwrap();
    assert!(close(&cone.inertia(), &reference.inertia(), err_tol));
}

#[test]
fn uv_sphere_converges_at_second_order() {
    let sphere = |n: usize| {
        let profile: Vec<(f64, f64)> = (0..=n)
            .map(|k| k as f64 * PI / n as f64)
            .map(|t| (t.sin(), -t.cos()))
            .collect();
        mesh_body(&revolve(&profile, 2 * n), 1.0).unwrap()
    };
    let err = |b: &MassProperties| {
        let exact = inertia::solid_sphere(4.0 / 3.0 * PI, 1.0).unwrap();
        (b.inertia() - exact.inertia()).amax() / exact.inertia().amax()
    };
    let (e1, e2) = (err(&sphere(32)), err(&sphere(64)));
    // Halving the facet size divides the error by ~4 (second-order faceting error).
    assert!(e2 < e1 && (e1 / e2 - 4.0).abs() < 0.3, "{e1} {e2}");
    assert_eq!(sphere(64).kind(1e-9).unwrap(), TopKind::SymmetricTop);
    assert_eq!(sphere(64).kind(1e-2).unwrap(), TopKind::SphericalTop);
}

#[test]
fn mesh_refusals_say_what_is_wrong() {
    let good = box_mesh(1.0, 2.0, 3.0);
    assert!(mesh_body(&good, 1.0).is_ok());
    let expect = |m: &Mesh, arg: &str, words: &[&str]| {
        let e = mesh_body(m, 1.0).unwrap_err();
        assert_eq!(e.kind, ErrorKind::InvalidMesh, "{e}");
        assert_eq!(e.argument, arg, "{e}");
        for w in words {
            assert!(e.message.contains(w), "{e} lacks {w}");
        }
    };
    // Open: two faces removed (a whole side of the box) leaves 4 boundary edges.
    expect(
        &Mesh {
            v: good.v.clone(),
            f: good.f[2..].to_vec(),
        },
        "faces",
        &["open", "4 boundary edge"],
    );
    // Non-manifold: a second box sharing the edge (0, 1)... simpler: a fin of two faces.
    let mut f = good.f.clone();
    let mut v = good.v.clone();
    v.push([0.5, -1.0, 0.0]);
    f.push([0, 1, 8]);
    f.push([1, 0, 8]);
    expect(
        &Mesh { v, f },
        "faces",
        &["non-manifold", "used by 4 faces"],
    );
    // Inconsistent orientation: one face flipped.
    let mut f = good.f.clone();
    f[5] = [f[5][0], f[5][2], f[5][1]];
    expect(
        &Mesh {
            v: good.v.clone(),
            f,
        },
        "faces",
        &["inconsistently oriented"],
    );
    // Inside-out: every face flipped.
    let f = good.f.iter().map(|t| [t[0], t[2], t[1]]).collect();
    expect(
        &Mesh {
            v: good.v.clone(),
            f,
        },
        "faces",
        &["oriented inward", "reverse the winding"],
    );
    // Index out of range, non-finite vertex.
    let mut f = good.f.clone();
    f[3][2] = 99;
    expect(
        &Mesh {
            v: good.v.clone(),
            f,
        },
        "faces",
        &["99", "out of range"],
    );
    let mut v = good.v.clone();
    v[2][0] = f64::INFINITY;
    expect(
        &Mesh {
            v,
            f: good.f.clone(),
        },
        "vertices",
        &["finite", "vertex 2"],
    );
    // Zero volume: a box squashed flat.
    let v = good.v.iter().map(|p| [p[0], p[1], 0.0]).collect();
    expect(
        &Mesh {
            v,
            f: good.f.clone(),
        },
        "vertices",
        &["zero volume"],
    );
    // All degenerate: every vertex at one point.
    expect(
        &Mesh {
            v: vec![[1.0; 3]; 8],
            f: good.f.clone(),
        },
        "faces",
        &["degenerate"],
    );
    // Density must be positive.
    assert_eq!(mesh_body(&good, 0.0).unwrap_err().argument, "density");
    // Negative control: a closed mesh with a degenerate (repeated-index) face still passes.
    let mut f = good.f.clone();
    f.push([0, 0, 1]);
    assert!(mesh_body(
        &Mesh {
            v: good.v.clone(),
            f
        },
        1.0
    )
    .is_ok());
}

#[test]
fn two_component_shell_mesh() {
    // Outer sphere outward, inner sphere inward: a thick shell; closed and consistent.
    let sphere = |radius: f64, outward: bool| {
        let n = 48;
        let profile: Vec<(f64, f64)> = (0..=n)
            .map(|k| k as f64 * PI / n as f64)
            .map(|t| (radius * t.sin(), -radius * t.cos()))
            .collect();
        let mut m = revolve(&profile, 2 * n);
        if !outward {
            m.f.iter_mut().for_each(|t| t.swap(1, 2));
        }
        m
    };
    let (outer, inner) = (sphere(1.0, true), sphere(0.9, false));
    let off = outer.v.len() as u32;
    let mut v = outer.v.clone();
    v.extend(inner.v.iter());
    let mut f = outer.f.clone();
    f.extend(inner.f.iter().map(|t| t.map(|i| i + off)));
    let shell = mesh_body(&Mesh { v, f }, 1.0).unwrap();
    let o = mesh_body(&outer, 1.0).unwrap();
    let mut inner_out = inner;
    inner_out.f.iter_mut().for_each(|t| t.swap(1, 2));
    let i = mesh_body(&inner_out, 1.0).unwrap();
    assert!((shell.mass() - (o.mass() - i.mass())).abs() <= EXACT);
    assert!(close(&shell.inertia(), &(o.inertia() - i.inertia()), 1e-12));
}

// ---------------------------------------------------------------------------------------------
// Density cubature.

#[test]
fn density_of_uniform_ellipsoid_is_within_its_error_estimate() {
    let (a, b, c, rho) = (1.0, 0.7, 0.5, 3.0);
    let r = inertia::density_mass_properties(
        |p: &[[f64; 3]], v: &mut [f64]| {
            for (x, o) in p.iter().zip(v.iter_mut()) {
                let s = (x[0] / a).powi(2) + (x[1] / b).powi(2) + (x[2] / c).powi(2);
                *o = if s <= 1.0 { rho } else { 0.0 };
            }
            Ok(())
        },
        [[-a, a], [-b, b], [-c, c]],
        &CubatureOptions {
            rtol: 1e-2,
            ..Default::default()
        },
    )
    .unwrap();
    let m = rho * 4.0 / 3.0 * PI * a * b * c;
    let exact = inertia::ellipsoid(m, [a, b, c]).unwrap();
    assert!(r.converged);
    assert!(
        (r.body.mass() - m).abs() <= r.mass_error,
        "{} vs {m} ± {}",
        r.body.mass(),
        r.mass_error
    );
    assert!((r.body.inertia() - exact.inertia()).amax() <= r.inertia_error);
    assert!(r.body.center_of_mass().amax() <= r.center_of_mass_error);
}

#[test]
fn density_of_smooth_gaussian_converges_tightly() {
    // ρ = exp(−(x²/σx² + y²/σy² + z²/σz²)/2) shifted to c: m = (2π)^{3/2} σx σy σz,
    // I_xx = m (σy² + σz²), products zero.
    let (s, c) = ([0.5, 0.8, 1.1], [0.3, -0.2, 0.1]);
    let r = inertia::density_mass_properties(
        |p: &[[f64; 3]], v: &mut [f64]| {
            for (x, o) in p.iter().zip(v.iter_mut()) {
                let q: f64 = (0..3).map(|i| ((x[i] - c[i]) / s[i]).powi(2)).sum();
                *o = (-0.5 * q).exp();
            }
            Ok(())
        },
        [[-8.0, 8.0], [-9.0, 9.0], [-10.0, 10.0]],
        &CubatureOptions {
            rtol: 1e-8,
            ..Default::default()
        },
    )
    .unwrap();
    let m = (2.0 * PI).powf(1.5) * s[0] * s[1] * s[2];
    let v = s.map(|x| x * x);
    let expect = diag(m * (v[1] + v[2]), m * (v[2] + v[0]), m * (v[0] + v[1]));
    assert!(r.converged);
    assert!((r.body.mass() - m).abs() <= r.mass_error.max(1e-14 * m));
    assert!((r.body.mass() - m).abs() <= 1e-8 * m);
    assert!((r.body.center_of_mass() - Vec3::from(c)).amax() <= 1e-8);
    assert!(close(&r.body.inertia(), &expect, 1e-8));
    assert_eq!(r.body.kind(1e-6).unwrap(), TopKind::AsymmetricTop);
}

#[test]
fn density_budget_exhausted_returns_flagged_estimate() {
    let r = inertia::density_mass_properties(
        |p: &[[f64; 3]], v: &mut [f64]| {
            for (x, o) in p.iter().zip(v.iter_mut()) {
                *o = if x[0] * x[0] + x[1] * x[1] + x[2] * x[2] <= 1.0 {
                    1.0
                } else {
                    0.0
                };
            }
            Ok(())
        },
        [[-1.0, 1.0]; 3],
        &CubatureOptions {
            rtol: 1e-9,
            atol: 0.0,
            max_evals: 100_000,
        },
    )
    .unwrap();
    assert!(!r.converged && r.evaluations <= 100_000);
    assert!((r.body.mass() - 4.0 / 3.0 * PI).abs() <= r.mass_error);
}

// ---------------------------------------------------------------------------------------------
// L, T and the holding torque against particles.

#[test]
fn holding_torque_is_the_rate_of_change_of_l() {
    // Particles turning rigidly at constant ω about the fixed point P: L(t) = Σ m r × (ω × r)
    // with r(t) = R(t) r₀; dL/dt by central differences must equal ω × L (2.58–2.59).
    let masses = [1.0, 2.0, 0.5];
    let pos = [[1.0, 0.2, 0.9], [-0.4, 0.3, -0.5], [0.3, -1.2, 0.4]];
    let p = Vec3::new(0.1, -0.2, 0.3);
    let w = Vec3::new(0.3, -0.4, 1.7);
    let body = MassProperties::from_point_masses(&masses, &pos).unwrap();
    let l_at = |t: f64| -> Vec3 {
        // R(t): rotation by |ω| t about ω (quaternion cos(θ/2), sin(θ/2) ω̂).
        let (s, c) = (0.5 * w.norm() * t).sin_cos();
        let axis = w / w.norm();
        let rt = rot([c, s * axis[0], s * axis[1], s * axis[2]]);
        masses
            .iter()
            .zip(pos.iter())
            .map(|(m, r0)| {
                let r = rt * (Vec3::from(*r0) - p);
                r.cross(&w.cross(&r)) * *m
            })
            .sum()
    };
    let dt = 1e-4;
    let dl = (l_at(dt) - l_at(-dt)) / (2.0 * dt);
    let n = body.holding_torque(&w, Some(&p)).unwrap();
    // Central differences: error O(dt² |ω|³ |L|/|ω|) ≈ 1e-8 relative.
    assert!((dl - n).amax() <= 1e-6 * n.norm(), "{dl} vs {n}");
    assert!(n.norm() > 0.1, "the set-up must need a torque");
    // L and T about P against the direct sums (2.44, 2.53).
    let l0 = l_at(0.0);
    assert!((body.angular_momentum(&w, Some(&p)).unwrap() - l0).amax() <= EXACT * l0.norm());
    let t_direct: f64 = masses
        .iter()
        .zip(pos.iter())
        .map(|(m, r0)| 0.5 * m * w.cross(&(Vec3::from(*r0) - p)).norm_squared())
        .sum();
    assert!((body.kinetic_energy(&w, Some(&p)).unwrap() - t_direct).abs() <= EXACT * t_direct);
    // Negative control: along a principal axis no torque is needed.
    let axis = body
        .principal(DEFAULT_KIND_RTOL)
        .axes
        .column(1)
        .into_owned();
    assert!(body.holding_torque(&axis, None).unwrap().norm() <= 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Invariants (proptest).

fn point_cloud() -> impl Strategy<Value = (Vec<f64>, Vec<[f64; 3]>)> {
    (2usize..8).prop_flat_map(|n| {
        (
            proptest::collection::vec(0.1f64..5.0, n),
            proptest::collection::vec(proptest::array::uniform3(-3.0f64..3.0), n),
        )
    })
}

fn quaternion() -> impl Strategy<Value = [f64; 4]> {
    proptest::array::uniform4(-1.0f64..1.0)
        .prop_filter("non-zero", |q| q.iter().map(|x| x * x).sum::<f64>() > 0.01)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, rng_seed: proptest::test_runner::RngSeed::Fixed(20261121), ..ProptestConfig::default() })]

    #[test]
    fn rotated_body_has_the_same_principal_moments((m, p) in point_cloud(), q in quaternion()) {
        let body = MassProperties::from_point_masses(&m, &p).unwrap();
        let r = rot(q);
        let turned = body.rotated(&r).unwrap();
        let (a, b) = (body.principal(1e-9), turned.principal(1e-9));
        let scale = a.moments[2];
        for k in 0..3 {
            prop_assert!((a.moments[k] - b.moments[k]).abs() <= 1e-12 * scale);
        }
        // The rotated body equals the body built from the rotated particles.
        let moved: Vec<[f64; 3]> = p.iter().map(|x| (r * Vec3::from(*x)).into()).collect();
        let direct = MassProperties::from_point_masses(&m, &moved).unwrap();
        prop_assert!(close(&turned.inertia(), &direct.inertia(), 1e-12));
        prop_assert!((turned.center_of_mass() - direct.center_of_mass()).amax() <= 1e-12);
        // Principal axes: a proper rotation that diagonalises.
        let ax = b.axes;
        prop_assert!((ax.determinant() - 1.0).abs() <= 1e-12);
        let d = ax.transpose() * turned.inertia() * ax;
        prop_assert!(close(&d, &Mat3::from_diagonal(&Vec3::from(b.moments)), 1e-11));
    }

    #[test]
    fn parallel_axis_there_and_back((m, p) in point_cloud(), q in proptest::array::uniform3(-5.0f64..5.0)) {
        let body = MassProperties::from_point_masses(&m, &p).unwrap();
        let point = Vec3::from(q);
        let i_p = body.inertia_about(&point).unwrap();
        // Against the direct sum about the point (2.46–2.50 with r measured from it).
        let direct: Mat3 = m.iter().zip(&p).map(|(mi, r)| {
            let d = Vec3::from(*r) - point;
            (Mat3::identity() * d.norm_squared() - d * d.transpose()) * *mi
        }).sum();
        prop_assert!(close(&i_p, &direct, 1e-12));
        let back = MassProperties::from_inertia_about(body.mass(), body.center_of_mass(), i_p, point).unwrap();
        prop_assert!((back.inertia() - body.inertia()).amax() <= 1e-11 * i_p.amax());
    }

    #[test]
    fn stored_tensors_pass_the_strict_check_again((m, p) in point_cloud(), q in quaternion(), line in proptest::bool::ANY) {
        // What poinsot stores can always be fed back (pickling, from_inertia round trips),
        // also for collinear masses (a rotor, on the triangle boundary).
        let p: Vec<[f64; 3]> = if line { p.iter().map(|x| [x[0], 0.5 * x[0], -2.0 * x[0]]).collect() } else { p };
        let body = MassProperties::from_point_masses(&m, &p).unwrap();
        let parts: Vec<MassProperties> = m.iter().zip(&p)
            .map(|(mi, r)| MassProperties::from_point_masses(&[*mi], &[*r]).unwrap())
            .collect();
        for b in [body, body.rotated(&rot(q)).unwrap(), MassProperties::combine(&parts).unwrap()] {
            prop_assert!(MassProperties::new(b.mass(), b.center_of_mass(), b.inertia()).is_ok(), "{}", b.inertia());
        }
    }

    #[test]
    fn composition_is_associative_and_matches_particles((m, p) in point_cloud()) {
        let all = MassProperties::from_point_masses(&m, &p).unwrap();
        let parts: Vec<MassProperties> = m.iter().zip(&p)
            .map(|(mi, r)| MassProperties::from_point_masses(&[*mi], &[*r]).unwrap())
            .collect();
        let combined = MassProperties::combine(&parts).unwrap();
        prop_assert!(close(&combined.inertia(), &all.inertia(), 1e-11));
        prop_assert!((combined.mass() - all.mass()).abs() <= 1e-12 * all.mass());
    }

    #[test]
    fn l_and_t_match_direct_sums((m, p) in point_cloud(), w in proptest::array::uniform3(-3.0f64..3.0)) {
        let body = MassProperties::from_point_masses(&m, &p).unwrap();
        let w = Vec3::from(w);
        let com = body.center_of_mass();
        let l: Vec3 = m.iter().zip(&p).map(|(mi, r)| {
            let r = Vec3::from(*r) - com;
            r.cross(&w.cross(&r)) * *mi
        }).sum();
        let l_body = body.angular_momentum(&w, None).unwrap();
        prop_assert!((l_body - l).amax() <= 1e-12 * (1.0 + l.norm()));
        let t = body.kinetic_energy(&w, None).unwrap();
        prop_assert!((t - 0.5 * w.dot(&l)).abs() <= 1e-12 * (1.0 + t.abs()));
        prop_assert!(t >= 0.0);
    }
}

#[test]
fn inertia_tensor_refusals() {
    let e = MassProperties::new(1.0, Vec3::zeros(), diag(1.0, 1.0, 2.5)).unwrap_err();
    assert_eq!(e.kind, ErrorKind::InvalidInertia);
    assert!(
        e.message.contains("I1 + I2 >= I3") && e.message.contains("by 5.0"),
        "{e}"
    );
    let mut asym = diag(2.0, 2.0, 2.0);
    asym[(1, 2)] = 0.5;
    let e = MassProperties::new(1.0, Vec3::zeros(), asym).unwrap_err();
    assert!(e.message.contains("symmetric"), "{e}");
    // A rotated thin plate and a rotated rod sit exactly on the boundary and pass.
    for d in [diag(1.0, 2.0, 3.0), diag(0.0, 1.0, 1.0)] {
        for q in [
            [0.3, 0.1, -0.7, 0.2],
            [1.0, 2.0, 3.0, 4.0],
            [-0.1, 0.9, 0.0, 0.4],
        ] {
            let r = rot(q);
            assert!(MassProperties::new(1.0, Vec3::zeros(), r * d * r.transpose()).is_ok());
        }
    }
}

// ---- cuboid_sides: the inverse of cuboid -----------------------------------------------------

proptest! {
    /// The sides come back from the box's moments to a few ulps, at any scale of the double
    /// range (the moments of a 1e-150 m box are 1e-300 kg·m²; of a 1e150 m box 1e300).
    #[test]
    fn cuboid_sides_inverts_cuboid(
        a in 0.05f64..20.0, b in 0.05f64..20.0, c in 0.05f64..20.0,
        mass in 0.01f64..100.0, scale in -140i32..140,
    ) {
        let s = 10f64.powi(scale);
        let body = inertia::cuboid(mass, [a * s, b * s, c * s]).unwrap();
        let i = body.inertia();
        let sides = inertia::cuboid_sides(mass, [i[(0, 0)], i[(1, 1)], i[(2, 2)]]).unwrap();
        // The box's own moments carry a few ulps; their differences (b² + c² − a² form) lose
        // up to a factor (largest side / smallest side)² ≤ 400², hence the tolerance.
        for (got, want) in sides.iter().zip([a * s, b * s, c * s]) {
            prop_assert!(((got - want) / want).abs() < 1e-10, "{got} vs {want}");
        }
    }
}

#[test]
fn cuboid_sides_refuses_what_is_not_a_box() {
    // A thin rod along z (I_x = I_y, I_z = 0) is the limit of a box with two zero sides.
    let rod = inertia::thin_rod(1.0, 2.0).unwrap().inertia();
    let err = inertia::cuboid_sides(1.0, [rod[(0, 0)], rod[(1, 1)], rod[(2, 2)]]).unwrap_err();
    assert_eq!(err.kind, ErrorKind::InvalidArgument);
    assert_eq!(err.argument, "moments");
    // 1 + 1 < 3: no box has these moments (negative control beside the round trip above).
    let err = inertia::cuboid_sides(1.0, [1.0, 1.0, 3.0]).unwrap_err();
    assert!(
        err.message.contains("not the moments of a box"),
        "{}",
        err.message
    );
    assert_eq!(
        inertia::cuboid_sides(0.0, [1.0, 1.0, 1.0])
            .unwrap_err()
            .argument,
        "mass"
    );
    assert_eq!(
        inertia::cuboid_sides(1.0, [f64::NAN, 1.0, 1.0])
            .unwrap_err()
            .argument,
        "moments"
    );
    assert_eq!(
        inertia::cuboid_sides(1.0, [-1.0, 1.0, 1.0])
            .unwrap_err()
            .argument,
        "moments"
    );
    // A cube of side 1 m and 12 kg has moments 2 kg·m² about each axis (closed form).
    let s = inertia::cuboid_sides(12.0, [2.0, 2.0, 2.0]).unwrap();
    assert!(s.iter().all(|x| (x - 1.0).abs() < 1e-15), "{s:?}");
    // Sides beyond the double range are refused, not returned as inf.
    let err = inertia::cuboid_sides(1e-308, [1e308, 1e308, 1e308]).unwrap_err();
    assert_eq!(err.argument, "moments");
}
