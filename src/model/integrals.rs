//! The non-dimensional load and area integrals of docs/model.md §3 at one separation.
//!
//! ```text
//! P̄(h)  = ∫_0^{Δc} p_e(Δ) φ̄ dΔ + ∫_{Δc}^∞ (c_p Δ - c_0) φ̄ dΔ      (eq. 8, corrected)
//! Ā(h)  = ∫_0^∞ Δ φ̄ dΔ,   Ā_p(h) = ∫_{Δc}^∞ Δ φ̄ dΔ                (eqs. 15, 16)
//! φ̄(Δ) = exp(-(h+Δ)²/2)
//! ```
//!
//! The elastic integral is taken in `s = Δ1^{1/4}` (Δ = s⁴ - c_d s,
//! p_e = s⁶ - c_a s³), a polynomial times a Gaussian on a finite interval,
//! by composite Gauss–Legendre on panels over which the log-weight changes by a
//! bounded amount. Everything else is closed form in erfc/erfcx. Every result is
//! a mantissa scaled by `e^{κ(h)}`, κ(h) = max(h,0)²/2.

use super::asperity_law::Tabulated;
use super::capillary::{Capillary, CapillaryShare};
use super::coefficients::{Coefficients, Transition};
use super::dmt::{hertz, noncontact, Noncontact};
use super::gauss;
use super::law::{AsperityLaw, Attraction};
use super::quadrature::{contact_level, Quadrature};
use super::scaled::Scaled;
use super::special::{gauss_scaled, kappa, tail0, tail1_given};
use std::sync::Arc;

/// The largest scale difference κ - E at which [`Integrals`] adds the shares at
/// the contact scale (the non-contact mantissa times e^{κ-E} ≤ e^{300} stays finite;
/// beyond it the contact share is below e^{-300} of the other).
const NONCONTACT_GAP_LIMIT: f64 = 300.0;

/// The model at fixed coefficients and one asperity law: precomputes the
/// transition once, then evaluates any separation with [`Model::at`].
///
/// The law ([`AsperityLaw`]) decides the contact coefficients the integrals
/// use and the non-contact term: JKR uses `coefficients` as they are; DMT uses
/// c_a = c_d = 0 (Hertz contact, Δc = c_h²) with the constant -c_0 of the elastic
/// asperity load in closed form and its Hertz integral by `dmt::hertz`, plus the
/// attraction of `dmt.rs`. DMT without adhesion (c_0 = 0) is the JKR path itself.
#[derive(Debug, Clone)]
pub struct Model {
    /// The load-law coefficients (c_a, c_0 carry γ whatever the law).
    pub coefficients: Coefficients,
    /// The asperity law.
    pub law: AsperityLaw,
    /// The coefficients of the contact integrals (equal to `coefficients` for JKR).
    contact: Coefficients,
    /// The constant subtracted from the elastic asperity load (c_0 for DMT, 0 for JKR).
    elastic_offset: f64,
    /// The elastic–plastic transition.
    pub transition: Transition,
    /// Quadrature settings.
    pub quadrature: Quadrature,
    /// s0, s at Δ = 0: `c_d^{1/3}`.
    s_touch: f64,
    /// s0³ (= c_d to an ulp), the constant of the cancellation-free Δ(v).
    c_d_cubed: f64,
    /// The capillary term of docs/model.md §10 (None: dry, or no meniscus).
    pub capillary: Option<Capillary>,
    /// The law whose integrals are taken: `law` itself, except where a
    /// closed-form limit stands in for it (see [`Model::stand_in`]).
    effective: AsperityLaw,
    /// The attraction of asperities out of contact that the effective law
    /// adds in closed form (DMT's), read from the law once.
    attraction: Option<Attraction>,
    /// A law's own rough-surface integrals (the Lennard-Jones law's table and
    /// its quadrature nodes over the separations most evaluations ask for),
    /// built once with the model (shared by its clones).
    tabulated: Option<Arc<dyn Tabulated>>,
}

/// One asperity's load in contact under JKR or DMT (docs/model.md §3, §7): for
/// Δ ≤ Δc the JKR p_e = s⁶ - c_a s³ at Δ = s⁴ - c_d s (s = s0 + v), or, where
/// `hertz_offset` (c_0) is not 0, DMT's Δ^{3/2} - c_0; beyond Δc, c_p Δ - c_0.
#[derive(Debug, Clone, Copy)]
pub(super) struct ContactLaw {
    pub hertz_offset: f64,
    pub c_a: f64,
    pub s_touch: f64,
    pub c_d_cubed: f64,
    pub c_p: f64,
    pub c_0: f64,
    pub critical_interference: f64,
}

