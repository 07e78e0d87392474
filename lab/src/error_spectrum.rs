//! The power spectrum of an error image: how much of a render's error sits at low spatial
//! frequencies, where a denoiser or the eye cannot remove it, and how much at high ones, where
//! it can (blue noise).
//!
//! The periodogram `P(u, v) = |Σ_{x,y} (e(x, y) − ē) e^(−2πi (u x / W + v y / H))|²` of the
//! centred image is taken on every frequency of the `W × H` grid (a separable FFT for power-of-two
//! sides, a direct DFT otherwise). A frequency's radius is `ρ = √((u/W)² + (v/H)²)` in cycles
//! per pixel, with `u`, `v` folded into `(−W/2, W/2]` and `(−H/2, H/2]`; the Nyquist radius is ½.
//!
//! Powers are stated relative to white noise of the same variance, whose expected periodogram
//! is the same at every frequency: each figure is a mean power divided by the mean over all
//! frequencies but 0. So white error measures about 1 everywhere, blue error well below 1 at
//! low radii, and a smooth error image far above 1 there.
//!
//! The low-frequency ratio of one image is an estimate. The periodogram values of a stationary
//! error are, for large images, independent exponentials about its spectrum `S`, apart from the
//! pairs `P(u, v) = P(−u, −v)`. So a sum `L = Σ P` over a set of frequencies closed under that
//! pairing has variance `4 Σ_pairs S²`, and `Σ P²` over the set estimates it without bias
//! (`E[P²] = 2S²` for an exponential). The ratio is `(L/n) / (A/(W·H − 1))`, with `L` the sum
//! over the `n` band frequencies and `A` over every frequency, which holds `L`. With `R = A − L`
//! and `Q_L`, `Q_R` the sums of `P²` in and out of the band, the delta method gives the ratio's
//! variance as `(W·H − 1)² (Q_L R² + Q_R L²) / (n² A⁴)`
//! ([`ErrorSpectrum::low_frequency_ratio_se`]). Two images' ratios differ by more than the draw
//! explains when `|r₁ − r₂| / √(se₁² + se₂²)` is large (above 2 about one time in 22 by
//! chance). An image whose error is not stationary (a render whose error sits on a few edges)
//! varies more than this says.
//!
//! ```
//! use nyquist_lab::error_spectrum::error_spectrum;
//! // A checkerboard's power is all at the highest frequency: none below a quarter of Nyquist.
//! let img: Vec<f64> = (0..32 * 32).map(|i| f64::from(((i % 32) + (i / 32)) % 2)).collect();
//! let s = error_spectrum(&img, 32, 32).unwrap();
//! assert!(s.low_frequency_ratio < 1e-12 && s.low_frequency_rmse < 1e-12);
//! assert_eq!(s.low_frequency_ratio_se, 0.0); // no power in the band, no spread either
//! // Its one frequency, (½, ½) cycle per pixel, lies past the annuli (ρ = 0.71 > ½); the
//! // innermost annulus has no frequency of a 32² grid (NaN).
//! assert!(s.radial[0].is_nan() && s.radial[1..].iter().all(|&r| r < 1e-12));
//! ```

use nyquist_film::Error;

/// Radius of the low band, in cycles per pixel: a quarter of the Nyquist radius.
pub const LOW_RADIUS: f64 = 0.125;

/// Width of an annulus of [`ErrorSpectrum::radial`], in cycles per pixel (16 annuli up to the
/// Nyquist radius ½).
pub const ANNULUS_WIDTH: f64 = 1.0 / 32.0;

/// Largest side [`error_spectrum`] takes (its direct DFT costs `W · H · (W + H)` for sides that
/// are not powers of two).
pub const MAX_SIDE: u32 = 8192;

/// An error image's spectrum, relative to white noise of the same variance.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorSpectrum {
    /// Mean power at the frequencies `0 < ρ < ¼ · ½` ([`LOW_RADIUS`]), over the mean power of
    /// every frequency but 0: about 1 for white error, well below 1 for blue error. `NaN` if
    /// the band holds no frequency (both sides 8 or less).
    pub low_frequency_ratio: f64,
    /// The standard error of [`low_frequency_ratio`](Self::low_frequency_ratio) as an estimate
    /// of the error's spectrum (module docs): about `ratio / √(n/2)` for `n` band frequencies,
    /// 0.10 for white error on a 64² image; `NaN` where the ratio is. An image that repeats a
    /// tile has the tile's; the model assumes the error is stationary across the image.
    pub low_frequency_ratio_se: f64,
    /// The RMS of the error left by an ideal low-pass filter that keeps the same band (and not
    /// the mean): what a denoiser or the eye cannot remove, in the image's units. The ratio
    /// says how the error is spread; this says how much is left, so it compares samplers whose
    /// errors differ in size (one with less error can have a higher ratio and less left).
    pub low_frequency_rmse: f64,
    /// Mean power in each annulus `k · w ≤ ρ < (k + 1) · w` (`w` = [`ANNULUS_WIDTH`], `k` =
    /// 0 … 15, frequency 0 left out), over the same mean; `NaN` for an annulus the grid has
    /// no frequency in (the innermost ones of a small image).
    pub radial: Vec<f64>,
}

