//! [`Pmj02Sampler`]: the desktop PMJ(0,2) sampler with each table point rebuilt on the fly by
//! running the construction backwards, instead of the 512 KiB table.

use crate::Error;
use crate::hash::lcg_draw;
use crate::sampler::{self, Pmj02Keys, Sampler};
use crate::scramble::{rev_to_f32, reverse16};
use crate::sequence::PMJ02_TABLE_SEED;

/// The per-level XOR constants of the construction, x then y: those of
/// [`pmj02_build`](crate::sequence::pmj02_build) (Helmer, Christensen & Kensler 2021, as
/// shipped by OpenQMC). The tests rebuild the whole table and every prefix of other seeds with
/// them.
const XORS: [[u32; 16]; 2] = [
    [
        0x0000, 0x0000, 0x0002, 0x0006, 0x0006, 0x000e, 0x0036, 0x004e, 0x0016, 0x002e, 0x0276,
        0x06ce, 0x0716, 0x0c2e, 0x3076, 0x40ce,
    ],
    [
        0x0000, 0x0001, 0x0003, 0x0003, 0x0007, 0x001b, 0x0027, 0x000b, 0x0017, 0x013b, 0x0367,
        0x038b, 0x0617, 0x183b, 0x2067, 0x008b,
    ],
];

/// Coordinate `dim` (0 or 1) of point `index mod 2¹⁶` of the pmj02 sequence of `seed`, as a
/// 32-bit fraction: what [`pmj02_build`](crate::sequence::pmj02_build) writes there, with no
/// buffer.
///
/// The construction makes point `p = 2^L + i` (level `L`) from old point `q = i ⊕ c[L]`: the
/// first `L` digits of `q`, digit `L + 1` of `q` flipped, and the digits below from the
/// generator's draw for `p` (OpenQMC's 32-bit LCG, reached by a jump of three multiply-adds).
/// So the digits of `p` are found by walking back along `p, q, …` to point 0: each point
/// on the way gives the digits its level draws that no later point overrode, and flips one.
/// At most 16 steps and 17 draws (Helmer, Christensen & Kensler 2021 describe the
/// construction; evaluating it backwards is what lets a sampler read any point alone).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn pmj02_point(seed: u32, index: u32, dim: usize) -> u32 {
    let half = |p: u32| lcg_draw(seed, 2 * p + dim as u32);
    let (mut x, mut known, mut flips) = (0u32, 0u32, 0u32);
    let mut p = index & 0xffff;
    while p != 0 {
        let level = 31 - p.leading_zeros();
        let swap = 0x8000_0000u32 >> level;
        let low = swap - 1;
        x |= half(p) & low & !known;
        known |= low;
        flips ^= swap;
        p = (p - (1 << level)) ^ XORS[dim][level as usize];
    }
    (x | (half(0) & !known)) ^ flips
}

/// Progressive multi-jittered (0,2) sampling without the table: bit for bit what
/// [`sampler::Pmj02Sampler`] returns for every spp, seed, pixel, sample index and dimension.
///
/// The desktop sampler reads its points from a 512 KiB table (the construction of
/// [`pmj02_build`](crate::sequence::pmj02_build) for
/// [`PMJ02_TABLE_SEED`](crate::sequence::PMJ02_TABLE_SEED)); this one rebuilds each point it
/// needs by running that construction backwards from the point (Helmer, Christensen & Kensler
/// 2021, "Stochastic Generation of (t, s) Sample Sequences"): at most 17 generator draws
/// (three multiply-adds each) per coordinate instead of a table read. The keys, shuffles and
/// scrambles are the desktop sampler's own. Allocates: no.
///
/// ```
/// use nyquist::{compact, sampler::{self, Sampler}};
/// let mut small = compact::Pmj02Sampler::new(16, 7).unwrap();
/// let mut desk = sampler::Pmj02Sampler::new(16, 7).unwrap();
/// assert_eq!(small.camera_sample([3, 4], 11), desk.camera_sample([3, 4], 11));
/// assert_eq!(small.get_2d(), desk.get_2d());
/// ```
#[derive(Clone, Debug)]
pub struct Pmj02Sampler {
    inner: sampler::Pmj02Sampler,
    dim: u32,
}

impl Pmj02Sampler {
    /// A pmj02 sampler with `spp` samples per pixel (not rounded), as
    /// [`sampler::Pmj02Sampler::new`].
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp == 0`; [`Error::TooMany`] if `spp > 65536`.
    ///
    /// ```
    /// use nyquist::{compact::Pmj02Sampler, sampler::Sampler};
    /// assert_eq!(Pmj02Sampler::new(100, 1).unwrap().samples_per_pixel(), 100);
    /// assert!(Pmj02Sampler::new(65_537, 1).is_err());
    /// ```
    pub fn new(spp: u32, seed: u64) -> Result<Self, Error> {
        Ok(Self {
            inner: sampler::Pmj02Sampler::new(spp, seed)?,
            dim: 0,
        })
    }

    /// The seed.
    ///
    /// ```
    /// assert_eq!(nyquist::compact::Pmj02Sampler::new(4, 9).unwrap().seed(), 9);
    /// ```
    pub fn seed(&self) -> u64 {
        self.inner.seed()
    }

    /// Point `row` of the desktop sampler's bit-reversed table (table point `reverse16(row)`),
    /// Owen-scrambled by `keys`.
    #[inline(never)]
    fn point(keys: &Pmj02Keys, row: usize) -> [f32; 2] {
        let j = reverse16(row as u32);
        [
            rev_to_f32(
                keys.x
                    .hash(pmj02_point(PMJ02_TABLE_SEED, j, 0).reverse_bits()),
            ),
            rev_to_f32(
                keys.y
                    .hash(pmj02_point(PMJ02_TABLE_SEED, j, 1).reverse_bits()),
            ),
        ]
    }

    /// The image pair: table point `index` itself, unshuffled.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn image_point(&self) -> [f32; 2] {
        Self::point(&self.inner.keys(0), (self.inner.index_rev >> 16) as usize)
    }
}

impl Sampler for Pmj02Sampler {
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
        self.dim = self.dim.wrapping_add(1);
        let keys = self.inner.keys(2 * u64::from(d) + 1);
        let row = keys.row(self.inner.index_rev);
        rev_to_f32(keys.x.hash(reverse16(row as u32)))
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_2d(&mut self) -> [f32; 2] {
        let d = self.dim;
        self.dim = self.dim.wrapping_add(2);
        if d == 0 {
            return self.image_point();
        }
        let keys = self.inner.keys(2 * u64::from(d));
        Self::point(&keys, keys.row(self.inner.index_rev))
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn get_pixel_2d(&mut self) -> [f32; 2] {
        self.dim = self.dim.max(2);
        self.image_point()
    }
}