/// The shares of the plastic junctions beyond Δc in closed form, scaled by
/// e^{κ(h)}: the count T_0(u_c), the area, the load c_p Ā_p − c_0 T_0 and its
/// first two h-derivatives, φ̄(u_c) and u_c φ̄(u_c) (u_c = h + Δc).
#[derive(Debug, Clone, Copy, Default)]
struct Plastic {
    contacts: f64,
    area: f64,
    load: f64,
    dload: f64,
    d2load: f64,
    gauss: f64,
    u_gauss: f64,
}

impl Plastic {
    fn at(c: &Coefficients, h: f64, dc: f64) -> Plastic {
        if !dc.is_finite() {
            return Plastic::default();
        }
        // Closed forms at u_c = h + Δc, rescaled from e^{κ(u_c)} to e^{κ(h)}.
        let u_c = h + dc;
        let rescale = if h > 0.0 {
            (-dc * (h + 0.5 * dc)).exp()
        } else {
            (-kappa(u_c)).exp()
        };
        // When the rescale underflows, the plastic asperities lie beyond the
        // weight's range (and c_p Δc may overflow): they carry nothing.
        if rescale == 0.0 {
            return Plastic::default();
        }
        let t0_c = tail0(u_c);
        let t0 = t0_c * rescale;
        let t1 = tail1_given(u_c, t0_c) * rescale;
        let g = gauss_scaled(u_c) * rescale;
        let area = t1 + dc * t0;
        Plastic {
            contacts: t0,
            area,
            load: c.c_p * area - c.c_0 * t0,
            dload: -(c.c_p * dc - c.c_0) * g - c.c_p * t0,
            d2load: ((c.c_p * dc - c.c_0) * u_c + c.c_p) * g,
            gauss: g,
            u_gauss: u_c * g,
        }
    }
}

/// Everything the model says at one separation h. Every field named as an
/// integral is a mantissa: multiply by `e^{-scale_exponent}` for its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Integrals {
    /// h, the mean-plane separation over σ.
    pub separation: f64,
    /// κ(h) = max(h,0)²/2: the value of a mantissa m is `m e^{-κ}`.
    pub scale_exponent: f64,
    /// Elastic (JKR) asperities' share of P̄.
    pub load_elastic: f64,
    /// Plastic asperities' share of P̄.
    pub load_plastic: f64,
    /// dP̄/dh, elastic share.
    pub dload_dh_elastic: f64,
    /// dP̄/dh, plastic share.
    pub dload_dh_plastic: f64,
    /// d²P̄/dh² (elastic and plastic together).
    pub d2load_dh2: f64,
    /// Ā, the total real area (all contacts counted as πRδ).
    pub area: f64,
    /// Ā_p, the real area of plastic junctions.
    pub plastic_area: f64,
    /// ∫_0^∞ φ̄ dΔ: contacts per asperity times √(2π).
    pub contacts: f64,
    /// ∫_{Δc}^∞ φ̄ dΔ: plastic contacts per asperity times √(2π).
    pub plastic_contacts: f64,
    /// The non-contact (attracted, DMT) share of P̄, a mantissa scaled by
    /// `e^{noncontact_exponent}` (not `scale_exponent`); 0 under JKR.
    pub load_noncontact: f64,
    /// dP̄/dh, non-contact share (same scale).
    pub dload_dh_noncontact: f64,
    /// d²P̄/dh², non-contact share (same scale).
    pub d2load_dh2_noncontact: f64,
    /// The scale exponent of the non-contact mantissas: the van der Waals term
    /// decays as a power of h, not like e^{-h²/2}, so it keeps its own scale.
    pub noncontact_exponent: f64,
    /// `scale_exponent - noncontact_exponent` computed without rounding either
    /// (Dugdale beyond its reach, where both are large: Δ_h (h - Δ_h/2)); None
    /// where the difference of the two fields is exact enough.
    pub noncontact_gap: Option<f64>,
    /// The capillary load of docs/model.md §10 and its derivatives, at their own
    /// scale (all 0 without a meniscus).
    pub capillary: CapillaryShare,
}

