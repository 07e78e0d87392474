//! pbrt-v2's low-discrepancy sampler: a scrambled, shuffled (0,2)-sequence per pixel.

use super::{Sampler, pixel_hash};
use crate::Error;
use crate::hash::{ArrayOrder, Permutation, mix64};
use crate::sequence::ZeroTwo;

/// Splits a 64-bit hash into the two 32-bit XOR scrambles of a [`ZeroTwo`].
#[inline]
fn scrambles(h: u64) -> [u32; 2] {
    [h as u32, (h >> 32) as u32]
}

/// Folds a 64-bit hash into a 32-bit permutation seed.
#[inline]
fn fold(h: u64) -> u32 {
    h as u32 ^ (h >> 32) as u32
}

/// The smallest power of two ≥ `requested` and whether that differs from `requested`
/// (`(0, true)` if `requested` is 0 or above 2³¹: no such `u32`).
fn round_up(requested: u32) -> (u32, bool) {
    match requested.checked_next_power_of_two() {
        Some(p) if requested > 0 => (p, p != requested),
        _ => (0, true),
    }
}

/// pbrt-v2's `LDSampler`: every pixel's samples, for every dimension pair, are the first `spp`
/// points of a (0,2)-sequence ([`ZeroTwo`]: van der Corput × Sobol's second dimension) with a
/// random XOR scramble, visited in a hash-permuted order.
///
/// For pair `k` (the image sample is pair 0; [`Sampler::get_2d`] at dimension `d` is pair `d`),
/// sample `i` of pixel `p` is point `permute(i, spp, h)` of `ZeroTwo::new(scramble(h))`, with
/// `h = hash(hash(p, seed), k)` — except the image pair, which takes point `i` itself (as
/// pbrt-v2 does: one order is enough, the others are shuffled against it). A scramble and a
/// reordering keep the first `spp` points a (0, log₂ spp, 2)-net, so every pair is stratified in
/// every elementary interval; the permutations decorrelate the pairs from each other. 1D values
/// use the van der Corput component the same way.
///
/// `spp` is rounded up to a power of two ([`ZeroTwoSampler::rounded_spp`] says so ahead of
/// time); `sample_index >= spp` wraps modulo `spp`. Arrays ([`Sampler::get_array_1d`],
/// [`Sampler::get_array_2d`]) are scrambled, shuffled (0,2) points, their size rounded to a power
/// of two by [`Sampler::round_size`].
///
/// ```
/// use nyquist::sampler::{Sampler, ZeroTwoSampler};
/// assert_eq!(ZeroTwoSampler::rounded_spp(6), (8, true));
/// let mut s = ZeroTwoSampler::new(6, 0).unwrap();
/// assert_eq!(s.samples_per_pixel(), 8);
/// let mut seen = [false; 8];
/// for i in 0..8 {
///     s.start_pixel_sample([1, 1], i, 0);
///     seen[(s.get_pixel_2d()[0] * 8.0) as usize] = true;
/// }
/// assert!(seen.iter().all(|&b| b)); // one sample in each column of width 1/8
/// ```
#[derive(Clone, Debug)]
pub struct ZeroTwoSampler {
    spp: u32,
    seed: u64,
    pixel: [u32; 2],
    /// `hash(pixel, seed)`, cached across samples of one pixel.
    pixel_key: u64,
    /// The camera's pairs of the current pixel (image, time, lens), built once per pixel.
    camera: [PairSource; 3],
    index: u32,
    dim: u32,
}

/// Odd constant separating dimension pairs in the per-pair hash.
const PAIR_STEP: u64 = 0x9e37_79b9_7f4a_7c15;
const ARRAY_STEP: u64 = 0xc2b2_ae3d_27d4_eb4f;

/// The per-(pixel, pair) shuffle and scramble: pair `pair` of sample `i` is point `perm(i)` of
/// `ZeroTwo::new(scramble)`.
#[derive(Clone, Copy, Debug)]
struct PairSource {
    perm: Permutation,
    z: ZeroTwo,
}

impl PairSource {
    #[inline]
    fn new(pixel_key: u64, spp: u32, pair: u32) -> PairSource {
        let h = mix64(pixel_key ^ u64::from(pair).wrapping_mul(PAIR_STEP));
        PairSource {
            perm: Permutation::new(spp, fold(h)),
            z: ZeroTwo::new(scrambles(mix64(h ^ 0x3032_3032))),
        }
    }

    #[inline]
    fn point(&self, index: u32) -> [f32; 2] {
        self.z.sample_2d(self.perm.apply(index))
    }
}

/// The pair keys of the camera's dimensions: image (0), time (dimension 2, a 1D value, so in the
/// 1D key space) and lens (3).
const CAMERA_PAIRS: [u32; 3] = [0, 2 | 0x8000_0000, 3];

fn camera_sources(pixel_key: u64, spp: u32) -> [PairSource; 3] {
    // The image pair (0) is read in sample order: its permutation is never applied, so a
    // one-element one (free to build) stands in.
    CAMERA_PAIRS.map(|pair| PairSource::new(pixel_key, if pair == 0 { 1 } else { spp }, pair))
}

impl ZeroTwoSampler {
    /// The samples per pixel a request of `requested` becomes (the next power of two), and
    /// whether that differs from `requested`, so a front end can print a notice. `(0, true)` for
    /// 0 or a request above 2³¹ (which [`ZeroTwoSampler::new`] rejects).
    ///
    /// ```
    /// use nyquist::sampler::ZeroTwoSampler;
    /// assert_eq!(ZeroTwoSampler::rounded_spp(16), (16, false));
    /// assert_eq!(ZeroTwoSampler::rounded_spp(17), (32, true));
    /// ```
    pub fn rounded_spp(requested: u32) -> (u32, bool) {
        round_up(requested)
    }

