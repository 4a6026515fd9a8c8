//! The standard solids, uniform density, in closed form.
//!
//! Conventions: the axis of symmetry is `z`; every shape is centred on its centre of mass
//! except the cone, whose **apex is at the origin** with its axis along `+z`, so that its centre
//! of mass is at `(0, 0, 3h/4)`. Masses in kg, lengths in m, inertia in kg·m² about the centre
//! of mass. Each function checks that `mass` and the dimensions are finite and `> 0` and names
//! the argument otherwise.
//!
//! **Range.** The moments are computed on mantissas (mass and lengths scaled by exact powers of
//! two) and the exponent is applied last, so a moment that is a normal double is exact (the
//! same bits as the formula at unit scale, times the power of two) even when `r²` alone would
//! overflow (`r = 1e200`) or underflow (`r = 1e-200`). A moment beyond `f64::MAX` (no finite
//! answer: `solid_sphere(1.0, 1e308)`) or a largest moment below the smallest normal double
//! (`2.2e-308`, where precision is lost) is an [`Error::invalid`](crate::Error::invalid)
//! naming the more extreme of `mass` and the dimension, with the magnitude it would have.

use crate::error::{check_positive, Error, Result};
use crate::inertia::body::MassProperties;
use crate::inertia::scaling::{check_margins, check_range, exponent, ldexp, split};
use crate::{Mat3, Vec3};

/// What to do when the moments leave the range of doubles.
const HINT: &str = "express the body in other units (e.g. g and mm, or t and km)";

/// The body with centre of mass `com` and principal moments `m · q(l / 2^e) · 2^(2e)` about the
/// axes, where `l` are the dimensions (named `length`), `2^e` their largest power of two and
/// `q` the formula of the solid on scaled dimensions (a homogeneous quadratic). Errors name
/// `mass` or `length`, whichever is further from 1 in order of magnitude.
fn solid(
    mass: f64,
    length: &str,
    dims: &[f64],
    com: Vec3,
    q: impl Fn(&[f64]) -> [f64; 3],
) -> Result<MassProperties> {
    let (m, em) = split(mass);
    let e = exponent(dims.iter().fold(0.0f64, |a, x| a.max(*x)));
    let scaled: Vec<f64> = dims.iter().map(|x| ldexp(*x, -e)).collect();
    let d = q(&scaled).map(|x| m * x);
    let k = em + 2 * e;
    let largest = d.iter().fold(0.0f64, |a, x| a.max(*x));
    let blame = if (2 * e).abs() >= em.abs() {
        length
    } else {
        "mass"
    };
    check_range(
        blame,
        "the largest moment of inertia (kg·m²)",
        largest,
        k,
        HINT,
    )?;
    check_margins(blame, d, k, HINT)?;
    Ok(MassProperties::from_parts(
        mass,
        com,
        Mat3::from_diagonal(&Vec3::from(d.map(|x| ldexp(x, k)))),
    ))
}

/// A solid sphere of radius `radius`: `I = 2/5 m r²` about every axis.
pub fn solid_sphere(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    solid(mass, "radius", &[radius], Vec3::zeros(), |l| {
        let i = 0.4 * l[0] * l[0];
        [i, i, i]
    })
}

/// A thin spherical shell of radius `radius`: `I = 2/3 m r²` about every axis.
pub fn spherical_shell(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    solid(mass, "radius", &[radius], Vec3::zeros(), |l| {
        let i = 2.0 / 3.0 * l[0] * l[0];
        [i, i, i]
    })
}

/// A solid cylinder of radius `radius` and height `height` along `z`:
/// `I_zz = m r²/2`, `I_xx = I_yy = m (3 r² + h²)/12`.
pub fn solid_cylinder(mass: f64, radius: f64, height: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    check_positive("height", height)?;
    let length = if height > radius { "height" } else { "radius" };
    solid(mass, length, &[radius, height], Vec3::zeros(), |l| {
        let (r, h) = (l[0], l[1]);
        let ixx = (3.0 * r * r + h * h) / 12.0;
        [ixx, ixx, 0.5 * r * r]
    })
}

/// A solid right circular cone of base radius `radius` and height `height`, **apex at the
/// origin**, axis along `+z` (base at `z = h`): centre of mass `(0, 0, 3h/4)`;
/// about it `I_zz = 3/10 m r²`, `I_xx = I_yy = 3/20 m r² + 3/80 m h²`.
pub fn solid_cone(mass: f64, radius: f64, height: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    check_positive("height", height)?;
    let length = if height > radius { "height" } else { "radius" };
    let com = Vec3::new(0.0, 0.0, 0.75 * height);
    solid(mass, length, &[radius, height], com, |l| {
        let (r2, h) = (l[0] * l[0], l[1]);
        let ixx = 3.0 / 20.0 * r2 + 3.0 / 80.0 * h * h;
        [ixx, ixx, 0.3 * r2]
    })
}