impl Integrals {
    fn scaled(&self, m: f64) -> Scaled {
        Scaled::new(m, self.scale_exponent)
    }
    fn with_noncontact(&self, contact: f64, noncontact: f64) -> Scaled {
        let c = self.scaled(contact);
        if noncontact == 0.0 {
            return c;
        }
        match self.noncontact_gap {
            Some(gap) if gap <= NONCONTACT_GAP_LIMIT => {
                // Both shares at the contact scale, with the exact difference.
                self.scaled(contact + noncontact * gap.exp())
            }
            _ => c.plus(Scaled::new(noncontact, self.noncontact_exponent)),
        }
    }
    fn with_capillary(&self, solid: Scaled, capillary: f64) -> Scaled {
        if capillary == 0.0 {
            solid
        } else {
            solid.plus(Scaled::new(capillary, self.capillary.exponent))
        }
    }
    /// P̄(h): the solid law's contact and non-contact shares and the capillary load.
    pub fn load(&self) -> Scaled {
        self.with_capillary(self.solid_load(), self.capillary.load)
    }
    /// The solid law's P̄(h), contact and non-contact shares together (without the
    /// capillary load).
    pub fn solid_load(&self) -> Scaled {
        self.with_noncontact(self.load_elastic + self.load_plastic, self.load_noncontact)
    }
    /// The capillary load P̄_cap(h) (≤ 0; 0 without a meniscus).
    pub fn capillary_load(&self) -> Scaled {
        Scaled::new(self.capillary.load, self.capillary.exponent)
    }
    /// The share of P̄ carried by asperities in contact.
    pub fn contact_load(&self) -> Scaled {
        self.scaled(self.load_elastic + self.load_plastic)
    }
    /// The share of P̄ carried by attracted asperities not in contact (≤ 0; 0 under JKR).
    pub fn noncontact_load(&self) -> Scaled {
        Scaled::new(self.load_noncontact, self.noncontact_exponent)
    }
    /// True when a term beside the contacts acts here: DMT's attraction with
    /// adhesion, or a capillary load.
    pub fn has_noncontact(&self) -> bool {
        self.load_noncontact != 0.0 || self.dload_dh_noncontact != 0.0 || self.has_capillary()
    }
    /// True when a capillary load acts here.
    pub fn has_capillary(&self) -> bool {
        self.capillary.load != 0.0 || self.capillary.dload_dh != 0.0
    }
    /// dP̄/dh.
    pub fn dload_dh(&self) -> Scaled {
        self.with_capillary(
            self.with_noncontact(
                self.dload_dh_elastic + self.dload_dh_plastic,
                self.dload_dh_noncontact,
            ),
            self.capillary.dload_dh,
        )
    }
    /// d²P̄/dh².
    pub fn d2load_dh2(&self) -> Scaled {
        self.with_capillary(
            self.with_noncontact(self.d2load_dh2, self.d2load_dh2_noncontact),
            self.capillary.d2load_dh2,
        )
    }
    /// Ā(h).
    pub fn area(&self) -> Scaled {
        self.scaled(self.area)
    }
    /// Ā_p(h).
    pub fn plastic_area(&self) -> Scaled {
        self.scaled(self.plastic_area)
    }
    /// Ā(h) - Ā_p(h): the real area of elastic contacts.
    pub fn elastic_area(&self) -> Scaled {
        // Clamped: when every contact is plastic the difference is rounding.
        self.scaled((self.area - self.plastic_area).max(0.0))
    }
    /// Contacts per asperity times √(2π).
    pub fn contacts(&self) -> Scaled {
        self.scaled(self.contacts)
    }
    /// Plastic contacts per asperity times √(2π).
    pub fn plastic_contacts(&self) -> Scaled {
        self.scaled(self.plastic_contacts)
    }
}

impl Model {
    /// The model for these coefficients with the default quadrature.
    pub fn new(coefficients: Coefficients) -> Self {
        Model::with_quadrature(coefficients, Quadrature::default())
    }

    /// The JKR model with explicit quadrature settings (validated by the caller).
    pub fn with_quadrature(coefficients: Coefficients, quadrature: Quadrature) -> Self {
        Model::with_law(coefficients, AsperityLaw::Jkr, quadrature)
    }

    /// The model of an asperity law with explicit quadrature settings. Under
    /// DMT the attraction range (z0 or Δ_h) must be finite and > 0.
    pub fn with_law(coefficients: Coefficients, law: AsperityLaw, quadrature: Quadrature) -> Self {
        let prepared = law.law().prepare(law, &coefficients);
        let contact = prepared.contact;
        let transition = match &prepared.tabulated {
            Some(table) => table.transition(&coefficients),
            None => contact.transition(),
        };
        Model {
            coefficients,
            law,
            contact,
            elastic_offset: prepared.elastic_offset,
            transition,
            quadrature,
            s_touch: contact.c_d.cbrt(),
            c_d_cubed: contact.c_d.cbrt().powi(3),
            capillary: None,
            attraction: prepared
                .effective
                .law()
                .closed_form_attraction(prepared.effective),
            effective: prepared.effective,
            tabulated: prepared.tabulated,
        }
    }

    /// The law whose integrals are taken: the scene's, or the closed-form law
    /// that stands in for it ([`Model::stand_in`]).
    pub fn effective_law(&self) -> AsperityLaw {
        self.effective
    }

    /// The attraction of asperities out of contact that the model adds in
    /// closed form (DMT's; None under the other laws).
    pub fn closed_form_attraction(&self) -> Option<Attraction> {
        self.attraction
    }

    /// The law's own integrals where it takes them (None for the closed-form
    /// contacts, and where a closed form stands in).
    pub fn tabulated(&self) -> Option<&dyn Tabulated> {
        self.tabulated.as_deref()
    }

