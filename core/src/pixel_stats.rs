//! Per-pixel error statistics: how far a pixel's weighted mean may be from its limit, from the
//! variance of the mean or from two independent halves of its samples. A film keeps them to
//! stop converged pixels (adaptive sampling) and to feed a denoiser; [`PixelStats`] keeps them
//! for one pixel of a renderer's own film, and `nyquist-film` keeps the same sums per pixel.
//!
//! **Variance.** A pixel's value is the weighted mean I = Σ fᵢxᵢ / Σ fᵢ of its samples' values
//! xᵢ with filter weights fᵢ. Its variance, by the delta method, is Σ fᵢ²(xᵢ − I)² / (Σ fᵢ)²,
//! and with the effective sample count n = (Σ fᵢ)²/Σ fᵢ² in place of n − 1 (unbiased for equal
//! weights: the familiar s²/n) it is Q / ((Σ fᵢ)² − Σ fᵢ²), Q = Σ fᵢ²(xᵢ − I)².
//! Q is kept without cancellation: [`Moments`] holds the f²-weighted mean m and the sum
//! S = Σ fᵢ²(xᵢ − m)², updated per sample by Welford's method with weights (West 1979,
//! "Updating mean and variance estimates: an improved method"), so Q = S + (m − I)²·Σ fᵢ², since
//! Σ fᵢ²(xᵢ − m) = 0. The weights f² are never negative, so negative filter lobes cannot make
//! the update unstable. Partial sums (tiles, threads) are merged by Chan, Golub and LeVeque's
//! pairwise formula (1979, "Updating formulae and a pairwise algorithm for computing sample
//! variances"); merged in a fixed order, the result is the same bits whatever the thread count.
//!
//! **Halves.** A sample's class is the parity of `popcount(index & 0xaaaa…aaaa)`
//! ([`sample_half`]; Christensen, Kensler and Kilpatrick 2018, "Progressive multi-jittered
//! sample sequences", §10.2.1; Cycles' adaptive sampling): for (0,2) sequences such as PMJ02 and
//! Sobol each class is itself well stratified, so the two half-images are independent estimates
//! of the pixel with half the samples each, and their difference measures the error:
//! E|A − B|/2 ≈ the standard error of I. The sums of the B half are kept; A is the whole less B.
//!
//! ```
//! use nyquist::pixel_stats::{ErrorEstimate, PixelStats};
//! let mut p = PixelStats::default();
//! for (i, v) in [1.0, 2.0, 3.0, 2.0].into_iter().enumerate() {
//!     p.add(i as u64, 1.0, [v; 3]).unwrap();
//! }
//! let e = p.estimate();
//! assert_eq!(e.value, [2.0; 3]);
//! assert_eq!(e.variance, Some([1.0 / 6.0; 3])); // s² = 2/3 over n = 4
//! assert_eq!(e.halves, Some([[1.5; 3], [2.5; 3]])); // indices 0, 1 are A; 2, 3 are B
//! let r = e.relative_error(ErrorEstimate::Halves, 0.0).unwrap();
//! assert_eq!(r, 0.25); // |1.5 − 2.5| / 2 over 2, summed over channels
//! ```

use crate::error::Error;
use crate::math::sqrt;

/// The half a sample of index `index` belongs to: 0 (A) or 1 (B), the parity of
/// `popcount(index & 0xaaaa_aaaa_aaaa_aaaa)`. Of every 4 consecutive indices from a multiple of
/// 4, two fall in each half; below 2³² this is Cycles' rule.
///
/// ```
/// use nyquist::pixel_stats::sample_half;
/// let halves: [usize; 8] = core::array::from_fn(|i| sample_half(i as u64));
/// assert_eq!(halves, [0, 0, 1, 1, 0, 0, 1, 1]);
/// ```
#[inline]
pub fn sample_half(index: u64) -> usize {
    ((index & 0xaaaa_aaaa_aaaa_aaaa).count_ones() & 1) as usize
}

/// One pixel's second moments of three channels: Σ f², the f²-weighted mean of each channel and
/// the sum of f²-weighted squared deviations from it (the module docs give the estimator). With
/// the pixel's Σ f and Σ f·x, [`Moments::variance_of_mean`] gives the variance of its value.
///
/// ```
/// use nyquist::pixel_stats::Moments;
/// let mut m = Moments::default();
/// for v in [1.0, 2.0, 3.0] {
///     m.add(1.0, [v, 0.0, 0.0]);
/// }
/// assert_eq!((m.weight2_sum(), m.mean()[0], m.deviation_sum()[0]), (3.0, 2.0, 2.0));
/// assert_eq!(m.variance_of_mean(3.0, 6.0, 0), Some(1.0 / 3.0));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Moments {
    w2: f64,
    mean: [f64; 3],
    m2: [f64; 3],
}

