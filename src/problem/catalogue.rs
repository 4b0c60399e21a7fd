//! A small catalogue of MEMS materials: typical room-temperature properties.
//!
//! These are handbook and review values, chosen near the middle of the published range
//! for thin films as used in MEMS. Real films vary with deposition, anneal, grain size,
//! orientation and test method, often by ±20 % in modulus and more in hardness; the
//! work of adhesion varies by orders of magnitude with surface chemistry, humidity and
//! coatings. Each entry's comment says where the number comes from and how wide the
//! spread is. A problem file can override any value, and should when measurements exist.
//!
//! The work of adhesion is given as a *typical range* for like-on-like contacts in
//! laboratory air: the catalogue never supplies γ to a scene (the file must state it);
//! the range is there to judge whether a stated γ is plausible and to bound a design
//! sweep.

pub use crate::model::Material;

const GPA: f64 = 1e9;

static MATERIALS: [Material; 10] = [
    // Polysilicon (LPCVD, as in SUMMiT/MUMPs). Sharpe et al., "Measurements of Young's
    // modulus, Poisson's ratio and tensile strength of polysilicon", IEEE MEMS 1997:
    // E ≈ 160-170 GPa, ν ≈ 0.22. Nanoindentation hardness of polysilicon films is about
    // 9-12 GPa. γ: hydrophilic (native-oxide) surfaces in air ≈ 0.1 J/m²; hydrophobic
    // SAM-coated (OTS, FDTS) surfaces are 1-2 orders lower; cantilever-beam adhesion
    // energies reviewed by Maboudian & Howe (J. Vac. Sci. Technol. B 15, 1997).
    Material {
        name: "polysilicon",
        aliases: &["poly-si", "polycrystalline silicon", "poly silicon"],
        youngs_modulus: 160.0 * GPA,
        poisson_ratio: 0.22,
        hardness: 10.0 * GPA,
        work_of_adhesion: (0.02, 0.1),
        source: "Sharpe et al. 1997 (E, nu); nanoindentation of films (H 9-12 GPa); \
                 Maboudian & Howe 1997 (gamma)",
    },
    // Single-crystal silicon. Petersen, "Silicon as a mechanical material", Proc. IEEE
    // 70 (1982): E from 130 GPa <100> to 188 GPa <111>, taken 165 GPa (between <100> and
    // <110>, 169 GPa); ν from 0.06 to 0.28 with direction, taken 0.22; Knoop hardness
    // 850 kg/mm² ≈ 8.5 GPa there, nanoindentation gives 10-13 GPa: taken 11 GPa.
    // γ as polysilicon (native oxide).
    Material {
        name: "single-crystal silicon",
        aliases: &["silicon", "si", "monocrystalline silicon", "c-si"],
        youngs_modulus: 165.0 * GPA,
        poisson_ratio: 0.22,
        hardness: 11.0 * GPA,
        work_of_adhesion: (0.02, 0.1),
        source: "Petersen 1982, Proc. IEEE 70 (E 130-188 GPa with direction); \
                 nanoindentation (H 10-13 GPa)",
    },
    // Silicon nitride, LPCVD films. Film values are lower than bulk Si3N4 (Petersen 1982
    // lists E ≈ 385 GPa, Knoop ≈ 34 GPa for bulk): nanoindentation of LPCVD films gives
    // E ≈ 200-300 GPa and H ≈ 15-22 GPa; ν ≈ 0.23-0.27. γ: hydrophilic surface in air,
    // similar to oxide, 0.02-0.1 J/m².
    Material {
        name: "silicon nitride",
        aliases: &["si3n4", "sin", "nitride", "lpcvd nitride"],
        youngs_modulus: 250.0 * GPA,
        poisson_ratio: 0.23,
        hardness: 18.0 * GPA,
        work_of_adhesion: (0.02, 0.1),
        source: "LPCVD film nanoindentation (E 200-300 GPa, H 15-22 GPa); \
                 bulk values in Petersen 1982 are higher",
    },
    // Silicon dioxide (thermal oxide / fused silica). Oliver & Pharr, J. Mater. Res. 7
    // (1992) use fused silica as the nanoindentation reference: E = 72 GPa, ν = 0.17,
    // H ≈ 9 GPa. γ: hydrophilic silica in humid air ≈ 0.1-0.15 J/m² (capillary-dominated,
    // ≈ 2γ_water); dry or silane-treated much less.
    Material {
        name: "silicon dioxide",
        aliases: &["sio2", "silica", "oxide", "fused silica", "thermal oxide"],
        youngs_modulus: 72.0 * GPA,
        poisson_ratio: 0.17,
        hardness: 9.0 * GPA,
        work_of_adhesion: (0.02, 0.15),
        source: "Oliver & Pharr 1992, J. Mater. Res. 7 (fused silica: E 72 GPa, nu 0.17, H ~9 GPa)",
    },
    // Diamond-like carbon (a-C:H and ta-C coatings). Robertson, "Diamond-like amorphous
    // carbon", Mater. Sci. Eng. R 37 (2002): E ≈ 100-300 GPa and H ≈ 10-30 GPa for a-C:H,
    // up to E ≈ 750 GPa, H ≈ 80 GPa for ta-C. Mid a-C:H values taken: E 200 GPa, H 20 GPa;
    // ν is rarely measured, 0.2 is the usual assumption. γ: DLC surface energies are
    // ≈ 30-50 mJ/m², so like-on-like γ ≈ 2γ_s ≲ 0.1 J/m²; low end for hydrogen- or
    // fluorine-rich films.
    Material {
        name: "DLC",
        aliases: &["diamond-like carbon", "a-c:h"],
        youngs_modulus: 200.0 * GPA,
        poisson_ratio: 0.2,
        hardness: 20.0 * GPA,
        work_of_adhesion: (0.02, 0.1),
        source: "Robertson 2002, Mater. Sci. Eng. R 37 (a-C:H: E 100-300 GPa, H 10-30 GPa)",
    },
    // Gold (sputtered or evaporated films, RF-MEMS switch contacts). Bulk E ≈ 79 GPa,
    // ν ≈ 0.42 (standard handbook values, e.g. CRC Handbook); film hardness ≈ 1-2 GPa by
    // nanoindentation (bulk annealed gold is much softer, ≈ 0.3 GPa), taken 1 GPa. γ: clean
    // Au-Au ≈ 1 J/m² or more (surface energy ≈ 1.5 J/m²); adsorbed contamination in air
    // brings the effective value down to a few tenths.
    Material {
        name: "gold",
        aliases: &["au"],
        youngs_modulus: 79.0 * GPA,
        poisson_ratio: 0.42,
        hardness: 1.0 * GPA,
        work_of_adhesion: (0.2, 1.5),
        source: "handbook bulk E 79 GPa, nu 0.42 (CRC); film nanoindentation H 1-2 GPa",
    },
    // Nickel (electroplated / LIGA). Bulk E ≈ 200 GPa, ν ≈ 0.31 (handbook); electroplated
    // MEMS nickel measures E ≈ 160-210 GPa and, being fine-grained, is much harder than
    // annealed bulk nickel (≈ 1 GPa): H ≈ 3-6 GPa, taken 4 GPa (see Hemker & Sharpe,
    // "Microscale characterization of mechanical properties", Annu. Rev. Mater. Res. 37,
    // 2007). γ: oxidised in air, 0.1-1 J/m²; clean metal more.
    Material {
        name: "nickel",
        aliases: &["ni", "electroplated nickel"],
        youngs_modulus: 200.0 * GPA,
        poisson_ratio: 0.31,
        hardness: 4.0 * GPA,
        work_of_adhesion: (0.1, 1.0),
        source: "handbook E 200 GPa, nu 0.31; electroplated films H 3-6 GPa (Hemker & Sharpe 2007)",
    },
    // Steel, hardened bearing steel (AISI 52100, as the steel ball of docs/model.md §5).
    // E ≈ 210 GPa, ν ≈ 0.30 (handbook); HRC 60-64 ≈ 7-8 GPa Vickers, taken 8 GPa
    // (Petersen 1982 lists a Knoop 1500 kg/mm² ≈ 15 GPa for the hardest tool steel).
    // γ: oxidised, contaminated surface in air, 0.05-0.5 J/m².
    Material {
        name: "steel",
        aliases: &["bearing steel", "52100", "aisi 52100"],
        youngs_modulus: 210.0 * GPA,
        poisson_ratio: 0.3,
        hardness: 8.0 * GPA,
        work_of_adhesion: (0.05, 0.5),
        source: "handbook AISI 52100: E 210 GPa, nu 0.30, HV ~750 (H ~7-8 GPa)",
    },
    // Silicon carbide (CVD 3C-SiC films). Petersen 1982 lists E ≈ 700 GPa and Knoop
    // 2480 kg/mm² ≈ 24 GPa for single-crystal SiC; polycrystalline CVD films measure
    // E ≈ 400-450 GPa and H ≈ 25-35 GPa; ν ≈ 0.17-0.21. Taken E 430 GPa, ν 0.19, H 28 GPa.
    // γ: native oxide, hydrophilic, 0.02-0.1 J/m².
    Material {
        name: "silicon carbide",
        aliases: &["sic", "3c-sic"],
        youngs_modulus: 430.0 * GPA,
        poisson_ratio: 0.19,
        hardness: 28.0 * GPA,
        work_of_adhesion: (0.02, 0.1),
        source: "CVD film nanoindentation (E 400-450 GPa, H 25-35 GPa); Petersen 1982 (bulk)",
    },
    // Diamond (single crystal; (ultra)nanocrystalline films are softer: E ≈ 900-1000 GPa).
    // Petersen 1982 lists E ≈ 1035 GPa and Knoop 7000 kg/mm² ≈ 69 GPa; accepted single-
    // crystal values are E ≈ 1050-1140 GPa, ν ≈ 0.07, H ≈ 70-100 GPa. Taken E 1050 GPa,
    // H 80 GPa. γ: hydrogen-terminated diamond is inert, 0.01-0.1 J/m².
    Material {
        name: "diamond",
        aliases: &["single-crystal diamond"],
        youngs_modulus: 1050.0 * GPA,
        poisson_ratio: 0.07,
        hardness: 80.0 * GPA,
        work_of_adhesion: (0.01, 0.1),
        source: "Petersen 1982 (E ~1035 GPa, Knoop ~69 GPa); single-crystal E 1050-1140 GPa",
    },
];