    /// One asperity's pull-off under the model's law in units of πγR: JKR's
    /// 1.5, DMT's 2, the Lennard-Jones sphere's from its table (between them).
    pub fn asperity_pull_off(&self) -> f64 {
        match &self.tabulated {
            Some(table) => table.asperity_pull_off(),
            // A closed form that stands in for a tabulated law has its own (below
            // the Lennard-Jones table, Bradley's rigid sphere at contact, 2πγR,
            // is its DMT stand-in's).
            None => self.effective.law().closed_form_pull_off().unwrap_or(1.5),
        }
    }

    /// The closed-form law that stands in for the scene's (under the
    /// Lennard-Jones law outside its curves: JKR above μ = 3.58e6, DMT with van
    /// der Waals attraction below μ = 0.01); None where the scene's law is used.
    pub fn stand_in(&self) -> Option<AsperityLaw> {
        (self.effective != self.law && self.coefficients.has_adhesion()).then_some(self.effective)
    }

    /// This model with a capillary term (docs/model.md §10) added to its load.
    pub fn with_capillary(self, capillary: Option<Capillary>) -> Self {
        Model { capillary, ..self }
    }

    /// True when P̄ has a tensile part: γ > 0 or a meniscus.
    pub fn has_adhesion(&self) -> bool {
        self.coefficients.has_adhesion() || self.capillary.is_some()
    }

    /// Δc, the actual critical interference (∞ without plasticity).
    pub fn critical_interference(&self) -> f64 {
        self.transition.critical_interference
    }

    /// s = Δ1^{1/4} for an actual interference Δ ≥ 0 (the root ≥ c_d^{1/3} of
    /// `s⁴ - c_d s = Δ`).
    pub fn s_of_interference(&self, delta: f64) -> f64 {
        self.s_touch + self.v_of_interference(delta)
    }

    /// What the exchanged work integral ([`super::work`]) needs of the model's
    /// asperity law in contact: None under the Lennard-Jones law's table.
    pub(super) fn contact_law(&self) -> Option<ContactLaw> {
        if self.tabulated.is_some() {
            return None;
        }
        Some(ContactLaw {
            hertz_offset: self.elastic_offset,
            c_a: self.contact.c_a,
            s_touch: self.s_touch,
            c_d_cubed: self.c_d_cubed,
            c_p: self.contact.c_p,
            c_0: self.contact.c_0,
            critical_interference: self.transition.critical_interference,
        })
    }

    /// Δ as a function of v = s - s0, s0 = c_d^{1/3}:
    /// `Δ = v (3 s0³ + 6 s0² v + 4 s0 v² + v³)`, free of the cancellation in
    /// `s⁴ - c_d s` near s0 (c_d is taken as s0³, one ulp from the input).
    #[inline]
    pub(super) fn interference_of_v(&self, v: f64) -> f64 {
        let s0 = self.s_touch;
        v * (3.0 * self.c_d_cubed + v * (6.0 * s0 * s0 + v * (4.0 * s0 + v)))
    }

    /// v = s - s0 for an actual interference Δ ≥ 0: Newton from the right on
    /// the convex increasing quartic; `min(Δ/(3 s0³), Δ^{1/4})` bounds the root above.
    pub fn v_of_interference(&self, delta: f64) -> f64 {
        if delta <= 0.0 {
            return 0.0;
        }
        let s0 = self.s_touch;
        if s0 == 0.0 {
            return delta.sqrt().sqrt();
        }
        let mut v = (delta / (3.0 * self.c_d_cubed)).min(delta.sqrt().sqrt());
        for _ in 0..100 {
            let f = self.interference_of_v(v) - delta;
            let df = 3.0 * self.c_d_cubed + v * (12.0 * s0 * s0 + v * (12.0 * s0 + 4.0 * v));
            let next = v - f / df;
            if next >= v || next.is_nan() {
                break;
            }
            v = next;
        }
        v
    }

    /// As [`Model::at`], refusing a non-finite h (the guarded entry point; build
    /// the model from [`Coefficients::checked`] to guard the coefficients too).
    pub fn checked_at(&self, h: f64) -> Result<Integrals, super::coefficients::DomainError> {
        if h.is_nan() || h.abs() > super::coefficients::MAX_SEPARATION {
            return Err(super::coefficients::DomainError::Separation(h));
        }
        Ok(self.at(h))
    }

    /// Ā_p(h), the real area of the plastic junctions, with a scale of its own
    /// (`e^{-κ(u_c)}`, u_c = h + Δc): what [`Integrals::plastic_area`] holds
    /// where it does not underflow against `e^{-κ(h)}`, and its true size where it
    /// does (junctions far out in the weight's tail, e.g. 10^-6622 of the nominal
    /// area): T_1(u_c) + Δc T_0(u_c) in closed form. Zero without plasticity.
    pub fn plastic_area_scaled(&self, h: f64) -> Scaled {
        let dc = self.transition.critical_interference;
        if !dc.is_finite() || h.is_nan() {
            return Scaled::ZERO;
        }
        let u_c = h + dc;
        let t0 = tail0(u_c);
        Scaled::new(tail1_given(u_c, t0) + dc * t0, kappa(u_c))
    }

