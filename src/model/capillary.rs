//! Capillary adhesion at a relative humidity (docs/model.md §10).
//!
//! A liquid (water unless given) condenses in every gap narrower than the Kelvin
//! length d_K = r_K (cos θ_a + cos θ_b), r_K = γ_L V_m / (R_g T ln(1/RH)), and
//! pulls with the Laplace pressure Δp = γ_L / r_K on the wetted area. One summit at
//! interference δ wets 2πR (d_K + δ) for -d_K ≤ δ < 0 and 2πR d_K in contact (a
//! Dugdale law of range d_K, docs/model.md §7's table). Per unit nominal area the
//! independent menisci cover F_w(d) = N ∫ a_w(z - d) φ(z) dz; placed at random they
//! overlap, and the wet fraction is 1 - e^{-F_w} (the Boolean model of random
//! discs). The load is
//!
//! ```text
//! P_cap(d) = -Δp (1 - e^{-F_w(d)})            (≤ 0, per unit nominal area)
//! ```
//!
//! **Non-dimensional form** (the scales of §3: lengths by σ, loads by
//! K N R^{1/2} σ^{3/2} / √(2π)). With k = d_K/σ and
//!
//! ```text
//! J(h) = ∫_{-k}^{0} (1 + Δ/k) φ̄(Δ) dΔ + ∫_0^∞ φ̄(Δ) dΔ,   φ̄ = e^{-(h+Δ)²/2}
//! F_w = f J,   f = √(2π) R N d_K,      P̄_cap = -p (1 - e^{-F_w}),   p = √(2π) Δp / (K N R^{1/2} σ^{3/2})
//! ```
//!
//! so that p f = c_cap = 2π γ_c R^{1/2} / (K σ^{3/2}) with γ_c = Δp d_K = γ_L (cos θ_a +
//! cos θ_b): while F_w ≪ 1, P̄_cap = -c_cap J, the §7 Dugdale law of range k with c_0
//! replaced by c_cap, contact term included. With u = h + Δ the two parts join into
//! one mean of the Gaussian tail, J = (1/k) ∫_{h-k}^{h} T_0(u) du = (T_1(h - k) -
//! T_1(h))/k, taken without the cancellation of that difference for k ≪ 1
//! ([`Capillary::coverage`]). Then
//!
//! ```text
//! P̄_cap' = -p e^{-F} F',   P̄_cap'' = -p e^{-F} (F'' - F'²)
//! J'(h) = -(1/k) ∫_{-k}^{0} φ̄ dΔ ≤ 0   (integrating ∂_h φ̄ = ∂_Δ φ̄ by parts)
//! ```
//!
//! **The single-minimum fact survives.** P̄_cap'/φ(h) = p e^{-F(h)} · (f/k) ∫_{-k}^0
//! e^{-hΔ-Δ²/2} dΔ is a product of two positive functions that increase with h
//! (F falls as h grows; e^{-hΔ} grows for Δ < 0). Added to the solid law's P̄'/φ,
//! which increases with h wherever its load jump J ≥ 0 (`separation.rs`), the sum
//! still increases: P̄' changes sign once, and the searches of §4 apply unchanged.
//! Where J < 0 the sign scan of `separation.rs` isolates the critical points, and its
//! left end allows for this term (|P̄_cap'| ≤ c_cap φ(h)). tests/all/capillary.rs
//! checks the sign change on a grid.
//!
//! **Scales.** J is carried as a mantissa at the smaller of the two parts' scales.
//! Where that scale passes e^{-600} (F_w < 1e-250), 1 - e^{-F} = F to the last bit
//! and P̄_cap = -c_cap J keeps the scale, so it never underflows to a false 0;
//! elsewhere the values are formed directly (`expm1`, no cancellation).

