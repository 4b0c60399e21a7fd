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
    /// E* |q| / 2 / (nx ny), the stiffness (the kernel's inverse off q = 0),
    /// transposed like it; made on first use.
    stiffness: Vec<f64>,
    /// Column spectra, `mx` columns of `ny` (the transposed layout).
    columns: Vec<Complex<f64>>,
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
            stiffness: Vec::new(),
            columns: vec![Complex::default(); mx * ny],
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
    ///
    /// The transposes are fused into the row passes: a block of `BLOCK` rows
    /// is transformed in cache and scattered into the column spectra (and
    /// gathered back on the way out), so the map's spectrum crosses memory
    /// twice an application instead of six times.
    pub fn apply(&mut self, field: &[f64], output: &mut [f64]) {
        self.convolve(field, output, false);
    }

    /// `output = K⁻¹ * field`, the pressures of displacements `field` (Westergaard's
    /// stiffness `E* |q| / 2`; the mean of `output` is zero, and so is the mean
    /// of `field` taken to be).
    pub fn apply_inverse(&mut self, field: &[f64], output: &mut [f64]) {
        if self.stiffness.is_empty() {
            let scale = 1.0 / (self.nx as f64 * self.ny as f64);
            self.stiffness = self
                .kernel
                .iter()
                .map(|&k| if k > 0.0 { scale * scale / k } else { 0.0 })
                .collect();
        }
        self.convolve(field, output, true);
    }

    fn convolve(&mut self, field: &[f64], output: &mut [f64], inverse: bool) {
        let (nx, ny, mx) = (self.nx, self.ny, self.mx);
        assert_eq!(field.len(), nx * ny);
        assert_eq!(output.len(), nx * ny);
        // Rows: real to complex, scattered into the transposed layout.
        let forward = &self.forward_rows;
        let columns = SharedColumns(self.columns.as_mut_ptr(), self.columns.len());
        let columns = &columns;
        field.par_chunks(BLOCK * nx).enumerate().for_each_init(
            || {
                (
                    vec![0.0; nx],
                    vec![Complex::default(); BLOCK * mx],
                    forward.make_scratch_vec(),
                )
            },
            |(row, block, scratch), (b, rows)| {
                let j0 = b * BLOCK;
                let count = rows.len() / nx;
                for (jj, input) in rows.chunks_exact(nx).enumerate() {
                    // realfft uses its input as scratch: a copy in cache.
                    row.copy_from_slice(input);
                    let spectrum = &mut block[jj * mx..(jj + 1) * mx];
                    // Lengths match by construction: the call cannot fail.
                    let _ = forward.process_with_scratch(row, spectrum, scratch);
                }
                for kx in 0..mx {
                    for jj in 0..count {
                        // SAFETY: index kx·ny + j0 + jj < mx·ny, and row
                        // block b alone writes rows j0..j0 + count.
                        unsafe { columns.write(kx * ny + j0 + jj, block[jj * mx + kx]) };
                    }
                }
            },
        );
        // Columns: forward, times the kernel, inverse.
        let (fwd, inv) = (&self.forward_columns, &self.inverse_columns);
        let scratch_len = fwd
            .get_outofplace_scratch_len()
            .max(inv.get_outofplace_scratch_len());
        let kernel = if inverse {
            &self.stiffness
        } else {
            &self.kernel
        };
        self.columns
            .par_chunks_mut(ny)
            .zip(kernel.par_chunks(ny))
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
        // Rows: gathered from the columns, complex to real. The zero and (even
        // nx) Nyquist bins of a real row's spectrum are real; rounding leaves
        // ~1e-16 imaginary parts there, which realfft would refuse.
        let inverse = &self.inverse_rows;
        let even = nx % 2 == 0;
        let columns = &self.columns;
        output.par_chunks_mut(BLOCK * nx).enumerate().for_each_init(
            || {
                (
                    vec![Complex::default(); BLOCK * mx],
                    inverse.make_scratch_vec(),
                )
            },
            |(block, scratch), (b, rows)| {
                let j0 = b * BLOCK;
                let count = rows.len() / nx;
                for kx in 0..mx {
                    let column = &columns[kx * ny + j0..kx * ny + j0 + count];
                    for (jj, &c) in column.iter().enumerate() {
                        block[jj * mx + kx] = c;
                    }
                }
                for (jj, row) in rows.chunks_exact_mut(nx).enumerate() {
                    let spectrum = &mut block[jj * mx..(jj + 1) * mx];
                    spectrum[0].im = 0.0;
                    if even {
                        spectrum[mx - 1].im = 0.0;
                    }
                    let _ = inverse.process_with_scratch(spectrum, row, scratch);
                }
            },
        );
    }
}

/// Rows transformed together before their spectra are scattered into columns.
const BLOCK: usize = 8;

/// The column spectra, written by several row blocks at once, each to its own
/// rows (disjoint indices).
struct SharedColumns(*mut Complex<f64>, usize);

// SAFETY: the pointer is only written through `write`, at indices each task
// owns alone (see `Compliance::apply`), while `apply` holds `&mut self`.
unsafe impl Send for SharedColumns {}
unsafe impl Sync for SharedColumns {}

impl SharedColumns {
    /// # Safety
    /// `index < len`, and no other thread reads or writes `index` meanwhile.
    unsafe fn write(&self, index: usize, value: Complex<f64>) {
        debug_assert!(index < self.1);
        unsafe { self.0.add(index).write(value) };
    }
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

    /// The stiffness undoes the compliance on any zero-mean field.
    #[test]
    fn the_stiffness_inverts_the_compliance() {
        let (nx, ny) = (24, 10);
        let mut k = Compliance::new(nx, ny, 1e-9, 2e-9, 3e9);
        let field: Vec<f64> = (0..nx * ny)
            .map(|i| ((i * 7919) % 101) as f64 - 50.0)
            .collect();
        let mean = field.iter().sum::<f64>() / field.len() as f64;
        let (mut u, mut back) = (vec![0.0; nx * ny], vec![0.0; nx * ny]);
        k.apply(&field, &mut u);
        k.apply_inverse(&u, &mut back);
        for (f, b) in field.iter().zip(&back) {
            assert!((f - mean - b).abs() < 1e-12 * 50.0);
        }
    }
}