    /// All integrals at separation h (finite; see [`Model::checked_at`]).
    pub fn at(&self, h: f64) -> Integrals {
        let mut out = match self.tabulated.as_deref() {
            Some(table) => self.tabulated_at(table, h),
            None => self.contact_at(h),
        };
        if let Some(c) = &self.capillary {
            out.capillary = c.at(h);
        }
        if let Some(attraction) = self.attraction {
            let n: Noncontact = noncontact(attraction, self.coefficients.c_0, h);
            out.load_noncontact = n.load;
            out.dload_dh_noncontact = n.dload_dh;
            out.d2load_dh2_noncontact = n.d2load_dh2;
            out.noncontact_exponent = n.exponent;
            // Dugdale beyond its reach (h > Δ_h): κ = h²/2 and E = (h - Δ_h)²/2 are
            // each rounded to an ulp of themselves, 1e-7 absolute at h = 4e4 — far
            // more than the shares' difference near a weak-adhesion minimum
            // (h ~ 1e4–1e5). The sums use the exact κ - E = Δ_h (h - Δ_h/2) instead.
            if let Attraction::Dugdale { range } = attraction {
                if h > range && n.exponent > 0.0 {
                    out.noncontact_gap = Some(range * (h - 0.5 * range));
                }
            }
        }
        out
    }

    /// The integrals over the asperities in contact.
    fn contact_at(&self, h: f64) -> Integrals {
        let c = &self.contact;
        let dc = self.transition.critical_interference;
        let scale_exponent = kappa(h);
        let t0_h = tail0(h);
        let mut out = Integrals {
            separation: h,
            scale_exponent,
            load_elastic: 0.0,
            load_plastic: 0.0,
            dload_dh_elastic: 0.0,
            dload_dh_plastic: 0.0,
            d2load_dh2: 0.0,
            area: tail1_given(h, t0_h),
            plastic_area: 0.0,
            contacts: t0_h,
            plastic_contacts: 0.0,
            load_noncontact: 0.0,
            dload_dh_noncontact: 0.0,
            d2load_dh2_noncontact: 0.0,
            noncontact_exponent: 0.0,
            noncontact_gap: None,
            capillary: CapillaryShare::ZERO,
        };
        // The plastic junctions beyond u_c = h + Δc (0 beyond the weight's range
        // or without plasticity).
        let plastic = Plastic::at(c, h, dc);
        let (t0, g, ug) = (plastic.contacts, plastic.gauss, plastic.u_gauss);
        out.plastic_contacts = plastic.contacts;
        out.plastic_area = plastic.area;
        out.load_plastic = plastic.load;
        out.dload_dh_plastic = plastic.dload;
        out.d2load_dh2 = plastic.d2load;
        let (mut load, mut dload, mut d2load) = self.elastic(h, dc);
        let offset = self.elastic_offset;
        if offset != 0.0 {
            // DMT: the constant -c_0 of the elastic asperity load in closed form,
            // -c_0 ∫_0^{Δc} {1, -u, u² - 1} φ̄ dΔ = -c_0 {T_0(h) - T_0(u_c),
            // φ̄(u_c) - φ̄(h), h φ̄(h) - u_c φ̄(u_c)}: exact, where the quadrature of
            // c_0 u φ̄ across the weight's peak cancels (by e^{h²/2} at h < 0).
            let gh = gauss_scaled(h);
            load -= offset * (out.contacts - t0);
            dload -= offset * (g - gh);
            d2load -= offset * (h * gh - ug);
        }
        out.d2load_dh2 += d2load;
        out.load_elastic = load;
        out.dload_dh_elastic = dload;
        out
    }

