//! Stratified (jittered) and uniform (cell-centre) sampling, hash-permuted per dimension.

use super::{CameraSample, Sampler, film_coordinate, pixel_hash};
use crate::Error;
use crate::hash::{ArrayOrder, Permutation, mix64, permute, unit_f32};
use crate::math::ONE_MINUS_EPSILON;

/// `x ≥ 0` (finite by construction here) kept below 1: one `minss`, no branch.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn below_one(x: f32) -> f32 {
    x.min(ONE_MINUS_EPSILON)
}

pub use crate::stratify::Jitter;

/// Stratified sampling: `x_samples × y_samples` strata per pixel (pbrt's `StratifiedSampler`).
///
/// - The image sample (dimensions 0, 1) and every [`Sampler::get_2d`] pair are stratified on
///   the `x_samples × y_samples` grid: sample `i` of a pixel takes stratum
///   `s = permute(i, spp, hash(pixel, dim, seed))`, cell `(s % x_samples, s / x_samples)`.
/// - Every [`Sampler::get_1d`] value is stratified on `spp` strata: `(s + jitter) / spp`.
/// - Each dimension has its own permutation, so time and lens are shuffled against image
///   position; the jitter comes from `hash(pixel, i, dim, seed)`.
/// - Arrays ([`Sampler::get_array_1d`] / [`Sampler::get_array_2d`]) are Latin hypercubes of
///   their length (one value per stratum on every axis), hash-permuted: any array length works,
///   where a grid of strata would need a count such as 7 to factor (pbrt-v2's `StratifiedSampler`
///   answers that with Latin hypercubes too).
///
/// `sample_index >= spp` wraps the stratum modulo `spp` (the jitter still changes).
///
/// ```
/// use nyquist::sampler::{Jitter, Sampler, StratifiedSampler};
/// let mut s = StratifiedSampler::new(4, 4, Jitter::Jittered, 9).unwrap();
/// let mut seen = [false; 16];
/// for i in 0..16 {
///     s.start_pixel_sample([2, 3], i, 0);
///     let [x, y] = s.get_pixel_2d();
///     seen[(y * 4.0) as usize * 4 + (x * 4.0) as usize] = true;
/// }
/// assert!(seen.iter().all(|&b| b)); // one sample per stratum
/// ```
#[derive(Clone, Debug)]
pub struct StratifiedSampler {
    xs: u32,
    ys: u32,
    spp: u32,
    /// Lemire's `⌊2⁶⁴ / xs⌋ + 1` (0 when `xs == 1`): `s / xs` by one multiplication.
    div_xs: u64,
    /// `[1/xs, 1/ys, 1/spp]`: multiplications instead of divisions in the hot path.
    inv: [f32; 3],
    jitter: Jitter,
    seed: u64,
    pixel: [u32; 2],
    /// `hash(pixel, seed)`, cached across samples of one pixel.
    pixel_key: u64,
    /// The time and lens permutations of the current pixel (dimensions 2 and 3), built once
    /// per pixel.
    camera_perms: [Permutation; 2],
    /// `pixel_key ^ index·step`: the jitter source of the current sample (hashed with the
    /// dimension before use).
    sample_key: u64,
    index: u32,
    dim: u32,
}

/// Odd constants separating dimensions in the per-dimension hashes.
const DIM_STEP: u64 = 0x9e37_79b9_7f4a_7c15;
const JITTER_STEP: u64 = 0xc2b2_ae3d_27d4_eb4f;
const ARRAY_STEP: u64 = 0x1656_67b1_9e37_79f9;

/// The permutation key of dimension `dim` of the pixel keyed by `pixel_key`.
#[inline]
fn dim_key(pixel_key: u64, dim: u32) -> u32 {
    let key = mix64(pixel_key ^ u64::from(dim).wrapping_mul(DIM_STEP));
    key as u32 ^ (key >> 32) as u32
}

fn camera_perms(pixel_key: u64, spp: u32) -> [Permutation; 2] {
    [
        Permutation::new(spp, dim_key(pixel_key, 2)),
        Permutation::new(spp, dim_key(pixel_key, 3)),
    ]
}

impl StratifiedSampler {
    /// A stratified sampler with `x_samples × y_samples` samples per pixel.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if either count is 0; [`Error::TooMany`] if the product passes
    /// `u32::MAX`.
    ///
    /// ```
    /// use nyquist::sampler::{Jitter, Sampler, StratifiedSampler};
    /// assert_eq!(StratifiedSampler::new(3, 2, Jitter::Jittered, 0).unwrap().samples_per_pixel(), 6);
    /// assert!(StratifiedSampler::new(0, 2, Jitter::Jittered, 0).is_err());
    /// ```
    pub fn new(x_samples: u32, y_samples: u32, jitter: Jitter, seed: u64) -> Result<Self, Error> {
        if x_samples == 0 || y_samples == 0 {
            return Err(Error::ZeroSize { what: "samples" });
        }
        let spp = x_samples.checked_mul(y_samples).ok_or(Error::TooMany {
            what: "spp",
            value: u64::from(x_samples) * u64::from(y_samples),
            max: u64::from(u32::MAX),
        })?;
        Ok(Self {
            xs: x_samples,
            ys: y_samples,
            spp,
            div_xs: (u64::MAX / u64::from(x_samples)).wrapping_add(1),
            inv: [
                1.0 / x_samples as f32,
                1.0 / y_samples as f32,
                1.0 / spp as f32,
            ],
            jitter,
            seed,
            pixel: [0; 2],
            pixel_key: pixel_hash([0; 2], seed, 0x7374_7261),
            camera_perms: camera_perms(pixel_hash([0; 2], seed, 0x7374_7261), spp),
            sample_key: 0,
            index: 0,
            dim: 0,
        })
    }

