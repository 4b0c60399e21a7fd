//! The two-dimensional real FFT of a periodic map and the Westergaard kernel.
//!
//! A map of `ny` rows of `nx` points is transformed by a real FFT along each row
//! (`nx / 2 + 1` complex outputs) and a complex FFT along each column of that
//! half-spectrum. The spectrum is kept transposed (column `kx` contiguous, `ny`
//! long), where the kernel multiplies it point by point; the inverse runs the
//! same steps backwards. Plans and buffers are made once per map and reused by
//! every convolution. Rows and columns are independent, so rayon transforms
//! them side by side; each one's arithmetic is the same on any number of threads.

use std::f64::consts::PI;
use std::sync::Arc;

use rayon::prelude::*;
use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

/// The compliance of an elastic half-space applied to a periodic field by FFT:
/// `u = K * p`, with `ũ(q) = 2 p̃(q) / (E* |q|)` and the mean (q = 0) mode set
/// to zero (the mean displacement is fixed by the load, not by the kernel).
pub struct Compliance {
    nx: usize,
    ny: usize,
    /// `nx / 2 + 1`.
    mx: usize,
    forward_rows: Arc<dyn RealToComplex<f64>>,
    inverse_rows: Arc<dyn ComplexToReal<f64>>,
    forward_columns: Arc<dyn Fft<f64>>,
    inverse_columns: Arc<dyn Fft<f64>>,
    /// 2 / (E* |q|) / (nx ny), transposed (index `kx * ny + ky`); 0 at q = 0.
    kernel: Vec<f64>,
    /// Row spectra, `ny` rows of `mx`.
    rows: Vec<Complex<f64>>,
    /// Column spectra, `mx` columns of `ny` (the transposed layout).
    columns: Vec<Complex<f64>>,
    /// A copy of the input (realfft uses its input as scratch).
    input: Vec<f64>,
}

impl Compliance {
    /// The compliance of a half-space of composite modulus `modulus` (E*, Pa) on a
    /// periodic grid of `ny` rows of `nx` points, `dx` × `dy` metres each.
    pub fn new(nx: usize, ny: usize, dx: f64, dy: f64, modulus: f64) -> Self {
        let mx = nx / 2 + 1;
        let mut real = RealFftPlanner::<f64>::new();
        let mut complex = FftPlanner::<f64>::new();
        let (lx, ly) = (nx as f64 * dx, ny as f64 * dy);
        let wavenumber = |k: usize, n: usize, l: f64| {
            // Signed index: 0, 1, …, n/2, −(n − 1)/2 … −1 (only its square is used).
            let signed = if k <= n / 2 {
                k as f64
            } else {
                k as f64 - n as f64
            };
            2.0 * PI * signed / l
        };
        let scale = 1.0 / (nx as f64 * ny as f64);
        let mut kernel = vec![0.0; mx * ny];
        for kx in 0..mx {
            let qx = wavenumber(kx, nx, lx);
            for ky in 0..ny {
                let qy = wavenumber(ky, ny, ly);
                let q = qx.hypot(qy);
                kernel[kx * ny + ky] = if q > 0.0 {
                    2.0 / (modulus * q) * scale
                } else {
                    0.0
                };
            }
        }
        Compliance {
            nx,
            ny,
            mx,
            forward_rows: real.plan_fft_forward(nx),
            inverse_rows: real.plan_fft_inverse(nx),
            forward_columns: complex.plan_fft_forward(ny),
            inverse_columns: complex.plan_fft_inverse(ny),
            kernel,
            rows: vec![Complex::default(); mx * ny],
            columns: vec![Complex::default(); mx * ny],
            input: vec![0.0; nx * ny],
        }
    }

    /// Points of the grid.
    pub fn len(&self) -> usize {
        self.nx * self.ny
    }

    /// Whether the grid is empty (never, for a valid map).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The largest eigenvalue of K: its kernel's largest value, 2 / (E* q_min).
    pub fn largest_eigenvalue(&self) -> f64 {
        let scale = (self.nx * self.ny) as f64;
        self.kernel.iter().copied().fold(0.0, f64::max) * scale
    }

