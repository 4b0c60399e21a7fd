//! Accuracy settings of the elastic quadrature ([`Quadrature`]) and the panel level
//! both contact quadratures (JKR in `integrals.rs`, DMT's Hertz part in `dmt.rs`)
//! share: the floor beneath both, so that neither imports the other's settings.

use super::gauss;

/// Accuracy settings of the elastic quadrature (the only non-closed-form part).
///
/// Build them with [`Quadrature::new`] (or take the default): settings that
/// fail [`Quadrature::check`] never make the model panic, but its numbers then
/// mean nothing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quadrature {
    /// Gauss–Legendre points per panel; one of [`gauss::ORDERS`].
    pub order: usize,
    /// Largest change of the log-weight `(h+Δ)²/2` across one panel.
    pub log_weight_step: f64,
    /// The integral is cut where the weight has fallen by `e^{-log_weight_cut}`
    /// below its largest value on the interval.
    pub log_weight_cut: f64,
}

impl Default for Quadrature {
    /// 20 points per panel (graded down on far panels), panels of log-weight
    /// change ≤ 12, cut at e^{-46}. `wearopt accuracy` measured it against an
    /// independent adaptive Gauss–Kronrod reference over 1123 points of θ ∈
    /// [1e-3, 1e8], λ ∈ [1e-6, 1e6], h ∈ [-4, 60] and the limits: worst 2.8e-14
    /// relative to |elastic| + |plastic|, as accurate as step 6 and 1.7× faster.
    fn default() -> Self {
        Quadrature {
            order: 20,
            log_weight_step: 12.0,
            log_weight_cut: 46.0,
        }
    }
}

impl Quadrature {
    /// Panel breakpoints never exceed this many.
    pub const MAX_PANELS: usize = 64;

    /// The Gauss–Legendre order for a panel whose weight is at most
    /// `e^{-level}` of the largest weight on the interval: such a panel needs only
    /// ≈ 1e-16·e^{level}/1e4 relative accuracy (the 1e4 covers the growth of
    /// p_e), so the order steps down every 6 units of level, never above
    /// [`Quadrature::order`].
    pub fn panel_order(&self, level: f64) -> usize {
        const SCHEDULE: [(f64, usize); 5] =
            [(10.0, 20), (16.0, 16), (22.0, 12), (28.0, 8), (34.0, 6)];
        let wanted = SCHEDULE
            .iter()
            .find(|(below, _)| level < *below - 1e-9)
            .map_or(4, |&(_, n)| n);
        // The largest supported order not above the settings' (4 at least), so
        // that settings built without `check` never ask for a missing rule.
        let cap = wanted.min(self.order);
        gauss::ORDERS
            .iter()
            .rev()
            .copied()
            .find(|&n| n <= cap)
            .unwrap_or(gauss::ORDERS[0])
    }

    /// Settings from their three values, checked as [`Quadrature::check`] does.
    pub fn new(
        order: usize,
        log_weight_step: f64,
        log_weight_cut: f64,
    ) -> Result<Self, super::scene::InputError> {
        let q = Quadrature {
            order,
            log_weight_step,
            log_weight_cut,
        };
        q.check()?;
        Ok(q)
    }

    /// Checks the settings: `order` one of [`gauss::ORDERS`], `log_weight_cut`
    /// in [10, 200], and `log_weight_step` giving 1 to 31 panels per side
    /// (`log_weight_cut / log_weight_step` in [1, 31]: at most
    /// [`Quadrature::MAX_PANELS`] breakpoints).
    pub fn check(&self) -> Result<(), super::scene::InputError> {
        use super::scene::check;
        check(
            "order",
            self.order as f64,
            gauss::ORDERS.contains(&self.order),
            "one of 4, 6, 8, 12, 16, 20, 24, 32",
        )?;
        let cut = self.log_weight_cut;
        check(
            "log_weight_cut",
            cut,
            (10.0..=200.0).contains(&cut),
            "in [10, 200]",
        )?;
        let panels = cut / self.log_weight_step;
        check(
            "log_weight_step",
            self.log_weight_step,
            panels.is_finite() && panels >= 1.0 && panels * 2.0 + 2.0 <= Self::MAX_PANELS as f64,
            "such that log_weight_cut / log_weight_step lies in [1, 31]",
        )
    }

    /// Checks the settings; returns a message naming the bad field
    /// ([`Quadrature::check`] in words).
    pub fn validate(&self) -> Result<(), String> {
        self.check().map_err(|e| e.to_string())
    }
}

/// The level of the contact panel [a, b] (in Δ) at separation h: how far the
/// log-weight (h + Δ)²/2 at the panel's point nearest its minimum over [0, Δc]
/// (at Δ = `peak` = min(max(-h, 0), Δc)) lies above that minimum; for h ≥ 0,
/// a (h + a/2) without cancellation.
#[inline]
pub(super) fn contact_level(h: f64, peak: f64, a: f64, b: f64) -> f64 {
    if h >= 0.0 {
        a * (h + 0.5 * a)
    } else {
        let x = (-h).max(a).min(b);
        0.5 * ((h + x) * (h + x) - (h + peak) * (h + peak))
    }
}
