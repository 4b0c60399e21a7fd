//! Space-filling designs in the unit cube, each point computable from its index
//! alone (so that a shard, a resumed run or a remote worker needs no state and
//! memory does not grow with the number of samples).
//!
//! * Sobol′ (Gray-code order, Joe & Kuo direction numbers) with a random
//!   digital shift drawn from the seed: a shifted (t, m, s)-net keeps the
//!   stratification of the unshifted one.
//! * Latin hypercube: in each dimension the strata `0..N` are visited in the
//!   order of a seeded pseudo-random permutation (a Feistel network with cycle
//!   walking: a bijection of `0..N` evaluated at one index in O(1) memory), with
//!   a seeded jitter inside the stratum.
//! * Full factorial grid: `m` levels per dimension including both ends, the
//!   last variable varying fastest.

/// The most dimensions a Sobol′ point has here (direction numbers tabulated).
pub const MAX_DIMENSIONS: usize = 10;

/// Joe & Kuo (2008), `new-joe-kuo-6.21201`, dimensions 2 to 10: the degree `s`,
/// the coefficients `a` of the primitive polynomial and the initial direction
/// integers `m_1 … m_s`. Dimension 1 is the van der Corput sequence (all `m = 1`).
const JOE_KUO: [(u32, u32, &[u32]); MAX_DIMENSIONS - 1] = [
    (1, 0, &[1]),
    (2, 1, &[1, 3]),
    (3, 1, &[1, 3, 1]),
    (3, 2, &[1, 1, 1]),
    (4, 1, &[1, 1, 3, 3]),
    (4, 4, &[1, 3, 5, 13]),
    (5, 2, &[1, 1, 5, 5, 17]),
    (5, 4, &[1, 1, 5, 5, 5]),
    (5, 7, &[1, 1, 7, 11, 19]),
];

/// The 32 direction numbers `V_k = m_k 2^{32-k}` of dimension `d` (0-based).
fn direction_numbers(d: usize) -> [u32; 32] {
    let mut v = [0u32; 32];
    if d == 0 {
        for (k, vk) in v.iter_mut().enumerate() {
            *vk = 1u32 << (31 - k);
        }
        return v;
    }
    let (s, a, m) = JOE_KUO[d - 1];
    let s = s as usize;
    for k in 0..s {
        v[k] = m[k] << (31 - k);
    }
    for k in s..32 {
        let mut x = v[k - s] ^ (v[k - s] >> s);
        for j in 1..s {
            if (a >> (s - 1 - j)) & 1 == 1 {
                x ^= v[k - j];
            }
        }
        v[k] = x;
    }
    v
}

/// The unscrambled Sobol′ point `index` (Gray-code order, the order of
/// `scipy.stats.qmc.Sobol(scramble=False)`) as 32-bit integers, one per dimension.
/// `index < 2^32`, `dims ≤ MAX_DIMENSIONS`.
pub fn sobol_bits(index: u64, dims: usize) -> Vec<u32> {
    let gray = index ^ (index >> 1);
    (0..dims.min(MAX_DIMENSIONS))
        .map(|d| {
            let v = direction_numbers(d);
            let mut x = 0u32;
            for (k, vk) in v.iter().enumerate() {
                if (gray >> k) & 1 == 1 {
                    x ^= vk;
                }
            }
            x
        })
        .collect()
}

