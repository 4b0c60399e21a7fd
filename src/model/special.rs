//! Gaussian tail moments, the closed-form building blocks of docs/model.md §4.
//!
//! `T_n(u) = ∫_0^∞ x^n e^{-(u+x)²/2} dx` for n = 0, 1. Each is returned as a
//! mantissa scaled by `e^{κ(u)}`, κ(u) = max(u, 0)²/2, so the functions stay
//! representable for any u (they decay like `e^{-u²/2}` for large u).

use std::f64::consts::FRAC_1_SQRT_2;

/// √(π/2).
pub const SQRT_HALF_PI: f64 = 1.253_314_137_315_500_1;

/// The scale exponent κ(u) = max(u, 0)²/2 used throughout the model.
#[inline]
pub fn kappa(u: f64) -> f64 {
    if u > 0.0 {
        0.5 * u * u
    } else {
        0.0
    }
}

/// `T_0(u) e^{κ(u)}`, where `T_0(u) = ∫_0^∞ e^{-(u+x)²/2} dx = √(π/2) erfc(u/√2)`.
///
/// Uses erfcx for u > 0 (no underflow, no cancellation) and erfc for u ≤ 0
/// (where erfc(u/√2) lies in [1, 2)).
#[inline]
pub fn tail0(u: f64) -> f64 {
    if u > 0.0 {
        SQRT_HALF_PI * puruspe::erfcx(u * FRAC_1_SQRT_2)
    } else {
        SQRT_HALF_PI * puruspe::erfc(u * FRAC_1_SQRT_2)
    }
}

/// `T_0(u) = ∫_u^∞ e^{-x²/2} dx = √(π/2) erfc(u/√2)` itself (0 where it underflows).
#[inline]
pub fn gaussian_tail(u: f64) -> f64 {
    if u > 0.0 {
        tail0(u) * (-0.5 * u * u).exp()
    } else {
        tail0(u)
    }
}

/// The Mills ratio M(x) = T_0(x) e^{x²/2} (= [`tail0`] for x > 0) on
/// [0, MILLS_END] as Taylor series of degree MILLS_DEGREE about the centres
/// of pieces MILLS_STEP wide, built once per process: c_0 = M(x_c) from
/// erfcx, the rest from M' = xM − 1, i.e. c_{k+1} = (x_c c_k + c_{k−1})/(k+1)
/// with c_k = M^{(k)}(x_c)/k!. M is completely monotone (the c_k alternate
/// in sign), so that recurrence cancels forwards for large x; there it runs
/// backwards from k = 60 (Miller's algorithm), normalised by c_0, where each
/// c_k comes out to a few ulps of itself. On a piece |x − x_c| ≤ 1/32, and the terms
/// beyond degree 14 are below 1e-18 of c_0 everywhere on [0, 10].
const MILLS_STEP: f64 = 0.0625;
const MILLS_END: f64 = 10.0;
const MILLS_DEGREE: usize = 14;
/// Below this x the recurrence's two solutions decay alike (x → 0: even and
/// odd terms apart, each like 1/k!!) and Miller's algorithm cannot tell them
/// apart; it runs forwards there, where its cancellation is still mild.
const MILLS_FORWARD: f64 = 3.0;

fn mills_pieces() -> &'static [[f64; MILLS_DEGREE + 1]] {
    static PIECES: std::sync::OnceLock<Vec<[f64; MILLS_DEGREE + 1]>> = std::sync::OnceLock::new();
    PIECES.get_or_init(|| {
        const START: usize = 60;
        let count = (MILLS_END / MILLS_STEP).round() as usize;
        (0..count)
            .map(|i| {
                let x = (i as f64 + 0.5) * MILLS_STEP;
                let mut out = [0.0; MILLS_DEGREE + 1];
                if x < MILLS_FORWARD {
                    // Forwards from c_0 and c_1 = x c_0 − 1.
                    out[0] = tail0(x);
                    out[1] = x * out[0] - 1.0;
                    for k in 1..MILLS_DEGREE {
                        out[k + 1] = (x * out[k] + out[k - 1]) / (k + 1) as f64;
                    }
                } else {
                    // Backwards: c_{k−1} = (k + 1) c_{k+1} − x c_k.
                    let mut c = vec![0.0f64; START + 2];
                    c[START] = 1e-200;
                    for k in (1..=START).rev() {
                        c[k - 1] = (k + 1) as f64 * c[k + 1] - x * c[k];
                    }
                    let norm = tail0(x) / c[0];
                    for (o, ck) in out.iter_mut().zip(&c) {
                        *o = ck * norm;
                    }
                }
                out
            })
            .collect()
    })
}