/// The spectrum of the `width × height` image `image` (row-major), centred first, so a
/// constant offset (a biased estimator) does not count.
///
/// # Errors
/// [`Error::Config`] if `image.len() != width · height`, a side is 0 or above [`MAX_SIDE`],
/// or the image has fewer than two pixels or a non-finite value; an image with no variation
/// has no spectrum (`Error::Config` too).
///
/// ```
/// use nyquist_lab::error_spectrum::error_spectrum;
/// assert!(error_spectrum(&[0.0; 6], 3, 2).is_err()); // constant
/// assert!(error_spectrum(&[0.0, 1.0], 3, 2).is_err()); // wrong length
/// ```
pub fn error_spectrum(image: &[f64], width: u32, height: u32) -> Result<ErrorSpectrum, Error> {
    let (w, h) = (width as usize, height as usize);
    if w == 0 || h == 0 || width > MAX_SIDE || height > MAX_SIDE || w * h < 2 {
        return Err(Error::Config(format!(
            "error spectrum of a {width} × {height} image: sides from 1 to {MAX_SIDE}, two pixels at least"
        )));
    }
    if image.len() != w * h {
        return Err(Error::Config(format!(
            "error spectrum: {} values for a {width} × {height} image",
            image.len()
        )));
    }
    if image.iter().any(|v| !v.is_finite()) {
        return Err(Error::Config(
            "error spectrum: the image has a value that is not finite".into(),
        ));
    }
    let mean = image.iter().sum::<f64>() / image.len() as f64;
    let mut data: Vec<(f64, f64)> = image.iter().map(|v| (v - mean, 0.0)).collect();
    let row_plan = Dft::new(w);
    for row in data.chunks_exact_mut(w) {
        row_plan.run(row);
    }
    let col_plan = Dft::new(h);
    let mut col = vec![(0.0, 0.0); h];
    for u in 0..w {
        for (y, c) in col.iter_mut().enumerate() {
            *c = data[y * w + u];
        }
        col_plan.run(&mut col);
        for (y, c) in col.iter().enumerate() {
            data[y * w + u] = *c;
        }
    }
    let annuli = (0.5 / ANNULUS_WIDTH) as usize;
    // The band's and the other frequencies' sums of powers and of squared powers.
    let (mut low, mut low_squares, mut nlow) = (0.0, 0.0, 0usize);
    let (mut rest, mut rest_squares) = (0.0, 0.0);
    let mut ring = vec![(0.0, 0usize); annuli];
    for v in 0..h {
        for u in 0..w {
            if (u, v) == (0, 0) {
                continue;
            }
            let (re, im) = data[v * w + u];
            let p = re * re + im * im;
            let fold = |k: usize, n: usize| (if k > n / 2 { n - k } else { k }) as f64 / n as f64;
            let rho = fold(u, w).hypot(fold(v, h));
            if rho < LOW_RADIUS {
                low += p;
                low_squares += p * p;
                nlow += 1;
            } else {
                rest += p;
                rest_squares += p * p;
            }
            let k = (rho / ANNULUS_WIDTH) as usize;
            if k < annuli {
                ring[k].0 += p;
                ring[k].1 += 1;
            }
        }
    }
    let all = low + rest;
    let white = all / (w * h - 1) as f64;
    if white <= 0.0 {
        return Err(Error::Config(
            "error spectrum: the image is constant (no error to analyse)".into(),
        ));
    }
    let ratio = |sum: f64, n: usize| {
        if n == 0 {
            f64::NAN
        } else {
            sum / n as f64 / white
        }
    };
    // Parseval: the filtered image's sum of squares is the band's power over the pixel count.
    let pixels = (w * h) as f64;
    Ok(ErrorSpectrum {
        low_frequency_ratio: ratio(low, nlow),
        // The module docs' variance: (N − 1)/(n A²) = 1/(n · white · A).
        low_frequency_ratio_se: ratio(
            (low_squares * rest * rest + rest_squares * low * low).sqrt() / all,
            nlow,
        ),
        low_frequency_rmse: low.sqrt() / pixels,
        radial: ring.iter().map(|&(s, n)| ratio(s, n)).collect(),
    })
}