/// A solid cuboid with sides `sides = [a, b, c]` along `x, y, z`:
/// `I_xx = m (b² + c²)/12` and cyclically. The argument is named `sides`.
pub fn cuboid(mass: f64, sides: [f64; 3]) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    for s in sides {
        check_positive("sides", s)?;
    }
    solid(mass, "sides", &sides, Vec3::zeros(), |l| {
        let [a, b, c] = [l[0] * l[0], l[1] * l[1], l[2] * l[2]];
        [(b + c) / 12.0, (c + a) / 12.0, (a + b) / 12.0]
    })
}

/// The sides `[a, b, c]` (m) of the uniform solid cuboid of mass `mass` (kg) whose principal
/// moments about `x, y, z` are `moments` (kg·m²): the inverse of [`cuboid`], from
/// `I_xx = m (b² + c²)/12` and cyclically, `a² = 6 (I_yy + I_zz − I_xx)/m` and cyclically.
///
/// Computed on mantissas (the moments and the mass scaled by exact powers of two), so any
/// moments of the double range give sides good to the last bits. Errors: `mass` not finite and
/// `> 0`; `moments` not finite and `≥ 0`, or not those of a box — every side needs
/// `I_yy + I_zz > I_xx` (and cyclically), strictly: a box has no side of length zero — or sides
/// beyond the double range (named `moments`).
///
/// ```
/// use poinsot::inertia::{cuboid, cuboid_sides};
/// let box_ = cuboid(2.0, [1.0, 2.0, 3.0]).unwrap();
/// let i = box_.inertia();
/// let sides = cuboid_sides(2.0, [i[(0, 0)], i[(1, 1)], i[(2, 2)]]).unwrap();
/// assert!((sides[0] - 1.0).abs() < 1e-15 && (sides[2] - 3.0).abs() < 1e-15);
/// ```
pub fn cuboid_sides(mass: f64, moments: [f64; 3]) -> Result<[f64; 3]> {
    check_positive("mass", mass)?;
    for m in moments {
        if !(m.is_finite() && m >= 0.0) {
            return Err(Error::invalid(
                "moments",
                format!("must be finite and >= 0, got {moments:?}"),
            ));
        }
    }
    let (mm, em) = split(mass);
    let k = exponent(moments.iter().fold(0.0f64, |a, x| a.max(*x)));
    let i = moments.map(|x| ldexp(x, -k));
    let mut sides = [0.0; 3];
    for n in 0..3 {
        let d = i[(n + 1) % 3] + i[(n + 2) % 3] - i[n];
        // d is finite: the moments were checked finite above.
        if d <= 0.0 {
            return Err(Error::invalid(
                "moments",
                format!(
                    "{moments:?} kg·m² are not the moments of a box: side {} would need \
                     I{} + I{} > I{}",
                    ["a", "b", "c"][n],
                    (n + 1) % 3 + 1,
                    (n + 2) % 3 + 1,
                    n + 1
                ),
            ));
        }
        // s² = 6 d / mm · 2^(k − em); an even exponent keeps the square root exact in scale.
        let mut e = k - em;
        let mut q = 6.0 * d / mm;
        if e % 2 != 0 {
            q *= 2.0;
            e -= 1;
        }
        sides[n] = ldexp(q.sqrt(), e / 2);
        if !(sides[n].is_finite() && sides[n] > 0.0 && sides[n] >= f64::MIN_POSITIVE) {
            return Err(Error::invalid(
                "moments",
                format!(
                    "the box's side {} (2^{} m) lies outside the range of doubles; {HINT}",
                    ["a", "b", "c"][n],
                    e / 2
                ),
            ));
        }
    }
    Ok(sides)
}

/// A solid ellipsoid with semi-axes `semi_axes = [a, b, c]` along `x, y, z`:
/// `I_xx = m (b² + c²)/5` and cyclically. The argument is named `semi_axes`.
pub fn ellipsoid(mass: f64, semi_axes: [f64; 3]) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    for s in semi_axes {
        check_positive("semi_axes", s)?;
    }
    solid(mass, "semi_axes", &semi_axes, Vec3::zeros(), |l| {
        let [a, b, c] = [l[0] * l[0], l[1] * l[1], l[2] * l[2]];
        [(b + c) / 5.0, (c + a) / 5.0, (a + b) / 5.0]
    })
}

/// A thin rod of length `length` along `z`: `I_xx = I_yy = m L²/12`, `I_zz = 0` (a rotor).
pub fn thin_rod(mass: f64, length: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("length", length)?;
    solid(mass, "length", &[length], Vec3::zeros(), |l| {
        let i = l[0] * l[0] / 12.0;
        [i, i, 0.0]
    })
}

/// A thin uniform disk of radius `radius` in the `xy` plane: `I_xx = I_yy = m r²/4`,
/// `I_zz = m r²/2`.
pub fn thin_disk(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    solid(mass, "radius", &[radius], Vec3::zeros(), |l| {
        let i = 0.25 * l[0] * l[0];
        [i, i, 2.0 * i]
    })
}

/// A thin ring (hoop) of radius `radius` in the `xy` plane: `I_xx = I_yy = m r²/2`,
/// `I_zz = m r²`.
pub fn thin_ring(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    solid(mass, "radius", &[radius], Vec3::zeros(), |l| {
        let i = 0.5 * l[0] * l[0];
        [i, i, 2.0 * i]
    })
}