/// The Mills ratio at 0 ≤ x < [`MILLS_END`] from its Taylor piece.
#[inline]
fn mills_piece(x: f64) -> f64 {
    let pieces = mills_pieces();
    let i = ((x / MILLS_STEP) as usize).min(pieces.len() - 1);
    let y = x - (i as f64 + 0.5) * MILLS_STEP;
    let c = &pieces[i];
    let mut mills = c[MILLS_DEGREE];
    for &ck in c[..MILLS_DEGREE].iter().rev() {
        mills = mills * y + ck;
    }
    mills
}

/// [`tail0`] without a special function where |u| < 10: the Mills ratio
/// from its Taylor pieces for u ≥ 0; below 0, √(2π) less the mirror image
/// (no cancellation: the result is at least half of √(2π)). Within a few ulps
/// of it (`fast_gaussian_tail_is_erfcs`); the meniscus's coverage takes two
/// or four per evaluation.
#[inline]
pub fn tail0_fast(u: f64) -> f64 {
    let x = u.abs();
    if x.is_nan() || x >= MILLS_END {
        return tail0(u);
    }
    let mills = mills_piece(x);
    if u >= 0.0 {
        mills
    } else {
        SQRT_TWO_PI - mills * exp_fast(-0.5 * x * x)
    }
}

/// [`gaussian_tail`] without a special function where |u| < 10: e^{-u²/2}
/// ([`exp_fast`]) times the Mills ratio from its Taylor pieces
/// (`mills_pieces`), √(2π) less the mirror image below 0: within a few ulps
/// (`fast_gaussian_tail_is_erfcs`) at a fraction of erfc's cost. The work of
/// separation's sums take one per node.
#[inline]
pub fn gaussian_tail_fast(u: f64) -> f64 {
    let x = u.abs();
    if x.is_nan() || x >= MILLS_END {
        return gaussian_tail(u);
    }
    let mills = mills_piece(x);
    // e^{-x²/2} with x² split exactly (Dekker: x = a + b, a with 26 bits):
    // −x²/2 rounded would err by up to 2e-15 relative at x = 7.
    let a = f64::from_bits(x.to_bits() & !((1u64 << 27) - 1));
    let b = x - a;
    let s = b * (a + 0.5 * b); // below 2^-26 x²: two terms of e^{-s} suffice
    let tail = exp_fast(-0.5 * a * a) * (1.0 - s * (1.0 - 0.5 * s)) * mills;
    if u >= 0.0 {
        tail
    } else {
        SQRT_TWO_PI - tail
    }
}

/// Above this u, [`tail1_given`] uses its asymptotic series; below, `1 - u T_0`
/// (whose cancellation costs at most u² ulps ≈ 3e-14 relative at u = 12).
const TAIL1_SERIES_FROM: f64 = 12.0;

/// [`tail1_given`] with its own `tail0(u)`.
#[cfg(test)]
pub fn tail1(u: f64) -> f64 {
    tail1_given(u, tail0(u))
}

/// `T_1(u) e^{κ(u)}`, where `T_1(u) = ∫_0^∞ x e^{-(u+x)²/2} dx = e^{-u²/2} - u T_0(u)`,
/// from `t0 = tail0(u)`, which the contact integrals have at hand (one erfc fewer).
///
/// This is the non-dimensional real area Ā(h) = √(2π) F_1(h) of
/// Greenwood–Williamson. For u ≥ 12 it sums the asymptotic series
/// `Σ_k (-1)^k (2k+1)!! / u^{2k+2}`, whose truncation error after 20 terms is
/// below 1e-18 relative there.
#[inline]
pub fn tail1_given(u: f64, t0: f64) -> f64 {
    if u <= 0.0 {
        (-0.5 * u * u).exp() - u * t0
    } else if u < TAIL1_SERIES_FROM {
        1.0 - u * t0
    } else {
        let r = 1.0 / (u * u);
        // r(1 - 3r(1 - 5r(1 - 7r(…)))) by Horner, innermost term k = 20.
        let mut inner = 1.0;
        for k in (1..=20).rev() {
            inner = 1.0 - (2 * k + 1) as f64 * r * inner;
        }
        r * inner
    }
}