/// A one-dimensional DFT of length `n`: radix-2 FFT for a power of two, the direct sum
/// otherwise, with the twiddles `e^(−2πi k/n)` computed once.
struct Dft {
    n: usize,
    twiddles: Vec<(f64, f64)>,
}

impl Dft {
    fn new(n: usize) -> Dft {
        let twiddles = (0..n)
            .map(|k| {
                let a = -std::f64::consts::TAU * k as f64 / n as f64;
                (libm::cos(a), libm::sin(a))
            })
            .collect();
        Dft { n, twiddles }
    }

    /// Replaces `x` by its DFT.
    fn run(&self, x: &mut [(f64, f64)]) {
        let n = self.n;
        let mul = |(a, b): (f64, f64), (c, d): (f64, f64)| (a * c - b * d, a * d + b * c);
        if !n.is_power_of_two() {
            let out: Vec<(f64, f64)> = (0..n)
                .map(|k| {
                    x.iter().enumerate().fold((0.0, 0.0), |acc, (j, &v)| {
                        let t = mul(v, self.twiddles[(k * j) % n]);
                        (acc.0 + t.0, acc.1 + t.1)
                    })
                })
                .collect();
            x.copy_from_slice(&out);
            return;
        }
        // Bit-reversal permutation, then butterflies of growing span.
        let bits = n.trailing_zeros();
        for i in 0..n {
            let j = if bits == 0 {
                0
            } else {
                i.reverse_bits() >> (usize::BITS - bits)
            };
            if i < j {
                x.swap(i, j);
            }
        }
        let mut span = 1;
        while span < n {
            let step = n / (2 * span);
            for start in (0..n).step_by(2 * span) {
                for k in 0..span {
                    let t = mul(x[start + k + span], self.twiddles[k * step]);
                    let a = x[start + k];
                    x[start + k] = (a.0 + t.0, a.1 + t.1);
                    x[start + k + span] = (a.0 - t.0, a.1 - t.1);
                }
            }
            span *= 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The FFT equals the direct DFT (lengths 1 … 64, powers of two and not).
    #[test]
    fn fft_is_the_dft() {
        for n in [1usize, 2, 3, 4, 6, 8, 16, 17, 64] {
            let x: Vec<(f64, f64)> = (0..n)
                .map(|i| (((i * 7 + 3) % 11) as f64 - 5.0, ((i * 5) % 7) as f64))
                .collect();
            let mut fast = x.clone();
            Dft::new(n).run(&mut fast);
            for (k, got) in fast.iter().enumerate() {
                let mut want = (0.0, 0.0);
                for (j, v) in x.iter().enumerate() {
                    let a = -std::f64::consts::TAU * (k * j) as f64 / n as f64;
                    want.0 += v.0 * a.cos() - v.1 * a.sin();
                    want.1 += v.0 * a.sin() + v.1 * a.cos();
                }
                assert!(
                    (got.0 - want.0).abs() < 1e-9 && (got.1 - want.1).abs() < 1e-9,
                    "{n} {k}"
                );
            }
        }
    }

    /// A cosine's power lands in its annulus and the low band, nowhere else, on a square and
    /// on a non-square grid (a side that is not a power of two takes the direct DFT), and the
    /// band's low-pass keeps all of it.
    #[test]
    fn a_cosine_lands_in_its_annulus_and_band() {
        for (w, h) in [(32u32, 32u32), (48, 20)] {
            // u = 3 cycles across: ρ = 3 / w, in the low band and annulus ⌊ρ / w⌋.
            let img: Vec<f64> = (0..w * h)
                .map(|i| (std::f64::consts::TAU * 3.0 * f64::from(i % w) / f64::from(w)).cos())
                .collect();
            let s = error_spectrum(&img, w, h).unwrap();
            let rho = 3.0 / f64::from(w);
            assert!(s.low_frequency_ratio > 10.0, "{w}×{h} {s:?}");
            // The low-pass keeps the whole cosine: RMS 1/√2.
            assert!(
                (s.low_frequency_rmse - 0.5f64.sqrt()).abs() < 1e-9,
                "{w}×{h} {s:?}"
            );
            let k = (rho / ANNULUS_WIDTH) as usize;
            for (j, r) in s.radial.iter().enumerate() {
                if j == k {
                    assert!(*r > 1.0, "{w}×{h} annulus {j}: {r}");
                } else if r.is_finite() {
                    assert!(*r < 1e-9, "{w}×{h} annulus {j}: {r}");
                }
            }
        }
    }

    /// White noise: the low-frequency ratio's mean over 16 images of 64² is within 0.1 of 1
    /// (its standard deviation per image is about 1/√(π·8²/2) ≈ 0.10, so the mean's is 0.025:
    /// a false alarm is a 4-σ event), and every annulus near 1.
    #[test]
    fn white_noise_measures_one() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state = nyquist::hash::mix64(state.wrapping_add(0x9e37_79b9_7f4a_7c15));
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut ratios = Vec::new();
        let mut radial = [0.0; 16];
        for _ in 0..16 {
            let img: Vec<f64> = (0..64 * 64).map(|_| next()).collect();
            let s = error_spectrum(&img, 64, 64).unwrap();
            ratios.push(s.low_frequency_ratio);
            for (a, r) in radial.iter_mut().zip(&s.radial) {
                *a += r / 16.0;
            }
        }
        let mean = ratios.iter().sum::<f64>() / 16.0;
        assert!((mean - 1.0).abs() < 0.1, "{ratios:?}");
        for (k, r) in radial.iter().enumerate().skip(1) {
            assert!((r - 1.0).abs() < 0.25, "annulus {k}: {r}");
        }
    }

    /// The standard error says how far the ratio moves from image to image: over 1600 images
    /// of 64² each of white noise, of a high-pass of it (blue: `w(x) − w(x+1)`) and of a
    /// low-pass (red: six neighbours summed, ratio 4.6), the ratios' standard deviation is
    /// within 10 % of the standard errors' RMS (measured: 1.012, 1.021, 1.009). The deviation
    /// from 1600 draws has a relative spread of 1/√3200 = 1.8 %, so a false alarm is a
    /// 4-σ event even with the 2 % the measured ratios are off by. Without the delta method's
    /// covariance term the red case measures 0.79.
    #[test]
    fn the_ratio_standard_error_is_its_spread() {
        let mut state = 0x5eed_0f5e_u64;
        let mut next = || {
            state = nyquist::hash::mix64(state.wrapping_add(0x9e37_79b9_7f4a_7c15));
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        let n = 64usize;
        let at = |w: &[f64], x: usize, y: usize| w[(y % n) * n + x % n];
        // A filter makes pixel (x, y) of the image from the noise `w`.
        type Filter<'a> = &'a dyn Fn(&[f64], usize, usize) -> f64;
        let filters: [(&str, Filter); 3] = [
            ("white", &|w, x, y| at(w, x, y)),
            ("blue", &|w, x, y| at(w, x, y) - at(w, x + 1, y)),
            ("red", &|w, x, y| {
                (0..3).map(|d| at(w, x + d, y) + at(w, x, y + d + 1)).sum()
            }),
        ];
        for (name, filter) in filters {
            let (mut ratios, mut ses) = (Vec::new(), Vec::new());
            for _ in 0..1600 {
                let w: Vec<f64> = (0..n * n).map(|_| next()).collect();
                let img: Vec<f64> = (0..n * n).map(|i| filter(&w, i % n, i / n)).collect();
                let s = error_spectrum(&img, n as u32, n as u32).unwrap();
                ratios.push(s.low_frequency_ratio);
                ses.push(s.low_frequency_ratio_se);
            }
            let mean = ratios.iter().sum::<f64>() / 1600.0;
            let sd = (ratios.iter().map(|r| (r - mean).powi(2)).sum::<f64>() / 1599.0).sqrt();
            let se = (ses.iter().map(|s| s * s).sum::<f64>() / 1600.0).sqrt();
            assert!(
                (sd / se - 1.0).abs() < 0.1,
                "{name}: mean {mean}, sd {sd}, se {se}"
            );
        }
    }

    /// The band holds a frequency once a side is longer than 8 (`ρ = 1/9 < ⅛`); before that
    /// the ratio and its standard error are NaN, as documented.
    #[test]
    fn an_image_of_sides_8_has_no_band() {
        for (side, band) in [(8u32, false), (9, true)] {
            let img: Vec<f64> = (0..side * side).map(|i| f64::from(i * 7 % 5)).collect();
            let s = error_spectrum(&img, side, side).unwrap();
            assert_eq!(s.low_frequency_ratio.is_finite(), band, "{side}: {s:?}");
            assert_eq!(s.low_frequency_ratio_se.is_finite(), band, "{side}: {s:?}");
        }
    }

    #[test]
    fn bad_images_are_refused() {
        assert!(error_spectrum(&[], 0, 0).is_err());
        assert!(error_spectrum(&[1.0], 1, 1).is_err());
        assert!(error_spectrum(&[1.0, f64::NAN], 2, 1).is_err());
        assert!(error_spectrum(&[1.0, 2.0, 3.0], 2, 1).is_err());
        assert!(error_spectrum(&[2.0; 4], 2, 2).is_err());
        assert!(error_spectrum(&[0.0; 2], MAX_SIDE + 1, 1).is_err());
        assert!(error_spectrum(&[1.0, 2.0], 2, 1).is_ok());
    }
}
