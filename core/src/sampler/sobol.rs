//! pbrt-v3's Sobol sampler: one Sobol sequence over the whole image.

use super::Sampler;
use crate::Error;
use crate::hash::hash2;
use crate::math::fraction_to_f32;
use crate::scramble::{Scramble, scramble_u32};
use crate::sequence::{SOBOL_DIMS as DIMS, padded_u32, sobol_run_f32, sobol_u32, sobol_u64};

/// Sobol sampling over the whole image (pbrt-v3's `SobolSampler`).
///
/// The image is embedded in a `2^m × 2^m` square, `m = ⌈log₂ max(width, height)⌉`, and
/// dimensions 0 and 1 of the Sobol sequence (a (0,2)-sequence) are scaled by `2^m`: among the
/// first `2^(2m)` points each pixel of the square owns exactly one, and among the first
/// `spp · 2^(2m)` exactly `spp`, which form a (0, log₂ spp, 2)-net inside the pixel. Sample `s`
/// of pixel `p` is index `idx = s · 2^(2m) + low`, where `low` solves the `2m × 2m` GF(2) system
/// "top `m` bits of dimensions 0 and 1 equal `p`" after the contribution of `s · 2^(2m)` is
/// XOR-ed out; the inverse matrix is computed once, at construction, by Gaussian elimination.
///
/// Image sample: the fractional part of `(x · 2^m − p.x, y · 2^m − p.y)`; dimension
/// `2 ≤ d < 1024` is Sobol dimension `d` at `idx`. Dimensions from 1024 on are padding
/// (Burley 2020, §6): independently seeded Owen-scrambled 4-D blocks of the pixel's own
/// sample index, keyed by the pixel and the seed, so they stay stratified in each pixel and no
/// dimension repeats a lower one. A nonzero seed adds a digital shift
/// (XOR) from `hash(seed, d)` to every dimension — for dimensions 0 and 1 only below the top
/// `m` bits, so pixels keep their samples. Digital shifts keep every net a net.
///
/// [`Scramble::PermuteDigits`] is that digital shift; any other [`Scramble`] can be chosen: with the Owen scrambles
/// every dimension's value is scrambled under `hash(seed, d)` — dimensions 0 and 1 inside the
/// pixel (the fraction below the top `m` bits), so each pixel keeps its samples and their nets.
///
/// `spp` is rounded up to a power of two ([`SobolSampler::rounded_spp`]); it is only a hint.
/// Sobol indices are 64-bit ([`sobol_u64`]), so **every** `sample_index` of the `u32` range is a
/// new sample of the pixel: sample `s` is the `s`-th Sobol point in the pixel, and the first
/// `2^k` of them are a (0, k, 2)-net in the pixel for every `k` (progressive rendering past the
/// hint loses nothing). The square's side must be at most 2¹⁶ pixels (`m ≤ 16`).
///
/// **Pixels outside the image** are not an error: a pixel is read modulo the `2^m × 2^m`
/// square (its low `m` bits per axis), so pixel `(x + 2^m, y)` repeats pixel `(x, y)`'s
/// samples. An 8 × 8 image has `m = 3`: pixel (8, 0) gives pixel (0, 0)'s samples, and a 6 × 6
/// image (also `m = 3`) gives pixels 6 and 7 of each axis samples of their own, then repeats.
///
/// ```
/// use nyquist::scramble::Scramble;
/// use nyquist::sampler::{Sampler, SobolSampler};
/// let mut s = SobolSampler::new([4, 4], 4, Scramble::None, 0).unwrap();
/// s.start_pixel_sample([3, 1], 2, 0);
/// let [x, y] = s.get_pixel_2d();
/// assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
/// ```
#[derive(Clone, Debug)]
pub struct SobolSampler {
    spp: u32,
    seed: u64,
    scramble: Scramble,
    /// `scramble` is one of the Owen scrambles.
    owen: bool,
    m: u32,
    /// `inverse[r]`: the low index bits that flip target bit `r` (bits `0..m` are x's top bits,
    /// `m..2m` are y's).
    inverse: [u32; 32],
    shift: [u32; 2],
    /// `Inverse·want(pixel)` of the current pixel (see [`SobolSampler::sequence_index`]).
    pixel: [u32; 2],
    pixel_low: u32,
    /// `Inverse·have(2^b)` per bit `b` of the sample index: `have` and the inverse are linear
    /// over GF(2), so a sample's share of the index is the XOR over its set bits.
    sample_low: [u32; 32],
    /// The scrambles of dimensions `2 .. 2 + SCRAMBLES` (the camera's and the first
    /// integrator dimensions), hashed once.
    scrambles: [u32; SCRAMBLES],
    index: u64,
    /// The sample's number in the pixel (what the padding dimensions index).
    sample: u32,
    dim: u32,
}

