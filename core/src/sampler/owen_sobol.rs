//! Owen-scrambled Sobol per pixel, decorrelated by hashing the full pixel coordinates, the frame
//! and the seed.

use super::{CameraSample, Domain, Sampler, film_coordinate};
use crate::Error;
use crate::hash::{hash_slice, mix32};
use crate::math::fraction_to_f32;
use crate::sequence::{DimSeeds, IndexShuffle, SOBOL_DIMS, owen_sobol_rev_f32, padded_u32};

/// Dimensions whose scramble seeds are hashed once per pixel: the camera's five.
const CACHED: usize = 5;

/// Owen-scrambled Sobol samples (Burley 2020), one independent scramble per pixel and frame.
///
/// Sample `i` of pixel `p` in frame `f` is point `i` of the 1024-dimensional Owen-scrambled
/// Sobol sequence ([`OwenSobol`](crate::sequence::OwenSobol)'s construction) whose index
/// shuffle and per-dimension scrambles are seeded by a 64-bit hash of `(p.x, p.y, f, seed)`:
///
/// - every pixel's first `2^k` samples are a (0, k, 2)-net in dimensions (0, 1) (the image
///   sample) and stratified into `2^k` intervals in every dimension, for any `spp`;
/// - no tiling period and no aliasing: pixels, frames and seeds enter the hash as full 32- and
///   64-bit words, so pixel (3, 5) and (259, 517) are unrelated, and so are frame 1's sample `i`
///   and frame 0's sample `i + 65536` (samplers that add the frame to the index, or hash
///   coordinates modulo 256, repeat there);
/// - every sample index (all of `u32`) is a new point; `spp` is what the sampler reports, not a
///   wrap.
///
/// Dimensions from 1024 on are padding (Burley 2020, §6): independently seeded Owen-scrambled
/// 4-D blocks of the sample index under the pixel's key, as
/// [`OwenSobol`](crate::sequence::OwenSobol) pads, so they too are nets in every pixel and no
/// dimension repeats a lower one.
///
/// ```
/// use nyquist::sampler::{OwenSobolSampler, Sampler};
/// let mut s = OwenSobolSampler::new(16, 7).unwrap();
/// s.start_pixel_sample([3, 5], 0, 0);
/// let a = s.get_pixel_2d();
/// s.start_pixel_sample([259, 517], 0, 0);
/// assert_ne!(s.get_pixel_2d(), a);
/// let mut next = s.clone().with_frame(1);
/// next.start_pixel_sample([3, 5], 0, 0);
/// assert_ne!(next.get_pixel_2d(), a);
/// ```
#[derive(Clone, Debug)]
pub struct OwenSobolSampler {
    spp: u32,
    seed: u64,
    frame: u32,
    /// The pixel whose key is cached (`None` before the first), and that key.
    pixel: Option<[u32; 2]>,
    key: u64,
    shuffle: IndexShuffle,
    pub(crate) seeds: DimSeeds<CACHED>,
    /// The current sample's reversed shuffled index, and the sample index itself.
    pub(crate) r: u32,
    pub(crate) index: u32,
    dim: u32,
}

impl OwenSobolSampler {
    /// A sampler taking `spp` samples per pixel, frame 0.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`.
    ///
    /// ```
    /// assert!(nyquist::sampler::OwenSobolSampler::new(0, 1).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        Ok(Self {
            spp,
            seed,
            frame: 0,
            pixel: None,
            key: 0,
            shuffle: IndexShuffle::default(),
            seeds: DimSeeds::new(0),
            r: 0,
            index: 0,
            dim: 0,
        })
    }

    /// The same sampler for animation frame `frame` (a new, independent scramble per frame).
    ///
    /// ```
    /// use nyquist::sampler::OwenSobolSampler;
    /// assert_eq!(OwenSobolSampler::new(4, 1).unwrap().with_frame(9).frame(), 9);
    /// ```
    pub fn with_frame(mut self, frame: u32) -> Self {
        self.frame = frame;
        self.pixel = None;
        self
    }

    /// The frame this sampler draws for.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::OwenSobolSampler::new(4, 1).unwrap().frame(), 0);
    /// ```
    pub fn frame(&self) -> u32 {
        self.frame
    }

    /// The seed of every scramble.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::OwenSobolSampler::new(4, 3).unwrap().seed(), 3);
    /// ```
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The current pixel sample as a [`Domain`]: its dimension `d` is this sampler's dimension
    /// `d`, and [`Domain::split`], [`Domain::branch`] and the others derive sub-streams from it
    /// (valid after [`Sampler::start_pixel_sample`]; [`Sampler::domain`] returns the same).
    ///
    /// ```
    /// use nyquist::sampler::{OwenSobolSampler, Sampler};
    /// let mut s = OwenSobolSampler::new(4, 1).unwrap();
    /// s.start_pixel_sample([2, 2], 3, 6);
    /// let d = s.pixel_domain();
    /// assert_eq!(d.index(), 3);
    /// assert_eq!(d.get_1d(6), s.get_1d());
    /// ```
    pub fn pixel_domain(&self) -> Domain {
        Domain::new(self.key, u64::from(self.index))
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, dim: u32) -> f32 {
        if dim >= SOBOL_DIMS {
            return self.padded(dim);
        }
        owen_sobol_rev_f32(self.r, dim, self.seeds.get(dim))
    }

    /// A padding dimension (`dim >= 1024`) of the current sample.
    #[inline(never)]
    fn padded(&self, dim: u32) -> f32 {
        fraction_to_f32(padded_u32(self.seeds.key(), u64::from(self.index), dim))
    }

    /// Dimensions `dim, dim + 1, …` into `out`: always one run.
    #[inline]
    fn batch(&self, dim: u32, out: &mut [f32]) -> bool {
        let mut d = dim;
        for x in out {
            *x = self.sample(d);
            d = d.wrapping_add(1);
        }
        true
    }
}