#[cfg(test)]
use super::dmt::noncontact;
#[cfg(test)]
use super::law::Attraction;
#[cfg(test)]
use super::special::tail0;
use super::special::{
    exp_fast, gauss_scaled, kappa, tail0_fast, tail1_given, SQRT_HALF_PI, SQRT_TWO_PI,
};
use std::f64::consts::FRAC_1_SQRT_2;

pub use super::environment::{
    water_surface_tension, Environment, HumidityRange, Liquid, Meniscus, GAS_CONSTANT,
    MIN_KELVIN_RADIUS, ROOM_TEMPERATURE, WATER_CRITICAL_TEMPERATURE, WATER_MOLAR_VOLUME,
};

/// The capillary term of the model in its non-dimensional form (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Capillary {
    /// k = d_K/σ, > 0.
    pub range: f64,
    /// f = √(2π) R N d_K: F_w over J.
    pub wetting: f64,
    /// p = √(2π) Δp / (K N R^{1/2} σ^{3/2}): the flooded load in model units.
    pub flooded: f64,
}

impl Capillary {
    /// The term for a meniscus on a surface of roughness σ, summit radius R and
    /// density N, with K = 4E/3 (SI inputs).
    pub fn new(meniscus: &Meniscus, k_modulus: f64, sigma: f64, radius: f64, density: f64) -> Self {
        Capillary {
            range: meniscus.height / sigma,
            wetting: SQRT_TWO_PI * radius * density * meniscus.height,
            flooded: SQRT_TWO_PI * meniscus.laplace_pressure
                / (k_modulus * density * radius.sqrt() * sigma * sigma.sqrt()),
        }
    }

    /// c_cap = p f: the load of independent menisci per unit of J.
    pub fn independent(&self) -> f64 {
        self.flooded * self.wetting
    }

    /// J(h), J'(h), J''(h) as mantissas at the scale exponent κ(h - k), the
    /// fourth element (module docs). With a = h - k, m = h - k/2 and T_1' = -T_0,
    /// T_0' = -φ:
    ///
    /// ```text
    /// J = (T_1(a) - T_1(h))/k,   J' = (T_0(h) - T_0(a))/k,   J'' = (φ(a) - φ(h))/k
    /// ```
    ///
    /// each a mean over [a, h] (of T_0, -φ, u φ). J'' is formed as
    /// φ·expm1(±k m), exact. Where the interval is short against the weight's
    /// scale, k max(1, |m|) ≤ 1, the differences of J and J' would cancel: there
    /// they are their Taylor series about m, T_0(m) + φ(m) Σ_{j≥1} He_{2j-1}(m)
    /// (k/2)^{2j}/(2j+1)! and -φ(m) Σ_{j≥0} He_{2j}(m) (k/2)^{2j}/(2j+1)! (terms
    /// below 1e-20 of the first after twelve). Elsewhere the closed forms lose at
    /// most a few bits: for a ≥ 0 scaled by e^{κ(a)} (the h-terms by e^{-k m});
    /// for h ≤ 0 through T_0(u) = √(2π) - T_0(-u) so that only tails are
    /// subtracted; across 0 as √(2π)|a| + T_1(|a|) - T_1(h) and
    /// √(π/2) (erf(h/√2) + erf(|a|/√2)), sums of positive terms.
    pub fn coverage(&self, h: f64) -> [f64; 4] {
        self.coverage_of::<true>(h)
    }

