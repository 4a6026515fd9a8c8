//! Bindings of `poinsot::earth::fit_wobble` (conversion and error mapping only): the fit of the
//! real pole's motion to a trend, the Chandler wobble and the annual wobble. The public,
//! documented function is `poinsot.fit_wobble` (python/poinsot/polar.py), which builds its
//! result from the dict returned here.
use numpy::PyReadonlyArray1;
use poinsot::earth::{self as ea, ChandlerPeriod, WobbleTerm};
use poinsot_py_macros::export;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::control::run;
use crate::convert::{fields_dict, vec_in};

/// One circle as a dict of the core's fields (SI: s, rad).
fn term<'py>(py: Python<'py>, w: &WobbleTerm) -> PyResult<Bound<'py, PyDict>> {
    Ok(fields_dict!(py, w; period, period_sigma, amplitude, amplitude_sigma, phase,
        phase_sigma, prograde))
}

/// The core's `fit_wobble` of the pole (x, y) (rad) at times `t` (s), the GIL released and
/// stoppable by Ctrl-C. `chandler_period`: a fixed period (s), or `None` to search the band
/// `chandler_band` (s, s) (the core's default band when `None`). The result as a dict of the
/// core's `WobbleFit` fields.
#[export]
#[pyo3(signature = (t, x, y, chandler_period=None, chandler_band=None, annual_period=ea::ANNUAL_PERIOD))]
fn fit_wobble<'py>(
    py: Python<'py>,
    t: PyReadonlyArray1<'py, f64>,
    x: PyReadonlyArray1<'py, f64>,
    y: PyReadonlyArray1<'py, f64>,
    chandler_period: Option<f64>,
    chandler_band: Option<(f64, f64)>,
    annual_period: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let (t, x, y) = (vec_in(&t), vec_in(&x), vec_in(&y));
    let chandler = match (chandler_period, chandler_band) {
        (Some(p), _) => ChandlerPeriod::Fixed(p),
        (None, Some((lo, hi))) => ChandlerPeriod::Search(lo, hi),
        (None, None) => ChandlerPeriod::default(),
    };
    let f = run(py, None, || {
        ea::fit_wobble(&t, &x, &y, chandler, annual_period)
    })?;
    Ok(fields_dict!(py, f; residual_rms, serial_correlation, sigma_inflation,
        chandler_false_alarm, samples;
        chandler = term(py, &f.chandler)?,
        annual_prograde = term(py, &f.annual_prograde)?,
        annual_retrograde = term(py, &f.annual_retrograde)?,
        offset = (f.offset[0], f.offset[1]),
        offset_sigma = (f.offset_sigma[0], f.offset_sigma[1]),
        drift = (f.drift[0], f.drift[1]),
        drift_sigma = (f.drift_sigma[0], f.drift_sigma[1]),
        chandler_significant = f.chandler_significant(),
    ))
}

/// Registers `fit_wobble` and the wobble's constants on the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    add_functions!(m; fit_wobble);
    m.add("ANNUAL_PERIOD", ea::ANNUAL_PERIOD)?;
    m.add("CHANDLER_SEARCH", ea::CHANDLER_SEARCH)?;
    Ok(())
}
