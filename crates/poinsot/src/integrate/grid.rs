//! Sample grids: evenly spaced output times.

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

#[cfg(test)]
mod tests {
    use super::*;

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