    /// The integrals of a law that takes its own (the Lennard-Jones law's
    /// table): the elastic and non-contact shares from the law, the plastic
    /// junctions of each of its curves (own Δc and weight) in closed form, and
    /// §3's area and counts over Δ ≥ 0 (MODEL.md §8).
    fn tabulated_at(&self, table: &dyn Tabulated, h: f64) -> Integrals {
        let t0_h = tail0(h);
        let shares = table.shares(h);
        let mut out = Integrals {
            separation: h,
            scale_exponent: kappa(h),
            load_elastic: shares.elastic[0],
            load_plastic: 0.0,
            dload_dh_elastic: shares.elastic[1],
            dload_dh_plastic: 0.0,
            d2load_dh2: shares.elastic[2],
            area: tail1_given(h, t0_h),
            plastic_area: 0.0,
            contacts: t0_h,
            plastic_contacts: 0.0,
            load_noncontact: shares.noncontact[0],
            dload_dh_noncontact: shares.noncontact[1],
            d2load_dh2_noncontact: shares.noncontact[2],
            noncontact_exponent: shares.noncontact_exponent,
            noncontact_gap: None,
            capillary: CapillaryShare::ZERO,
        };
        // The load of each curve's plastic junctions beyond its own Δc, where its
        // elastic share ends (so the two meet as the integrals interpolate);
        // the count and area at the interpolated Δc (the transition's), which
        // keeps them ≥ 0 where the Lagrange weights are not.
        let mut shares = [0.0; 3];
        let (mut lowest, mut highest) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        table.plastic_junctions(&mut |dc, weight| {
            let p = Plastic::at(&self.coefficients, h, dc);
            shares[0] += weight * p.load;
            shares[1] += weight * p.dload;
            shares[2] += weight * p.d2load;
            if p.load < lowest[0] {
                lowest = [p.load, p.dload, p.d2load];
            }
            if p.load > highest[0] {
                highest = [p.load, p.dload, p.d2load];
            }
        });
        // Where the junctions lie far out in the weight's tail, or where the
        // weight's peak sits among the curves' Δc, their shares change by
        // orders of magnitude from one curve's Δc to the next, and the
        // Lagrange weights (some < 0) can carry the sum outside the curves'
        // own range — even to the wrong sign. It is held to that range (the
        // nearest curve's share and slopes beyond it): continuous in h, where
        // switching to another rule at a sign was not (a humid scene at h = −17
        // jumped by 1 % of its load there and its separation stopped on the
        // jump, the million-case run found).
        if shares[0] < lowest[0] {
            shares = lowest;
        } else if shares[0] > highest[0] {
            shares = highest;
        }
        let plastic = Plastic::at(&self.coefficients, h, self.transition.critical_interference);
        out.load_plastic = shares[0];
        out.dload_dh_plastic = shares[1];
        out.d2load_dh2 += shares[2];
        out.plastic_contacts = plastic.contacts.min(out.contacts);
        out.plastic_area = plastic.area.min(out.area);
        out
    }

    /// The elastic integral and its first two h-derivatives, scaled by e^{κ(h)}.
    fn elastic(&self, h: f64, dc: f64) -> (f64, f64, f64) {
        let mut bounds = [0.0f64; Quadrature::MAX_PANELS + 1];
        let mut n = self.elastic_breakpoints(h, dc, &mut bounds);
        if n < 2 {
            return (0.0, 0.0, 0.0);
        }
        if self.elastic_offset != 0.0 {
            // DMT with adhesion (c_a = c_d = 0): the Hertz part in Δ^{1/2}; its
            // constant -c_0 is added in closed form by the caller.
            return hertz(&self.quadrature, h, dc, &bounds[..n]);
        }
        // A panel near Δ = 0 that reaches far beyond Δ0 = c_d^{4/3}, where Δ(s) is
        // already quartic, carries a weight like e^{-q x⁸} in s: split it at half
        // its length in s (Δ/16), where the exponent is q/256, so both halves are
        // smooth. Every such panel is split once: the one from 0 and, when a tiny
        // peak -h sits just right of 0, the long one after it.
        let delta0 = self.c_d_cubed.powf(4.0 / 9.0);
        let mut k = n - 1;
        while k > 0 && n < bounds.len() {
            k -= 1;
            if 16.0 * bounds[k] < bounds[k + 1] && delta0 < bounds[k + 1] {
                bounds.copy_within(k + 1..n, k + 2);
                bounds[k + 1] = bounds[k + 2] / 16.0;
                n += 1;
            }
        }
        let c_a = self.contact.c_a;
        // The log-weight's minimum over [0, Δc]: panels are graded from it.
        let peak = (-h).max(0.0).min(dc);
        let level_of = |a: f64, b: f64| contact_level(h, peak, a, b);
        let s0 = self.s_touch;
        let s0_3 = self.c_d_cubed;
        let mut load = 0.0;
        let mut dload = 0.0;
        let mut d2load = 0.0;
        // For h ≤ 0, u = h + Δ(v) is formed as (h + Δ(v_ref)) + (Δ(v) - Δ(v_ref))
        // around one reference at the weight's peak, the difference by the exact
        // factorisation (v - v_ref)·Q(v, v_ref), with nodes placed by their offset
        // from v_ref: far left (h ≈ -3e7) the direct sum carries ε|h| of rounding
        // into each node's weight (8e-9 in the load); a common offset error is
        // only a shift of h.
        let v_ref = self.v_of_interference(peak);
        let u_ref = h + self.interference_of_v(v_ref);
        let mut v_lo = self.v_of_interference(bounds[0]);
        let mut d_lo = bounds[0];
        for &bound in &bounds[1..n] {
            let rule = gauss::rule(self.quadrature.panel_order(level_of(d_lo, bound)));
            d_lo = bound;
            let v_hi = self.v_of_interference(bound);
            // The panel in offsets from v_ref (exact subtractions near v_ref), so
            // adjacent panels meet exactly in the coordinate the nodes use.
            let (dv_lo, dv_hi) = (v_lo - v_ref, v_hi - v_ref);
            let to_mid = 0.5 * (dv_lo + dv_hi);
            let half = 0.5 * (dv_hi - dv_lo);
            let (mut pl, mut pd, mut pdd) = (0.0, 0.0, 0.0);
            for (x, w) in rule.nodes.iter().zip(&rule.weights) {
                let dv = to_mid + half * x;
                let v = v_ref + dv;
                let s = s0 + v;
                let s3 = s * s * s;
                // dΔ/ds = 4s³ - c_d = 3 s0³ + 12 s0² v + 12 s0 v² + 4 v³.
                let jac = 3.0 * s0_3 + v * (12.0 * s0 * s0 + v * (12.0 * s0 + 4.0 * v));
                let (u, exponent) = if h > 0.0 {
                    let delta = self.interference_of_v(v);
                    (h + delta, -delta * (h + 0.5 * delta))
                } else {
                    let r = v_ref;
                    let q = 3.0 * s0_3
                        + 6.0 * s0 * s0 * (v + r)
                        + 4.0 * s0 * (v * v + v * r + r * r)
                        + (v + r) * (v * v + r * r);
                    let u = u_ref + dv * q;
                    (u, -0.5 * u * u)
                };
                // p_e dΔ = (s⁶ - c_a s³)(4s³ - c_d) ds.
                let pe = s3 * (s3 - c_a);
                let f = pe * jac * w * exponent.exp();
                pl += f;
                pd -= f * u;
                pdd += f * (u * u - 1.0);
            }
            load += pl * half;
            dload += pd * half;
            d2load += pdd * half;
            v_lo = v_hi;
        }
        (load, dload, d2load)
    }

