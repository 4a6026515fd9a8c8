//! What an integrator needs of a state and of a system.

use nalgebra::SVector;

/// A state vector of an ODE: anything that can be viewed as a slice of `f64`.
///
/// Implemented for `[f64; N]`, `Vec<f64>` and nalgebra's `SVector<f64, N>`. The integrators
/// clone the initial state to make their work arrays, so a state's length never changes.
pub trait OdeState: Clone {
    /// The components, read-only.
    fn as_slice(&self) -> &[f64];
    /// The components, writable.
    fn as_mut_slice(&mut self) -> &mut [f64];
}

impl<const N: usize> OdeState for [f64; N] {
    #[inline]
    fn as_slice(&self) -> &[f64] {
        self
    }
    #[inline]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        self
    }
}

impl OdeState for Vec<f64> {
    #[inline]
    fn as_slice(&self) -> &[f64] {
        self
    }
    #[inline]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        self
    }
}

impl<const N: usize> OdeState for SVector<f64, N> {
    #[inline]
    fn as_slice(&self) -> &[f64] {
        nalgebra::Matrix::as_slice(self)
    }
    #[inline]
    fn as_mut_slice(&mut self) -> &mut [f64] {
        nalgebra::Matrix::as_mut_slice(self)
    }
}

/// A first-order system `dy/dt = f(t, y)`.
///
/// Implemented for every closure `FnMut(f64, &S, &mut S)` that writes `f(t, y)` into its
/// third argument (every component must be written).
pub trait OdeSystem<S> {
    /// Writes `f(t, y)` into `dy`.
    fn rhs(&mut self, t: f64, y: &S, dy: &mut S);
}

impl<S, F: FnMut(f64, &S, &mut S)> OdeSystem<S> for F {
    #[inline]
    fn rhs(&mut self, t: f64, y: &S, dy: &mut S) {
        self(t, y, dy)
    }
}
