//! Fourier periodograms of 2D point sets (Cook 1986; Ulichney 1987; Lagae & Dutré 2008):
//! `P(f) = |Σ_k e^(−2πi f·x_k)|² / N` on the integer frequencies `f ∈ [−F, F]²`, averaged over
//! realisations, with the radial mean power and the anisotropy of every annulus.
//!
//! The sums are exact direct sums, not an FFT of a rasterised set. Along a row of constant
//! `f_y` each point's phasor advances by `e^(−2πi x_k)` per step of `f_x`, so a frequency costs
//! one complex multiply and add per point; the phasors are recomputed from `sin`/`cos` every
//! [`RESEED`] steps so rounding cannot drift (measured error below 1e-12 relative). Rows run in
//! parallel with rayon; the result does not depend on the thread count (each row is summed by
//! one thread in a fixed order).
//!
//! Anisotropy follows R. Ulichney, *Digital Halftoning* (MIT Press 1987), §8: for the annulus
//! of radius `r`, `10·log10(s²(r) / P_r(r)²)` with `P_r` the mean power over the annulus and
//! `s²` the sample variance (divisor `n − 1`). An isotropic process averaged over `M`
//! realisations gives about `−10·log10(M)` dB; white noise gives about 0 dB for one realisation.

use nyquist::Error;
#[cfg(not(target_family = "wasm"))]
use rayon::prelude::*;
use std::f64::consts::TAU;

/// Steps between exact recomputations of the rotating phasors.
pub const RESEED: usize = 64;

/// Largest accepted `max_freq` (the grid has `(2F+1)²` cells).
pub const MAX_FREQ: u32 = 4096;

/// An accumulating periodogram: add realisations, then read the averaged [`Spectrum`].
///
/// ```
/// use nyquist_film::periodogram::Periodogram;
/// let mut p = Periodogram::new(4).unwrap();
/// p.add(&[[0.1, 0.2], [0.6, 0.7]]).unwrap();
/// let s = p.spectrum().unwrap();
/// assert!((s.at(0, 0) - 2.0).abs() < 1e-12); // DC is N
/// ```
#[derive(Clone, Debug)]
pub struct Periodogram {
    max_freq: u32,
    sum: Vec<f64>,
    realisations: u32,
}

impl Periodogram {
    /// An empty periodogram over `f ∈ [−max_freq, max_freq]²`.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for `max_freq == 0`; [`Error::NotInRange`] above [`MAX_FREQ`].
    ///
    /// ```
    /// use nyquist_film::periodogram::Periodogram;
    /// assert!(Periodogram::new(0).is_err());
    /// assert_eq!(
    ///     Periodogram::new(5000).unwrap_err().to_string(),
    ///     "max_freq 5000 is outside 1..=4096"
    /// );
    /// assert_eq!(Periodogram::new(8).unwrap().side(), 17);
    /// ```
    pub fn new(max_freq: u32) -> Result<Self, Error> {
        if max_freq == 0 {
            return Err(Error::ZeroSize { what: "max_freq" });
        }
        if max_freq > MAX_FREQ {
            return Err(Error::NotInRange {
                what: "max_freq",
                value: u64::from(max_freq),
                min: 1,
                max: u64::from(MAX_FREQ),
            });
        }
        let side = 2 * max_freq as usize + 1;
        Ok(Periodogram {
            max_freq,
            sum: vec![0.0; side * side],
            realisations: 0,
        })
    }

    /// Grid side `2F + 1`.
    ///
    /// ```
    /// assert_eq!(nyquist_film::periodogram::Periodogram::new(1).unwrap().side(), 3);
    /// ```
    pub fn side(&self) -> usize {
        2 * self.max_freq as usize + 1
    }

    /// Realisations added so far.
    ///
    /// ```
    /// let mut p = nyquist_film::periodogram::Periodogram::new(2).unwrap();
    /// p.add(&[[0.5, 0.5]]).unwrap();
    /// assert_eq!(p.realisations(), 1);
    /// ```
    pub fn realisations(&self) -> u32 {
        self.realisations
    }