    /// The `uniform` sampler: cell centres of an `x_samples × y_samples` grid, no jitter
    /// (the aliasing baseline). Same as `new(x_samples, y_samples, Jitter::Centered, seed)`.
    ///
    /// # Errors
    /// As [`StratifiedSampler::new`].
    ///
    /// ```
    /// use nyquist::sampler::{Sampler, StratifiedSampler};
    /// let mut s = StratifiedSampler::uniform(2, 2, 0).unwrap();
    /// s.start_pixel_sample([0, 0], 0, 0);
    /// let [x, y] = s.get_pixel_2d();
    /// assert!([0.25, 0.75].contains(&x) && [0.25, 0.75].contains(&y));
    /// ```
    pub fn uniform(x_samples: u32, y_samples: u32, seed: u64) -> Result<Self, Error> {
        Self::new(x_samples, y_samples, Jitter::Centered, seed)
    }

    /// The jitter mode.
    ///
    /// ```
    /// use nyquist::sampler::{Jitter, StratifiedSampler};
    /// assert_eq!(StratifiedSampler::uniform(1, 1, 0).unwrap().jitter(), Jitter::Centered);
    /// ```
    pub fn jitter(&self) -> Jitter {
        self.jitter
    }

    /// Strata per axis `[x_samples, y_samples]`.
    ///
    /// ```
    /// use nyquist::sampler::StratifiedSampler;
    /// assert_eq!(StratifiedSampler::uniform(3, 2, 0).unwrap().strata(), [3, 2]);
    /// ```
    pub fn strata(&self) -> [u32; 2] {
        [self.xs, self.ys]
    }

    /// Two jitters (high and low 32 bits of one hash) for dimension `dim` of this sample.
    #[inline]
    fn jitters(&self, dim: u32) -> [f32; 2] {
        match self.jitter {
            // Time (2) and lens (3) share one hash: 21 bits each, finer than any stratum
            // needs (the value keeps 24 bits), so a camera sample hashes twice, not three times.
            Jitter::Jittered if dim == 2 || dim == 3 => {
                let h = mix64(self.sample_key ^ 2u64.wrapping_mul(JITTER_STEP));
                let bits =
                    |shift: u32| ((h >> shift) as u32 & 0x1f_ffff) as f32 * (1.0 / 2_097_152.0);
                if dim == 2 {
                    [bits(43), 0.5]
                } else {
                    [bits(22), bits(1)]
                }
            }
            _ => jitter_pair(self.sample_key, dim, self.jitter),
        }
    }

    /// This sample's stratum in dimension `dim`: a per-(pixel, dim) permutation of the sample
    /// index; dimension 0 (the image sample) needs none and takes `index mod spp`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn stratum(&self, dim: u32) -> u32 {
        if dim == 0 {
            return if self.index < self.spp {
                self.index
            } else {
                self.index % self.spp
            };
        }
        match dim {
            // The camera's time and lens permutations, cached per pixel.
            2 | 3 => self.camera_perms[(dim - 2) as usize].apply(self.index),
            _ => permute(self.index, self.spp, dim_key(self.pixel_key, dim)),
        }
    }

    /// Stratum `s` as a grid cell `(s % xs, s / xs)`, dividing by multiplication (Lemire, Kaser
    /// & Kurz 2019, "Faster remainder by direct computation": exact for every `u32` `s`).
    #[inline]
    fn cell(&self, s: u32) -> (u32, u32) {
        if self.xs == 1 {
            return (0, s);
        }
        let q = ((u128::from(self.div_xs) * u128::from(s)) >> 64) as u32;
        (s - q * self.xs, q)
    }

    #[inline]
    fn value_2d(&self, dim: u32) -> [f32; 2] {
        self.cell_value(self.stratum(dim), self.jitters(dim))
    }

    /// The point of grid stratum `s` at jitter `[jx, jy]` within its cell.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn cell_value(&self, s: u32, [jx, jy]: [f32; 2]) -> [f32; 2] {
        let (cx, cy) = self.cell(s);
        [
            below_one((cx as f32 + jx) * self.inv[0]),
            below_one((cy as f32 + jy) * self.inv[1]),
        ]
    }

    /// The value of 1D stratum `s` (of `spp`) at jitter `j` within it.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn stratum_value(&self, s: u32, j: f32) -> f32 {
        below_one((s as f32 + j) * self.inv[2])
    }
}

