//! Bindings of `poinsot::inertia` (conversion and error mapping only).
//!
//! `MassProperties` wraps `poinsot::inertia::MassProperties`; the public, documented class is
//! `poinsot.RigidBody` (python/poinsot/body.py), which holds one of these.
use numpy::{PyArray1, PyArray3, PyReadonlyArray1, PyReadonlyArray2, PyUntypedArrayMethods};
use poinsot::inertia::{self, CubatureOptions, MassProperties};
use poinsot::{Error, Vec3};
use poinsot_py_macros::export;
use pyo3::prelude::*;

use crate::convert::{
    from_mat, matrix, mats3_out, opt_vector, rows3_slice, rows_view, vec3, vector, Matrix, Rows,
    Values, Vector,
};
use crate::errors::{invalid, IntoPy};

/// Mass properties of a rigid body (private; use `poinsot.RigidBody`).
#[pyclass(module = "poinsot._core", name = "MassProperties", frozen)]
pub struct PyMassProperties {
    inner: MassProperties,
}

fn wrap(r: poinsot::Result<MassProperties>) -> PyResult<PyMassProperties> {
    Ok(PyMassProperties { inner: r.py()? })
}

/// `#[export] impl PyMassProperties { … }`: the methods written out after the lists, the
/// standard solids of scalar dimensions (`solids { name(dimension, …); … }`: the static method
/// `name(mass, dimension, …)` calling the core's `inertia::name`), and one method per quantity
/// of the core's `MassProperties` at each ω of (N, 3) angular velocities, named after it
/// (`per_omega { name -> output; … }`, through `per_omega`, with the optional reference point
/// `about`). pyo3 takes one `#[pymethods]` block per class, so the generated
/// methods go into that block.
macro_rules! mass_properties_export {
    (
        solids { $($(#[$sdoc:meta])* $solid:ident($($dim:ident),+);)* }
        per_omega { $($(#[$doc:meta])* $name:ident -> $out:ty;)* }
        $($methods:tt)*
    ) => {
        #[export]
        impl PyMassProperties {
            $($(#[$sdoc])*
            #[staticmethod]
            fn $solid(mass: f64, $($dim: f64),+) -> PyResult<Self> {
                wrap(inertia::$solid(mass, $($dim),+))
            })*
            $($(#[$doc])*
            #[pyo3(signature = (omega, about=None))]
            fn $name(
                &self,
                py: Python<'_>,
                omega: Omegas<'_>,
                about: About<'_>,
            ) -> PyResult<$out> {
                self.per_omega(py, &omega, &about, MassProperties::$name)
            })*
            $($methods)*
        }
    };
}

mass_properties_export! {
    solids {
        /// Solid sphere.
        solid_sphere(radius);
        /// Thin spherical shell.
        spherical_shell(radius);
        /// Solid cylinder along z.
        solid_cylinder(radius, height);
        /// Solid cone, apex at the origin, axis +z.
        solid_cone(radius, height);
        /// Thin rod along z.
        thin_rod(length);
        /// Thin disk in the xy plane.
        thin_disk(radius);
        /// Thin ring in the xy plane.
        thin_ring(radius);
    }
    per_omega {
        /// L = I·ω (kg·m²/s) for each ω of `omega` (rad/s, (N, 3)), about `about` (m) or the
        /// centre of mass → (N, 3).
        angular_momentum -> Rows<3>;
        /// T = ½ ω·I·ω (J) for each ω of `omega` (rad/s, (N, 3)) → (N,).
        kinetic_energy -> Values;
        /// N = ω × L (N·m) for each ω of `omega` (rad/s, (N, 3)) → (N, 3).
        holding_torque -> Rows<3>;
        /// Angle between L and ω (rad) for each ω of `omega` (rad/s, (N, 3)) → (N,).
        momentum_angle -> Values;
    }

    /// Mass (kg), centre of mass (m, (3,)) and inertia about it (kg·m², (3, 3)), checked.
    #[staticmethod]
    fn from_inertia(
        mass: f64,
        center_of_mass: PyReadonlyArray1<'_, f64>,
        inertia: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Self> {
        let com = vector("center_of_mass", &center_of_mass)?;
        wrap(MassProperties::new(mass, com, matrix("inertia", &inertia)?))
    }

    /// Like `from_inertia`, with `inertia` about the point `about` (m, (3,)).
    #[staticmethod]
    fn from_inertia_about(
        mass: f64,
        center_of_mass: PyReadonlyArray1<'_, f64>,
        inertia: PyReadonlyArray2<'_, f64>,
        about: PyReadonlyArray1<'_, f64>,
    ) -> PyResult<Self> {
        let com = vector("center_of_mass", &center_of_mass)?;
        let i = matrix("inertia", &inertia)?;
        wrap(MassProperties::from_inertia_about(
            mass,
            com,
            i,
            vector("about", &about)?,
        ))
    }

    /// Point masses (kg, (N,)) at positions (m, (N, 3)).
    #[staticmethod]
    fn from_point_masses(
        py: Python<'_>,
        masses: PyReadonlyArray1<'_, f64>,
        positions: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Self> {
        let m = masses
            .as_slice()
            .map_err(|_| invalid("masses", "must be a contiguous array"))?;
        let p = rows_view::<3>("positions", &positions)?;
        let inner = crate::control::run(py, None, || MassProperties::from_point_masses(m, &p))?;
        Ok(Self { inner })
    }

    /// Cuboid with sides (3,) along x, y, z.
    #[staticmethod]
    fn cuboid(mass: f64, sides: PyReadonlyArray1<'_, f64>) -> PyResult<Self> {
        wrap(inertia::cuboid(mass, vec3("sides", &sides)?))
    }

    /// The sides (3,) of the uniform cuboid of `mass` with principal `moments` (3,) about
    /// x, y, z: the inverse of `cuboid` (`inertia::cuboid_sides`).
    #[staticmethod]
    fn cuboid_sides(mass: f64, moments: PyReadonlyArray1<'_, f64>) -> PyResult<Vector> {
        let m = vec3("moments", &moments)?;
        Ok(Vector::from(inertia::cuboid_sides(mass, m).py()?))
    }

    /// Solid ellipsoid with semi-axes (3,) along x, y, z.
    #[staticmethod]
    fn ellipsoid(mass: f64, semi_axes: PyReadonlyArray1<'_, f64>) -> PyResult<Self> {
        wrap(inertia::ellipsoid(mass, vec3("semi_axes", &semi_axes)?))
    }

    /// Closed triangle mesh: vertices (m, (N, 3) float64), faces ((M, 3) int64), density
    /// (kg/m³); `merge`: first merge vertices within the core's tolerance
    /// (`mesh_mass_properties_merging`). Runs without the GIL; Ctrl-C stops it.
    #[staticmethod]
    #[pyo3(signature = (vertices, faces, density, merge = false))]
    fn from_mesh(
        py: Python<'_>,
        vertices: PyReadonlyArray2<'_, f64>,
        faces: PyReadonlyArray2<'_, i64>,
        density: f64,
        merge: bool,
    ) -> PyResult<Self> {
        let v = rows3_slice("vertices", &vertices)?;
        let f = rows3_slice("faces", &faces)?;
        let inner = crate::control::run(py, None, || {
            if merge {
                inertia::mesh_mass_properties_merging(v, f, density)
            } else {
                inertia::mesh_mass_properties(v, f, density)
            }
        })?;
        Ok(Self { inner })
    }

    /// Density (a callable (N, 3) float64 → (N,) float64, kg/m³) over bounds ((3, 2), m), to
    /// the cubature's `options` `(rtol, atol, max_evals)` (the core's `CubatureOptions`).
    /// Returns (body, mass_error, center_of_mass_error, inertia_error, evaluations, converged).
    #[staticmethod]
    fn from_density(
        py: Python<'_>,
        density: Bound<'_, PyAny>,
        bounds: PyReadonlyArray2<'_, f64>,
        options: (f64, f64, usize),
    ) -> PyResult<(Self, f64, f64, f64, usize, bool)> {
        let shape = bounds.shape().to_vec();
        if shape != [3, 2] {
            return Err(invalid(
                "bounds",
                format!("must have shape (3, 2), got {shape:?}"),
            ));
        }
        let b = bounds.as_array();
        let bounds = [
            [b[[0, 0]], b[[0, 1]]],
            [b[[1, 0]], b[[1, 1]]],
            [b[[2, 0]], b[[2, 1]]],
        ];
        let (rtol, atol, max_evals) = options;
        let options = CubatureOptions {
            rtol,
            atol,
            max_evals,
        };
        let mut failure: Option<PyErr> = None;
        let result = inertia::density_mass_properties(
            |points: &[[f64; 3]], out: &mut [f64]| {
                let mut call = || -> PyResult<()> {
                    use numpy::PyArrayMethods;
                    let arr = PyArray1::from_slice(py, points.as_flattened())
                        .reshape([points.len(), 3])?;
                    let values = density.call1((arr,))?;
                    let values: PyReadonlyArray1<'_, f64> = values.extract().map_err(|_| {
                        invalid("density", "must return a float64 array of shape (N,)")
                    })?;
                    let s = values
                        .as_slice()
                        .map_err(|_| invalid("density", "must return a contiguous array"))?;
                    if s.len() != out.len() {
                        return Err(invalid(
                            "density",
                            format!("must return shape ({},), got ({},)", out.len(), s.len()),
                        ));
                    }
                    out.copy_from_slice(s);
                    Ok(())
                };
                call().map_err(|e| {
                    failure = Some(e);
                    Error::invalid("density", "the density function raised an exception")
                })
            },
            bounds,
            &options,
        );
        if let Some(e) = failure {
            return Err(e);
        }
        let r = result.py()?;
        Ok((
            Self { inner: r.body },
            r.mass_error,
            r.center_of_mass_error,
            r.inertia_error,
            r.evaluations,
            r.converged,
        ))
    }

    /// The body made of all of `bodies` (a sequence of MassProperties).
    #[staticmethod]
    fn combine(bodies: Vec<PyRef<'_, PyMassProperties>>) -> PyResult<Self> {
        let v: Vec<MassProperties> = bodies.iter().map(|b| b.inner).collect();
        wrap(MassProperties::combine(&v))
    }

    /// Mass (kg).
    #[getter]
    fn mass(&self) -> f64 {
        self.inner.mass()
    }

    /// Centre of mass (m), shape (3,).
    #[getter]
    fn center_of_mass(&self) -> Vector {
        Vector(self.inner.center_of_mass())
    }

    /// Inertia about the centre of mass (kg·m²), shape (3, 3).
    #[getter]
    fn inertia(&self) -> Matrix {
        Matrix(self.inner.inertia())
    }

    /// Inertia about each point of `points` (m, (N, 3)) → (N, 3, 3) kg·m².
    fn inertia_about<'py>(
        &self,
        py: Python<'py>,
        points: PyReadonlyArray2<'_, f64>,
    ) -> PyResult<Bound<'py, PyArray3<f64>>> {
        let mats = crate::control::map_each(py, &rows_view::<3>("point", &points)?, |p| {
            Ok(from_mat(&self.inner.inertia_about(&Vec3::from(*p))?))
        })?;
        mats3_out(py, mats.into_flattened().into_flattened())
    }

    /// The body moved by `offset` (m, (3,)).
    fn translated(&self, offset: PyReadonlyArray1<'_, f64>) -> PyResult<Self> {
        wrap(self.inner.translated(&vector("offset", &offset)?))
    }

    /// The body rotated by the rotation matrix `rotation` ((3, 3)) about the origin.
    fn rotated(&self, rotation: PyReadonlyArray2<'_, f64>) -> PyResult<Self> {
        wrap(self.inner.rotated(&matrix("rotation", &rotation)?))
    }

    /// (principal moments ascending (3,), principal axes as columns (3, 3)).
    fn principal(&self, rtol: f64) -> (Vector, Matrix) {
        let p = self.inner.principal(rtol);
        (Vector::from(p.moments), Matrix(p.axes))
    }

    /// Kind of top with relative tolerance `rtol`.
    fn kind(&self, rtol: f64) -> PyResult<&'static str> {
        Ok(self.inner.kind(rtol).py()?.as_str())
    }

    /// (I₁, I₃, m g l) (kg·m², kg·m², N·m) of the heavy top made of this symmetric body pivoted
    /// on its axis 3 at `pivot_distance` (m) below its centre of mass, under gravity `g` (m/s²).
    fn heavy_top_parameters(&self, pivot_distance: f64, g: f64) -> PyResult<(f64, f64, f64)> {
        let [i1, i3, mgl] =
            poinsot::analytic::heavy_top_parameters(&self.inner, pivot_distance, g).py()?;
        Ok((i1, i3, mgl))
    }
}

/// The angular velocities of a per-ω method: rad/s, (N, 3).
type Omegas<'py> = PyReadonlyArray2<'py, f64>;
/// The optional reference point of a per-ω method: m, (3,); the centre of mass if None.
type About<'py> = Option<PyReadonlyArray1<'py, f64>>;

impl PyMassProperties {
    /// `f(body, ω, about)` for each row ω of `omega`, mapping core errors (the GIL released,
    /// Ctrl-C polled every chunk of rows: [`crate::control::map_each`]).
    fn per_omega<T: Send, O: FromIterator<T>>(
        &self,
        py: Python<'_>,
        omega: &Omegas<'_>,
        about: &About<'_>,
        f: impl Fn(&MassProperties, &Vec3, Option<&Vec3>) -> poinsot::Result<T> + Send + Sync,
    ) -> PyResult<O> {
        let about = opt_vector("about", about)?;
        let each = crate::control::map_each(py, &rows_view::<3>("omega", omega)?, |w| {
            f(&self.inner, &Vec3::from(*w), about.as_ref())
        })?;
        Ok(each.into_iter().collect())
    }
}

/// Kind of top of principal moments `moments` (kg·m², (3,)) with relative tolerance `rtol`.
#[export]
fn classify(moments: PyReadonlyArray1<'_, f64>, rtol: f64) -> PyResult<&'static str> {
    Ok(inertia::classify(vec3("moments", &moments)?, rtol)
        .py()?
        .as_str())
}

/// Checks an inertia tensor (kg·m², (3, 3)); returns it symmetrised.
#[export]
fn check_inertia(inertia: PyReadonlyArray2<'_, f64>) -> PyResult<Matrix> {
    inertia::check_inertia("inertia", &matrix("inertia", &inertia)?)
        .map(Matrix)
        .py()
}

/// Checks that reading a mesh file of `triangles` triangles fits in the memory budget; the
/// error names `path`.
#[export]
fn check_mesh_file(triangles: f64) -> PyResult<()> {
    inertia::check_mesh_file(triangles).py()
}

/// Registers this file's functions and classes on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyMassProperties>()?;
    m.add_function(wrap_pyfunction!(classify, m)?)?;
    m.add_function(wrap_pyfunction!(check_inertia, m)?)?;
    m.add_function(wrap_pyfunction!(check_mesh_file, m)?)?;
    Ok(())
}