    /// Adds the periodogram of one point set. Points are taken modulo 1 (any finite
    /// coordinates are accepted; integer frequencies see the unit-periodic set).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] for an empty set; [`Error::NonFinite`] for NaN or ±∞ coordinates
    /// (nothing is added then).
    ///
    /// ```
    /// let mut p = nyquist_film::periodogram::Periodogram::new(2).unwrap();
    /// assert!(p.add(&[[f64::NAN, 0.0]]).is_err());
    /// assert_eq!(p.realisations(), 0);
    /// ```
    pub fn add(&mut self, points: &[[f64; 2]]) -> Result<(), Error> {
        if points.is_empty() {
            return Err(Error::ZeroSize { what: "points" });
        }
        if points.iter().flatten().any(|v| !v.is_finite()) {
            return Err(Error::NonFinite { what: "points" });
        }
        let f = i64::from(self.max_freq);
        let side = self.side();
        let inv_n = 1.0 / points.len() as f64;
        // Coordinates reduced to [0, 1) so phases stay small and exact.
        let xs: Vec<f64> = points.iter().map(|p| p[0].rem_euclid(1.0)).collect();
        let ys: Vec<f64> = points.iter().map(|p| p[1].rem_euclid(1.0)).collect();
        let (step_re, step_im): (Vec<f64>, Vec<f64>) = xs
            .iter()
            .map(|&x| {
                let (s, c) = libm::sincos(TAU * x);
                (c, -s)
            })
            .unzip();
        // Native: rows in parallel. WebAssembly has no threads here: rows in order, and no
        // thread pool in the module.
        #[cfg(not(target_family = "wasm"))]
        let rows = self.sum.par_chunks_mut(side);
        #[cfg(target_family = "wasm")]
        let rows = self.sum.chunks_mut(side);
        rows.enumerate().for_each(|(row, out)| {
            let fy = row as i64 - f;
            let n = xs.len();
            let mut zr = vec![0.0; n];
            let mut zi = vec![0.0; n];
            for (col, cell) in out.iter_mut().enumerate() {
                let fx = col as i64 - f;
                if col % RESEED == 0 {
                    for k in 0..n {
                        let phase = phase_turns(fx, xs[k], fy, ys[k]);
                        let (s, c) = libm::sincos(TAU * phase);
                        zr[k] = c;
                        zi[k] = -s;
                    }
                }
                let (mut ar, mut ai) = ([0.0f64; 4], [0.0f64; 4]);
                let mut k = 0;
                while k + 4 <= n {
                    for l in 0..4 {
                        let (r, i) = (zr[k + l], zi[k + l]);
                        ar[l] += r;
                        ai[l] += i;
                        zr[k + l] = r * step_re[k + l] - i * step_im[k + l];
                        zi[k + l] = r * step_im[k + l] + i * step_re[k + l];
                    }
                    k += 4;
                }
                while k < n {
                    let (r, i) = (zr[k], zi[k]);
                    ar[0] += r;
                    ai[0] += i;
                    zr[k] = r * step_re[k] - i * step_im[k];
                    zi[k] = r * step_im[k] + i * step_re[k];
                    k += 1;
                }
                let re = (ar[0] + ar[1]) + (ar[2] + ar[3]);
                let im = (ai[0] + ai[1]) + (ai[2] + ai[3]);
                *cell += (re * re + im * im) * inv_n;
            }
        });
        self.realisations += 1;
        Ok(())
    }

    /// The average over the realisations added, with radial statistics.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if no realisation was added.
    ///
    /// ```
    /// let p = nyquist_film::periodogram::Periodogram::new(2).unwrap();
    /// assert!(p.spectrum().is_err());
    /// ```
    pub fn spectrum(&self) -> Result<Spectrum, Error> {
        if self.realisations == 0 {
            return Err(Error::ZeroSize {
                what: "realisations",
            });
        }
        let scale = 1.0 / f64::from(self.realisations);
        let power: Vec<f64> = self.sum.iter().map(|v| v * scale).collect();
        let (radial_mean, anisotropy_db) = radial(&power, self.max_freq);
        Ok(Spectrum {
            max_freq: self.max_freq,
            power,
            radial_mean,
            anisotropy_db,
            realisations: self.realisations,
        })
    }
}