    /// `output = K * field` (both `ny` rows of `nx`, row-major). The mean of
    /// `output` is zero.
    pub fn apply(&mut self, field: &[f64], output: &mut [f64]) {
        let (nx, ny, mx) = (self.nx, self.ny, self.mx);
        debug_assert_eq!(field.len(), nx * ny);
        debug_assert_eq!(output.len(), nx * ny);
        self.input.copy_from_slice(field);
        // Rows: real to complex.
        let forward = &self.forward_rows;
        self.input
            .par_chunks_mut(nx)
            .zip(self.rows.par_chunks_mut(mx))
            .for_each_init(
                || forward.make_scratch_vec(),
                |scratch, (row, spectrum)| {
                    // Lengths match by construction: the call cannot fail.
                    let _ = forward.process_with_scratch(row, spectrum, scratch);
                },
            );
        transpose(&self.rows, &mut self.columns, ny, mx);
        // Columns: forward, times the kernel, inverse.
        let (fwd, inv) = (&self.forward_columns, &self.inverse_columns);
        let scratch_len = fwd
            .get_outofplace_scratch_len()
            .max(inv.get_outofplace_scratch_len());
        self.columns
            .par_chunks_mut(ny)
            .zip(self.kernel.par_chunks(ny))
            .for_each_init(
                || {
                    (
                        vec![Complex::default(); ny],
                        vec![Complex::default(); scratch_len],
                    )
                },
                |(spectrum, scratch), (column, kernel)| {
                    // Out of place both ways (in place, rustfft copies through
                    // a buffer anyway).
                    fwd.process_outofplace_with_scratch(column, spectrum, scratch);
                    for (c, k) in spectrum.iter_mut().zip(kernel) {
                        *c *= *k;
                    }
                    inv.process_outofplace_with_scratch(spectrum, column, scratch);
                },
            );
        transpose(&self.columns, &mut self.rows, mx, ny);
        // Rows: complex to real. The zero and (even nx) Nyquist bins of a real
        // row's spectrum are real; rounding leaves ~1e-16 imaginary parts there,
        // which realfft would refuse.
        let inverse = &self.inverse_rows;
        let even = nx % 2 == 0;
        self.rows
            .par_chunks_mut(mx)
            .zip(output.par_chunks_mut(nx))
            .for_each_init(
                || inverse.make_scratch_vec(),
                |scratch, (spectrum, row)| {
                    spectrum[0].im = 0.0;
                    if even {
                        spectrum[mx - 1].im = 0.0;
                    }
                    let _ = inverse.process_with_scratch(spectrum, row, scratch);
                },
            );
    }
}

/// `to[c * rows + r] = from[r * cols + c]` (the transpose crate's cache-aware
/// blocked transpose, which rustfft itself uses).
fn transpose(from: &[Complex<f64>], to: &mut [Complex<f64>], rows: usize, cols: usize) {
    transpose::transpose(from, to, cols, rows);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A single Fourier mode is an eigenfunction: cos(q·x) → 2/(E*|q|) cos(q·x)
    /// (the Westergaard solution), for odd and even sizes and non-square pixels.
    #[test]
    fn a_cosine_is_scaled_by_two_over_e_star_q() {
        for &(nx, ny, dx, dy) in &[
            (16, 8, 1.0, 1.0),
            (15, 9, 2e-9, 3e-9),
            (32, 1 + 1, 0.5, 0.25),
        ] {
            let e = 7.0e10;
            let mut k = Compliance::new(nx, ny, dx, dy, e);
            let (mxk, myk) = (3.0, 1.0);
            let (lx, ly) = (nx as f64 * dx, ny as f64 * dy);
            let (qx, qy) = (2.0 * PI * mxk / lx, 2.0 * PI * myk / ly);
            let field: Vec<f64> = (0..nx * ny)
                .map(|i| {
                    let (x, y) = ((i % nx) as f64 * dx, (i / nx) as f64 * dy);
                    (qx * x + qy * y).cos() + 5.0
                })
                .collect();
            let mut out = vec![0.0; nx * ny];
            k.apply(&field, &mut out);
            let factor = 2.0 / (e * qx.hypot(qy));
            for (f, o) in field.iter().zip(&out) {
                assert!((o - factor * (f - 5.0)).abs() < 1e-13 * factor, "{nx}×{ny}");
            }
        }
    }
}
