//! Independent uniform random values.

use super::{Sampler, pixel_hash};
use crate::Error;
use crate::rng::uniform_f32;
use rand_pcg::Pcg32;

/// Independent uniform random samples from PCG32 (O'Neill 2014).
///
/// For sample `i` of pixel `p`, dimension `d` is output `d` of a PCG32 generator whose state
/// is a hash of (`p`, `i`, seed), reached with PCG's O(log d) jump-ahead, so any value can be
/// asked for first. (Hashing the sample index into the state, rather than jumping `i · 65536`
/// ahead in one per-pixel stream, keeps the jump short: the camera sample needs none.)
/// Every dimension of the `u32` range is its own output (no wrap to an earlier one; the jump is
/// at most 32 steps), and every `sample_index` gives new values (no wrap at
/// `samples_per_pixel`).
///
/// ```
/// use nyquist::sampler::{RandomSampler, Sampler};
/// let mut s = RandomSampler::new(16, 1).unwrap();
/// s.start_pixel_sample([0, 0], 0, 5);
/// let x = s.get_1d();
/// s.start_pixel_sample([0, 0], 0, 4);
/// s.get_1d();
/// assert_eq!(s.get_1d(), x);
/// ```
#[derive(Clone, Debug)]
pub struct RandomSampler {
    spp: u32,
    seed: u64,
    rng: Pcg32,
    pixel: [u32; 2],
    /// `hash(pixel, seed)`.
    key: u64,
    /// `hash(key, sample index)`: the generator state at dimension 0.
    base: u64,
    dim: u32,
}

/// PCG stream selector shared by every pixel (the state differs per pixel).
const STREAM: u64 = 0x2545_f491_4f6c_dd1d;

impl RandomSampler {
    /// A random sampler with `spp` samples per pixel.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`.
    ///
    /// ```
    /// assert!(nyquist::sampler::RandomSampler::new(0, 1).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        if spp == 0 {
            return Err(Error::ZeroSize { what: "spp" });
        }
        Ok(Self {
            spp,
            seed,
            rng: Pcg32::new(0, STREAM),
            pixel: [0; 2],
            key: pixel_hash([0; 2], seed, 0x7261_6e64),
            base: 0,
            dim: 0,
        })
    }

    fn at(&self, dim: u32) -> Pcg32 {
        let mut rng = Pcg32::new(self.base, STREAM);
        if dim != 0 {
            rng.advance(u64::from(dim));
        }
        rng
    }
}

impl Sampler for RandomSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if pixel != self.pixel {
            self.pixel = pixel;
            self.key = pixel_hash(pixel, self.seed, 0x7261_6e64);
        }
        self.base = crate::hash::mix64(
            self.key ^ u64::from(sample_index).wrapping_mul(0x9e37_79b9_7f4a_7c15),
        );
        self.dim = dim;
        self.rng = self.at(dim);
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_1d(&mut self) -> f32 {
        let v = uniform_f32(&mut self.rng);
        self.dim = self.dim.wrapping_add(1);
        if self.dim == 0 {
            // The cursor wrapped past u32::MAX: dimension 0 again.
            self.rng = self.at(0);
        }
        v
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_2d(&mut self) -> [f32; 2] {
        let u = self.get_1d();
        [u, self.get_1d()]
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        if self.dim == 0 {
            // The cursor is already at dimension 0 (as after `camera_sample`'s start).
            return self.get_2d();
        }
        let mut rng = self.at(0);
        let p = [uniform_f32(&mut rng), uniform_f32(&mut rng)];
        if self.dim < 2 {
            self.dim = 2;
            self.rng = rng;
        }
        p
    }

    /// The default arrays: one dimension per value.
    fn arrays_are_dimension_runs(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// No dimension repeats an earlier one: 65536 and up are their own outputs, a run across
    /// 65536 equals starting there, and the cursor past `u32::MAX` starts again at 0.
    #[test]
    fn dimensions_do_not_wrap_before_u32_max() {
        let mut s = RandomSampler::new(4, 9).unwrap();
        let at = |s: &mut RandomSampler, d: u32| {
            s.start_pixel_sample([3, 4], 1, d);
            s.get_1d()
        };
        for d in [0u32, 1, 7, 60_000] {
            assert_ne!(at(&mut s, d), at(&mut s, d + 65_536), "{d}");
        }
        s.start_pixel_sample([3, 4], 1, 65_534);
        let run = [s.get_1d(), s.get_1d(), s.get_1d()];
        assert_eq!(run, [65_534, 65_535, 65_536].map(|d| at(&mut s, d)));
        s.start_pixel_sample([3, 4], 1, u32::MAX);
        let (last, first) = (s.get_1d(), s.get_1d());
        assert_eq!([last, first], [at(&mut s, u32::MAX), at(&mut s, 0)]);
    }
}