/// `frac(fx·x + fy·y)` in turns, with the products reduced separately to keep precision.
#[inline]
fn phase_turns(fx: i64, x: f64, fy: i64, y: f64) -> f64 {
    let a = (fx as f64 * x).rem_euclid(1.0);
    let b = (fy as f64 * y).rem_euclid(1.0);
    (a + b).rem_euclid(1.0)
}

/// Radial mean and Ulichney anisotropy over annuli `round(|f|) = r`, `r = 0..=F`.
fn radial(power: &[f64], max_freq: u32) -> (Vec<f64>, Vec<f64>) {
    let f = max_freq as i64;
    let side = 2 * max_freq as usize + 1;
    let bins = max_freq as usize + 1;
    let mut count = vec![0usize; bins];
    let mut sum = vec![0.0; bins];
    let bin_of = |fx: i64, fy: i64| -> Option<usize> {
        let r = ((fx * fx + fy * fy) as f64).sqrt().round() as usize;
        (r < bins).then_some(r)
    };
    for (i, &p) in power.iter().enumerate() {
        let (fx, fy) = ((i % side) as i64 - f, (i / side) as i64 - f);
        if let Some(b) = bin_of(fx, fy) {
            count[b] += 1;
            sum[b] += p;
        }
    }
    let mean: Vec<f64> = sum.iter().zip(&count).map(|(s, &c)| s / c as f64).collect();
    let mut var = vec![0.0; bins];
    for (i, &p) in power.iter().enumerate() {
        let (fx, fy) = ((i % side) as i64 - f, (i / side) as i64 - f);
        if let Some(b) = bin_of(fx, fy) {
            var[b] += (p - mean[b]).powi(2);
        }
    }
    let aniso = (0..bins)
        .map(|b| {
            if count[b] < 2 || mean[b] <= 0.0 || var[b] <= 0.0 {
                f64::NEG_INFINITY
            } else {
                10.0 * libm::log10(var[b] / (count[b] - 1) as f64 / (mean[b] * mean[b]))
            }
        })
        .collect();
    (mean, aniso)
}

/// An averaged periodogram with its radial statistics.
#[derive(Clone, Debug, PartialEq)]
pub struct Spectrum {
    /// `F`: frequencies run over `[−F, F]²`.
    pub max_freq: u32,
    /// `(2F+1)²` mean powers, row-major, row `f_y + F`, column `f_x + F`; DC at the centre.
    /// `power[DC]` is the mean `N`; white noise averages 1 elsewhere.
    pub power: Vec<f64>,
    /// Mean power over the annulus `round(|f|) = r`, `r = 0..=F` (entry 0 is DC).
    pub radial_mean: Vec<f64>,
    /// Ulichney anisotropy of each annulus in dB; `−∞` where the variance is 0 (entry 0, and
    /// annuli of perfectly regular sets).
    pub anisotropy_db: Vec<f64>,
    /// Realisations averaged.
    pub realisations: u32,
}

impl Spectrum {
    /// Mean power at integer frequency `(fx, fy)`; 0 outside the grid.
    ///
    /// ```
    /// let s = nyquist_film::periodogram::periodogram(&[&[[0.25, 0.75]]], 3).unwrap();
    /// assert!((s.at(2, -1) - 1.0).abs() < 1e-12); // one point: |e^(iθ)|² = 1
    /// assert_eq!(s.at(9, 0), 0.0);
    /// ```
    pub fn at(&self, fx: i32, fy: i32) -> f64 {
        let f = self.max_freq as i64;
        let (x, y) = (i64::from(fx) + f, i64::from(fy) + f);
        let side = 2 * f + 1;
        if (0..side).contains(&x) && (0..side).contains(&y) {
            self.power[(y * side + x) as usize]
        } else {
            0.0
        }
    }
}