/// The top `m` bits of `v`, as an `m`-bit number.
#[inline]
fn top(v: u32, m: u32) -> u32 {
    if m == 0 { 0 } else { v >> (32 - m) }
}

impl SobolSampler {
    /// As [`ZeroTwoSampler::rounded_spp`](super::ZeroTwoSampler::rounded_spp): the next power
    /// of two and whether it differs from `requested`.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::SobolSampler::rounded_spp(5), (8, true));
    /// ```
    pub fn rounded_spp(requested: u32) -> (u32, bool) {
        super::ZeroTwoSampler::rounded_spp(requested)
    }

    /// A Sobol sampler for an image of `resolution` pixels, `spp` rounded up to a power of two,
    /// scrambled by `scramble` under `seed` ([`Scramble::None`]: the plain sequence; the seed is
    /// then ignored).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0; [`Error::TooMany`] if
    /// `spp > 2³¹` or a side of the image passes 65536 (`m > 16`, see above).
    ///
    /// ```
    /// use nyquist::{sampler::{Sampler, SobolSampler}, scramble::Scramble};
    /// assert!(SobolSampler::new([16384, 16384], 4096, Scramble::None, 0).is_ok());
    /// assert!(SobolSampler::new([65537, 16], 1, Scramble::None, 0).is_err());
    /// let mut s = SobolSampler::new([8, 8], 4, Scramble::Owen, 3).unwrap();
    /// s.start_pixel_sample([2, 5], 1, 0);
    /// let [x, y] = s.get_pixel_2d();
    /// assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
        Self::build(resolution, spp, scramble, seed, sobol_u64)
    }

    /// [`SobolSampler::new`] with Sobol dimensions 0 and 1 read through `sobol01`
    /// (`sobol01(index, dim)` for `dim < 2`, equal to [`sobol_u64`]): the setup's only reads of
    /// the sequence, so that `compact::SobolSampler` builds the same sampler without its
    /// tables.
    pub(crate) fn build(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
        sobol01: impl Fn(u64, u32) -> u32 + Copy,
    ) -> Result<Self, Error> {
        let seed = if scramble == Scramble::None { 0 } else { seed };
        super::check_image(resolution, spp)?;
        let requested = spp;
        let (spp, _) = Self::rounded_spp(spp);
        if spp == 0 {
            return Err(Error::TooMany {
                what: "spp",
                value: u64::from(requested),
                max: 1 << 31,
            });
        }
        let side = resolution[0].max(resolution[1]);
        let m = 32 - (side - 1).leading_zeros();
        if m > 16 {
            return Err(Error::TooMany {
                what: "resolution",
                value: u64::from(side),
                max: 1 << 16,
            });
        }
        let shift = if scramble != Scramble::PermuteDigits {
            [0; 2]
        } else {
            let low = |d: u64| {
                let h = hash2(seed, d) as u32;
                if m == 0 { h } else { h & (u32::MAX >> m) }
            };
            [low(0), low(1)]
        };
        let inverse = Self::invert(m, sobol01);
        let mut sample_low = [0u32; 32];
        for (b, low) in sample_low.iter_mut().enumerate() {
            // 2m + b < 64: m ≤ 16 and b < 32.
            *low = apply_inverse(&inverse, have(1u64 << (2 * m as usize + b), m, sobol01));
        }
        let scrambles = core::array::from_fn(|k| match scramble {
            Scramble::None => 0,
            Scramble::PermuteDigits => xor_scramble(seed, 2 + k as u32),
            Scramble::FastOwen | Scramble::Owen => owen_seed(seed, 2 + k as u32),
        });
        let mut sampler = Self {
            spp,
            seed,
            scramble,
            owen: matches!(scramble, Scramble::FastOwen | Scramble::Owen),
            m,
            inverse,
            shift,
            pixel: [0; 2],
            pixel_low: 0,
            sample_low,
            scrambles,
            index: 0,
            sample: 0,
            dim: 0,
        };
        sampler.pixel_low = apply_inverse(&sampler.inverse, sampler.want([0; 2]));
        Ok(sampler)
    }

    /// Gauss–Jordan elimination over GF(2) of the map "low 2m index bits → top m bits of
    /// dimensions 0 and 1".
    fn invert(m: u32, sobol01: impl Fn(u64, u32) -> u32) -> [u32; 32] {
        let n = (2 * m) as usize;
        // rows[i]: low 32 bits = row i of the map (which index bits feed target bit i),
        // high 32 bits = row i of the identity, becoming the inverse.
        let mut rows = [0u64; 32];
        for c in 0..n as u32 {
            let x = top(sobol01(1 << c, 0), m);
            let y = top(sobol01(1 << c, 1), m);
            let target = u64::from(x) | (u64::from(y) << m);
            for (i, row) in rows.iter_mut().enumerate().take(n) {
                if target >> i & 1 == 1 {
                    *row |= 1 << c;
                }
            }
        }
        for (i, row) in rows.iter_mut().enumerate().take(n) {
            *row |= 1 << (32 + i);
        }
        for col in 0..n {
            // Dimensions 0 and 1 of Sobol form a (0,2)-sequence, so the map is invertible and
            // a pivot always exists; `unwrap_or` keeps this total regardless.
            let pivot = (col..n).find(|&r| rows[r] >> col & 1 == 1).unwrap_or(col);
            rows.swap(col, pivot);
            for r in 0..n {
                if r != col && rows[r] >> col & 1 == 1 {
                    rows[r] ^= rows[col];
                }
            }
        }
        // Row i of the inverse says which target bits feed low bit i; transpose to columns.
        let mut inverse = [0u32; 32];
        for (i, row) in rows.iter().enumerate().take(n) {
            let inv_row = (row >> 32) as u32;
            for (r, col) in inverse.iter_mut().enumerate().take(n) {
                if inv_row >> r & 1 == 1 {
                    *col |= 1 << i;
                }
            }
        }
        inverse
    }

    /// The global Sobol index of sample `sample_index` of `pixel` (coordinates wrap modulo
    /// `2^m`): below `2^(2m) · (sample_index + 1)`.
    ///
    /// ```
    /// use nyquist::scramble::Scramble;
    /// use nyquist::sampler::SobolSampler;
    /// let s = SobolSampler::new([2, 2], 1, Scramble::None, 0).unwrap();
    /// let mut all: Vec<u64> = (0..4).map(|k| s.sequence_index([k % 2, k / 2], 0)).collect();
    /// all.sort();
    /// assert_eq!(all, [0, 1, 2, 3]);
    /// // Past the spp hint, and past 2^32: sample 2^31 of a 65536² image.
    /// let big = SobolSampler::new([65536, 65536], 1, Scramble::None, 0).unwrap();
    /// assert_eq!(big.sequence_index([0, 0], 1 << 31) >> 32, 1 << 31);
    /// ```
    pub fn sequence_index(&self, pixel: [u32; 2], sample_index: u32) -> u64 {
        self.sequence_index_by(pixel, sample_index, sobol_u64)
    }

    /// [`SobolSampler::sequence_index`] with Sobol dimensions 0 and 1 read through `sobol01`
    /// (see [`SobolSampler::build`]).
    pub(crate) fn sequence_index_by(
        &self,
        pixel: [u32; 2],
        sample_index: u32,
        sobol01: impl Fn(u64, u32) -> u32,
    ) -> u64 {
        let high = self.sample_bits(sample_index);
        high | u64::from(apply_inverse(
            &self.inverse,
            self.want(pixel) ^ have(high, self.m, sobol01),
        ))
    }

    /// The index bits sample `s` sets above the pixel's `2m` (`2m + 32 ≤ 64`).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample_bits(&self, s: u32) -> u64 {
        u64::from(s) << (2 * self.m)
    }

    /// The padding key of `pixel`, from its coordinates modulo `2^m`.
    fn pad_key_of(&self, pixel: [u32; 2]) -> u32 {
        super::padding_key(u64::from(self.want(pixel)), self.seed)
    }

    /// The pixel's low coordinate bits, interleaved as the index search wants them.
    #[inline]
    fn want(&self, pixel: [u32; 2]) -> u32 {
        let m = self.m;
        let mask = if m == 0 { 0 } else { u32::MAX >> (32 - m) };
        (pixel[0] & mask) | ((pixel[1] & mask) << m)
    }

    /// The scramble used, [`Scramble::None`] included.
    ///
    /// ```
    /// use nyquist::{sampler::SobolSampler, scramble::Scramble};
    /// assert_eq!(SobolSampler::new([4, 4], 4, Scramble::PermuteDigits, 1).unwrap().scramble(), Scramble::PermuteDigits);
    /// ```
    pub fn scramble(&self) -> Scramble {
        self.scramble
    }

    #[inline]
    fn sample(&self, dim: u32) -> f32 {
        // Below 2³² the 32-bit product alone: the path (and speed) of the 32-bit sampler.
        if (self.index >> 32) as u32 == 0 {
            self.sample_by(dim, |i, d| sobol_u32(i as u32, d), padded_u32)
        } else {
            self.sample_wide(dim)
        }
    }

    /// [`SobolSampler::sample`] at an index past 2³², out of line.
    #[cold]
    #[inline(never)]
    fn sample_wide(&self, dim: u32) -> f32 {
        self.sample_by(dim, sobol_u64, padded_u32)
    }

    /// Dimension `dim` of the current sample, with `sobol(index, d)` (`d < 1024`, equal to
    /// [`sobol_u64`] for the desktop sampler) the source of the Sobol values and `pad` (equal
    /// to [`padded_u32`]) that of the padding dimensions.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn sample_by(
        &self,
        dim: u32,
        sobol: impl Fn(u64, u32) -> u32,
        pad: impl Fn(u32, u64, u32) -> u32,
    ) -> f32 {
        if dim >= DIMS {
            return self.padded(dim, pad);
        }
        if self.owen {
            return self.owen_sample(dim, sobol);
        }
        let mut v = sobol(self.index, dim);
        if dim < 2 {
            // `m ≤ 16` (checked in `new`): keep the bits below the pixel's.
            v = (v ^ self.shift[dim as usize]) << self.m;
        } else if let Some(&x) = self.scrambles.get((dim - 2) as usize) {
            v ^= x;
        } else if self.scramble == Scramble::PermuteDigits {
            v ^= xor_scramble(self.seed, dim);
        }
        fraction_to_f32(v)
    }

    /// [`SobolSampler::sample`] under an Owen scramble, out of line so that the plain and
    /// digit-permuted paths stay as short as before the scrambles came (inlined, the match
    /// cost the camera sample 14 %).
    #[inline(never)]
    fn owen_sample(&self, dim: u32, sobol: impl Fn(u64, u32) -> u32) -> f32 {
        let v = sobol(self.index, dim);
        let seed = if dim >= 2
            && let Some(&x) = self.scrambles.get((dim - 2) as usize)
        {
            x
        } else {
            owen_seed(self.seed, dim)
        };
        // Dimensions 0 and 1: the fraction inside the pixel.
        let w = if dim < 2 { v << self.m } else { v };
        fraction_to_f32(scramble_u32(w, seed, self.scramble))
    }

    /// A padding dimension (`dim >= 1024`) of the current sample, through `pad`, keyed by the
    /// current pixel (hashed here: padding dimensions are rare, pixel changes are not).
    #[cold]
    #[inline(never)]
    fn padded(&self, dim: u32, pad: impl Fn(u32, u64, u32) -> u32) -> f32 {
        let key = self.pad_key_of(self.pixel);
        fraction_to_f32(pad(key, u64::from(self.sample), dim))
    }

    /// Dimensions `dim, dim + 1, …` into `out` as `sample` gives them, when they are a run of
    /// dimensions 2 and up with cached scrambles and byte tables at an index below 2³²: one
    /// loop. `false`, with nothing written, otherwise.
    #[inline]
    fn batch(&self, dim: u32, out: &mut [f32]) -> bool {
        let d = dim as usize;
        let Ok(index) = u32::try_from(self.index) else {
            return false;
        };
        !self.owen
            && d >= 2
            && self
                .scrambles
                .get(d - 2..)
                .and_then(|shifts| sobol_run_f32(index, d, shifts, out))
                .is_some()
    }
}