/// splitmix64 (Steele, Lea & Flood 2014): a well-mixed 64-bit hash.
pub fn splitmix(mut z: u64) -> u64 {
    z = z.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// A hash of (seed, stream, index): independent streams per purpose and dimension.
fn mix(seed: u64, stream: u64, index: u64) -> u64 {
    splitmix(splitmix(splitmix(seed) ^ stream.wrapping_mul(0xD6E8_FEB8_6659_FD93)) ^ index)
}

/// A uniform double in [0, 1) from 53 bits of a hash.
fn unit(bits: u64) -> f64 {
    (bits >> 11) as f64 / (1u64 << 53) as f64
}

/// The digitally shifted Sobol′ point `index` in [0, 1)^dims.
pub fn sobol(index: u64, dims: usize, seed: u64) -> Vec<f64> {
    sobol_bits(index, dims)
        .into_iter()
        .enumerate()
        .map(|(d, x)| {
            let shift = (mix(seed, 1 + d as u64, 0) >> 32) as u32;
            (x ^ shift) as f64 / 4_294_967_296.0
        })
        .collect()
}

/// A seeded bijection of `0..n`, evaluated at `i < n`: a four-round balanced
/// Feistel network on the smallest even bit width covering `n`, cycle-walked
/// back into `0..n` (each walk step stays inside the permutation's cycle, so
/// the restriction is again a bijection).
pub fn permute(i: u64, n: u64, key: u64) -> u64 {
    debug_assert!(i < n);
    if n <= 1 {
        return 0;
    }
    let bits = 64 - (n - 1).leading_zeros();
    let half = bits.div_ceil(2);
    let mask = (1u64 << half) - 1;
    let mut x = i;
    loop {
        let (mut l, mut r) = (x >> half, x & mask);
        for round in 0..4u64 {
            let f = splitmix(key ^ r ^ round.wrapping_mul(0xA24B_AED4_963E_E407)) & mask;
            (l, r) = (r, l ^ f);
        }
        x = (l << half) | r;
        if x < n {
            return x;
        }
    }
}

/// The Latin-hypercube point `index` of `n` in [0, 1)^dims.
pub fn latin_hypercube(index: u64, n: u64, dims: usize, seed: u64) -> Vec<f64> {
    (0..dims)
        .map(|d| {
            let stream = 1000 + d as u64;
            let stratum = permute(index, n, mix(seed, stream, u64::MAX));
            let jitter = unit(mix(seed, stream, index));
            ((stratum as f64 + jitter) / n as f64).min(1.0 - f64::EPSILON / 2.0)
        })
        .collect()
}

/// `m` with `m^dims == n`, if there is one.
pub fn grid_levels(n: u64, dims: usize) -> Option<u64> {
    if dims == 0 {
        return None;
    }
    let guess = (n as f64).powf(1.0 / dims as f64).round() as u64;
    (guess.saturating_sub(1)..=guess + 1)
        .find(|&m| m >= 1 && (m as u128).checked_pow(dims as u32) == Some(n as u128))
}

/// The grid point `index` with `levels` per dimension: level `j` at `j/(levels-1)`
/// (a single level sits at the centre), the last dimension varying fastest.
pub fn grid(index: u64, levels: u64, dims: usize) -> Vec<f64> {
    let mut out = vec![0.0; dims];
    let mut rest = index;
    for slot in out.iter_mut().rev() {
        let j = rest % levels;
        rest /= levels;
        *slot = if levels == 1 {
            0.5
        } else {
            j as f64 / (levels - 1) as f64
        };
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permutation_is_a_bijection() {
        for n in [1u64, 2, 3, 7, 64, 1000, 1025] {
            for key in [0u64, 1, 0xDEAD_BEEF] {
                let mut seen = vec![false; n as usize];
                for i in 0..n {
                    let p = permute(i, n, key);
                    assert!(p < n);
                    assert!(!seen[p as usize], "n {n} key {key}: {p} twice");
                    seen[p as usize] = true;
                }
            }
        }
    }

    #[test]
    fn grid_levels_only_for_exact_powers() {
        assert_eq!(grid_levels(1000, 3), Some(10));
        assert_eq!(grid_levels(999, 3), None);
        assert_eq!(grid_levels(1, 5), Some(1));
        assert_eq!(grid_levels(7, 1), Some(7));
        assert_eq!(grid_levels(1 << 40, 2), Some(1 << 20));
    }

    #[test]
    fn grid_covers_both_ends() {
        assert_eq!(grid(0, 3, 2), vec![0.0, 0.0]);
        assert_eq!(grid(1, 3, 2), vec![0.0, 0.5]);
        assert_eq!(grid(8, 3, 2), vec![1.0, 1.0]);
        assert_eq!(grid(0, 1, 2), vec![0.5, 0.5]);
    }
}

#[cfg(test)]
mod scipy_reference {
    use super::*;

    /// `scipy.stats.qmc.Sobol(d=10, scramble=False, bits=32)` (SciPy 1.17.1), advanced with
    /// `fast_forward(i)` and `random(1)`, times 2^32: an independent implementation with the
    /// same Joe & Kuo direction numbers. Large indices exercise the high direction numbers.
    const TABLE: [(u64, [u32; 10]); 5] = [
        (
            7,
            [
                536870912, 2684354560, 1610612736, 536870912, 536870912, 1610612736, 2684354560,
                2684354560, 2684354560, 3758096384,
            ],
        ),
        (
            1000,
            [
                943718400, 415236096, 2227175424, 2906652672, 1203765248, 3896508416, 197132288,
                3862953984, 2151677952, 297795584,
            ],
        ),
        (
            123457,
            [
                2261286912, 2932375552, 3467149312, 4081549312, 2874114048, 3020455936, 926973952,
                4140597248, 886734848, 3217195008,
            ],
        ),
        (
            1048593,
            [
                2550142976, 2147514368, 1442347008, 4250712064, 1840314368, 2608920576, 3256813568,
                1307809792, 1574639616, 734492672,
            ],
        ),
        (
            4000000000,
            [
                4029081, 1592571143, 3353822765, 712656571, 3960376661, 1314381763, 3643749407,
                1872652665, 1479076361, 3616889337,
            ],
        ),
    ];

    #[test]
    fn sobol_matches_scipy() {
        for (i, want) in TABLE {
            assert_eq!(sobol_bits(i, 10), want.to_vec(), "index {i}");
        }
    }

    #[test]
    fn first_power_of_two_points_stratify_every_axis() {
        // A (t, m, s)-net property that the digital shift keeps: the first 2^k points
        // put exactly one point in each interval [j/2^k, (j+1)/2^k) of every axis.
        for seed in [0u64, 7] {
            let k = 8;
            for d in 0..MAX_DIMENSIONS {
                let mut seen = vec![false; 1 << k];
                for i in 0..(1u64 << k) {
                    let u = sobol(i, MAX_DIMENSIONS, seed)[d];
                    let j = (u * (1 << k) as f64) as usize;
                    assert!(!seen[j], "seed {seed} dim {d}: stratum {j} twice");
                    seen[j] = true;
                }
            }
        }
    }

    #[test]
    fn latin_hypercube_hits_each_stratum_once() {
        for n in [1u64, 5, 100, 257] {
            for d in 0..3 {
                let mut seen = vec![false; n as usize];
                for i in 0..n {
                    let u = latin_hypercube(i, n, 3, 42)[d];
                    assert!((0.0..1.0).contains(&u));
                    let j = (u * n as f64) as usize;
                    assert!(!seen[j]);
                    seen[j] = true;
                }
            }
        }
    }
}
