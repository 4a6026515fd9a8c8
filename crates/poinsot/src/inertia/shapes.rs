//! The standard solids, uniform density, in closed form.
//!
//! Conventions: the axis of symmetry is `z`; every shape is centred on its centre of mass
//! except the cone, whose **apex is at the origin** with its axis along `+z`, so that its centre
//! of mass is at `(0, 0, 3h/4)`. Masses in kg, lengths in m, inertia in kg·m² about the centre
//! of mass. Each function checks that `mass` and the dimensions are finite and `> 0` and names
//! the argument otherwise.

use crate::error::{check_positive, Result};
use crate::inertia::body::MassProperties;
use crate::{Mat3, Vec3};

fn diag(mass: f64, com: Vec3, d: [f64; 3]) -> MassProperties {
    MassProperties::from_parts(mass, com, Mat3::from_diagonal(&Vec3::from(d)))
}

/// A solid sphere of radius `radius`: `I = 2/5 m r²` about every axis.
pub fn solid_sphere(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    let i = 0.4 * mass * radius * radius;
    Ok(diag(mass, Vec3::zeros(), [i, i, i]))
}

/// A thin spherical shell of radius `radius`: `I = 2/3 m r²` about every axis.
pub fn spherical_shell(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    let i = 2.0 / 3.0 * mass * radius * radius;
    Ok(diag(mass, Vec3::zeros(), [i, i, i]))
}

/// A solid cylinder of radius `radius` and height `height` along `z`:
/// `I_zz = m r²/2`, `I_xx = I_yy = m (3 r² + h²)/12`.
pub fn solid_cylinder(mass: f64, radius: f64, height: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    check_positive("height", height)?;
    let ixx = mass * (3.0 * radius * radius + height * height) / 12.0;
    Ok(diag(
        mass,
        Vec3::zeros(),
        [ixx, ixx, 0.5 * mass * radius * radius],
    ))
}

/// A solid right circular cone of base radius `radius` and height `height`, **apex at the
/// origin**, axis along `+z` (base at `z = h`): centre of mass `(0, 0, 3h/4)`;
/// about it `I_zz = 3/10 m r²`, `I_xx = I_yy = 3/20 m r² + 3/80 m h²`.
pub fn solid_cone(mass: f64, radius: f64, height: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    check_positive("height", height)?;
    let r2 = radius * radius;
    let ixx = mass * (3.0 / 20.0 * r2 + 3.0 / 80.0 * height * height);
    Ok(diag(
        mass,
        Vec3::new(0.0, 0.0, 0.75 * height),
        [ixx, ixx, 0.3 * mass * r2],
    ))
}

/// A solid cuboid with sides `sides = [a, b, c]` along `x, y, z`:
/// `I_xx = m (b² + c²)/12` and cyclically. The argument is named `sides`.
pub fn cuboid(mass: f64, sides: [f64; 3]) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    for s in sides {
        check_positive("sides", s)?;
    }
    let [a, b, c] = sides.map(|s| s * s);
    Ok(diag(
        mass,
        Vec3::zeros(),
        [
            mass * (b + c) / 12.0,
            mass * (c + a) / 12.0,
            mass * (a + b) / 12.0,
        ],
    ))
}

/// A solid ellipsoid with semi-axes `semi_axes = [a, b, c]` along `x, y, z`:
/// `I_xx = m (b² + c²)/5` and cyclically. The argument is named `semi_axes`.
pub fn ellipsoid(mass: f64, semi_axes: [f64; 3]) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    for s in semi_axes {
        check_positive("semi_axes", s)?;
    }
    let [a, b, c] = semi_axes.map(|s| s * s);
    Ok(diag(
        mass,
        Vec3::zeros(),
        [
            mass * (b + c) / 5.0,
            mass * (c + a) / 5.0,
            mass * (a + b) / 5.0,
        ],
    ))
}

/// A thin rod of length `length` along `z`: `I_xx = I_yy = m L²/12`, `I_zz = 0` (a rotor).
pub fn thin_rod(mass: f64, length: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("length", length)?;
    let i = mass * length * length / 12.0;
    Ok(diag(mass, Vec3::zeros(), [i, i, 0.0]))
}

/// A thin uniform disk of radius `radius` in the `xy` plane: `I_xx = I_yy = m r²/4`,
/// `I_zz = m r²/2`.
pub fn thin_disk(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    let i = 0.25 * mass * radius * radius;
    Ok(diag(mass, Vec3::zeros(), [i, i, 2.0 * i]))
}

/// A thin ring (hoop) of radius `radius` in the `xy` plane: `I_xx = I_yy = m r²/2`,
/// `I_zz = m r²`.
pub fn thin_ring(mass: f64, radius: f64) -> Result<MassProperties> {
    check_positive("mass", mass)?;
    check_positive("radius", radius)?;
    let i = 0.5 * mass * radius * radius;
    Ok(diag(mass, Vec3::zeros(), [i, i, 2.0 * i]))
}