    /// [`Capillary::coverage`], J'' (and across 0 J') only where `SLOPES`
    /// (0 otherwise): J itself is the same to the bit.
    #[inline]
    fn coverage_of<const SLOPES: bool>(&self, h: f64) -> [f64; 4] {
        let k = self.range;
        let a = h - k;
        let m = h - 0.5 * k;
        let exponent = kappa(a);
        // (h² - a²)/2 = k m.
        let x = k * m;
        let d2j = if !SLOPES {
            0.0
        } else if a >= 0.0 {
            -(-x).exp_m1() / k
        } else if x > 0.0 {
            (-0.5 * a * a).exp() * -(-x).exp_m1() / k
        } else {
            (-0.5 * h * h).exp() * x.exp_m1() / k
        };
        if k * m.abs().max(1.0) <= 1.0 {
            let q = 0.25 * k * k;
            // At the loop's start: He_{2j-2}, He_{2j-1}.
            let (mut he_even, mut he_odd) = (1.0, m);
            let (mut sum_j, mut sum_dj) = (0.0, 1.0);
            let (mut power, mut factorial) = (1.0, 1.0);
            for j in 1..=12 {
                let n = (2 * j) as f64;
                power *= q;
                factorial *= n * (n + 1.0);
                let c = power / factorial;
                sum_j += he_odd * c;
                let he_next = m * he_odd - (n - 1.0) * he_even;
                sum_dj += he_next * c;
                he_even = he_next;
                he_odd = m * he_next - n * he_odd;
            }
            // T_0(m) and φ(m) at the scale e^{κ(a)}.
            let (t0, phi) = if a >= 0.0 {
                let g = (-0.25 * k * (m + a)).exp();
                (tail0_fast(m) * g, g)
            } else {
                let g = (-kappa(m)).exp();
                (tail0_fast(m) * g, gauss_scaled(m) * g)
            };
            return [t0 + phi * sum_j, -phi * sum_dj, d2j, exponent];
        }
        let (j, dj) = if a >= 0.0 {
            // e^{-k m} (0 where it underflows: exp_fast clamps).
            let r = if x < 708.0 { exp_fast(-x) } else { 0.0 };
            let (t0a, t0h) = (tail0_fast(a), tail0_fast(h));
            let (t1a, t1h) = (tail1_given(a, t0a), tail1_given(h, t0h));
            ((t1a - t1h * r) / k, (t0h * r - t0a) / k)
        } else if h <= 0.0 {
            // Tails at b = -h and c = -a = b + k, at the scale e^{κ(b)}.
            let (b, c) = (-h, -a);
            let rb = (-kappa(b)).exp();
            let r = (-k * (b + 0.5 * k)).exp();
            let (t0b, t0c) = (tail0_fast(b), tail0_fast(c));
            let (t1b, t1c) = (tail1_given(b, t0b), tail1_given(c, t0c));
            (
                SQRT_TWO_PI - rb * (t1b - t1c * r) / k,
                rb * (t0c * r - t0b) / k,
            )
        } else {
            let c = -a;
            let (t0c, t0h) = (tail0_fast(c), tail0_fast(h));
            let t1c = tail1_given(c, t0c) * (-kappa(c)).exp();
            let t1h = tail1_given(h, t0h) * (-kappa(h)).exp();
            let dj = if SLOPES {
                let erfs = puruspe::erf(h * FRAC_1_SQRT_2) + puruspe::erf(c * FRAC_1_SQRT_2);
                -SQRT_HALF_PI * erfs / k
            } else {
                0.0
            };
            ((SQRT_TWO_PI * c + t1c - t1h) / k, dj)
        };
        [j, dj, d2j, exponent]
    }

    /// [`Capillary::coverage`] by the Dugdale quadrature of `dmt::noncontact`
    /// plus the Gaussian tail (an independent method, for the tests).
    #[cfg(test)]
    fn coverage_by_quadrature(&self, h: f64) -> [f64; 4] {
        let k = self.range;
        let nc = noncontact(Attraction::Dugdale { range: k }, 1.0, h);
        let kap = kappa(h);
        let (t, dt, d2t) = {
            let g = gauss_scaled(h);
            (tail0(h), -g, h * g)
        };
        // The parts' scales: e^{nc.exponent} and e^{κ}. Take the smaller (the larger
        // part); the factor of the other is e^{-(gap)}, with the gap exact where
        // both are large (h > k: κ - u_n²/2 = k (h - k/2)).
        let gap = if h > k {
            k * (h - 0.5 * k)
        } else {
            kap - nc.exponent
        };
        let (exponent, f_nc, f_t) = if gap >= 0.0 {
            (nc.exponent, 1.0, (-gap).exp())
        } else {
            (kap, gap.exp(), 1.0)
        };
        [
            -nc.load * f_nc + t * f_t,
            -nc.dload_dh * f_nc + dt * f_t,
            -nc.d2load_dh2 * f_nc + d2t * f_t,
            exponent,
        ]
    }

