//! The surface displacement of an elastic half-space under a uniform pressure on
//! a disk (Johnson, *Contact Mechanics*, §3.4), from the complete elliptic
//! integrals K and E, which the arithmetic–geometric mean gives to a few ulps.

use std::f64::consts::FRAC_PI_2;

/// K(k) and E(k) from the complementary modulus k' = √(1 − k²) and k itself
/// (both given, so that k → 1 loses nothing: callers form k' without
/// cancellation). Arithmetic–geometric mean (Abramowitz & Stegun 17.6).
pub fn complete_elliptic(k: f64, k_complement: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0_f64, k_complement);
    // Σ 2^{n-1} c_n², c_0 = k.
    let mut sum = 0.5 * k * k;
    let mut power = 0.5;
    for _ in 0..40 {
        let c = 0.5 * (a - b);
        power *= 2.0;
        sum += power * c * c;
        let next = (0.5 * (a + b), (a * b).sqrt());
        a = next.0;
        b = next.1;
        if c.abs() <= 1e-17 * a {
            break;
        }
    }
    let big_k = FRAC_PI_2 / a;
    (big_k, big_k * (1.0 - sum))
}

/// E(k) − k'² K(k) = (π/2) Σ_{m≥1} c_{m−1}² k^{2m}/(2m), c_m = (2m−1)!!/(2m)!!,
/// summed directly for k ≤ 1/2 (where the difference cancels) and from the
/// mean above otherwise.
fn e_minus_k(k: f64, k_complement: f64) -> f64 {
    if k <= 0.5 {
        let k2 = k * k;
        let (mut c, mut power, mut sum) = (1.0_f64, 1.0_f64, 0.0_f64);
        for m in 1..60 {
            power *= k2;
            let term = c * c * power / (2 * m) as f64;
            sum += term;
            if term <= 1e-17 * sum {
                break;
            }
            c *= (2 * m - 1) as f64 / (2 * m) as f64;
        }
        FRAC_PI_2 * sum
    } else {
        let (big_k, big_e) = complete_elliptic(k, k_complement);
        big_e - k_complement * k_complement * big_k
    }
}

/// The displacement at radius `r` of a unit pressure on the disk of radius
/// `a`, over the factor 4/(πE) of the kernel: a E(r/a) inside, r [E(a/r) −
/// (1 − a²/r²) K(a/r)] outside (so π a/2 at the centre, a at the rim).
pub fn disk(a: f64, r: f64) -> f64 {
    if a <= 0.0 {
        0.0
    } else if r < a {
        let k = r / a;
        let kc = ((a - r) * (a + r)).sqrt() / a;
        a * complete_elliptic(k, kc).1
    } else if r == a {
        a
    } else {
        let k = a / r;
        let kc = ((r - a) * (r + a)).sqrt() / r;
        r * e_minus_k(k, kc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// K and E at k² = 1/2 (A&S table 17.1: K = 1.854 074 677 301 372,
    /// E = 1.350 643 881 047 675).
    #[test]
    fn lemniscatic_values() {
        let k = std::f64::consts::FRAC_1_SQRT_2;
        let (big_k, big_e) = complete_elliptic(k, k);
        assert!((big_k - 1.854_074_677_301_372).abs() < 4e-15);
        assert!((big_e - 1.350_643_881_047_675).abs() < 4e-15);
    }

    /// The disk displacement is continuous at the rim and at the switch of the
    /// outside formula between the series and the mean (k = 1/2).
    #[test]
    fn disk_is_continuous() {
        let a = 1.3;
        assert!((disk(a, a * (1.0 - 1e-12)) - a).abs() < 1e-9);
        assert!((disk(a, a * (1.0 + 1e-12)) - a).abs() < 1e-9);
        let (lo, hi) = (
            disk(a, 2.0 * a * (1.0 - 1e-13)),
            disk(a, 2.0 * a * (1.0 + 1e-13)),
        );
        // The two sides differ by the change of r (2e-13 relative) and rounding.
        assert!((lo - hi).abs() < 1e-12 * lo);
        // Far away the disk acts as a point load: π a²/(4 r).
        let r = 1e4;
        let far = std::f64::consts::PI * a * a / (4.0 * r);
        assert!((disk(a, r) - far).abs() < 1e-7 * far);
    }
}