/// The crystalline materials whose atomic scale the catalogue gives
/// ([`atomic_scale`]): the stress-assisted wear law's defaults (docs/model.md §12).
pub const ATOMIC_SCALE_MATERIALS: [&str; 6] = [
    "polysilicon",
    "single-crystal silicon",
    "diamond",
    "silicon carbide",
    "gold",
    "nickel",
];

/// (a₀, Ω) of a catalogue material (m, m³): the spacing of surface sites and the
/// volume of one atom, from the lattice constant a of the crystal at room
/// temperature. Diamond-cubic (Si, C) and zinc-blende (3C-SiC) crystals have 8 atoms
/// per cube, a₀ = a/√2 (the (110) row spacing), Ω = a³/8: silicon a = 0.5431 nm
/// gives a₀ = 0.384 nm and Ω = 0.02002 nm³ (the values of Jacobs & Carpick 2013),
/// diamond a = 0.3567 nm, 3C-SiC a = 0.4360 nm. Face-centred cubic metals have 4
/// atoms per cube, a₀ = a/√2 (nearest neighbours), Ω = a³/4: gold a = 0.4078 nm,
/// nickel a = 0.3524 nm (Kittel, Introduction to Solid State Physics, table 1.3).
/// Amorphous or compound films (oxide, nitride, DLC, steel) have none: a file gives
/// them. None for those and for names outside the catalogue.
pub fn atomic_scale(name: &str) -> Option<(f64, f64)> {
    let (lattice, atoms) = match name {
        "polysilicon" | "single-crystal silicon" => (0.5431e-9, 8.0),
        "diamond" => (0.3567e-9, 8.0),
        "silicon carbide" => (0.4360e-9, 8.0),
        "gold" => (0.4078e-9, 4.0),
        "nickel" => (0.3524e-9, 4.0),
        _ => return None,
    };
    let a: f64 = lattice;
    Some((a / std::f64::consts::SQRT_2, a * a * a / atoms))
}