    /// The capillary load alone at separation h, as (mantissa, scale
    /// exponent): [`Capillary::at`]'s `load` and `exponent` to the bit, without
    /// the slopes (what the work's quadrature over h takes).
    pub fn load_at(&self, h: f64) -> (f64, f64) {
        let [j, _, _, exponent] = self.coverage_of::<false>(h);
        if exponent >= SMALL_COVERAGE_EXPONENT {
            return (-self.independent() * j, exponent);
        }
        let f = self.wetting * j * exp_fast(-exponent);
        (self.flooded * (-f).exp_m1(), 0.0)
    }

    /// The capillary load and its h-derivatives at separation h.
    pub fn at(&self, h: f64) -> CapillaryShare {
        let [j, dj, d2j, exponent] = self.coverage(h);
        if exponent >= SMALL_COVERAGE_EXPONENT {
            // F_w < e^{-600}: 1 - e^{-F} = F and F'² ≪ F'' to the last bit.
            let c = self.independent();
            return CapillaryShare {
                load: -c * j,
                dload_dh: -c * dj,
                d2load_dh2: -c * d2j,
                exponent,
                wetted_fraction: 0.0,
            };
        }
        let s = exp_fast(-exponent);
        let (f, df, d2f) = (
            self.wetting * j * s,
            self.wetting * dj * s,
            self.wetting * d2j * s,
        );
        let e = (-f).exp();
        let p = self.flooded;
        CapillaryShare {
            load: p * (-f).exp_m1(),
            dload_dh: -p * e * df,
            d2load_dh2: -p * e * (d2f - df * df),
            exponent: 0.0,
            wetted_fraction: -(-f).exp_m1(),
        }
    }
}

/// From this scale exponent on, the coverage is so small that the load is linear in it.
const SMALL_COVERAGE_EXPONENT: f64 = 600.0;

/// The capillary load at one separation, non-dimensional: mantissas scaled by
/// `e^{exponent}` (value = mantissa · e^{-exponent}).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CapillaryShare {
    /// P̄_cap (≤ 0).
    pub load: f64,
    /// dP̄_cap/dh (≥ 0).
    pub dload_dh: f64,
    /// d²P̄_cap/dh².
    pub d2load_dh2: f64,
    /// The scale exponent of the three mantissas.
    pub exponent: f64,
    /// 1 - e^{-F_w}: the wet fraction of the nominal area (a value, not a mantissa).
    pub wetted_fraction: f64,
}

