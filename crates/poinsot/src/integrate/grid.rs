//! Sample grids: evenly spaced output times, and finding the sample at or before a time.
//!
//! [`sample_times`] is the one way the core and its front ends make evenly spaced output times
//! (`samples` of them, both ends included): it checks the count first, then calls
//! [`even_times`]. [`sample_before`] is the first step of seeking a time in a sampled run.

use crate::error::{check_finite, Error, Result};
use crate::limits::check_count;

/// `n` evenly spaced times from `t0` to `t_end`, both ends included exactly:
/// `t_i = t0 + (t_end − t0)·i/(n − 1)`, the last exactly `t_end` (`[t_end]` when `n < 2`).
///
/// Callers check `n` against the memory budget first ([`crate::limits::check_count`]).
///
/// ```
/// let t = poinsot::integrate::even_times(0.0, 1.0, 5);
/// assert_eq!(t, vec![0.0, 0.25, 0.5, 0.75, 1.0]);
/// ```
pub fn even_times(t0: f64, t_end: f64, n: usize) -> Vec<f64> {
    if n < 2 {
        return vec![t_end];
    }
    let last = (n - 1) as f64;
    let span = t_end - t0;
    // Near the top of the double range (t_end − t0)·i would overflow: interpolate instead.
    let overflows = !(span * last).is_finite();
    (0..n)
        .map(|i| {
            if i + 1 == n {
                t_end
            } else if overflows {
                let f = i as f64 / last;
                t0 * (1.0 - f) + t_end * f
            } else {
                t0 + span * i as f64 / last
            }
        })
        .collect()
}

/// `samples` evenly spaced times from `t0` to `t_end` (s), both ends included exactly
/// ([`even_times`]: `t_i = t0 + (t_end − t0)·i/(samples − 1)`), after checking the count:
/// `samples ≥ 2`, and `samples` outputs of `bytes_each` bytes each (the time and what the
/// caller stores per sample) within the memory budget ([`crate::limits::check_count`]). The
/// errors name `samples` (a count out of range is refused, never clamped), or `t0` / `t_end`
/// when not finite.
///
/// ```
/// let t = poinsot::integrate::sample_times(0.0, 2.0, 5, 8).unwrap();
/// assert_eq!(t, vec![0.0, 0.5, 1.0, 1.5, 2.0]);
/// assert!(poinsot::integrate::sample_times(0.0, 2.0, 1, 8).unwrap_err().to_string().starts_with("samples: must be >= 2"));
/// assert!(poinsot::integrate::sample_times(0.0, f64::NAN, 5, 8).unwrap_err().to_string().starts_with("t_end"));
/// ```
pub fn sample_times(t0: f64, t_end: f64, samples: usize, bytes_each: usize) -> Result<Vec<f64>> {
    check_finite("t0", &[t0])?;
    check_finite("t_end", &[t_end])?;
    check_count("samples", samples, 2, bytes_each)?;
    Ok(even_times(t0, t_end, samples))
}

/// The index of the last of the increasing sample `times` at or before `t` (s): where a run
/// sampled at `times` is continued to reach `t`. The error names `t` when it is not finite or
/// lies outside `[times[0], times[last]]`, and `times` when there are none.
///
/// ```
/// let times = [0.0, 1.0, 2.0];
/// assert_eq!(poinsot::integrate::sample_before(&times, 1.5).unwrap(), 1);
/// assert_eq!(poinsot::integrate::sample_before(&times, 2.0).unwrap(), 2);
/// assert!(poinsot::integrate::sample_before(&times, 2.5).is_err());
/// ```
pub fn sample_before(times: &[f64], t: f64) -> Result<usize> {
    check_finite("t", &[t])?;
    let (Some(&lo), Some(&hi)) = (times.first(), times.last()) else {
        return Err(Error::invalid("times", "must hold at least one sample"));
    };
    if !(t >= lo && t <= hi) {
        return Err(Error::invalid(
            "t",
            format!("must lie in [{lo}, {hi}], the run, got {t}"),
        ));
    }
    Ok(times.partition_point(|&ti| ti <= t).saturating_sub(1))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn sample_times_refuse_a_count_out_of_range_and_never_clamp() {
        for n in [0, 1] {
            let e = sample_times(0.0, 1.0, n, 8).unwrap_err();
            assert_eq!(e.argument, "samples");
            assert!(e.message.contains(">= 2"), "{e}");
        }
        let e = sample_times(0.0, 1.0, 1 << 40, 64).unwrap_err();
        assert_eq!(e.argument, "samples");
        assert!(e.message.contains("would need"), "{e}");
        // Negative control: the smallest count in range works.
        assert_eq!(sample_times(0.0, 1.0, 2, 64).unwrap(), vec![0.0, 1.0]);
    }

    #[test]
    fn sample_before_names_t_outside_the_run() {
        let times = [0.0, 0.5, 1.0];
        assert_eq!(sample_before(&times, 0.0).unwrap(), 0);
        assert_eq!(sample_before(&times, 0.75).unwrap(), 1);
        for t in [-1e-300, 1.0 + 1e-15, f64::NAN, f64::INFINITY] {
            assert_eq!(sample_before(&times, t).unwrap_err().argument, "t");
        }
        assert_eq!(sample_before(&[], 0.0).unwrap_err().argument, "times");
    }

    proptest! {
        /// Both ends exact, strictly increasing, and each time within round-off of the ideal.
        #[test]
        fn sample_times_are_even_and_exact_at_both_ends(t_end in 1e-6f64..1e9, n in 2usize..3000) {
            let t = sample_times(0.0, t_end, n, 8).unwrap();
            prop_assert_eq!(t.len(), n);
            prop_assert_eq!(t[0], 0.0);
            prop_assert_eq!(t[n - 1], t_end);
            prop_assert!(t.windows(2).all(|w| w[0] < w[1]));
            for (i, ti) in t.iter().enumerate() {
                let ideal = t_end * i as f64 / (n - 1) as f64;
                prop_assert!((ti - ideal).abs() <= 2.0 * f64::EPSILON * t_end);
            }
        }

        /// The sample found is at or before t, and the next one after it.
        #[test]
        fn sample_before_brackets_t(t_end in 1e-3f64..1e6, n in 2usize..500, f in 0.0f64..=1.0) {
            let times = even_times(0.0, t_end, n);
            let t = f * t_end;
            let i = sample_before(&times, t).unwrap();
            prop_assert!(times[i] <= t);
            prop_assert!(i + 1 == n || times[i + 1] > t);
        }
    }

    #[test]
    fn even_times_stay_finite_at_the_top_of_the_range() {
        let t = even_times(0.0, f64::MAX, 1001);
        assert!(t.iter().all(|x| x.is_finite()));
        assert!(t.windows(2).all(|w| w[0] < w[1]));
        assert_eq!(t[1000], f64::MAX);
        let t = even_times(-1e308, 1e308, 5);
        assert_eq!(t, vec![-1e308, -5e307, 0.0, 5e307, 1e308]);
    }
}