/// Number of dimensions (from 2 on) whose scramble the sampler caches.
const SCRAMBLES: usize = 30;

/// The seed of dimension `dim`'s Owen scramble.
#[inline]
fn owen_seed(seed: u64, dim: u32) -> u32 {
    (hash2(seed, u64::from(dim)) >> 32) as u32
}

/// The XOR word (digit permutation) of dimension `dim ≥ 2` under `seed`; every seed, 0
/// included, gives a permutation.
#[inline]
fn xor_scramble(seed: u64, dim: u32) -> u32 {
    hash2(seed, u64::from(dim)) as u32
}

/// The top `m` bits of dimensions 0 and 1 of Sobol point `high`, interleaved.
#[inline]
fn have(high: u64, m: u32, sobol01: impl Fn(u64, u32) -> u32) -> u32 {
    top(sobol01(high, 0), m) | (top(sobol01(high, 1), m) << m)
}

/// `inverse · t` over GF(2).
#[inline]
fn apply_inverse(inverse: &[u32; 32], mut t: u32) -> u32 {
    let mut low = 0u32;
    while t != 0 {
        low ^= inverse[t.trailing_zeros() as usize];
        t &= t - 1;
    }
    low
}

impl Sampler for SobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        // Equal to `sequence_index(pixel, sample_index)`, split into a per-pixel and a
        // per-sample share (both linear over GF(2)).
        if pixel != self.pixel {
            self.pixel = pixel;
            self.pixel_low = apply_inverse(&self.inverse, self.want(pixel));
        }
        let high = self.sample_bits(sample_index);
        let mut low = self.pixel_low;
        let mut bits = sample_index;
        while bits != 0 {
            low ^= self.sample_low[bits.trailing_zeros() as usize];
            bits &= bits - 1;
        }
        self.index = high | u64::from(low);
        self.sample = sample_index;
        self.dim = dim;
    }

    super::global_point_dimensions!();

    super::global_point_arrays!();
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{
        consistent_values, is_zero_two_net, progressive_nets, progressive_samples_are_distinct,
        threads_agree,
    };

    /// Past 2³², every dimension is the Sobol point of the 64-bit index (unscrambled: the plain
    /// `sobol_u64`; dimensions 0 and 1 the fraction inside the pixel).
    #[test]
    fn values_at_64_bit_indices_are_sobol_u64() {
        let mut s = SobolSampler::new([65536, 65536], 1, Scramble::None, 0).unwrap();
        for (pixel, i) in [([7u32, 9u32], 1u32), ([65535, 3], 1000)] {
            let index = s.sequence_index(pixel, i);
            assert!(index >> 32 != 0);
            s.start_pixel_sample(pixel, i, 2);
            let v: Vec<f32> = (0..4).map(|_| s.get_1d()).collect();
            let want: Vec<f32> = (2..6)
                .map(|d| fraction_to_f32(sobol_u64(index, d)))
                .collect();
            assert_eq!(v, want, "{pixel:?} {i}");
            s.start_pixel_sample(pixel, i, 0);
            let p = s.get_pixel_2d();
            assert_eq!(
                p,
                [0, 1].map(|d| fraction_to_f32(sobol_u64(index, d) << 16))
            );
        }
    }

    /// Dimensions past 1024: padding, per pixel (repeated where the pixels repeat).
    #[test]
    fn padding_repeats_where_the_pixels_repeat() {
        for scramble in Scramble::ALL {
            let mut s = SobolSampler::new([8, 8], 4, scramble, 7).unwrap();
            crate::sampler::tests::padding_holds(&mut s, [5, 6], [6, 6], [13, 14], 64);
        }
    }

    /// The in-pixel offset (`get_pixel_2d`, exact at any pixel coordinate, where `p_film` would
    /// round) and the next six dimensions of sample `i` of `pixel`.
    fn record(s: &mut impl Sampler, pixel: [u32; 2], i: u32) -> Vec<f32> {
        s.start_pixel_sample(pixel, i, 0);
        let mut v = s.get_pixel_2d().to_vec();
        v.extend((0..6).map(|_| s.get_1d()));
        v
    }
    use std::vec::Vec;

    /// Past the spp hint and past 32-bit indices: new samples, nets at every power of two.
    #[test]
    fn samples_past_the_hint_are_new_and_keep_the_nets() {
        for scramble in Scramble::ALL {
            let mut s = SobolSampler::new([64, 48], 4, scramble, 9).unwrap();
            progressive_nets(&mut s, [5, 40], None, 12);
            let mut big = SobolSampler::new([65536, 65536], 1, scramble, 9).unwrap();
            // 2m = 32: every sample past the first needs index bits past 2^32.
            assert!(big.sequence_index([7, 9], 1) >> 32 == 1);
            progressive_nets(&mut big, [7, 9], None, 10);
        }
        let mut s = SobolSampler::new([640, 480], 16, Scramble::FastOwen, 3).unwrap();
        assert_eq!(
            progressive_samples_are_distinct(&mut s, [100, 200]),
            1 << 20
        );
        let e = SobolSampler::new([65537, 4], 1, Scramble::None, 0).unwrap_err();
        assert_eq!(
            e,
            Error::TooMany {
                what: "resolution",
                value: 65537,
                max: 65536
            }
        );
    }

    /// [`dimensions_past_1024_are_padded_per_pixel`]'s first padded value per scramble (its
    /// `f32` bits without the low 12).
    const PADDED_FIRST: [u32; 4] = [0x3f1af, 0x3dc1a, 0x3dc1a, 0x3dc1a];

    /// Dimensions past 1024 are padding keyed by the pixel: (0, k, 2)-nets in each pixel, not
    /// a repeat of dimension `d − 1024`.
    #[test]
    fn dimensions_past_1024_are_padded_per_pixel() {
        for scramble in Scramble::ALL {
            let mut s = SobolSampler::new([32, 32], 16, scramble, 4).unwrap();
            // The padding's 4-D blocks start at multiples of 4: 4000 and 4001 are one block's
            // first pair, an Owen-scrambled Sobol (0, 2)-sequence of the pixel's sample index.
            let pairs: Vec<[f32; 2]> = (0..256)
                .map(|i| {
                    s.start_pixel_sample([3, 30], i, 4000);
                    s.get_2d()
                })
                .collect();
            for k in 0..=8 {
                assert!(is_zero_two_net(&pairs[..1 << k]), "{scramble:?} {k}");
            }
            let values = |s: &mut SobolSampler, pixel: [u32; 2], d: u32| -> Vec<f32> {
                (0..16)
                    .map(|i| {
                        s.start_pixel_sample(pixel, i, d);
                        s.get_1d()
                    })
                    .collect()
            };
            let a = values(&mut s, [3, 30], 2000);
            assert_ne!(values(&mut s, [3, 30], 1030), values(&mut s, [3, 30], 6));
            assert_ne!(values(&mut s, [4, 30], 2000), a);
            assert_eq!(values(&mut s, [3, 30], 2000), a);
            // Pinned: the padding's key is part of the sampler.
            assert_eq!(
                a[0].to_bits() >> 12,
                PADDED_FIRST[scramble as usize],
                "{scramble:?}"
            );
        }
    }

    /// As documented: a pixel is read modulo the 2^m square; inside it every pixel has samples
    /// of its own (an 8 × 8 image: pixel (8, 0) is pixel (0, 0); a 6 × 6 image: pixels 6 and 7
    /// are new, 8 repeats 0).
    #[test]
    fn pixels_outside_the_image_wrap_modulo_the_square() {
        for scramble in Scramble::ALL {
            for (res, pixel, same_as) in [
                ([8, 8], [8, 0], [0, 0]),
                ([8, 8], [13, 21], [5, 5]),
                ([6, 6], [8, 7], [0, 7]),
            ] {
                let mut s = SobolSampler::new(res, 4, scramble, 5).unwrap();
                for i in 0..4 {
                    let (a, b) = (record(&mut s, pixel, i), record(&mut s, same_as, i));
                    // Dimensions 0 and 1 are the offsets inside the pixel; the rest are values.
                    assert_eq!(a, b, "{scramble:?} {res:?} {pixel:?} {i}");
                }
            }
            let mut s = SobolSampler::new([6, 6], 4, scramble, 5).unwrap();
            assert_ne!(record(&mut s, [6, 0], 0), record(&mut s, [0, 0], 0));
            assert_ne!(record(&mut s, [7, 0], 1), record(&mut s, [5, 0], 1));
        }
    }

    /// The cached per-pixel and per-sample shares give the same index as the direct search.
    #[test]
    fn cached_index_equals_sequence_index() {
        for (res, spp, seed) in [
            ([64u32, 48u32], 16u32, 0u64),
            ([1024, 1024], 64, 5),
            ([3, 1], 1, 9),
        ] {
            let mut s =
                SobolSampler::new(res, spp, Scramble::ALL[seed as usize % 4], seed).unwrap();
            for pixel in [[0u32, 0u32], [1, 0], [63, 47], [5, 40], [1023, 2]] {
                for i in [0u32, 1, 2, 3, 7, spp - 1, spp, 3 * spp + 1, u32::MAX] {
                    s.start_pixel_sample(pixel, i, 0);
                    assert_eq!(s.index, s.sequence_index(pixel, i), "{pixel:?} {i}");
                }
            }
        }
    }

    #[test]
    fn sobol_arrays_equal_values_taken_one_at_a_time() {
        for scramble in Scramble::ALL {
            let s = SobolSampler::new([640, 480], 16, scramble, 9).unwrap();
            crate::sampler::tests::arrays_are_values_in_order(&s);
        }
    }

    #[test]
    fn sobol_is_consistent_and_thread_independent() {
        for scramble in Scramble::ALL {
            let s = SobolSampler::new([40, 30], 16, scramble, 9).unwrap();
            consistent_values(&s);
            threads_agree(&s);
        }
        for how in Scramble::ALL {
            let s = SobolSampler::new([40, 30], 16, how, 9).unwrap();
            consistent_values(&s);
            threads_agree(&s);
            crate::sampler::tests::arrays_are_values_in_order(&s);
        }
    }

    /// An Owen scramble maps intervals of 1/64 onto intervals of 1/64 one to one, so in every
    /// dimension a pixel's 64 samples hit exactly as many of them as unscrambled (all 64 in
    /// dimensions 0 and 1); and the values change.
    #[test]
    fn scrambles_keep_strata_and_change_values() {
        let plain = SobolSampler::new([16, 16], 64, Scramble::None, 0).unwrap();
        for how in [Scramble::FastOwen, Scramble::Owen] {
            let mut s = SobolSampler::new([16, 16], 64, how, 4).unwrap();
            let mut p = plain.clone();
            let mut differ = 0;
            for d in 0..12u32 {
                let (mut seen, mut seen_plain) = ([false; 64], [false; 64]);
                for i in 0..64 {
                    s.start_pixel_sample([5, 9], i, d);
                    p.start_pixel_sample([5, 9], i, d);
                    let (a, b) = (s.get_1d(), p.get_1d());
                    differ += usize::from(a != b);
                    seen[(a * 64.0) as usize] = true;
                    seen_plain[(b * 64.0) as usize] = true;
                }
                let count = |v: &[bool; 64]| v.iter().filter(|&&x| x).count();
                assert_eq!(count(&seen), count(&seen_plain), "{how:?} dim {d}");
                if d < 2 {
                    assert_eq!(count(&seen), 64);
                }
            }
            assert!(differ > 700, "{how:?}: {differ}");
        }
    }

    #[test]
    fn sobol_pixel_samples_are_nets_for_every_power_of_two_up_to_1024() {
        for m in 0..=10 {
            for (seed, how) in [
                (0, Scramble::None),
                (5, Scramble::PermuteDigits),
                (5, Scramble::FastOwen),
                (6, Scramble::Owen),
            ] {
                let mut s = SobolSampler::new([37, 20], 1 << m, how, seed).unwrap();
                for pixel in [[0, 0], [36, 19], [5, 11]] {
                    let pts: Vec<[f32; 2]> = (0..1u32 << m)
                        .map(|i| {
                            s.start_pixel_sample(pixel, i, 0);
                            s.get_pixel_2d()
                        })
                        .collect();
                    assert!(is_zero_two_net(&pts), "spp 2^{m} seed {seed} {pixel:?}");
                }
            }
        }
    }

    #[test]
    fn sobol_pixels_own_their_global_points() {
        // Over a 4 × 4 image, the 4 × 4 × 4 samples are exactly Sobol indices 0..64, and each
        // sample's film position is the global point scaled by 4.
        let mut s = SobolSampler::new([4, 4], 4, Scramble::None, 0).unwrap();
        let mut hit = [false; 64];
        for y in 0..4u32 {
            for x in 0..4u32 {
                for i in 0..4 {
                    let idx = s.sequence_index([x, y], i);
                    hit[idx as usize] = true;
                    s.start_pixel_sample([x, y], i, 0);
                    let [u, v] = s.get_pixel_2d();
                    let gx = f64::from(sobol_u64(idx, 0)) / 4_294_967_296.0 * 4.0;
                    let gy = f64::from(sobol_u64(idx, 1)) / 4_294_967_296.0 * 4.0;
                    assert!((gx - f64::from(x) - f64::from(u)).abs() < 1e-6);
                    assert!((gy - f64::from(y) - f64::from(v)).abs() < 1e-6);
                }
            }
        }
        assert!(hit.iter().all(|&b| b));
    }

    /// Without a scramble every dimension is the plain sequence at the sample's global index
    /// (dimensions 0 and 1 as the fraction inside the pixel), past the 30 cached scramble words
    /// too; a digit permutation changes them for every seed, 0 included.
    #[test]
    fn no_scramble_is_the_plain_sequence_and_seed_0_permutes() {
        let mut plain = SobolSampler::new([4, 4], 4, Scramble::None, 9).unwrap();
        let mut permuted = SobolSampler::new([4, 4], 4, Scramble::PermuteDigits, 0).unwrap();
        let mut changed = 0;
        for pixel in [[0, 0], [3, 1]] {
            for i in 0..4 {
                let idx = plain.sequence_index(pixel, i);
                plain.start_pixel_sample(pixel, i, 0);
                permuted.start_pixel_sample(pixel, i, 0);
                for d in 0..40u32 {
                    let (a, b) = (plain.get_1d(), permuted.get_1d());
                    let v = sobol_u64(idx, d);
                    let want = if d < 2 { v << 2 } else { v };
                    assert_eq!(
                        a,
                        fraction_to_f32(want),
                        "pixel {pixel:?} sample {i} dim {d}"
                    );
                    changed += usize::from(a != b && d >= 2);
                }
            }
        }
        assert!(changed > 8 * 30, "{changed}");
    }

    #[test]
    fn sobol_large_image_limit() {
        let mut s = SobolSampler::new([16384, 16384], 16, Scramble::PermuteDigits, 1).unwrap();
        let r = crate::sampler::tests::record(&mut s, [16383, 16383], 15);
        assert!(r.iter().all(|x| (0.0..1.0).contains(x)));
        assert_eq!(SobolSampler::rounded_spp(3), (4, true));
    }
}