impl Moments {
    /// Σ f².
    pub fn weight2_sum(&self) -> f64 {
        self.w2
    }

    /// Σ f²·x / Σ f² per channel (0 before the first sample of nonzero weight).
    pub fn mean(&self) -> [f64; 3] {
        self.mean
    }

    /// Σ f²·(x − mean)² per channel.
    pub fn deviation_sum(&self) -> [f64; 3] {
        self.m2
    }

    /// Moments from their three parts ([`weight2_sum`](Self::weight2_sum), [`mean`](Self::mean),
    /// [`deviation_sum`](Self::deviation_sum)), as stored elsewhere (a C struct, a file).
    ///
    /// # Errors
    /// [`Error::NonFinite`] if a part is NaN or infinite; [`Error::OutOfRange`] if Σ f² or a
    /// deviation sum is negative.
    ///
    /// ```
    /// use nyquist::pixel_stats::Moments;
    /// let m = Moments::from_parts(2.0, [1.0, 2.0, 3.0], [0.5, 0.0, 1.0]).unwrap();
    /// assert_eq!(m.deviation_sum(), [0.5, 0.0, 1.0]);
    /// assert!(Moments::from_parts(-1.0, [0.0; 3], [0.0; 3]).is_err());
    /// ```
    pub fn from_parts(
        weight2_sum: f64,
        mean: [f64; 3],
        deviation_sum: [f64; 3],
    ) -> Result<Moments, Error> {
        let finite = |what, v: f64| {
            if v.is_finite() {
                Ok(v)
            } else {
                Err(Error::NonFinite { what })
            }
        };
        let non_negative = |what, v: f64| {
            if finite(what, v)? < 0.0 {
                Err(Error::OutOfRange {
                    what,
                    value: v,
                    range: crate::error::Interval::at_least(0.0),
                })
            } else {
                Ok(v)
            }
        };
        Ok(Moments {
            w2: non_negative("weight2_sum", weight2_sum)?,
            mean: [
                finite("mean", mean[0])?,
                finite("mean", mean[1])?,
                finite("mean", mean[2])?,
            ],
            m2: [
                non_negative("deviation_sum", deviation_sum[0])?,
                non_negative("deviation_sum", deviation_sum[1])?,
                non_negative("deviation_sum", deviation_sum[2])?,
            ],
        })
    }

    /// Adds the value `x` with filter weight `f` (weight `f²`); a weight whose square is 0 adds
    /// nothing. Total: a NaN or infinite `f` or `x` makes the moments non-finite, and
    /// [`variance_of_mean`](Self::variance_of_mean) then gives `None` (callers that take
    /// arbitrary input check it first, as [`PixelStats::add`] does).
    #[inline]
    pub fn add(&mut self, f: f64, x: [f64; 3]) {
        let v = f * f;
        if v == 0.0 {
            return;
        }
        self.w2 += v;
        let r = v / self.w2;
        for c in 0..3 {
            let d = x[c] - self.mean[c];
            self.mean[c] += d * r;
            self.m2[c] += v * d * (x[c] - self.mean[c]);
        }
    }

    /// Merges `o` into these moments (Chan, Golub and LeVeque's pairwise update): the result
    /// equals adding `o`'s samples after these, up to rounding.
    ///
    /// ```
    /// use nyquist::pixel_stats::Moments;
    /// let (mut a, mut b, mut all) = (Moments::default(), Moments::default(), Moments::default());
    /// for (i, v) in [1.0, 4.0, 2.0, 8.0].into_iter().enumerate() {
    ///     if i < 2 { a.add(1.0, [v; 3]) } else { b.add(1.0, [v; 3]) }
    ///     all.add(1.0, [v; 3]);
    /// }
    /// a.merge(&b);
    /// assert_eq!(a, all);
    /// ```
    pub fn merge(&mut self, o: &Moments) {
        if o.w2 == 0.0 {
            return;
        }
        if self.w2 == 0.0 {
            *self = *o;
            return;
        }
        let w = self.w2 + o.w2;
        let r = o.w2 / w;
        let cross = self.w2 * r;
        for c in 0..3 {
            let d = o.mean[c] - self.mean[c];
            self.mean[c] += d * r;
            self.m2[c] += o.m2[c] + d * d * cross;
        }
        self.w2 = w;
    }

