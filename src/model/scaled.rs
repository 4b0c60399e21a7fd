//! Numbers carried with an exponential scale, so that `e^{-h²/2}` at h = 60 or
//! `P̄_min ≈ -2·10^{-11753}` are represented instead of underflowing to 0.

use std::cmp::Ordering;

/// The value `mantissa · e^{-exponent}`.
///
/// The model keeps every integral at a separation h as a mantissa scaled by
/// `e^{κ(h)}`, κ(h) = max(h, 0)²/2, so mantissas stay O(1) where the weight
/// `e^{-(h+Δ)²/2}` would underflow; `Scaled` carries such a pair around.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scaled {
    /// The mantissa; its sign is the sign of the value.
    pub mantissa: f64,
    /// The exponent k in `e^{-k}`; may be negative (large values).
    pub exponent: f64,
}

impl Scaled {
    /// Zero.
    pub const ZERO: Scaled = Scaled {
        mantissa: 0.0,
        exponent: 0.0,
    };

    /// `mantissa · e^{-exponent}`.
    pub fn new(mantissa: f64, exponent: f64) -> Self {
        Scaled { mantissa, exponent }
    }

    /// A plain f64 (exponent 0).
    pub fn from_f64(x: f64) -> Self {
        Scaled::new(x, 0.0)
    }

    /// The value as an f64; underflows to ±0 or overflows to ±inf when it must.
    pub fn value(self) -> f64 {
        if self.mantissa == 0.0 {
            return 0.0;
        }
        self.mantissa * (-self.exponent).exp()
    }

    /// ln |value| (−inf for zero).
    pub fn ln_abs(self) -> f64 {
        self.mantissa.abs().ln() - self.exponent
    }

    /// log10 |value| (−inf for zero).
    pub fn log10_abs(self) -> f64 {
        self.ln_abs() / std::f64::consts::LN_10
    }

    /// −1, 0 or 1.
    pub fn signum(self) -> f64 {
        if self.mantissa == 0.0 {
            0.0
        } else {
            self.mantissa.signum()
        }
    }

    /// The sum, kept at the larger of the two scales.
    pub fn plus(self, other: Scaled) -> Scaled {
        if self.mantissa == 0.0 {
            return other;
        }
        if other.mantissa == 0.0 {
            return self;
        }
        let k = self.exponent.min(other.exponent);
        Scaled::new(
            self.mantissa * (k - self.exponent).exp() + other.mantissa * (k - other.exponent).exp(),
            k,
        )
    }

    /// The difference.
    pub fn minus(self, other: Scaled) -> Scaled {
        self.plus(other.negate())
    }

    /// The negation.
    pub fn negate(self) -> Scaled {
        Scaled::new(-self.mantissa, self.exponent)
    }

    /// Multiplied by a plain number.
    pub fn scale(self, factor: f64) -> Scaled {
        Scaled::new(self.mantissa * factor, self.exponent)
    }

    /// The ratio `self / other` as a plain f64 (±inf or 0 where it must).
    pub fn ratio(self, other: Scaled) -> f64 {
        if self.mantissa == 0.0 {
            return 0.0;
        }
        (self.mantissa / other.mantissa) * (other.exponent - self.exponent).exp()
    }

    /// Compares the value with a plain number, exactly as far as the mantissa allows.
    pub fn cmp_f64(self, x: f64) -> Ordering {
        let (s, t) = (self.signum(), if x == 0.0 { 0.0 } else { x.signum() });
        if s != t {
            return s.partial_cmp(&t).unwrap_or(Ordering::Equal);
        }
        if s == 0.0 {
            return Ordering::Equal;
        }
        let by_magnitude = self
            .ln_abs()
            .partial_cmp(&x.abs().ln())
            .unwrap_or(Ordering::Equal);
        if s > 0.0 {
            by_magnitude
        } else {
            by_magnitude.reverse()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_across_scales() {
        // e^{-1000} + 2 e^{-1001}: both underflow as f64, the sum keeps its log.
        let a = Scaled::new(1.0, 1000.0);
        let b = Scaled::new(2.0, 1001.0);
        let s = a.plus(b);
        let expected = (1.0 + 2.0 * (-1.0f64).exp()).ln() - 1000.0;
        assert!((s.ln_abs() - expected).abs() < 1e-12);
        assert_eq!(s.value(), 0.0);
        assert!((a.ratio(b) - 0.5 * 1f64.exp()).abs() < 1e-14);
        assert_eq!(a.cmp_f64(0.0), Ordering::Greater);
        assert_eq!(a.negate().cmp_f64(-1e-300), Ordering::Greater);
        assert_eq!(Scaled::new(3.0, 0.0).cmp_f64(2.0), Ordering::Greater);
        assert_eq!(Scaled::new(-3.0, 0.0).cmp_f64(-2.0), Ordering::Less);
        assert_eq!(Scaled::ZERO.cmp_f64(-1.0), Ordering::Greater);
    }
}