    /// Breakpoints (ascending, in Δ) of the panels of the elastic integral over
    /// [0, Δc] ∩ {weight within e^{-cut} of its maximum there}. Returns their count.
    fn elastic_breakpoints(&self, h: f64, dc: f64, out: &mut [f64]) -> usize {
        if dc <= 0.0 {
            return 0;
        }
        let q = &self.quadrature;
        let walk = |at_level: &dyn Fn(f64) -> f64,
                    beyond: &dyn Fn(f64) -> bool,
                    limit: f64,
                    out: &mut [f64]| {
            walk_levels(
                q.log_weight_step,
                q.log_weight_cut,
                at_level,
                beyond,
                limit,
                out,
            )
        };
        if h >= 0.0 {
            // q(Δ) = Δ(h + Δ/2), rising from 0 at Δ = 0.
            out[0] = 0.0;
            1 + walk(
                &|level| 2.0 * level / (h + (h * h + 2.0 * level).sqrt()),
                &|d| d >= dc,
                dc,
                &mut out[1..],
            )
        } else if h + dc >= 0.0 {
            // The peak Δ = -h lies inside [0, Δc]: panels on both sides.
            let peak = -h;
            let nl = walk(
                &|level| peak - (2.0 * level).sqrt(),
                &|d| d <= 0.0,
                0.0,
                out,
            );
            out[..nl].reverse();
            let mut n = nl;
            if n == 0 || out[n - 1] != peak {
                out[n] = peak;
                n += 1;
            }
            n + walk(
                &|level| peak + (2.0 * level).sqrt(),
                &|d| d >= dc,
                dc,
                &mut out[n..],
            )
        } else {
            // u_c < 0: the weight rises towards Δc; panels leftwards from Δc.
            let u_c = h + dc;
            out[0] = dc;
            let n = 1 + walk(
                &|level| -(u_c * u_c + 2.0 * level).sqrt() - h,
                &|d| d <= 0.0,
                0.0,
                &mut out[1..],
            );
            out[..n].reverse();
            n
        }
    }
}

