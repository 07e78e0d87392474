//! Per-pixel error statistics for a renderer's own film: the core's
//! [`PixelStats`](nyquist::pixel_stats::PixelStats) as a plain C struct the caller owns (one per
//! pixel, in any array), with the variance of each channel's weighted mean, the A/B halves and
//! the relative error adaptive sampling stops on. No handle and no allocation: a zeroed
//! `NyqPixelStats` is an empty pixel.

use nyquist::pixel_stats::{ErrorEstimate, Moments, PixelStats, sample_half};

use crate::NyqStatus;
use crate::ffi::{get, get_mut, need, put, run};

/// One pixel's sums (the core's `PixelStats`): Σ f·x and Σ f, the second moments, and the B
/// half's sums. Zero every field (`NyqPixelStats s = {0};` or `memset`) for an empty pixel;
/// change them only through the `nyq_pixel_stats_` functions, which reject a struct no samples
/// could give (NaN, infinite, or a negative Σ f² or deviation sum) with `NYQ_ERR_NON_FINITE` or
/// `NYQ_ERR_OUT_OF_RANGE`. 120 bytes.
///
/// ```
/// let s = nyquist_capi::NyqPixelStats::default();
/// assert_eq!((s.weight, s.weight2_sum), (0.0, 0.0));
/// assert_eq!(size_of::<nyquist_capi::NyqPixelStats>(), 120);
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NyqPixelStats {
    /// Σ f·x per channel.
    pub sum: [f64; 3],
    /// Σ f.
    pub weight: f64,
    /// Σ f².
    pub weight2_sum: f64,
    /// Σ f²·x / Σ f² per channel.
    pub mean: [f64; 3],
    /// Σ f²·(x − mean)² per channel.
    pub deviation_sum: [f64; 3],
    /// Σ f·x per channel over the B half's samples.
    pub half_b_sum: [f64; 3],
    /// Σ f over the B half's samples.
    pub half_b_weight: f64,
}

/// A pixel's value and error estimates, from [`nyq_pixel_stats_estimate`].
///
/// ```
/// let e = nyquist_capi::NyqEstimate::default();
/// assert!(!e.has_variance && !e.has_halves);
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct NyqEstimate {
    /// The weighted mean per channel, Σ f·x / Σ f (0 where Σ f ≤ 0).
    pub value: [f64; 3],
    /// The variance of `value` per channel; 0 unless `has_variance`.
    pub variance: [f64; 3],
    /// The A half's mean per channel; 0 unless `has_halves`.
    pub half_a: [f64; 3],
    /// The B half's mean per channel; 0 unless `has_halves`.
    pub half_b: [f64; 3],
    /// Whether `variance` is set: more than one effective sample.
    pub has_variance: bool,
    /// Whether `half_a` and `half_b` are set: both halves have Σ f > 0.
    pub has_halves: bool,
}

/// Which estimate [`nyq_pixel_stats_relative_error`] uses.
///
/// ```
/// assert_eq!(nyquist_capi::NyqErrorEstimate::NYQ_ERROR_VARIANCE as u32, 1);
/// ```
#[repr(u32)]
#[allow(non_camel_case_types)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum NyqErrorEstimate {
    /// |A − B| / 2 from the two sample classes.
    NYQ_ERROR_HALVES = 0,
    /// The standard error, √variance.
    NYQ_ERROR_VARIANCE = 1,
}

impl NyqPixelStats {
    fn to_core(self) -> Result<PixelStats, NyqStatus> {
        let finite = |v: &[f64]| v.iter().all(|v| v.is_finite());
        if !finite(&self.sum) || !finite(&self.half_b_sum) {
            return Err(NyqStatus::NYQ_ERR_NON_FINITE);
        }
        if !finite(&[self.weight, self.half_b_weight]) {
            return Err(NyqStatus::NYQ_ERR_NON_FINITE);
        }
        Ok(PixelStats {
            sum: self.sum,
            weight: self.weight,
            moments: Moments::from_parts(self.weight2_sum, self.mean, self.deviation_sum)?,
            half_b_sum: self.half_b_sum,
            half_b_weight: self.half_b_weight,
        })
    }

    fn from_core(p: &PixelStats) -> NyqPixelStats {
        NyqPixelStats {
            sum: p.sum,
            weight: p.weight,
            weight2_sum: p.moments.weight2_sum(),
            mean: p.moments.mean(),
            deviation_sum: p.moments.deviation_sum(),
            half_b_sum: p.half_b_sum,
            half_b_weight: p.half_b_weight,
        }
    }
}

