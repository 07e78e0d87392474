//! [`ZSobolSampler`]: the desktop ZSobol sampler with Sobol dimensions 0 and 1 from their
//! direction numbers instead of the byte tables.

use super::{sobol_directions, sobol_directions_hi};
use crate::Error;
use crate::math::fraction_to_f32;
use crate::sampler::{self, Sampler, zsobol_key_seed, zsobol_scramble_dim0};
use crate::scramble::{Scramble, lk_hash, rev_to_f32, scramble_u32};
use crate::sequence::sobol_product;

/// Sobol dimension 1's direction numbers, and its columns past 32.
const SOBOL1: [u32; 32] = sobol_directions::<2>()[1];
const SOBOL1_HI: [u32; 32] = sobol_directions_hi::<2>()[1];

/// Sobol dimension 1 at a 64-bit index: the columns past 32 only where the upper half is set.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn sobol1(index: u64) -> u32 {
    let (lo, hi) = (index as u32, (index >> 32) as u32);
    let low = sobol_product(&SOBOL1, lo);
    if hi == 0 {
        low
    } else {
        low ^ sobol_product(&SOBOL1_HI, hi)
    }
}

/// [`SOBOL1`] with each column bit-reversed: the product over an index's bits is the reversed
/// value.
const SOBOL1_REVERSED: [u32; 32] = {
    let mut out = [0u32; 32];
    let mut k = 0;
    while k < 32 {
        out[k] = SOBOL1[k].reverse_bits();
        k += 1;
    }
    out
};

/// ZSobol sampling (Ahmed & Wonka 2020; pbrt-v4's `ZSobolSampler`) without the desktop tables:
/// bit for bit what [`sampler::ZSobolSampler`] returns for every resolution, spp, scramble,
/// seed, pixel, sample index and dimension.
///
/// The Morton-order index permutation is the desktop sampler's own (it needs no table); the
/// sampler reads only Sobol dimensions 0 and 1, which here come from 64 direction numbers
/// (dimension 0 is the index reversed) where the desktop sampler reads the Sobol byte tables
/// and a 4 KiB reversed table. Allocates: no.
///
/// ```
/// use nyquist::{compact, sampler::{self, Sampler}, scramble::Scramble};
/// let mut small = compact::ZSobolSampler::new([64, 64], 16, Scramble::FastOwen, 1).unwrap();
/// let mut desk = sampler::ZSobolSampler::new([64, 64], 16, Scramble::FastOwen, 1).unwrap();
/// assert_eq!(small.camera_sample([10, 20], 3), desk.camera_sample([10, 20], 3));
/// assert_eq!(small.get_1d(), desk.get_1d());
/// ```
#[derive(Clone, Debug)]
pub struct ZSobolSampler {
    inner: sampler::ZSobolSampler,
    dim: u32,
}

impl ZSobolSampler {
    /// The next power of two of `requested` (at least 1) and whether it differs, as
    /// [`sampler::ZSobolSampler::rounded_spp`].
    ///
    /// ```
    /// assert_eq!(nyquist::compact::ZSobolSampler::rounded_spp(12), (16, true));
    /// ```
    pub fn rounded_spp(requested: u32) -> (u32, bool) {
        sampler::ZSobolSampler::rounded_spp(requested)
    }

    /// A ZSobol sampler for an image of `resolution` pixels, `spp` rounded up to a power of two,
    /// as [`sampler::ZSobolSampler::new`].
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0; [`Error::TooMany`] if
    /// `spp > 2³¹` or a side passes 65536.
    ///
    /// ```
    /// use nyquist::{compact::ZSobolSampler, scramble::Scramble};
    /// assert!(ZSobolSampler::new([16384, 16384], 4096, Scramble::FastOwen, 0).is_ok());
    /// assert!(ZSobolSampler::new([65537, 2160], 512, Scramble::FastOwen, 0).is_err());
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
        Ok(Self {
            inner: sampler::ZSobolSampler::new(resolution, spp, scramble, seed)?,
            dim: 0,
        })
    }

    /// The scramble applied to the values.
    ///
    /// ```
    /// use nyquist::{compact::ZSobolSampler, scramble::Scramble};
    /// let s = ZSobolSampler::new([8, 8], 4, Scramble::Owen, 0).unwrap();
    /// assert_eq!(s.scramble(), Scramble::Owen);
    /// ```
    pub fn scramble(&self) -> Scramble {
        self.inner.scramble()
    }

    /// The permuted Sobol index of sample `sample_index` of `pixel` for the request at
    /// dimension `dim`, as [`sampler::ZSobolSampler::sequence_index`].
    ///
    /// ```
    /// use nyquist::{compact::ZSobolSampler, scramble::Scramble};
    /// let s = ZSobolSampler::new([2, 2], 1, Scramble::None, 3).unwrap();
    /// let mut all: Vec<u64> = (0..4).map(|k| s.sequence_index([k % 2, k / 2], 0, 7)).collect();
    /// all.sort();
    /// assert_eq!(all, [0, 1, 2, 3]);
    /// ```
    pub fn sequence_index(&self, pixel: [u32; 2], sample_index: u32, dim: u32) -> u64 {
        self.inner.sequence_index(pixel, sample_index, dim)
    }

    /// The request's index and key, out of line: one copy of the index permutation serves the
    /// 1D and 2D requests.
    #[inline(never)]
    fn index(&self, dim: u32) -> (u64, u64) {
        self.inner.index(dim)
    }

    /// The 1D request at `dim`: Sobol dimension 0 at the request's index, scrambled.
    #[inline]
    fn value_1d(&self, dim: u32) -> f32 {
        let (index, key) = self.index(dim);
        let index = index as u32; // Sobol dimension 0 reads the low half only.
        let how = self.inner.scramble();
        if how == Scramble::FastOwen {
            return rev_to_f32(lk_hash(index, key as u32));
        }
        fraction_to_f32(zsobol_scramble_dim0(index, key as u32, how))
    }

    /// The 2D request at `dim`: Sobol dimensions 0 and 1 at the request's index, scrambled.
    #[inline]
    fn value_2d(&self, dim: u32) -> [f32; 2] {
        let (wide, key) = self.index(dim);
        let index = wide as u32;
        let how = self.inner.scramble();
        if how == Scramble::FastOwen {
            let rev = if (wide >> 32) as u32 == 0 {
                sobol_product(&SOBOL1_REVERSED, index)
            } else {
                sobol1(wide).reverse_bits()
            };
            return [
                rev_to_f32(lk_hash(index, key as u32)),
                rev_to_f32(lk_hash(rev, zsobol_key_seed(key))),
            ];
        }
        let y = scramble_u32(sobol1(wide), (key >> 32) as u32, how);
        [
            fraction_to_f32(zsobol_scramble_dim0(index, key as u32, how)),
            fraction_to_f32(y),
        ]
    }
}

impl Sampler for ZSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.inner.samples_per_pixel()
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        self.inner.start_pixel_sample(pixel, sample_index, dim);
        self.dim = dim;
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_1d(&mut self) -> f32 {
        let d = self.dim;
        self.dim = d.wrapping_add(1);
        self.value_1d(d)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_2d(&mut self) -> [f32; 2] {
        let d = self.dim;
        self.dim = d.wrapping_add(2);
        self.value_2d(d)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        self.value_2d(0)
    }
}