/// The key of an integrator array at dimension `dim` of the current sample: one full hash.
#[inline]
fn array_key(sample_key: u64, dim: u32, tag: u64) -> u64 {
    mix64(sample_key ^ u64::from(dim).wrapping_mul(ARRAY_STEP) ^ tag)
}

/// Two jitters from one hash of `key` and `k` (a sample's dimension, or an array's point).
#[inline]
fn jitter_pair(key: u64, k: u32, jitter: Jitter) -> [f32; 2] {
    match jitter {
        Jitter::Jittered => {
            let h = mix64(key ^ u64::from(k).wrapping_mul(JITTER_STEP));
            [unit_f32((h >> 32) as u32), unit_f32(h as u32)]
        }
        Jitter::Centered => [0.5, 0.5],
    }
}

impl Sampler for StratifiedSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        if pixel != self.pixel {
            self.pixel = pixel;
            self.pixel_key = pixel_hash(pixel, self.seed, 0x7374_7261);
            self.camera_perms = camera_perms(self.pixel_key, self.spp);
        }
        self.index = sample_index;
        // Unmixed: every use passes it through a full hash with the dimension.
        self.sample_key = self.pixel_key ^ u64::from(sample_index).wrapping_mul(DIM_STEP);
        self.dim = dim;
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_1d(&mut self) -> f32 {
        let dim = self.dim;
        self.dim = self.dim.wrapping_add(1);
        self.stratum_value(self.stratum(dim), self.jitters(dim)[0])
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_2d(&mut self) -> [f32; 2] {
        let dim = self.dim;
        self.dim = self.dim.wrapping_add(2);
        self.value_2d(dim)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        self.value_2d(0)
    }

    /// The default's values with time and lens from one hash and one jitter-mode test (the
    /// separate calls hash twice: the compiler does not merge the two hashes across the mode
    /// branches).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        self.start_pixel_sample(pixel, sample_index, 0);
        let p = self.value_2d(0);
        let [jt, jx, jy] = match self.jitter {
            Jitter::Jittered => {
                let [t, _] = self.jitters(2);
                let [x, y] = self.jitters(3);
                [t, x, y]
            }
            Jitter::Centered => [0.5; 3],
        };
        // Dimensions 2 and 3: the camera permutations that `stratum` reads.
        let time = self.stratum_value(self.camera_perms[0].apply(self.index), jt);
        let lens = self.cell_value(self.camera_perms[1].apply(self.index), [jx, jy]);
        self.dim = 5;
        CameraSample {
            p_film: [
                film_coordinate(pixel[0], p[0]),
                film_coordinate(pixel[1], p[1]),
            ],
            lens,
            time,
        }
    }

    fn get_array_1d(&mut self, out: &mut [f32]) {
        let dim = self.dim;
        self.dim = self.dim.wrapping_add(1);
        let n = u32::try_from(out.len()).unwrap_or(u32::MAX);
        let key = array_key(self.sample_key, dim, 0x6c68_7331);
        let (order, inv_n) = (ArrayOrder::new(n, key), 1.0 / n as f32);
        for (j, x) in (0..n).zip(out) {
            let [o, _] = jitter_pair(key, j, self.jitter);
            // A Latin hypercube axis: value `j` of `n` is `(π(j) + jitter) / n`.
            *x = below_one((order.apply(j) as f32 + o) * inv_n);
        }
    }

    fn get_array_2d(&mut self, out: &mut [f32]) {
        let dim = self.dim;
        self.dim = self.dim.wrapping_add(2);
        let n = u32::try_from(out.len() / 2).unwrap_or(u32::MAX);
        // One hash per array: its halves seed the two axis permutations, and the jitters hash
        // it with the point index.
        let key = array_key(self.sample_key, dim, 0x6c68_7332);
        // The key's two halves order the two axes (each in the high bits, where a table
        // draw reads; a large array seeds its permutations with the low bits).
        let (px, py) = (
            ArrayOrder::new(n, key),
            ArrayOrder::new(n, key.rotate_left(32)),
        );
        let inv_n = 1.0 / n as f32;
        for (j, p) in (0..n).zip(out.chunks_exact_mut(2)) {
            let [ox, oy] = jitter_pair(key, j, self.jitter);
            p[0] = below_one((px.apply(j) as f32 + ox) * inv_n);
            p[1] = below_one((py.apply(j) as f32 + oy) * inv_n);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cell_division_is_exact() {
        for xs in [1u32, 2, 3, 5, 7, 16, 17, 1000, 65_535, u32::MAX] {
            let s = StratifiedSampler::new(xs, 1, Jitter::Jittered, 0).unwrap();
            for v in [
                0u32,
                1,
                2,
                xs - 1,
                xs,
                xs.wrapping_add(1),
                12_345_678,
                u32::MAX - 1,
                u32::MAX,
            ] {
                assert_eq!(s.cell(v), (v % xs, v / xs), "{v} / {xs}");
            }
        }
    }
}