/// Every catalogue material.
pub fn all() -> &'static [Material] {
    &MATERIALS
}

/// The canonical names, in catalogue order.
pub fn names() -> Vec<&'static str> {
    MATERIALS.iter().map(|m| m.name).collect()
}

/// Normalised form of a name for matching: lower case, `_`/`-` and runs of whitespace
/// read as one space.
fn normalize(name: &str) -> String {
    name.to_lowercase()
        .replace(['_', '-'], " ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// Finds a material by name or alias, ignoring case, hyphens and underscores.
pub fn lookup(name: &str) -> Option<&'static Material> {
    let wanted = normalize(name);
    MATERIALS
        .iter()
        .find(|m| normalize(m.name) == wanted || m.aliases.iter().any(|a| normalize(a) == wanted))
}

/// The catalogue name nearest to `name` (by edit distance over names and aliases), if
/// any is close enough to be a plausible typo.
pub fn suggest(name: &str) -> Option<&'static str> {
    let wanted = normalize(name);
    let mut best: Option<(usize, &'static str)> = None;
    for m in &MATERIALS {
        for candidate in std::iter::once(&m.name).chain(m.aliases.iter()) {
            let d = super::error::edit_distance(&wanted, &normalize(candidate));
            if best.is_none_or(|(bd, _)| d < bd) {
                best = Some((d, m.name));
            }
        }
    }
    best.filter(|&(d, _)| super::error::close_enough(d, wanted.chars().count()))
        .map(|(_, n)| n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lookup_is_case_and_punctuation_insensitive() {
        assert_eq!(lookup("Polysilicon").unwrap().name, "polysilicon");
        assert_eq!(lookup("silicon").unwrap().name, "single-crystal silicon");
        assert_eq!(
            lookup("Single_Crystal  Silicon").unwrap().name,
            "single-crystal silicon"
        );
        assert_eq!(lookup("dlc").unwrap().name, "DLC");
        assert_eq!(lookup("SiO2").unwrap().name, "silicon dioxide");
        assert_eq!(lookup("Au").unwrap().name, "gold");
        assert!(lookup("unobtainium").is_none());
    }

    #[test]
    fn required_materials_are_present_and_sane() {
        for name in [
            "polysilicon",
            "single-crystal silicon",
            "silicon nitride",
            "silicon dioxide",
            "DLC",
            "gold",
            "nickel",
            "steel",
            "silicon carbide",
            "diamond",
        ] {
            let m = lookup(name).unwrap_or_else(|| panic!("{name} missing"));
            assert!(m.youngs_modulus > 1e10 && m.youngs_modulus < 2e12, "{name}");
            assert!(m.poisson_ratio > 0.0 && m.poisson_ratio <= 0.5, "{name}");
            assert!(m.hardness > 1e8 && m.hardness < 2e11, "{name}");
            assert!(m.hardness < m.youngs_modulus, "{name}");
            let (lo, hi) = m.work_of_adhesion;
            assert!(lo > 0.0 && lo < hi && hi < 5.0, "{name}");
            assert!(!m.source.is_empty());
        }
    }

    #[test]
    fn names_and_aliases_are_unique() {
        let mut seen = std::collections::HashSet::new();
        for m in all() {
            for n in std::iter::once(&m.name).chain(m.aliases.iter()) {
                assert!(seen.insert(normalize(n)), "duplicate name {n}");
            }
        }
    }

    #[test]
    fn suggestions() {
        assert_eq!(suggest("polysilcon"), Some("polysilicon"));
        assert_eq!(suggest("gol"), Some("gold"));
        assert_eq!(suggest("silicon nitrde"), Some("silicon nitride"));
        assert_eq!(suggest("xyzzy"), None);
    }
}