/// The Gaussian density without its normalisation, `e^{-u²/2}`, scaled by `e^{κ(u)}`.
#[inline]
pub fn gauss_scaled(u: f64) -> f64 {
    if u > 0.0 {
        1.0
    } else {
        (-0.5 * u * u).exp()
    }
}

/// √(2π).
pub const SQRT_TWO_PI: f64 = 2.506_628_274_631_000_2;

/// e^x for x in [-708, 709] (clamped outside, so never Inf or NaN), to about
/// 1 ulp, without branches (so that loops over nodes vectorize): x = k ln 2 + r,
/// |r| ≤ ln 2/2 (Cody–Waite, with ln 2 split so that k·[`LN2_HI`] is exact), then
/// e^r = 1 + r + r² Q(r), Q the degree-10 Chebyshev fit of (e^r - 1 - r)/r² on
/// [-ln 2/2, ln 2/2] (mpmath `chebyfit`, 50 digits: its error is 2.3e-19 of e^r), and
/// 2^k is assembled in the exponent bits. The test `exp_fast_matches_std` (in `dmt.rs`)
/// bounds it against `f64::exp`.
#[inline(always)]
pub(crate) fn exp_fast(x: f64) -> f64 {
    /// 1.5·2^52: adding it rounds to an integer, which then sits in the low bits.
    const SHIFT: f64 = 6_755_399_441_055_744.0;
    const INV_LN2: f64 = std::f64::consts::LOG2_E;
    /// ln 2 = LN2_HI + LN2_LO, LN2_HI with 21 trailing zero bits (fdlibm).
    const LN2_HI: f64 = 6.931_471_803_691_238e-1;
    const LN2_LO: f64 = 1.908_214_929_270_587_7e-10;
    const Q: [f64; 11] = [
        2.091_467_937_658_393_5e-9,
        2.510_520_637_395_701e-8,
        2.755_727_366_134_863_7e-7,
        2.755_725_542_574_643_5e-6,
        2.480_158_732_553_336_3e-5,
        1.984_126_987_480_049_3e-4,
        1.388_888_888_888_375_2e-3,
        8.333_333_333_326_141e-3,
        4.166_666_666_666_667e-2,
        1.666_666_666_666_667e-1,
        0.5,
    ];
    let x = x.clamp(-708.0, 709.0);
    let shifted = x * INV_LN2 + SHIFT;
    let k = shifted - SHIFT;
    let r = (x - k * LN2_HI) - k * LN2_LO;
    // Q by Estrin's scheme (Q[10 - i] is the coefficient of r^i): a dependency
    // chain of 4 multiply–adds instead of Horner's 10.
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let p01 = Q[10] + Q[9] * r;
    let p23 = Q[8] + Q[7] * r;
    let p45 = Q[6] + Q[5] * r;
    let p67 = Q[4] + Q[3] * r;
    let p89 = Q[2] + Q[1] * r;
    let p0_3 = p01 + p23 * r2;
    let p4_7 = p45 + p67 * r2;
    let p8_10 = p89 + Q[0] * r2;
    let q = (p0_3 + p4_7 * r4) + p8_10 * r8;
    // k + 1023 in [1, 2046] lands in the exponent field; the higher bits of
    // `shifted` are shifted out.
    let scale = f64::from_bits(shifted.to_bits().wrapping_add(1023) << 52);
    (1.0 + (r + r2 * q)) * scale
}