/// Writes the half of the sample of index `index` within its pixel to `*out`: 0 (A) or 1 (B),
/// the parity of `popcount(index & 0xaaaa…aaaa)` (the core's
/// [`sample_half`](nyquist::pixel_stats::sample_half); below 2³² Cycles' rule).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_BUFFER` if it is misaligned.
///
/// # Safety
/// `out` is null or valid for writing a `uint32_t`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_sample_half};
/// let mut h = 9;
/// // SAFETY: `h` is a valid u32.
/// assert_eq!(unsafe { nyq_sample_half(2, &mut h) }, NyqStatus::NYQ_OK);
/// assert_eq!(h, 1);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sample_half(index: u64, out: *mut u32) -> NyqStatus {
    // SAFETY: `out` is null or valid for writing a u32 (caller).
    run(|| unsafe { put(out, sample_half(index) as u32) })
}

/// Adds the sample of index `index` within the pixel (its half is [`nyq_sample_half`]'s), with
/// filter weight `weight` (negative for a filter's negative lobes) and value `value[0..3]` (the
/// radiance times the sample's own weight), to `*stats`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_BUFFER` if one is misaligned;
/// `NYQ_ERR_NON_FINITE` if `weight` or a value is NaN or infinite, or if `*stats` holds one;
/// `NYQ_ERR_OUT_OF_RANGE` if `*stats` holds a negative Σ f² or deviation sum. `*stats` is
/// unchanged on error.
///
/// # Safety
/// `stats` is null or points to a `NyqPixelStats` not otherwise accessed during the call;
/// `value` is null or valid for reading 3 doubles.
///
/// ```
/// use nyquist_capi::{NyqPixelStats, NyqStatus, nyq_pixel_stats_add};
/// let mut s = NyqPixelStats::default();
/// for (i, v) in [1.0, 3.0].into_iter().enumerate() {
///     // SAFETY: `s` is a valid struct and the value holds 3 doubles.
///     assert_eq!(unsafe { nyq_pixel_stats_add(&mut s, i as u64, 0.5, [v; 3].as_ptr()) }, NyqStatus::NYQ_OK);
/// }
/// assert_eq!((s.sum, s.weight, s.weight2_sum), ([2.0; 3], 1.0, 0.5));
/// // SAFETY: as above.
/// let bad = unsafe { nyq_pixel_stats_add(&mut s, 2, f64::NAN, [0.0; 3].as_ptr()) };
/// assert_eq!(bad, NyqStatus::NYQ_ERR_NON_FINITE);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_pixel_stats_add(
    stats: *mut NyqPixelStats,
    index: u64,
    weight: f64,
    value: *const f64,
) -> NyqStatus {
    run(|| {
        need(stats)?;
        // SAFETY: `value` is null or readable for 3 doubles (caller).
        let value = unsafe { get(value.cast::<[f64; 3]>())? };
        // SAFETY: `stats` is null or exclusively ours for the call (caller).
        let stats = unsafe { get_mut(stats)? };
        let mut p = stats.to_core()?;
        p.add(index, weight, *value)?;
        *stats = NyqPixelStats::from_core(&p);
        Ok(())
    })
}

/// Merges `*other` (the same pixel's samples from another tile or thread) into `*stats`. Merged
/// in a fixed order, the result is the same bits for any number of threads.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_BUFFER` if one is misaligned;
/// `NYQ_ERR_NON_FINITE` or `NYQ_ERR_OUT_OF_RANGE` if either struct holds what no samples give
/// ([`NyqPixelStats`]). `*stats` is unchanged on error.
///
/// # Safety
/// `stats` is null or points to a `NyqPixelStats` not otherwise accessed during the call;
/// `other` is null or points to a readable `NyqPixelStats` (it may be `stats` itself).
///
/// ```
/// use nyquist_capi::{NyqPixelStats, NyqStatus, nyq_pixel_stats_add, nyq_pixel_stats_merge};
/// let (mut a, mut b) = (NyqPixelStats::default(), NyqPixelStats::default());
/// // SAFETY: valid structs, values of 3 doubles.
/// unsafe {
///     nyq_pixel_stats_add(&mut a, 0, 1.0, [1.0; 3].as_ptr());
///     nyq_pixel_stats_add(&mut b, 2, 1.0, [3.0; 3].as_ptr());
///     assert_eq!(nyq_pixel_stats_merge(&mut a, &b), NyqStatus::NYQ_OK);
/// }
/// assert_eq!((a.sum, a.half_b_sum, a.deviation_sum), ([4.0; 3], [3.0; 3], [2.0; 3]));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_pixel_stats_merge(
    stats: *mut NyqPixelStats,
    other: *const NyqPixelStats,
) -> NyqStatus {
    run(|| {
        need(stats)?;
        // SAFETY: `other` is null or readable (caller); it is copied before `stats` is borrowed
        // mutably, so `other == stats` is sound.
        let o = unsafe { *get(other)? };
        // SAFETY: `stats` is null or exclusively ours for the call (caller).
        let stats = unsafe { get_mut(stats)? };
        let mut p = stats.to_core()?;
        p.merge(&o.to_core()?);
        *stats = NyqPixelStats::from_core(&p);
        Ok(())
    })
}