/// Writes the Δ at which the log-weight has risen by `step`, 2·`step`, … (up to
/// `cut`) above its value where the walk starts — `at_level(level)` gives that Δ —
/// stopping with `limit` once a point lies `beyond` it. Returns the count.
fn walk_levels(
    step: f64,
    cut: f64,
    at_level: &dyn Fn(f64) -> f64,
    beyond: &dyn Fn(f64) -> bool,
    limit: f64,
    out: &mut [f64],
) -> usize {
    let mut n = 0;
    let mut level = 0.0;
    loop {
        level = f64::min(level + step, cut);
        let d = at_level(level);
        if beyond(d) {
            out[n] = limit;
            return n + 1;
        }
        out[n] = d;
        n += 1;
        if level >= cut {
            return n;
        }
        if n == out.len() {
            // Only settings that fail `Quadrature::check` (a step of 0, a NaN
            // cut) get here: end at the limit rather than overrun the buffer.
            out[n - 1] = limit;
            return n;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::special::SQRT_TWO_PI;

    /// Greenwood–Williamson: F_{3/2}(0) = 2^{1/4} Γ(5/4) / √(2π), Γ(5/4) = 0.906402477055477…
    #[test]
    fn greenwood_williamson_at_zero() {
        let m = Model::new(Coefficients::new(0.0, f64::INFINITY));
        let f32_0 = 2f64.powf(0.25) * 0.906_402_477_055_477_f64 / SQRT_TWO_PI;
        let got = m.at(0.0).load().value();
        let err = got / (SQRT_TWO_PI * f32_0) - 1.0;
        assert!(err.abs() < 1e-14, "{got}: {err:e}");
    }

    #[test]
    fn breakpoints_cover_the_window_in_order() {
        let m = Model::new(Coefficients::from_indices(0.1, 1e-3));
        for &h in &[-60.0, -27.0, -4.0, -0.5, 0.0, 0.5, 3.0, 60.0] {
            let mut b = [0.0; Quadrature::MAX_PANELS + 1];
            let n = m.elastic_breakpoints(h, m.critical_interference(), &mut b);
            assert!(n >= 2, "h={h}");
            for k in 1..n {
                assert!(b[k] > b[k - 1], "h={h}: {:?}", &b[..n]);
            }
            assert!(b[0] >= 0.0 && b[n - 1] <= m.critical_interference());
        }
    }

    /// The DMT Hertz quadrature (`dmt::hertz`) on the production layout against a
    /// fine one (order 32, log-weight step 1.5: 8× the panels, each of higher
    /// order) over θ ∈ [1e-3, 1e8], λ ∈ [1e-6, 1e6] and ∞, h ∈ [-4, 16] in steps of
    /// 1/8 and far out to -3e7 and 60: H, H', H'' relative to |H|, |H|(1 + |h|),
    /// |H|(1 + h²), the sizes of the terms they integrate. Measured 9.5e-16; a single
    /// panel from t = 0 across a log-weight step of 12 (no split) errs by 1.1e-12.
    #[test]
    fn hertz_matches_fine_layout() {
        let fine = Quadrature::new(32, 1.5, 46.0).unwrap();
        let mut worst = (0.0f64, String::new());
        let mut hs: Vec<f64> = (0..=160).map(|k| -4.0 + 0.125 * k as f64).collect();
        hs.extend([-6.0, -10.0, -30.0, -100.0, -1e3, -1e4, -3e7, 30.0, 60.0]);
        for theta in [1e-3, 1e-1, 10.0, 184.0, 1e4, 1e8] {
            for lambda in [1e-6, 1e-3, 1.0, 1e3, 1e6, f64::INFINITY] {
                let c = if lambda.is_infinite() {
                    let mut c = Coefficients::new(
                        (6.0 * std::f64::consts::PI / theta).sqrt(),
                        f64::INFINITY,
                    );
                    c.c_0 = 2.0 * std::f64::consts::PI / theta;
                    c
                } else {
                    Coefficients::from_indices(theta, lambda)
                };
                let law = AsperityLaw::Dmt(Attraction::VanDerWaals { range: 0.1 });
                let m = Model::with_law(c, law, Quadrature::default());
                let dc = m.critical_interference();
                for &h in &hs {
                    let mut b = [0.0; Quadrature::MAX_PANELS + 1];
                    let n = m.elastic_breakpoints(h, dc, &mut b);
                    let got = hertz(&m.quadrature, h, dc, &b[..n]);
                    let mf = Model::with_law(c, law, fine);
                    let nf = mf.elastic_breakpoints(h, dc, &mut b);
                    let want = hertz(&fine, h, dc, &b[..nf]);
                    let size = want.0.abs();
                    if size < 1e-280 {
                        // Underflow: both layouts agree that nothing is there.
                        let tiny = got.0.abs().max(got.1.abs()).max(got.2.abs());
                        assert!(tiny < 1e-280, "θ={theta} λ={lambda} h={h}: {got:?}");
                        continue;
                    }
                    for (what, g, w, s) in [
                        ("H", got.0, want.0, size),
                        ("H'", got.1, want.1, size * (1.0 + h.abs())),
                        ("H''", got.2, want.2, size * (1.0 + h * h)),
                    ] {
                        // The rounding of the log-weight at the window's peak,
                        // ε u_p²/2 (u_p = h + min(-h, Δc) < 0: no scale), is
                        // common to every layout and not the quadrature's.
                        let u_p = h + (-h).max(0.0).min(dc);
                        let e = (g - w).abs() / s / (1.0 + u_p * u_p);
                        if e > worst.0 {
                            worst = (e, format!("{what} θ={theta} λ={lambda} h={h}: {g} vs {w}"));
                        }
                    }
                }
            }
        }
        eprintln!("worst {:e}: {}", worst.0, worst.1);
        assert!(worst.0 < 4e-15, "worst {:e}: {}", worst.0, worst.1);
    }
}