    /// The variance of the weighted mean of channel `c` of a pixel whose filter weights sum to
    /// `weight_sum` (Σ f) and whose channel `c` sums to `sum` (Σ f·x):
    /// Q / ((Σ f)² − Σ f²) with Q = S + (m − I)²·Σ f² (module docs). `None` when the denominator
    /// is not positive (fewer than two effective samples), when `c > 2`, or when the result is
    /// not finite.
    pub fn variance_of_mean(&self, weight_sum: f64, sum: f64, c: usize) -> Option<f64> {
        let denominator = weight_sum * weight_sum - self.w2;
        if !(denominator > 0.0) {
            return None;
        }
        let d = *self.mean.get(c)? - sum / weight_sum;
        let v = (self.m2[c] + d * d * self.w2) / denominator;
        v.is_finite().then_some(v.max(0.0))
    }
}

/// Which estimate measures a pixel's error.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ErrorEstimate {
    /// |A − B| / 2 from the two sample classes ([`Estimate::half_difference`]).
    Halves,
    /// The standard error √Var ([`Estimate::standard_error`]).
    Variance,
}

/// A pixel's value and the error estimates kept for it.
///
/// ```
/// let e = nyquist::pixel_stats::Estimate {
///     value: [1.0; 3],
///     variance: Some([0.04, 0.09, 0.0]),
///     halves: Some([[1.1, 1.0, 1.0], [0.9, 1.0, 1.0]]),
/// };
/// assert_eq!(e.standard_error(), Some([0.2, 0.3, 0.0]));
/// let d = e.half_difference().unwrap();
/// assert!((d[0] - 0.1).abs() < 1e-12 && d[1] == 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate {
    /// The weighted mean per channel, Σ f·x / Σ f (0 where Σ f ≤ 0).
    pub value: [f64; 3],
    /// The variance of `value` per channel (module docs), when variance is kept and the pixel
    /// has more than one effective sample.
    pub variance: Option<[f64; 3]>,
    /// The means of the A and B halves, when halves are kept and both have Σ f > 0.
    pub halves: Option<[[f64; 3]; 2]>,
}

/// The mean `sum / weight` per channel, or 0 where `weight ≤ 0`.
fn mean(sum: [f64; 3], weight: f64) -> [f64; 3] {
    if weight > 0.0 {
        sum.map(|s| s / weight)
    } else {
        [0.0; 3]
    }
}

impl Estimate {
    /// The estimate of a pixel whose filter weights sum to `weight` (Σ f) and whose channels
    /// sum to `sum` (Σ f·x), with its moments if variance is kept and the B half's `(sum,
    /// weight)` if halves are kept.
    ///
    /// ```
    /// use nyquist::pixel_stats::Estimate;
    /// let e = Estimate::from_sums([6.0; 3], 3.0, None, Some(([2.0; 3], 1.0)));
    /// assert_eq!(e.value, [2.0; 3]);
    /// assert_eq!(e.halves, Some([[2.0; 3], [2.0; 3]]));
    /// assert_eq!(e.variance, None);
    /// ```
    pub fn from_sums(
        sum: [f64; 3],
        weight: f64,
        moments: Option<&Moments>,
        half_b: Option<([f64; 3], f64)>,
    ) -> Estimate {
        let variance = moments.and_then(|m| {
            let v = [0, 1, 2].map(|c| m.variance_of_mean(weight, sum[c], c));
            Some([v[0]?, v[1]?, v[2]?])
        });
        let halves = half_b.and_then(|(b_sum, b_weight)| {
            let a_sum = [0, 1, 2].map(|c| sum[c] - b_sum[c]);
            let a_weight = weight - b_weight;
            (a_weight > 0.0 && b_weight > 0.0)
                .then(|| [mean(a_sum, a_weight), mean(b_sum, b_weight)])
        });
        Estimate {
            value: mean(sum, weight),
            variance,
            halves,
        }
    }

    /// The standard error of `value`: the square root of `variance`.
    pub fn standard_error(&self) -> Option<[f64; 3]> {
        self.variance.map(|v| v.map(sqrt))
    }

