//! [`OwenSobolSampler<N>`]: the desktop Owen-Sobol pixel sampler with its first `N` dimensions'
//! direction numbers as constants instead of the byte tables.

use super::{check_dims, padded_u32, reversed_directions, wrap};
use crate::Error;
use crate::math::fraction_to_f32;
use crate::sampler::{self, Sampler};
use crate::scramble::{lk_hash, rev_to_f32};
use crate::sequence::sobol_product;

/// Owen-scrambled Sobol samples per pixel without the desktop tables: bit for bit what
/// [`sampler::OwenSobolSampler`] returns for every pixel, frame, sample index and seed, in
/// dimensions `0..N` (`1 <= N <= 1024`, checked at compile time).
///
/// The per-pixel hashing (index shuffle, scramble seeds) is the desktop sampler's own; the
/// values come from the `N` dimensions' direction numbers, computed at compile time (128 bytes
/// per dimension), by a 32-column masked XOR and a hash each, where the desktop sampler reads
/// 1 MB of byte tables. A dimension `N ≤ d < 1024` takes the direction numbers of `d mod N`
/// under its own scramble; from 1024 on, dimensions are the desktop sampler's padding, computed
/// from four dimensions' constants: with `N = 1024` every dimension is the desktop sampler's. A camera sample and an integrator's first few values
/// need `N = 8` (dimensions 0 to 7). Allocates: no.
///
/// ```
/// use nyquist::{compact, sampler::{self, Sampler}};
/// let mut small = compact::OwenSobolSampler::<8>::new(16, 7).unwrap().with_frame(3);
/// let mut desk = sampler::OwenSobolSampler::new(16, 7).unwrap().with_frame(3);
/// assert_eq!(small.camera_sample([640, 360], 5), desk.camera_sample([640, 360], 5));
/// assert_eq!(small.get_2d(), desk.get_2d()); // dimensions 5 and 6
/// ```
#[derive(Clone, Debug)]
pub struct OwenSobolSampler<const N: usize> {
    inner: sampler::OwenSobolSampler,
    dim: u32,
}

impl<const N: usize> OwenSobolSampler<N> {
    const REVERSED: [[u32; 32]; N] = reversed_directions::<N>();

    /// A sampler taking `spp` samples per pixel, frame 0, as
    /// [`sampler::OwenSobolSampler::new`]. `N` outside `1..=1024` does not compile.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`.
    ///
    /// ```
    /// use nyquist::compact::OwenSobolSampler;
    /// assert!(OwenSobolSampler::<8>::new(0, 1).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        const { check_dims::<N>() };
        Ok(Self {
            inner: sampler::OwenSobolSampler::new(spp, seed)?,
            dim: 0,
        })
    }

    /// The same sampler for animation frame `frame` (a new, independent scramble per frame).
    ///
    /// ```
    /// use nyquist::compact::OwenSobolSampler;
    /// assert_eq!(OwenSobolSampler::<8>::new(4, 1).unwrap().with_frame(9).frame(), 9);
    /// ```
    pub fn with_frame(self, frame: u32) -> Self {
        Self {
            inner: self.inner.with_frame(frame),
            dim: self.dim,
        }
    }

    /// The frame this sampler draws for.
    ///
    /// ```
    /// assert_eq!(nyquist::compact::OwenSobolSampler::<8>::new(4, 1).unwrap().frame(), 0);
    /// ```
    pub fn frame(&self) -> u32 {
        self.inner.frame()
    }

    /// The seed of every scramble.
    ///
    /// ```
    /// assert_eq!(nyquist::compact::OwenSobolSampler::<8>::new(4, 3).unwrap().seed(), 3);
    /// ```
    pub fn seed(&self) -> u64 {
        self.inner.seed()
    }

    /// Dimension `dim` of the current sample.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, dim: u32) -> f32 {
        if dim >= 1024 {
            let (key, index) = (self.inner.seeds.key(), u64::from(self.inner.index));
            return fraction_to_f32(padded_u32(key, index, dim));
        }
        let columns = &Self::REVERSED[wrap::<N>(dim)];
        rev_to_f32(lk_hash(
            sobol_product(columns, self.inner.r),
            self.inner.seeds.get(dim),
        ))
    }
}

impl<const N: usize> Sampler for OwenSobolSampler<N> {
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
