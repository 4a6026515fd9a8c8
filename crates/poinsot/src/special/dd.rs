//! Double-double arithmetic (an unevaluated sum `hi + lo` of two doubles, ~32 digits), just
//! enough to compute the quarter period K(m) for the argument reduction of the Jacobi
//! functions without losing the low-order digits (Dekker 1971; Hida, Li & Bailey 2001).

/// `hi + lo` with `|lo| <= ulp(hi)/2`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Dd {
    pub hi: f64,
    pub lo: f64,
}

#[inline]
fn two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    let bb = s - a;
    let err = (a - (s - bb)) + (b - bb);
    Dd { hi: s, lo: err }
}

#[inline]
fn quick_two_sum(a: f64, b: f64) -> Dd {
    let s = a + b;
    Dd {
        hi: s,
        lo: b - (s - a),
    }
}

#[inline]
fn two_prod(a: f64, b: f64) -> Dd {
    let p = a * b;
    Dd {
        hi: p,
        lo: a.mul_add(b, -p),
    }
}

impl Dd {
    /// The exact value of a double.
    pub(crate) const fn from(x: f64) -> Self {
        Dd { hi: x, lo: 0.0 }
    }

    /// The exact difference `a − b` of two doubles.
    pub(crate) fn diff(a: f64, b: f64) -> Self {
        two_sum(a, -b)
    }

    pub(crate) fn add(self, o: Dd) -> Dd {
        let s = two_sum(self.hi, o.hi);
        let t = two_sum(self.lo, o.lo);
        let s = quick_two_sum(s.hi, s.lo + t.hi);
        quick_two_sum(s.hi, s.lo + t.lo)
    }

    pub(crate) fn mul(self, o: Dd) -> Dd {
        let p = two_prod(self.hi, o.hi);
        quick_two_sum(p.hi, p.lo + (self.hi * o.lo + self.lo * o.hi))
    }

    pub(crate) fn scale(self, k: f64) -> Dd {
        // Exact for powers of two.
        Dd {
            hi: self.hi * k,
            lo: self.lo * k,
        }
    }

    pub(crate) fn div(self, o: Dd) -> Dd {
        // Long division: q1 + q2 + q3 (Hida, Li & Bailey).
        let q1 = self.hi / o.hi;
        let r = self.add(o.mul(Dd::from(-q1)));
        let q2 = r.hi / o.hi;
        let r = r.add(o.mul(Dd::from(-q2)));
        let q3 = r.hi / o.hi;
        quick_two_sum(q1, q2).add(Dd::from(q3))
    }

    pub(crate) fn sqrt(self) -> Dd {
        if self.hi <= 0.0 {
            return Dd::from(0.0);
        }
        // One Newton step from the double square root: x + (a − x²)/(2x).
        let x = self.hi.sqrt();
        let r = self.add(two_prod(x, x).scale(-1.0));
        quick_two_sum(x, r.hi / (2.0 * x))
    }
}

/// π to double-double precision.
pub(crate) const PI: Dd = Dd {
    hi: std::f64::consts::PI,
    lo: 1.224_646_799_147_353_2e-16,
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn double_double_keeps_thirty_digits() {
        // (1/3)·3 = 1 and sqrt(2)² = 2 to ~1e-31.
        let third = Dd::from(1.0).div(Dd::from(3.0));
        let one = third.mul(Dd::from(3.0)).add(Dd::from(-1.0));
        assert!(one.hi.abs() < 1e-31, "{one:?}");
        let s = Dd::from(2.0).sqrt();
        let two = s.mul(s).add(Dd::from(-2.0));
        assert!(two.hi.abs() < 1e-31, "{two:?}");
        // The exact difference of two doubles.
        let d = Dd::diff(1.0, 1e-20);
        assert_eq!(d.hi, 1.0);
        assert_eq!(d.lo, -1e-20);
    }
}