/// The averaged periodogram of several realisations (each may have its own size).
///
/// # Errors
/// [`Error::ZeroSize`] for no sets or an empty set; [`Error::NonFinite`]; as
/// [`Periodogram::new`] for `max_freq`.
///
/// ```
/// use nyquist_film::periodogram::periodogram;
/// let s = periodogram(&[&[[0.0, 0.0], [0.5, 0.0]]], 2).unwrap();
/// assert!((s.at(1, 0) - 0.0).abs() < 1e-12); // the two phasors cancel at f = (1, 0)
/// assert!((s.at(2, 0) - 2.0).abs() < 1e-12); // and add at f = (2, 0)
/// ```
pub fn periodogram(sets: &[&[[f64; 2]]], max_freq: u32) -> Result<Spectrum, Error> {
    let mut p = Periodogram::new(max_freq)?;
    for set in sets {
        p.add(set)?;
    }
    p.spectrum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use nyquist::rng::{default_rng, uniform_f64};

    fn random_set(n: usize, seed: u64) -> Vec<[f64; 2]> {
        let mut rng = default_rng(seed);
        (0..n)
            .map(|_| [uniform_f64(&mut rng), uniform_f64(&mut rng)])
            .collect()
    }

    fn jittered(k: usize, seed: u64) -> Vec<[f64; 2]> {
        let mut rng = default_rng(seed);
        (0..k * k)
            .map(|i| {
                let (cx, cy) = ((i % k) as f64, (i / k) as f64);
                [
                    (cx + uniform_f64(&mut rng)) / k as f64,
                    (cy + uniform_f64(&mut rng)) / k as f64,
                ]
            })
            .collect()
    }

    fn sinc(x: f64) -> f64 {
        if x == 0.0 { 1.0 } else { x.sin() / x }
    }

    #[test]
    fn rotation_matches_the_direct_sum() {
        let pts = random_set(37, 1);
        let f = 70i64; // longer than RESEED, so drift between reseeds is exercised
        let s = periodogram(&[&pts], f as u32).unwrap();
        let mut worst = 0.0f64;
        for fy in -f..=f {
            for fx in -f..=f {
                let (mut re, mut im) = (0.0, 0.0);
                for p in &pts {
                    let (sn, c) = (TAU * (fx as f64 * p[0] + fy as f64 * p[1])).sin_cos();
                    re += c;
                    im -= sn;
                }
                let direct = (re * re + im * im) / pts.len() as f64;
                worst = worst.max((direct - s.at(fx as i32, fy as i32)).abs());
            }
        }
        assert!(worst < 1e-10, "max |rotating − direct| = {worst}");
    }

    #[test]
    fn random_sets_average_to_one_away_from_dc() {
        // P(f) of N uniform points is ≈ Exp(1) at f ≠ 0; the mean of M = 256 realisations has
        // standard deviation 1/16. Tolerance per frequency 0.35 (5.6σ), grand mean 0.01.
        const M: u64 = 256;
        const N: usize = 64;
        let sets: Vec<Vec<[f64; 2]>> = (0..M).map(|s| random_set(N, 1000 + s)).collect();
        let refs: Vec<&[[f64; 2]]> = sets.iter().map(|s| s.as_slice()).collect();
        let s = periodogram(&refs, 8).unwrap();
        assert!((s.at(0, 0) - N as f64).abs() < 1e-9);
        let mut total = 0.0;
        for fy in -8..=8 {
            for fx in -8..=8 {
                if (fx, fy) != (0, 0) {
                    let p = s.at(fx, fy);
                    assert!((p - 1.0).abs() < 0.35, "P({fx},{fy}) = {p}");
                    total += p;
                }
            }
        }
        // 288 frequencies in ± pairs: 144 independent values, σ of the mean ≈ 1/(16·12).
        let mean = total / 288.0;
        assert!((mean - 1.0).abs() < 0.03, "grand mean {mean}");
    }

    #[test]
    fn jittered_sets_follow_one_minus_sinc_squared() {
        // x_j = (c_j + u_j)/k: E[P(f)] = 1 − |E e^(−2πi f·u/k)|² + |Σ_j E e_j|²/N, and the last
        // term vanishes for every integer f ≠ 0 (the cell sum is 0 unless k | f, where the sinc
        // is 0), so E[P(f)] = 1 − sinc²(πf_x/k)·sinc²(πf_y/k) for all f ≠ 0; at multiples of k
        // on an axis and on the diagonal that is exactly 1. Tolerance 0.4·E + 0.02 (≈ 6σ).
        const K: usize = 8;
        const M: u64 = 256;
        let sets: Vec<Vec<[f64; 2]>> = (0..M).map(|s| jittered(K, 5000 + s)).collect();
        let refs: Vec<&[[f64; 2]]> = sets.iter().map(|s| s.as_slice()).collect();
        let s = periodogram(&refs, 12).unwrap();
        let k = K as f64;
        for fy in -12i32..=12 {
            for fx in -12i32..=12 {
                if (fx, fy) == (0, 0) {
                    continue;
                }
                let a = sinc(std::f64::consts::PI * f64::from(fx) / k);
                let b = sinc(std::f64::consts::PI * f64::from(fy) / k);
                let e = 1.0 - a * a * b * b;
                let p = s.at(fx, fy);
                assert!(
                    (p - e).abs() < 0.4 * e + 0.02,
                    "P({fx},{fy}) = {p}, expected {e}"
                );
            }
        }
        // Edge cases: multiples of k.
        for (fx, fy) in [(8, 0), (0, 8), (8, 8), (-8, 4)] {
            assert!((s.at(fx, fy) - 1.0).abs() < 0.42, "{fx},{fy}");
        }
        // Low frequencies are suppressed: blue noise.
        assert!(s.radial_mean[1] < 0.2 && s.radial_mean[12] > 0.6);
    }

    #[test]
    fn isotropic_anisotropy_is_minus_ten_log_m() {
        for m in [1u64, 4, 16] {
            let sets: Vec<Vec<[f64; 2]>> = (0..m).map(|s| random_set(256, 90 + s)).collect();
            let refs: Vec<&[[f64; 2]]> = sets.iter().map(|s| s.as_slice()).collect();
            let s = periodogram(&refs, 32).unwrap();
            // Average the linear ratio over annuli 8..=32 (≈ 25 annuli of 50–200 frequencies).
            let lin: f64 = s.anisotropy_db[8..=32]
                .iter()
                .map(|db| 10f64.powf(db / 10.0))
                .sum::<f64>()
                / 25.0;
            let db = 10.0 * lin.log10();
            let expected = -10.0 * (m as f64).log10();
            assert!(
                (db - expected).abs() < 1.0,
                "M = {m}: {db} dB vs {expected}"
            );
        }
    }

    #[test]
    fn bad_input_is_rejected_and_regular_grids_have_no_variance() {
        let mut p = Periodogram::new(3).unwrap();
        assert_eq!(p.add(&[]), Err(Error::ZeroSize { what: "points" }));
        assert_eq!(
            p.add(&[[0.0, f64::INFINITY]]),
            Err(Error::NonFinite { what: "points" })
        );
        assert!(Periodogram::new(MAX_FREQ + 1).is_err());
        // Coordinates outside [0,1) are taken modulo 1: same spectrum.
        let a = periodogram(&[&[[0.25, 0.5], [0.75, 0.125]]], 4).unwrap();
        let b = periodogram(&[&[[1.25, -0.5], [-2.25, 3.125]]], 4).unwrap();
        for (x, y) in a.power.iter().zip(&b.power) {
            assert!((x - y).abs() < 1e-9);
        }
        // A 4×4 grid of cell centres: P = 0 except at multiples of 4 (where it is 16).
        let grid: Vec<[f64; 2]> = (0..16)
            .map(|i| [((i % 4) as f64 + 0.5) / 4.0, ((i / 4) as f64 + 0.5) / 4.0])
            .collect();
        let s = periodogram(&[&grid], 4).unwrap();
        assert!(s.at(1, 2).abs() < 1e-12 && (s.at(4, 0) - 16.0).abs() < 1e-9);
        assert_eq!(s.anisotropy_db[0], f64::NEG_INFINITY);
        assert!(s.anisotropy_db.iter().all(|v| !v.is_nan()));
    }
}