    /// Half the difference of the halves' means, |A − B| / 2: an estimate of the standard
    /// error of `value` from the halves (for independent halves of n/2 samples each,
    /// Var(A − B) = 4·Var(value), so |A − B|/2 has the standard error's scale).
    pub fn half_difference(&self) -> Option<[f64; 3]> {
        self.halves
            .map(|[a, b]| [0, 1, 2].map(|c| (a[c] - b[c]).abs() * 0.5))
    }

    /// The relative error adaptive sampling compares with its threshold: the error `estimate`
    /// gives, summed over the channels, over `Σ |value| + floor`; 0 when that error is 0 (a
    /// black pixel with no error is converged whatever the floor), `None` when the estimate is
    /// not available. The floor, meant to be ≥ 0, keeps dark pixels from asking for samples
    /// without end; with a floor of 0 a black pixel with some error has error +∞.
    ///
    /// ```
    /// use nyquist::pixel_stats::{ErrorEstimate, Estimate};
    /// let e = Estimate { value: [0.5; 3], variance: None, halves: Some([[0.6; 3], [0.4; 3]]) };
    /// let r = e.relative_error(ErrorEstimate::Halves, 0.0).unwrap();
    /// assert!((r - 0.2).abs() < 1e-15); // 3 × 0.1 over 1.5
    /// assert_eq!(e.relative_error(ErrorEstimate::Variance, 0.0), None);
    /// ```
    pub fn relative_error(&self, estimate: ErrorEstimate, floor: f64) -> Option<f64> {
        let err = match estimate {
            ErrorEstimate::Halves => self.half_difference()?,
            ErrorEstimate::Variance => self.standard_error()?,
        };
        let err: f64 = err.iter().sum();
        if err == 0.0 {
            return Some(0.0);
        }
        let value: f64 = self.value.iter().map(|v| v.abs()).sum();
        Some(err / (value + floor))
    }
}

/// All of one pixel's sums: Σ f·x and Σ f, the [`Moments`], and the B half's sums, for a
/// renderer that keeps its own film. 120 bytes; the C API's `NyqPixelStats` has the same fields.
///
/// ```
/// use nyquist::pixel_stats::PixelStats;
/// let (mut a, mut b) = (PixelStats::default(), PixelStats::default());
/// a.add(0, 0.5, [1.0, 2.0, 3.0]).unwrap();
/// b.add(2, 0.5, [3.0, 2.0, 1.0]).unwrap();
/// a.merge(&b);
/// let e = a.estimate();
/// assert_eq!(e.value, [2.0; 3]);
/// assert_eq!(e.halves, Some([[1.0, 2.0, 3.0], [3.0, 2.0, 1.0]]));
/// assert!(a.add(3, f64::NAN, [0.0; 3]).is_err());
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelStats {
    /// Σ f·x per channel.
    pub sum: [f64; 3],
    /// Σ f.
    pub weight: f64,
    /// The second moments, for the variance.
    pub moments: Moments,
    /// Σ f·x per channel over the B half's samples.
    pub half_b_sum: [f64; 3],
    /// Σ f over the B half's samples.
    pub half_b_weight: f64,
}

impl PixelStats {
    /// Adds the sample of index `index` within the pixel (its half is
    /// [`sample_half`]`(index)`), with filter weight `f` and value `x` (the radiance times the
    /// sample's own weight). Weights may be negative (filter lobes).
    ///
    /// # Errors
    /// [`Error::NonFinite`] if `f` or a channel of `x` is NaN or infinite; the sums are then
    /// unchanged.
    pub fn add(&mut self, index: u64, f: f64, x: [f64; 3]) -> Result<(), Error> {
        if !f.is_finite() {
            return Err(Error::NonFinite { what: "weight" });
        }
        if !x.iter().all(|v| v.is_finite()) {
            return Err(Error::NonFinite { what: "value" });
        }
        let fx = x.map(|v| f * v);
        for c in 0..3 {
            self.sum[c] += fx[c];
        }
        self.weight += f;
        self.moments.add(f, x);
        if sample_half(index) == 1 {
            for c in 0..3 {
                self.half_b_sum[c] += fx[c];
            }
            self.half_b_weight += f;
        }
        Ok(())
    }

    /// Merges the sums of `o` (the same pixel's samples from another tile or thread) into these.
    /// Merging in a fixed order gives the same bits for any number of threads.
    pub fn merge(&mut self, o: &PixelStats) {
        for c in 0..3 {
            self.sum[c] += o.sum[c];
            self.half_b_sum[c] += o.half_b_sum[c];
        }
        self.weight += o.weight;
        self.half_b_weight += o.half_b_weight;
        self.moments.merge(&o.moments);
    }

