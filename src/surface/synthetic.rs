//! Seeded synthetic surfaces: Gaussian random fields with a chosen isotropic power
//! spectrum, by the spectral method (random phases and Gaussian amplitudes on the discrete
//! wavevectors, inverse FFT). For tests, benchmarks and examples; deterministic for a seed.

use rustfft::num_complex::Complex;
use rustfft::FftPlanner;

use super::{HeightMap, SurfaceError};

/// SplitMix64: a small, well-mixed 64-bit generator (Steele, Lea, Flood 2014).
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in (0, 1).
    pub fn uniform(&mut self) -> f64 {
        ((self.next_u64() >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }
    /// Standard normal (Box–Muller).
    pub fn normal(&mut self) -> f64 {
        let (u, v) = (self.uniform(), self.uniform());
        (-2.0 * u.ln()).sqrt() * (2.0 * std::f64::consts::PI * v).cos()
    }
}

/// The spectrum of a synthetic surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Spectrum {
    /// Self-affine: C(q) ∝ q^{−2(1+H)} for q_r ≤ q ≤ q_s, flat below q_r (roll-off), zero
    /// above q_s. Wavenumbers in rad/m.
    SelfAffine {
        /// Hurst exponent H in (0, 1].
        hurst: f64,
        /// Roll-off wavenumber q_r.
        rolloff: f64,
        /// Short-wavelength cut-off q_s.
        cutoff: f64,
    },
    /// Gaussian autocorrelation exp(−r²/ℓ²): C(q) ∝ exp(−q² ℓ² / 4).
    Gaussian {
        /// Correlation length ℓ, m.
        correlation_length: f64,
    },
}

impl Spectrum {
    fn shape(&self, q: f64) -> f64 {
        match *self {
            Spectrum::SelfAffine {
                hurst,
                rolloff,
                cutoff,
            } => {
                if q > cutoff {
                    0.0
                } else {
                    q.max(rolloff).powf(-2.0 * (1.0 + hurst))
                }
            }
            Spectrum::Gaussian { correlation_length } => {
                (-(q * correlation_length).powi(2) / 4.0).exp()
            }
        }
    }
}

/// An `n × n` periodic Gaussian random surface with pixel size `pixel` (m), the given
/// spectrum, scaled to rms height `rms` (m) exactly, from `seed`.
pub fn random_surface(
    n: usize,
    pixel: f64,
    spectrum: Spectrum,
    rms: f64,
    seed: u64,
) -> Result<HeightMap, SurfaceError> {
    let mut rng = SplitMix64::new(seed);
    let two_pi = 2.0 * std::f64::consts::PI;
    let dq = two_pi / (n as f64 * pixel);
    let signed = |k: usize| {
        if k <= n / 2 {
            k as f64
        } else {
            k as f64 - n as f64
        }
    };
    let mut grid = vec![Complex::new(0.0, 0.0); n * n];
    for j in 0..n {
        for i in 0..n {
            let q = (signed(i) * dq).hypot(signed(j) * dq);
            let (a, b) = (rng.normal(), rng.normal());
            if i == 0 && j == 0 {
                continue;
            }
            let s = spectrum.shape(q).sqrt();
            grid[j * n + i] = Complex::new(a * s, b * s);
        }
    }
    let mut planner = FftPlanner::<f64>::new();
    let fft = planner.plan_fft_inverse(n);
    for row in grid.chunks_mut(n) {
        fft.process(row);
    }
    let mut col = vec![Complex::new(0.0, 0.0); n];
    for i in 0..n {
        for j in 0..n {
            col[j] = grid[j * n + i];
        }
        fft.process(&mut col);
        for j in 0..n {
            grid[j * n + i] = col[j];
        }
    }
    let mut h: Vec<f64> = grid.iter().map(|z| z.re).collect();
    let mean = h.iter().sum::<f64>() / h.len() as f64;
    let ms = h.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / h.len() as f64;
    let scale = if ms > 0.0 { rms / ms.sqrt() } else { 0.0 };
    for x in &mut h {
        *x = (*x - mean) * scale;
    }
    HeightMap::new(n, n, pixel, pixel, h)
}
