//! Archard's law (docs/model.md §3, eq. 13): V = k A L, the wearing area A being
//! the real area A_r or the plastic junctions' A_rp, k an input.

use super::{WearInput, WearLaw, WearOutcome};

/// V/L = k A.
pub struct Archard;

impl WearLaw for Archard {
    fn name(&self) -> &'static str {
        "archard"
    }
    fn label(&self) -> &'static str {
        "Archard"
    }
    fn formula(&self) -> &'static str {
        "V = k A L"
    }
    fn section(&self) -> &'static str {
        "docs/model.md §3"
    }
    fn rate(&self, input: &WearInput<'_>) -> WearOutcome {
        // One product, as before the registry: the numbers stay bit for bit.
        WearOutcome {
            rate: input
                .wearing_area
                .scale(input.area_scale * input.scene.wear_coefficient),
            details: None,
        }
    }
}