    /// The pixel's value, variance and halves.
    pub fn estimate(&self) -> Estimate {
        Estimate::from_sums(
            self.sum,
            self.weight,
            Some(&self.moments),
            Some((self.half_b_sum, self.half_b_weight)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tests::double_double::{ulps, variance_of_mean};
    use std::vec::Vec;

    /// Σ f·x of channel 0, Σ f, and the moments of `(f, [x, 2x, −x])` samples.
    fn pixel_of(samples: &[(f64, f64)]) -> (f64, f64, Moments) {
        let (mut sum, mut weight) = (0.0, 0.0);
        let mut m = Moments::default();
        for &(f, x) in samples {
            sum += f * x;
            weight += f;
            m.add(f, [x, 2.0 * x, -x]);
        }
        (sum, weight, m)
    }

    #[test]
    fn equal_weights_give_the_sample_variance_over_n() {
        // 1, 2, 3, 4: s² = 5/3, so the variance of the mean is 5/12.
        let s: Vec<(f64, f64)> = (1..=4).map(|x| (0.5, f64::from(x))).collect();
        let (sum, weight, m) = pixel_of(&s);
        assert_eq!(m.w2, 1.0);
        assert_eq!(m.mean, [2.5, 5.0, -2.5]);
        assert_eq!(m.m2, [1.25, 5.0, 1.25]);
        let v = m.variance_of_mean(weight, sum, 0).unwrap();
        assert!((v - 5.0 / 12.0).abs() < 1e-15, "{v}");
        let v = m.variance_of_mean(weight, 2.0 * sum, 1).unwrap();
        assert!((v - 4.0 * 5.0 / 12.0).abs() < 1e-15, "{v}");
        assert_eq!(m.variance_of_mean(weight, sum, 3), None);
    }

    #[test]
    fn one_sample_or_zero_weights_have_no_variance() {
        let (sum, weight, m) = pixel_of(&[(0.7, 3.0)]);
        assert_eq!(m.variance_of_mean(weight, sum, 0), None);
        let (sum, weight, m) = pixel_of(&[(0.0, 3.0), (0.0, 1.0)]);
        assert_eq!((m.w2, m.mean, m.m2), (0.0, [0.0; 3], [0.0; 3]));
        assert_eq!(m.variance_of_mean(weight, sum, 0), None);
        let mut huge = m;
        huge.add(1e200, [1.0; 3]);
        huge.add(1e200, [-1.0; 3]);
        assert_eq!(huge.variance_of_mean(2e200, 0.0, 0), None); // (Σf)² − Σf² = ∞ − ∞
    }

    #[test]
    fn a_constant_has_variance_zero() {
        let s: Vec<(f64, f64)> = (0..9).map(|i| (0.25 + f64::from(i) * 0.1, 7.5)).collect();
        let (sum, weight, m) = pixel_of(&s);
        assert_eq!(m.m2, [0.0; 3]);
        assert_eq!(m.mean, [7.5, 15.0, -7.5]);
        // Only the rounding of I = Σ f·x / Σ f (a few ulps of 7.5) is left.
        let v = m.variance_of_mean(weight, sum, 0).unwrap();
        assert!(v < (8.0 * f64::EPSILON * 7.5).powi(2), "{v}");
    }

    #[test]
    fn merging_halves_equals_adding_in_one_run() {
        let s: Vec<(f64, f64)> = (0..40)
            .map(|i| {
                let i = f64::from(i);
                (0.2 + (i * 0.37) % 1.0 - 0.1, (i * 1.618) % 3.0)
            })
            .collect();
        let (sum, weight, whole) = pixel_of(&s);
        for cut in [0, 1, 17, 39, 40] {
            let (_, _, mut a) = pixel_of(&s[..cut]);
            let (_, _, b) = pixel_of(&s[cut..]);
            a.merge(&b);
            assert!((a.w2 - whole.w2).abs() <= 1e-15 * whole.w2, "cut {cut}");
            for c in 0..3 {
                let scale = whole.mean[c].abs().max(1.0);
                assert!(
                    (a.mean[c] - whole.mean[c]).abs() <= 1e-14 * scale,
                    "cut {cut}"
                );
                assert!(
                    (a.m2[c] - whole.m2[c]).abs() <= 1e-13 * whole.m2[c],
                    "cut {cut}"
                );
            }
            let va = a.variance_of_mean(weight, sum, 0).unwrap();
            let vw = whole.variance_of_mean(weight, sum, 0).unwrap();
            assert!((va - vw).abs() <= 1e-13 * vw, "cut {cut}");
        }
    }

    #[test]
    fn the_variance_agrees_with_two_passes_in_double_double() {
        // Weights from a Mitchell-like range with negative lobes, values far from 0 (the case
        // where a one-pass Σx² form cancels: here the variance's relative condition is about
        // 10⁶, and a Σx² form loses every digit).
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst = 0.0f64;
        for n in [2usize, 3, 10, 100, 1000, 10_000] {
            let s: Vec<(f64, f64)> = (0..n)
                .map(|_| (next() * 1.2 - 0.1, 1000.0 + next()))
                .collect();
            let (sum, weight, m) = pixel_of(&s);
            let want = variance_of_mean(&s);
            let got = m.variance_of_mean(weight, sum, 0).unwrap();
            worst = worst.max(ulps(got, want));
        }
        // Measured: 6419 ulps (1.4·10⁻¹² relative) at most over these six sets, against a
        // condition number of about 10⁶; the bound is 2¹⁴ ulps.
        assert!(worst <= 16384.0, "{worst} ulps");
    }

    #[test]
    fn halves_alternate_in_pairs_and_balance_every_four() {
        for base in (0..1u64 << 12).step_by(4) {
            let b: usize = (base..base + 4).map(sample_half).sum();
            assert_eq!(b, 2, "indices {base}..{}", base + 4);
        }
        assert_eq!(sample_half(0xaaaa_aaaa_aaaa_aaaa), 0); // 32 bits set
        assert_eq!(sample_half(1 << 63), 1);
        assert_eq!(sample_half((1 << 62) | 1), 0);
    }

    #[test]
    fn the_error_estimates_are_the_square_root_and_half_the_difference() {
        let e = Estimate {
            value: [1.0, -2.0, 0.0],
            variance: Some([0.04, 0.09, 0.0]),
            halves: Some([[1.5, 1.0, 0.0], [0.5, 1.25, 0.0]]),
        };
        assert_eq!(e.standard_error(), Some([0.2, 0.3, 0.0]));
        assert_eq!(e.half_difference(), Some([0.5, 0.125, 0.0]));
        // Σ|value| = 3; with the floor 1 the denominator is 4.
        assert_eq!(
            e.relative_error(ErrorEstimate::Halves, 1.0),
            Some(0.625 / 4.0)
        );
        let r = e.relative_error(ErrorEstimate::Variance, 1.0).unwrap();
        assert!((r - 0.5 / 4.0).abs() < 1e-16, "{r}");
        let none = Estimate {
            variance: None,
            halves: None,
            ..e
        };
        assert_eq!(
            (none.standard_error(), none.half_difference()),
            (None, None)
        );
        assert_eq!(none.relative_error(ErrorEstimate::Halves, 1.0), None);
        let black = Estimate {
            value: [0.0; 3],
            variance: Some([0.0; 3]),
            halves: Some([[0.0; 3], [0.0, 1e-300, 0.0]]),
        };
        assert_eq!(
            black.relative_error(ErrorEstimate::Variance, 0.0),
            Some(0.0)
        );
        let r = black.relative_error(ErrorEstimate::Halves, 0.0);
        assert_eq!(r, Some(f64::INFINITY));
        assert_eq!(none.relative_error(ErrorEstimate::Variance, 1.0), None);
    }

    #[test]
    fn an_estimate_needs_weight_in_both_halves() {
        let both = Estimate::from_sums([4.0, 8.0, 0.0], 4.0, None, Some(([1.0, 6.0, 0.0], 1.0)));
        assert_eq!(both.value, [1.0, 2.0, 0.0]);
        assert_eq!(both.halves, Some([[1.0, 2.0 / 3.0, 0.0], [1.0, 6.0, 0.0]]));
        for b_weight in [0.0, 4.0, -1.0, 5.0] {
            let e = Estimate::from_sums([4.0; 3], 4.0, None, Some(([1.0; 3], b_weight)));
            assert_eq!(e.halves, None, "B weight {b_weight}");
        }
        let empty = Estimate::from_sums([4.0; 3], 0.0, None, None);
        assert_eq!(empty.value, [0.0; 3]);
        let negative = Estimate::from_sums([4.0; 3], -2.0, None, None);
        assert_eq!(negative.value, [0.0; 3]);
    }

    #[test]
    fn pixel_stats_keep_the_halves_and_the_variance_of_their_samples() {
        let mut p = PixelStats::default();
        let values = [1.0, 5.0, 2.0, 6.0, 3.0, 7.0, 4.0, 8.0];
        for (i, v) in values.into_iter().enumerate() {
            p.add(i as u64, 0.5, [v, -v, 2.0 * v]).unwrap();
        }
        // Halves: indices 0, 1, 4, 5 (A) and 2, 3, 6, 7 (B).
        assert_eq!(p.half_b_weight, 2.0);
        assert_eq!(p.half_b_sum, [10.0, -10.0, 20.0]);
        let e = p.estimate();
        assert_eq!(e.value, [4.5, -4.5, 9.0]);
        assert_eq!(e.halves, Some([[4.0, -4.0, 8.0], [5.0, -5.0, 10.0]]));
        // s² of 1..=8 is 6; over n = 8.
        let v = e.variance.unwrap();
        for (c, scale) in [1.0, 1.0, 4.0].into_iter().enumerate() {
            assert!((v[c] - 0.75 * scale).abs() < 1e-14, "{v:?}");
        }
        let before = p;
        assert_eq!(
            p.add(8, f64::INFINITY, [1.0; 3]),
            Err(Error::NonFinite { what: "weight" })
        );
        assert_eq!(
            p.add(8, 1.0, [1.0, f64::NAN, 1.0]),
            Err(Error::NonFinite { what: "value" })
        );
        assert_eq!(p, before);
    }

    #[test]
    fn pixel_stats_merge_every_part() {
        let mut a = PixelStats::default();
        let mut b = PixelStats::default();
        let mut whole = PixelStats::default();
        for i in 0..16u64 {
            let v = [(i * 7 % 5) as f64, i as f64, 1.0];
            let f = 0.25 + (i % 3) as f64;
            whole.add(i, f, v).unwrap();
            if i < 6 {
                a.add(i, f, v)
            } else {
                b.add(i, f, v)
            }
            .unwrap();
        }
        a.merge(&b);
        assert_eq!(a.sum, whole.sum);
        assert_eq!(a.weight, whole.weight);
        assert_eq!(a.half_b_sum, whole.half_b_sum);
        assert_eq!(a.half_b_weight, whole.half_b_weight);
        assert_eq!(a.moments.w2, whole.moments.w2);
        for c in 0..3 {
            assert!((a.moments.mean[c] - whole.moments.mean[c]).abs() < 1e-14);
            assert!((a.moments.m2[c] - whole.moments.m2[c]).abs() < 1e-12);
        }
        let mut empty = PixelStats::default();
        empty.merge(&whole);
        assert_eq!(empty, whole);
        let mut same = whole;
        same.merge(&PixelStats::default());
        assert_eq!(same, whole);
    }

    #[test]
    fn moments_from_parts_reject_what_no_samples_give() {
        let m = Moments::from_parts(2.0, [1.0, -2.0, 3.0], [0.5, 0.0, 1.0]).unwrap();
        assert_eq!(
            (m.w2, m.mean, m.m2),
            (2.0, [1.0, -2.0, 3.0], [0.5, 0.0, 1.0])
        );
        assert_eq!(
            (m.weight2_sum(), m.mean(), m.deviation_sum()),
            (2.0, [1.0, -2.0, 3.0], [0.5, 0.0, 1.0])
        );
        assert_eq!(
            Moments::from_parts(f64::NAN, [0.0; 3], [0.0; 3]),
            Err(Error::NonFinite {
                what: "weight2_sum"
            })
        );
        assert_eq!(
            Moments::from_parts(1.0, [0.0, 0.0, f64::INFINITY], [0.0; 3]),
            Err(Error::NonFinite { what: "mean" })
        );
        assert!(matches!(
            Moments::from_parts(1.0, [0.0; 3], [0.0, 0.0, -1e-300]),
            Err(Error::OutOfRange {
                what: "deviation_sum",
                ..
            })
        ));
        assert!(matches!(
            Moments::from_parts(-0.5, [0.0; 3], [0.0; 3]),
            Err(Error::OutOfRange { what: "weight2_sum", value, .. }) if value == -0.5
        ));
    }
}