    /// A (0,2) sampler with `spp` rounded up to a power of two.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`; [`Error::TooMany`] if `spp > 2³¹`.
    ///
    /// ```
    /// use nyquist::sampler::ZeroTwoSampler;
    /// assert!(ZeroTwoSampler::new(0, 0).is_err());
    /// assert!(ZeroTwoSampler::new((1 << 31) + 1, 0).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        let requested = spp;
        let (spp, _) = round_up(spp);
        if spp == 0 {
            return Err(Error::TooMany {
                what: "spp",
                value: u64::from(requested),
                max: 1 << 31,
            });
        }
        Ok(Self {
            spp,
            seed,
            pixel: [0; 2],
            pixel_key: pixel_hash([0; 2], seed, 0x3032),
            camera: camera_sources(pixel_hash([0; 2], seed, 0x3032), spp),
            index: 0,
            dim: 0,
        })
    }

    /// The key of an integrator array at dimension `d` of the current sample: one hash of the
    /// cached pixel key, the sample index, the dimension and the array kind.
    #[inline]
    fn array_key(&self, d: u32, tag: u64) -> u64 {
        mix64(
            self.pixel_key
                ^ u64::from(self.index).wrapping_mul(PAIR_STEP)
                ^ u64::from(d).wrapping_mul(ARRAY_STEP)
                ^ tag,
        )
    }

    #[inline]
    fn point(&self, pair: u32) -> [f32; 2] {
        match CAMERA_PAIRS.iter().position(|&p| p == pair) {
            // The image pair keeps the sample order (`spp` is a power of two).
            Some(0) => self.camera[0].z.sample_2d(self.index & (self.spp - 1)),
            Some(k) => self.camera[k].point(self.index),
            None => PairSource::new(self.pixel_key, self.spp, pair).point(self.index),
        }
    }
}

impl Sampler for ZeroTwoSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if pixel != self.pixel {
            self.pixel = pixel;
            self.pixel_key = pixel_hash(pixel, self.seed, 0x3032);
            self.camera = camera_sources(self.pixel_key, self.spp);
        }
        self.index = sample_index;
        self.dim = dim;
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_1d(&mut self) -> f32 {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(1);
        // A different key space from the pairs, so a 1D value is not a pair's first coordinate.
        self.point(d | 0x8000_0000)[0]
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_2d(&mut self) -> [f32; 2] {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(2);
        self.point(d)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        self.point(0)
    }

    fn round_size(&self, n: u32) -> u32 {
        n.checked_next_power_of_two().unwrap_or(1 << 31)
    }

    fn get_array_1d(&mut self, out: &mut [f32]) {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(1);
        let h = self.array_key(d, 0x6131);
        let n = u32::try_from(out.len()).unwrap_or(u32::MAX);
        let z = ZeroTwo::new(scrambles(mix64(h ^ 1)));
        let order = ArrayOrder::new(n, h);
        for (j, x) in (0..n).zip(out) {
            *x = z.sample_2d(order.apply(j))[0];
        }
    }

    fn get_array_2d(&mut self, out: &mut [f32]) {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(2);
        let h = self.array_key(d, 0x6132);
        let n = u32::try_from(out.len() / 2).unwrap_or(u32::MAX);
        let z = ZeroTwo::new(scrambles(mix64(h ^ 2)));
        let order = ArrayOrder::new(n, h);
        for (j, p) in (0..n).zip(out.chunks_exact_mut(2)) {
            let [u, v] = z.sample_2d(order.apply(j));
            p[0] = u;
            p[1] = v;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{consistent_values, is_latin, is_zero_two_net, threads_agree};
    use std::vec::Vec;

    #[test]
    fn zero_two_is_consistent_and_thread_independent() {
        let s = ZeroTwoSampler::new(16, 3).unwrap();
        consistent_values(&s);
        threads_agree(&s);
    }

    #[test]
    fn zero_two_pixel_samples_are_nets_for_every_power_of_two_up_to_1024() {
        for m in 0..=10 {
            let mut s = ZeroTwoSampler::new(1 << m, 7).unwrap();
            for pixel in [[0, 0], [3, 9], [1000, 7]] {
                for (dim, what) in [(0, "image"), (3, "lens"), (9, "pair 9")] {
                    let pts: Vec<[f32; 2]> = (0..1u32 << m)
                        .map(|i| {
                            s.start_pixel_sample(pixel, i, dim);
                            if dim == 0 {
                                s.get_pixel_2d()
                            } else {
                                s.get_2d()
                            }
                        })
                        .collect();
                    assert!(is_zero_two_net(&pts), "spp 2^{m} {pixel:?} {what}");
                }
                let xs: Vec<f32> = (0..1u32 << m)
                    .map(|i| {
                        s.start_pixel_sample(pixel, i, 2);
                        s.get_1d()
                    })
                    .collect();
                assert!(is_latin(&xs, 1), "spp 2^{m} time");
            }
        }
    }

    #[test]
    fn zero_two_arrays_are_nets() {
        let mut s = ZeroTwoSampler::new(4, 1).unwrap();
        assert_eq!(s.round_size(5), 8);
        for n in [1usize, 4, 16, 64] {
            s.start_pixel_sample([2, 2], 1, 5);
            let mut a = std::vec![0.0f32; 2 * n];
            s.get_array_2d(&mut a);
            let pts: Vec<[f32; 2]> = a.chunks_exact(2).map(|p| [p[0], p[1]]).collect();
            assert!(is_zero_two_net(&pts), "n={n}");
            let mut b = std::vec![0.0f32; n];
            s.get_array_1d(&mut b);
            assert!(is_latin(&b, 1));
        }
    }
}