/// Writes the value, variance and halves of the pixel `*stats` to `*out`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_BUFFER` if one is misaligned;
/// `NYQ_ERR_NON_FINITE` or `NYQ_ERR_OUT_OF_RANGE` if `*stats` holds what no samples give.
///
/// # Safety
/// `stats` is null or points to a readable `NyqPixelStats`; `out` is null or valid for writing
/// a `NyqEstimate`.
///
/// ```
/// use nyquist_capi::{NyqEstimate, NyqPixelStats, NyqStatus, nyq_pixel_stats_add, nyq_pixel_stats_estimate};
/// let mut s = NyqPixelStats::default();
/// let mut e = NyqEstimate::default();
/// // SAFETY: valid structs, values of 3 doubles.
/// unsafe {
///     for (i, v) in [1.0, 2.0, 3.0, 2.0].into_iter().enumerate() {
///         nyq_pixel_stats_add(&mut s, i as u64, 1.0, [v; 3].as_ptr());
///     }
///     assert_eq!(nyq_pixel_stats_estimate(&s, &mut e), NyqStatus::NYQ_OK);
/// }
/// assert_eq!((e.value, e.variance), ([2.0; 3], [1.0 / 6.0; 3]));
/// assert_eq!((e.half_a, e.half_b), ([1.5; 3], [2.5; 3]));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_pixel_stats_estimate(
    stats: *const NyqPixelStats,
    out: *mut NyqEstimate,
) -> NyqStatus {
    run(|| {
        need(stats)?;
        need(out)?;
        // SAFETY: `stats` is null or readable (caller).
        let e = unsafe { get(stats)? }.to_core()?.estimate();
        let [half_a, half_b] = e.halves.unwrap_or_default();
        let estimate = NyqEstimate {
            value: e.value,
            variance: e.variance.unwrap_or_default(),
            half_a,
            half_b,
            has_variance: e.variance.is_some(),
            has_halves: e.halves.is_some(),
        };
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, estimate) }
    })
}

/// Writes the relative error of the pixel `*stats` to `*out`: the error `estimate` gives
/// ([`NyqErrorEstimate`]), summed over the channels, over Σ |value| + `floor`. Adaptive
/// sampling stops a pixel once this is at or below its threshold; the floor keeps dark pixels
/// from asking for samples without end. Where the estimate does not exist yet (one effective
/// sample, an empty half) the error is +∞: such a pixel is never converged.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_BUFFER` if one is misaligned;
/// `NYQ_ERR_OUT_OF_RANGE` for an unknown `estimate`, or a negative `floor`;
/// `NYQ_ERR_NON_FINITE` if `floor` is NaN or infinite; `NYQ_ERR_NON_FINITE` or
/// `NYQ_ERR_OUT_OF_RANGE` if `*stats` holds what no samples give.
///
/// # Safety
/// `stats` is null or points to a readable `NyqPixelStats`; `out` is null or valid for writing
/// a double.
///
/// ```
/// use nyquist_capi::{NyqErrorEstimate, NyqPixelStats, NyqStatus, nyq_pixel_stats_add, nyq_pixel_stats_relative_error};
/// let mut s = NyqPixelStats::default();
/// let mut r = 0.0;
/// let halves = NyqErrorEstimate::NYQ_ERROR_HALVES as u32;
/// // SAFETY: valid structs, values of 3 doubles.
/// unsafe {
///     assert_eq!(nyq_pixel_stats_relative_error(&s, halves, 0.0, &mut r), NyqStatus::NYQ_OK);
///     assert_eq!(r, f64::INFINITY); // no samples yet
///     for (i, v) in [0.6, 0.6, 0.4, 0.4].into_iter().enumerate() {
///         nyq_pixel_stats_add(&mut s, i as u64, 1.0, [v; 3].as_ptr());
///     }
///     assert_eq!(nyq_pixel_stats_relative_error(&s, halves, 0.0, &mut r), NyqStatus::NYQ_OK);
/// }
/// assert!((r - 0.2).abs() < 1e-15); // 3 × |0.6 − 0.4| / 2 over 1.5
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_pixel_stats_relative_error(
    stats: *const NyqPixelStats,
    estimate: u32,
    floor: f64,
    out: *mut f64,
) -> NyqStatus {
    run(|| {
        need(stats)?;
        need(out)?;
        let estimate = match estimate {
            0 => ErrorEstimate::Halves,
            1 => ErrorEstimate::Variance,
            _ => return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE),
        };
        if !floor.is_finite() {
            return Err(NyqStatus::NYQ_ERR_NON_FINITE);
        }
        if floor < 0.0 {
            return Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE);
        }
        // SAFETY: `stats` is null or readable (caller).
        let e = unsafe { get(stats)? }.to_core()?.estimate();
        let r = e.relative_error(estimate, floor).unwrap_or(f64::INFINITY);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, r) }
    })
}
