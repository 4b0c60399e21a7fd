//! A small deterministic generator for resampling and Monte Carlo: values are
//! hashes of (seed, stream, index), so any draw is computable from its index.

use crate::sweep::sequence::splitmix;

/// A hash of (seed, stream, index): draw `index` of the SplitMix64 sequence
/// whose state starts at a key drawn from (seed, stream), mixed once more (a
/// counter keyed by XOR, `mix(key ^ index)`, feeds the mixer inputs that differ
/// in their low bits only).
pub(crate) fn hash(seed: u64, stream: u64, index: u64) -> u64 {
    let key = splitmix(splitmix(seed) ^ stream.wrapping_mul(0xD6E8_FEB8_6659_FD93));
    splitmix(splitmix(
        key.wrapping_add(index.wrapping_mul(0x9E37_79B9_7F4A_7C15)),
    ))
}

/// A uniform double in the open interval (0, 1) from 53 bits of a hash.
pub(crate) fn open_unit(bits: u64) -> f64 {
    ((bits >> 11) as f64 + 0.5) / (1u64 << 53) as f64
}

/// An index uniform in `0..n` (`n ≥ 1`) from a hash (Lemire's multiply-shift).
pub(crate) fn below(bits: u64, n: usize) -> usize {
    ((bits as u128 * n as u128) >> 64) as usize
}

/// A sequential generator (splitmix64 stream) for loops that draw in order.
#[derive(Debug, Clone)]
pub(crate) struct Rng {
    state: u64,
}

impl Rng {
    /// The stream `stream` of `seed`.
    pub(crate) fn new(seed: u64, stream: u64) -> Self {
        Rng {
            state: hash(seed, stream, 0x5EED),
        }
    }

    /// The next 64 random bits.
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// An index uniform in `0..n`.
    pub(crate) fn below(&mut self, n: usize) -> usize {
        below(self.next_u64(), n)
    }
}