impl CapillaryShare {
    /// No meniscus.
    pub const ZERO: CapillaryShare = CapillaryShare {
        load: 0.0,
        dload_dh: 0.0,
        d2load_dh2: 0.0,
        exponent: 0.0,
        wetted_fraction: 0.0,
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn water_at_room_temperature() {
        // IAPWS 1994 table: 71.97 mN/m at 25 °C.
        assert!((water_surface_tension(298.15) - 0.07197).abs() < 5e-6);
        assert_eq!(water_surface_tension(700.0), 0.0);
    }

    #[test]
    fn dry_or_hydrophobic_air_has_no_meniscus() {
        let dry = Environment::default();
        assert!(dry.meniscus().is_none());
        let wet = Environment {
            relative_humidity: 0.5,
            contact_angle_a: 2.0,
            contact_angle_b: 2.0,
            ..dry
        };
        assert!(wet.meniscus().is_none());
    }

    #[test]
    fn kelvin_radius_of_water_at_half_humidity() {
        // r_K = γ V_m / (R T ln 2) = 0.07197·1.8069e-5/(8.314462618·298.15·0.693147) ≈ 0.757 nm.
        let env = Environment {
            relative_humidity: 0.5,
            ..Environment::default()
        };
        let m = env.meniscus().unwrap();
        let expected = water_surface_tension(298.15) * WATER_MOLAR_VOLUME
            / (GAS_CONSTANT * 298.15 * std::f64::consts::LN_2);
        assert!((m.kelvin_radius / expected - 1.0).abs() < 1e-15);
        assert!((m.kelvin_radius - 0.7568e-9).abs() < 1e-12);
        assert!((m.height - 2.0 * m.kelvin_radius).abs() < 1e-24);
        assert!((m.laplace_pressure * m.height - m.adhesion).abs() < 1e-15 * m.adhesion);
    }

    /// The load alone is the full evaluation's load, bit for bit (the work's
    /// quadrature takes it): every branch of the coverage, small and flooding
    /// wetting, one scale where the coverage underflows.
    #[test]
    fn the_load_alone_is_the_loads_value() {
        let mut checked = 0;
        for k in [1e-4, 0.3, 1.0, 3.0, 400.0] {
            for (wetting, flooded) in [(1e-6, 2.0), (0.04, 1.3), (50.0, 0.2)] {
                let c = Capillary {
                    range: k,
                    wetting,
                    flooded,
                };
                for h in [-50.0, -1.2, 0.0, 0.3, 0.9, 2.9, 6.0, 60.0, 420.0] {
                    let (load, exponent) = c.load_at(h);
                    let full = c.at(h);
                    assert_eq!(load.to_bits(), full.load.to_bits(), "k {k} h {h}");
                    assert_eq!(exponent.to_bits(), full.exponent.to_bits());
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 135);
    }

    /// The closed forms and series against the Dugdale quadrature (independent:
    /// `dmt::noncontact` integrates the Dugdale law itself), on ranges from
    /// 1e-4 σ to 400 σ and separations from deep contact to far apart: J, J'
    /// and J'' as values at one scale (measured: 6.8e-14, 2.6e-13, 1.7e-12,
    /// the last the quadrature's: against the 40-digit table the closed form of
    /// J'' is within 2.2e-14, tests/all/capillary.rs).
    #[test]
    fn coverage_closed_forms_match_the_quadrature() {
        let mut worst = [0.0f64; 3];
        for k in [1e-4, 0.01, 0.3, 0.99, 1.0, 1.5, 3.0, 20.0, 400.0] {
            let c = Capillary {
                range: k,
                wetting: 1.0,
                flooded: 1.0,
            };
            for h in [
                -3e4, -50.0, -6.0, -1.2, -0.3, 0.0, 1e-3, 0.3, 0.5, 1.0, 2.9, 6.0, 10.0, 60.0,
                200.0, 420.0,
            ] {
                let a = c.coverage(h);
                let b = c.coverage_by_quadrature(h);
                let shift = (b[3] - a[3]).exp();
                // The sizes of the terms: J' and J'' against |J'| + |J''| (they
                // change sign or vanish where the other does not).
                let size = b[1].abs() + b[2].abs();
                for (i, w) in worst.iter_mut().enumerate() {
                    let (got, want) = (a[i] * shift, b[i]);
                    let scale = if i == 0 {
                        want.abs()
                    } else {
                        size.max(want.abs())
                    };
                    let e = if scale > 1e-300 {
                        (got - want).abs() / scale
                    } else {
                        0.0
                    };
                    assert!(
                        e < [1e-12, 1e-12, 1e-11][i] && got.is_finite(),
                        "k={k} h={h} [{i}]: {got} vs {want}"
                    );
                    *w = w.max(e);
                }
            }
        }
        assert!(worst[0] > 0.0, "{worst:?}");
    }
}