/// Ensures the constants above are what their names say (checked in tests).
#[cfg(test)]
fn constants_consistent() -> bool {
    use std::f64::consts::PI;
    ((PI / 2.0).sqrt() - SQRT_HALF_PI).abs() < 1e-16
        && ((2.0 * PI).sqrt() - SQRT_TWO_PI).abs() < 1e-15
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants() {
        assert!(constants_consistent());
    }

    #[test]
    fn tail0_at_zero_is_half_gaussian_mass() {
        // T0(0) = √(π/2) exactly (half of ∫ e^{-x²/2}).
        assert!((tail0(0.0) - SQRT_HALF_PI).abs() < 1e-16);
        // T0(-∞) → √(2π).
        assert!((tail0(-40.0) - SQRT_TWO_PI).abs() < 1e-15);
    }

    #[test]
    fn tail1_series_matches_subtraction_at_the_switch() {
        // Both forms are valid at u = 12; the subtraction loses ≈ u² ulps.
        let u = TAIL1_SERIES_FROM;
        let direct = 1.0 - u * tail0(u);
        let series = {
            let r = 1.0 / (u * u);
            let mut s = 0.0;
            let mut term = r;
            for k in 0..30 {
                s += term;
                term *= -(2.0 * k as f64 + 3.0) * r;
            }
            s
        };
        assert!((tail1(u) / series - 1.0).abs() < 1e-15);
        assert!((direct / series - 1.0).abs() < 1e-13);
    }

    /// The fast tail against 25-digit values (mpmath, √(π/2) erfc(u/√2) at
    /// 40 digits) within 6e-16 relative (3 ulps), and against erfc's own over a dense
    /// grid of u ∈ [−12, 12] (every piece, their ends, both sides of 0 and of
    /// the switch at 10) within 5e-15: erfc's path rounds −u²/2 before its
    /// exponential, which alone errs by up to 3.6e-15 at u = 10 (the largest
    /// difference, 4.0e-15, lies at u = 9.91; the 25-digit value there sides
    /// with the fast tail).
    #[test]
    #[allow(clippy::excessive_precision)] // the references as mpmath printed them
    fn fast_gaussian_tail_is_erfcs() {
        for (u, exact) in [
            (6.908625, 6.133389445473294778458061e-12),
            (3.3, 0.001211764623938419334945718),
            (0.7, 0.6065129320953369948153174),
            (9.9, 5.217233975297975232194736e-23),
            (-2.5, 2.491062951949414319071374),
            (0.03, 1.223318636708065335908427),
            (1.49, 0.1707317607403961974474518),
            (2.062375, 0.04909488099726193071663187),
            (2.97, 0.003732366355702311074449411),
            (3.03, 0.003065026580691971658849746),
            (5.0, 0.0000007185289350398080572041265),
            (8.5, 2.37616700156839919986162e-17),
            (-0.7, 1.900115342535663507600448),
            (-4.2, 2.506594821799171102764225),
        ] {
            let fast = gaussian_tail_fast(u);
            assert!(
                (fast / exact - 1.0).abs() <= 6e-16,
                "u = {u}: {fast:e} against {exact:e}"
            );
            // The scaled tail: e^{-u²/2} rounded in u²/2 errs by up to 5e-15
            // at u = 9.9 (below 0 the value itself).
            let scaled = tail0_fast(u) * (-kappa(u)).exp();
            assert!(
                (scaled / exact - 1.0).abs() <= 1e-14,
                "u = {u}: {scaled:e} against {exact:e}"
            );
        }
        let (mut worst, mut at) = (0.0f64, 0.0);
        let mut worst_scaled = 0.0f64;
        for i in -96_000..=96_000 {
            let u = i as f64 * 1.25e-4;
            let (fast, slow) = (gaussian_tail_fast(u), gaussian_tail(u));
            let e = (fast - slow).abs() / slow;
            if e > worst {
                (worst, at) = (e, u);
            }
            let (fast, slow) = (tail0_fast(u), tail0(u));
            worst_scaled = worst_scaled.max((fast - slow).abs() / slow);
        }
        assert!(worst <= 5e-15, "worst {worst:e} at u = {at}");
        assert!(worst_scaled <= 5e-15, "worst {worst_scaled:e}");
    }

    #[test]
    fn tail1_at_zero_is_one() {
        // T1(0) = ∫ x e^{-x²/2} = 1.
        assert!((tail1(0.0) - 1.0).abs() < 1e-16);
    }
}
