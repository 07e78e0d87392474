//! [`SobolSampler<N>`]: pbrt-v3's Sobol sampler over the whole image with its first `N`
//! dimensions' direction numbers as constants instead of the byte tables.

use super::{sobol_directions, sobol_directions_hi};
use crate::Error;
use crate::sampler::{self, Sampler};
use crate::scramble::Scramble;
use crate::sequence::sobol_product;

/// `N` is in `3 ..= 1024`, or the type does not compile.
const fn check_sampler_dims<const N: usize>() {
    assert!(
        N >= 3 && N <= 1024,
        "the sampler's dimension count must be in 3..=1024"
    );
}

/// Sobol sampling over the whole image (pbrt-v3's `SobolSampler`) without the desktop tables:
/// bit for bit what [`sampler::SobolSampler`] returns for every resolution, spp, scramble,
/// seed, pixel and sample index, in dimensions `0..N` (`3 <= N <= 1024`, checked at compile
/// time).
///
/// The image-to-index setup (the GF(2) inverse, the per-pixel and per-sample index shares) and
/// the scrambles are the desktop sampler's own; the values come from the `N` dimensions'
/// direction numbers (128 bytes each, computed at compile time) by a 32-column masked XOR
/// where the desktop sampler reads 280 KB of byte tables (and their columns past 32, 128 bytes
/// more each, for the sample indices past 2³²). Dimensions from 1024 on are the desktop
/// sampler's padding; a dimension `N ≤ d < 1024` takes the direction numbers of
/// `2 + (d − 2) mod (N − 2)` (never those of dimensions 0 and 1, which carry the pixel) under
/// its own scramble: with `N = 1024` every dimension is the desktop sampler's. A camera sample
/// and an integrator's first few values need `N = 8`. Allocates: no.
///
/// ```
/// use nyquist::{compact, sampler::{self, Sampler}, scramble::Scramble};
/// let mut small = compact::SobolSampler::<8>::new([64, 64], 16, Scramble::Owen, 3)
///     .unwrap();
/// let mut desk = sampler::SobolSampler::new([64, 64], 16, Scramble::Owen, 3).unwrap();
/// assert_eq!(small.camera_sample([10, 20], 5), desk.camera_sample([10, 20], 5));
/// assert_eq!(small.get_2d(), desk.get_2d());
/// ```
#[derive(Clone, Debug)]
pub struct SobolSampler<const N: usize> {
    inner: sampler::SobolSampler,
    dim: u32,
}

impl<const N: usize> SobolSampler<N> {
    const DIRECTIONS: [[u32; 32]; N] = sobol_directions::<N>();
    const DIRECTIONS_HI: [[u32; 32]; N] = sobol_directions_hi::<N>();

    /// Sobol dimension `dim` (below 1024) at `index`: dimension `dim`, or past `N` the
    /// dimension it wraps to.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sobol(index: u64, dim: u32) -> u32 {
        let d = dim as usize;
        let d = if d < N { d } else { 2 + (d - 2) % (N - 2) };
        let hi = (index >> 32) as u32;
        let upper = if hi == 0 {
            0
        } else {
            sobol_product(&Self::DIRECTIONS_HI[d], hi)
        };
        sobol_product(&Self::DIRECTIONS[d], index as u32) ^ upper
    }

    /// As [`sampler::SobolSampler::rounded_spp`]: the next power of two and whether it differs
    /// from `requested`.
    ///
    /// ```
    /// assert_eq!(nyquist::compact::SobolSampler::<8>::rounded_spp(5), (8, true));
    /// ```
    pub fn rounded_spp(requested: u32) -> (u32, bool) {
        sampler::SobolSampler::rounded_spp(requested)
    }

    /// A Sobol sampler for an image of `resolution` pixels, `spp` rounded up to a power of two,
    /// scrambled by `scramble` under `seed`, as [`sampler::SobolSampler::new`]. `N` outside
    /// `3..=1024` does not compile.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0; [`Error::TooMany`] if
    /// `spp > 2³¹` or a side passes 65536.
    ///
    /// ```
    /// use nyquist::{compact::SobolSampler, scramble::Scramble};
    /// assert!(SobolSampler::<8>::new([16384, 16384], 4096, Scramble::None, 0).is_ok());
    /// assert!(SobolSampler::<8>::new([65537, 16], 32, Scramble::None, 0).is_err());
    /// ```
    ///
    /// Dimensions 0 and 1 carry the pixel, so fewer than three do not compile:
    ///
    /// ```compile_fail
    /// let _ = nyquist::compact::SobolSampler::<2>::new([4, 4], 1, nyquist::scramble::Scramble::None, 0);
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
        const { check_sampler_dims::<N>() };
        Ok(Self {
            inner: sampler::SobolSampler::build(resolution, spp, scramble, seed, Self::sobol)?,
            dim: 0,
        })
    }

    /// The scramble used, [`Scramble::None`] included.
    ///
    /// ```
    /// use nyquist::{compact::SobolSampler, scramble::Scramble};
    /// assert_eq!(SobolSampler::<8>::new([4, 4], 4, Scramble::PermuteDigits, 1).unwrap().scramble(), Scramble::PermuteDigits);
    /// ```
    pub fn scramble(&self) -> Scramble {
        self.inner.scramble()
    }

    /// The global Sobol index of sample `sample_index` (modulo spp) of `pixel`, as
    /// [`sampler::SobolSampler::sequence_index`].
    ///
    /// ```
    /// use nyquist::scramble::Scramble;
    /// use nyquist::compact::SobolSampler;
    /// let s = SobolSampler::<8>::new([2, 2], 1, Scramble::None, 0).unwrap();
    /// let mut all: Vec<u64> = (0..4).map(|k| s.sequence_index([k % 2, k / 2], 0)).collect();
    /// all.sort();
    /// assert_eq!(all, [0, 1, 2, 3]);
    /// ```
    pub fn sequence_index(&self, pixel: [u32; 2], sample_index: u32) -> u64 {
        self.inner
            .sequence_index_by(pixel, sample_index, Self::sobol)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, dim: u32) -> f32 {
        self.inner.sample_by(dim, Self::sobol, super::padded_u32)
    }
}

impl<const N: usize> Sampler for SobolSampler<N> {
    fn samples_per_pixel(&self) -> u32 {
        self.inner.samples_per_pixel()
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        self.inner.start_pixel_sample(pixel, sample_index, dim);
        self.dim = dim;
    }

    crate::sampler::global_point_dimensions!();

    fn arrays_are_dimension_runs(&self) -> bool {
        true
    }
}
