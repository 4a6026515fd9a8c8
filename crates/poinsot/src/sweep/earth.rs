//! The rotating Earth's falling bodies and projectiles over a grid of heights, latitudes and
//! launches (the unit's 2.30, 2.32–2.42): where and when each lands, integrated as
//! [`Earth::drop`] and [`Earth::projectile`] integrate one.

use super::grid::{Grid, Param};
use crate::earth::{Earth, FallModel};
use crate::error::Result;

/// The keywords of [`drop`]: those of [`Earth::drop`], `height` (m) and `latitude` (rad).
pub const DROP_KEYWORDS: [&str; 2] = ["height", "latitude"];

/// The keywords of [`projectile`]: those of [`Earth::projectile`], `speed` (m/s),
/// `elevation`, `azimuth`, `latitude` (rad) and `height` (m).
pub const PROJECTILE_KEYWORDS: [&str; 5] = ["speed", "elevation", "azimuth", "latitude", "height"];

/// What a sweep of [`Earth::drop`] gives at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DropPoint {
    /// Time of fall (s).
    pub time: f64,
    /// Landing point east of the foot of the plumb line (m).
    pub east: f64,
    /// Landing point north of it (m; negative: south).
    pub north: f64,
    /// The unit's first-order eastward deflection 2.42 (m, [`Earth::eastward_deflection`]).
    pub first_order_east: f64,
    /// The second-order equatorward deflection (m, [`Earth::southward_deflection`]).
    pub second_order_south: f64,
}

/// What a sweep of [`Earth::projectile`] gives at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProjectilePoint {
    /// Time of flight (s).
    pub time: f64,
    /// Landing point east of the launch (m).
    pub east: f64,
    /// Landing point north of the launch (m).
    pub north: f64,
    /// Horizontal distance from launch to landing (m).
    pub range: f64,
    /// Landing displacement along the launch azimuth (m).
    pub downrange: f64,
    /// Landing displacement across it, positive to the right (m).
    pub drift: f64,
}

struct DropInputs<'a> {
    height: Param<'a>,
    latitude: Param<'a>,
}

impl<'a> DropInputs<'a> {
    fn of(grid: &Grid<'a>) -> Result<Self> {
        grid.check_keywords("drop", &DROP_KEYWORDS)?;
        Ok(Self {
            height: grid.required("height", 1)?,
            latitude: grid.required("latitude", 1)?,
        })
    }

    fn at(&self, p: usize) -> Result<(f64, f64)> {
        let (h, lat) = (self.height.scalar(p), self.latitude.scalar(p));
        Earth::check_drop(h, lat)?;
        Ok((h, lat))
    }
}

/// Checks every point of a sweep of [`Earth::drop`] as it checks its arguments, and the
/// integrator settings of `model`, without integrating; errors name the keyword and the first
/// point at fault.
pub fn check_drop(grid: &Grid<'_>, model: &FallModel) -> Result<()> {
    let inputs = DropInputs::of(grid)?;
    model.options.validate()?;
    grid.validate(|p| inputs.at(p).map(|_| ()))
}

/// [`Earth::drop`] on `earth` under `model` at every point of `grid`, in row-major order, in
/// parallel after [`check_drop`] and the memory budget passed (only the landing is kept: the
/// model's dense output is not needed). Stoppable through [`crate::control`]; a fall that
/// fails stops the sweep with its error, located.
pub fn drop(earth: &Earth, grid: &Grid<'_>, model: &FallModel) -> Result<Vec<DropPoint>> {
    let inputs = DropInputs::of(grid)?;
    model.options.validate()?;
    grid.check_memory(std::mem::size_of::<DropPoint>())?;
    grid.validate(|p| inputs.at(p).map(|_| ()))?;
    let mut model = *model;
    model.options.dense = false;
    grid.compute(|p| {
        let (h, lat) = inputs.at(p)?;
        let fall = earth.drop(h, lat, &model)?;
        Ok(DropPoint {
            time: fall.time,
            east: fall.east,
            north: fall.north,
            first_order_east: fall.first_order_east,
            second_order_south: fall.second_order_south,
        })
    })
}

struct ProjectileInputs<'a> {
    speed: Param<'a>,
    elevation: Param<'a>,
    azimuth: Param<'a>,
    latitude: Param<'a>,
    height: Param<'a>,
}

impl<'a> ProjectileInputs<'a> {
    fn of(grid: &Grid<'a>) -> Result<Self> {
        grid.check_keywords("projectile", &PROJECTILE_KEYWORDS)?;
        Ok(Self {
            speed: grid.required("speed", 1)?,
            elevation: grid.required("elevation", 1)?,
            azimuth: grid.required("azimuth", 1)?,
            latitude: grid.required("latitude", 1)?,
            height: grid.required("height", 1)?,
        })
    }

    fn at(&self, p: usize) -> Result<[f64; 5]> {
        let v = [
            self.speed.scalar(p),
            self.elevation.scalar(p),
            self.azimuth.scalar(p),
            self.latitude.scalar(p),
            self.height.scalar(p),
        ];
        Earth::check_projectile(v[0], v[1], v[2], v[3], v[4])?;
        Ok(v)
    }
}

/// Checks every point of a sweep of [`Earth::projectile`] as it checks its arguments, and the
/// integrator settings of `model`, without integrating; errors name the keyword and the first
/// point at fault.
pub fn check_projectile(grid: &Grid<'_>, model: &FallModel) -> Result<()> {
    let inputs = ProjectileInputs::of(grid)?;
    model.options.validate()?;
    grid.validate(|p| inputs.at(p).map(|_| ()))
}

/// [`Earth::projectile`] on `earth` under `model` at every point of `grid`, as [`drop`].
pub fn projectile(
    earth: &Earth,
    grid: &Grid<'_>,
    model: &FallModel,
) -> Result<Vec<ProjectilePoint>> {
    let inputs = ProjectileInputs::of(grid)?;
    model.options.validate()?;
    grid.check_memory(std::mem::size_of::<ProjectilePoint>())?;
    grid.validate(|p| inputs.at(p).map(|_| ()))?;
    let mut model = *model;
    model.options.dense = false;
    grid.compute(|p| {
        let [speed, elevation, azimuth, latitude, height] = inputs.at(p)?;
        let f = earth.projectile(speed, elevation, azimuth, latitude, height, &model)?;
        Ok(ProjectilePoint {
            time: f.time,
            east: f.east,
            north: f.north,
            range: f.range,
            downrange: f.downrange,
            drift: f.drift,
        })
    })
}