impl Sampler for OwenSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if self.pixel != Some(pixel) {
            self.pixel = Some(pixel);
            let h = hash_slice(&[
                u64::from(pixel[0]),
                u64::from(pixel[1]),
                u64::from(self.frame),
                self.seed,
            ]);
            self.key = h;
            self.shuffle = IndexShuffle::new(mix32((h >> 32) as u32));
            self.seeds = DimSeeds::new(h as u32);
        }
        self.r = self.shuffle.rev(sample_index);
        self.index = sample_index;
        self.dim = dim;
    }

    super::global_point_dimensions!();

    /// The default's values, the five camera dimensions straight from the cached seeds.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        self.start_pixel_sample(pixel, sample_index, 0);
        let v: [f32; 5] =
            core::array::from_fn(|d| owen_sobol_rev_f32(self.r, d as u32, self.seeds.kept()[d]));
        self.dim = 5;
        CameraSample {
            p_film: [
                film_coordinate(pixel[0], v[0]),
                film_coordinate(pixel[1], v[1]),
            ],
            lens: [v[3], v[4]],
            time: v[2],
        }
    }

    super::global_point_arrays!();

    fn domain(&self) -> Option<Domain> {
        Some(self.pixel_domain())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{
        arrays_are_values_in_order, consistent_values, is_zero_two_net, record, threads_agree,
    };

    /// Past 1024 dimensions: each padded block's first pair is a (0, k, 2)-net in every pixel,
    /// the pixels differ, and no dimension repeats the one 1024 below it. Any sample index is
    /// a new sample.
    #[test]
    fn padding_and_samples_past_the_hint() {
        let mut s = OwenSobolSampler::new(4, 11).unwrap();
        let pair = |s: &mut OwenSobolSampler, pixel: [u32; 2], d: u32| -> Vec<[f32; 2]> {
            (0..256)
                .map(|i| {
                    s.start_pixel_sample(pixel, i, d);
                    s.get_2d()
                })
                .collect()
        };
        s.start_pixel_sample([3, 4], 9, 0);
        assert_eq!(s.domain(), Some(s.pixel_domain()));
        assert_eq!(s.pixel_domain().index(), 9);
        let a = pair(&mut s, [3, 4], 5000);
        for k in 0..=8 {
            assert!(is_zero_two_net(&a[..1 << k]), "{k}");
        }
        assert_ne!(pair(&mut s, [3, 5], 5000), a);
        assert_ne!(pair(&mut s, [3, 4], 5000 - 1024), a);
        assert_eq!(a[0][0].to_bits() >> 12, 0x3f203, "pinned");
        crate::sampler::tests::progressive_nets(&mut s, [7, 7], None, 12);
        let n = crate::sampler::tests::progressive_samples_are_distinct(&mut s, [7, 7]);
        assert_eq!(n, 1 << 20);
    }
    use std::vec::Vec;

    #[test]
    fn owen_sobol_sampler_is_consistent_and_thread_independent() {
        for seed in [0, 9] {
            let s = OwenSobolSampler::new(16, seed).unwrap();
            consistent_values(&s);
            threads_agree(&s);
            arrays_are_values_in_order(&s);
            consistent_values(&s.clone().with_frame(3));
        }
    }

    #[test]
    fn every_pixel_is_a_net_for_every_power_of_two_up_to_1024() {
        for seed in [0u64, 1, 5, 6, 10, 15] {
            let mut s = OwenSobolSampler::new(1024, seed).unwrap();
            for y in 0..10 {
                for x in 0..10 {
                    let pts: Vec<[f32; 2]> = (0..1024)
                        .map(|i| {
                            s.start_pixel_sample([x, y], i, 0);
                            s.get_pixel_2d()
                        })
                        .collect();
                    for m in 0..=10 {
                        assert!(
                            is_zero_two_net(&pts[..1 << m]),
                            "seed {seed} pixel ({x}, {y}) 2^{m}"
                        );
                    }
                    // The lens dimensions, and every dimension alone, stay stratified.
                    for d in [2u32, 3, 4, 9] {
                        let mut seen = [false; 1024];
                        for i in 0..1024 {
                            s.start_pixel_sample([x, y], i, d);
                            let v = s.get_1d();
                            assert!((0.0..1.0).contains(&v));
                            assert!(!std::mem::replace(&mut seen[(v * 1024.0) as usize], true));
                        }
                    }
                }
            }
        }
    }

    /// The cases a modulo-256 pixel hash and an index-offset frame fail: all values differ.
    #[test]
    fn pixels_and_frames_are_decorrelated() {
        let s = OwenSobolSampler::new(16, 0).unwrap();
        let values = |s: &OwenSobolSampler, pixel: [u32; 2], index: u32| {
            let mut s = s.clone();
            record(&mut s, pixel, index)
        };
        for i in 0..16 {
            let a = values(&s, [3, 5], i);
            let b = values(&s, [259, 517], i);
            assert!(
                a.iter().zip(&b).all(|(x, y)| x != y),
                "sample {i}: {a:?} {b:?}"
            );
            let f1 = values(&s.clone().with_frame(1), [3, 5], i);
            let f0 = values(&s, [3, 5], i + 65_536);
            assert!(f1.iter().zip(&f0).all(|(x, y)| x != y), "sample {i}");
        }
    }

    #[test]
    fn new_checks_spp() {
        assert_eq!(
            OwenSobolSampler::new(0, 1).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
        assert_eq!(OwenSobolSampler::new(7, 1).unwrap().samples_per_pixel(), 7);
    }
}
