//! ZSobol: Sobol indices laid out along a Morton curve over the pixels and hash-permuted, so
//! that neighbouring pixels take well-spread samples and the error is blue noise in screen
//! space (Ahmed & Wonka 2020, "Screen-Space Blue-Noise Diffusion of Monte Carlo Sampling
//! Error via Hierarchical Ordering of Pixels"; the form pbrt-v4 ships as `ZSobolSampler`).

use super::{CameraSample, Sampler, film_coordinate};
use crate::Error;
use crate::hash::{hash2, mix32, mix64};
use crate::lazy_table::{baked_table, const_unless_lazy};
use crate::math::fraction_to_f32 as to_f32;
use crate::scramble::{Scramble, lk_hash, reversed_to_f32, scramble_u32};
use crate::sequence::{SOBOL_MATRICES, SOBOL_MATRICES_HI, sobol_product, sobol_u32, sobol_u64};

/// All 24 permutations of `0..4`, lexicographic, entry `k` in bits `2k .. 2k + 2`.
const PERMUTATIONS_4: [u8; 24] = permutations_4();

const fn permutations_4() -> [u8; 24] {
    let mut out = [0u8; 24];
    let mut n = 0;
    let mut a = 0;
    while a < 4 {
        let mut b = 0;
        while b < 4 {
            let mut c = 0;
            while c < 4 {
                let d = 6 - a - b - c;
                if a != b && a != c && b != c {
                    out[n] = (a | (b << 2) | (c << 4) | (d << 6)) as u8;
                    n += 1;
                }
                c += 1;
            }
            b += 1;
        }
        a += 1;
    }
    out
}

/// [`PERMUTATIONS_4`] with entry `k` in byte `k`.
const PERMUTATION_BYTES: [u32; 24] = {
    let mut out = [0u32; 24];
    let mut p = 0;
    while p < 24 {
        let perm = PERMUTATIONS_4[p] as u32;
        let mut k = 0;
        while k < 4 {
            out[p] |= ((perm >> (2 * k)) & 3) << (8 * k);
            k += 1;
        }
        p += 1;
    }
    out
};

/// `x`'s low 16 bits spread to the even bits of a `u32`.
#[inline]
fn spread(x: u32) -> u32 {
    let mut x = x & 0xffff;
    x = (x | (x << 8)) & 0x00ff_00ff;
    x = (x | (x << 4)) & 0x0f0f_0f0f;
    x = (x | (x << 2)) & 0x3333_3333;
    (x | (x << 1)) & 0x5555_5555
}

/// Samples per pixel up to which a pixel's sample-digit permutations are tabled.
const TABLE_SPP: u32 = 64;

/// The dimensions whose pixel digits are permuted once per pixel: the camera's requests
/// (image sample at 0, time at 2, lens at 3).
const CAMERA_DIMS: [u32; 3] = [0, 2, 3];

/// ZSobol sampling over an image (Ahmed & Wonka 2020; pbrt-v4's `ZSobolSampler`).
///
/// Sample `s` of pixel `p` gets the Morton index `m = (morton(p) << log₂ spp) | s`, whose
/// base-4 digits (and a last base-2 digit when `log₂ spp` is odd) are permuted, most
/// significant first, by one of the 24 permutations of four chosen by a hash of the digits above
/// it, the request's dimension and the seed. The permuted index `i` is a Sobol index:
/// a 2D request at dimension `d` returns Sobol dimensions (0, 1) at `i`, a 1D request Sobol
/// dimension 0, each scrambled by `scramble` with seeds hashed from `(d, seed)`.
///
/// - Each pixel's `spp` samples are one aligned block of Sobol indices: in every 2D request a
///   (0, log₂ spp, 2)-net, in every 1D request stratified into `spp` intervals.
/// - The pixels of an aligned `2^k × 2^k` square own one aligned block of `4^k · spp` indices:
///   with 1 spp, their `4^k` values of any 1D request fall one per interval of `1/4^k` — the
///   screen-space stratification that makes the error blue noise.
///
/// `spp` is rounded up to a power of two ([`ZSobolSampler::rounded_spp`]); the image is
/// embedded in a `2^r × 2^r` square with `r ≤ 16` (sides up to 65536 pixels). Sobol indices are
/// 64-bit ([`sobol_u64`]), so any `spp` up to 2³¹ fits at any such size (16384² at 4096 spp is
/// `2r + log₂ spp = 40` bits; below 2³² the values are the 32-bit construction's). Pixel
/// coordinates wrap modulo `2^r`.
///
/// **Past `spp`** (progressive rendering) every sample index is a new sample: samples
/// `spp·2^(k−1) .. spp·2^k` (`k ≥ 1`) are epoch `k`, a ZSobol pattern of its own with
/// `spp·2^(k−1)` samples per pixel under the seed `hash(seed, k)`. Each epoch is a net in every
/// pixel and blue across pixels as the first is, and epochs are independent. The union of two
/// epochs is not one net (a finer net of one pixel would need the index blocks of its
/// neighbours, whose values the pixel would then repeat, as pbrt-v4's ZSobol does past its
/// spp), so past `spp` the error of a smooth integrand falls as `1/N` (the first epoch's error
/// dominates the mean) instead of the net's `N^−1.5`. Below `spp`, a pixel's first `4^j`
/// samples are a net (`2·4^j` when `log₂ spp` is odd): a progressive renderer gives the
/// largest spp it may reach.
///
/// ```
/// use nyquist::sampler::{Sampler, ZSobolSampler};
/// use nyquist::scramble::Scramble;
/// let mut s = ZSobolSampler::new([64, 64], 16, Scramble::FastOwen, 1).unwrap();
/// let c = s.camera_sample([10, 20], 3);
/// assert!(c.p_film[0] >= 10.0 && c.p_film[0] < 11.0);
/// ```
#[derive(Clone, Debug)]
pub struct ZSobolSampler {
    spp: u32,
    log2_spp: u32,
    log2_res: u32,
    scramble: Scramble,
    seed: u64,
    /// Base-4 digits above the last base-2 one (when `log₂ spp` is odd).
    digits: u32,
    /// Base-4 digits that hold sample bits (the rest are the pixel's).
    sample_digits: u32,
    odd: u32,
    keys: [u64; 3],
    pixel: Option<[u32; 2]>,
    pixel_morton: u64,
    /// The permuted pixel digits of [`CAMERA_DIMS`], their permutations (per pixel digit, the
    /// lowest first) and their pixel words.
    prefix: [u64; 3],
    perms: [[u8; 16]; 3],
    words: [u64; 3],
    /// Whether `sample_bits` and `flips` hold the current pixel's permutations.
    tabled: bool,
    /// For `spp ≤ TABLE_SPP`, per camera request: the permuted sample bits for every value of
    /// the sample's base-4 digits, and the flips of the last base-2 digit (when `log₂ spp` is
    /// odd) by the digits above it; filled on the pixel's second sample.
    sample_bits: [[u8; TABLE_SPP as usize]; 3],
    flips: [u32; 3],
    morton: u64,
    /// The spp and seed the sampler was made with, and the progressive epoch (module docs)
    /// whose layout the fields above hold: 0 for samples below `base_spp`, `k ≥ 1` for samples
    /// `base_spp·2^(k−1) .. base_spp·2^k` (`spp` then `base_spp·2^(k−1)`, the seed
    /// `hash(base_seed, k)`).
    base_spp: u32,
    base_seed: u64,
    epoch: u32,
    dim: u32,
}

impl ZSobolSampler {
    /// The next power of two of `requested` (at least 1) and whether it differs.
    ///
    /// ```
    /// assert_eq!(nyquist::sampler::ZSobolSampler::rounded_spp(12), (16, true));
    /// ```
    pub fn rounded_spp(requested: u32) -> (u32, bool) {
        super::ZeroTwoSampler::rounded_spp(requested)
    }

    /// A ZSobol sampler for an image of `resolution` pixels, `spp` rounded up to a power of two.
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `spp` or a resolution component is 0; [`Error::TooMany`] if
    /// `spp > 2³¹` (`what: "spp"`) or a side passes 65536 (`what: "resolution"`).
    ///
    /// ```
    /// use nyquist::{sampler::ZSobolSampler, scramble::Scramble};
    /// assert!(ZSobolSampler::new([16384, 16384], 4096, Scramble::FastOwen, 0).is_ok());
    /// assert_eq!(
    ///     ZSobolSampler::new([65537, 2160], 512, Scramble::FastOwen, 0).unwrap_err().to_string(),
    ///     "resolution 65537 is above 65536"
    /// );
    /// ```
    pub fn new(
        resolution: [u32; 2],
        spp: u32,
        scramble: Scramble,
        seed: u64,
    ) -> Result<Self, Error> {
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
        let log2_res = 32 - (side - 1).leading_zeros();
        if log2_res > 16 {
            return Err(Error::TooMany {
                what: "resolution",
                value: u64::from(side),
                max: 1 << 16,
            });
        }
        Ok(Self::with_layout(log2_res, spp, scramble, seed))
    }

    /// The sampler for a `2^log2_res` square (`log2_res ≤ 16`) at `spp` (a power of two up to
    /// 2³¹) under `seed`: [`ZSobolSampler::new`] past its checks, and each progressive epoch.
    fn with_layout(log2_res: u32, spp: u32, scramble: Scramble, seed: u64) -> Self {
        let log2_spp = spp.trailing_zeros();
        let bits = 2 * log2_res + log2_spp;
        let mut s = Self {
            spp,
            log2_spp,
            log2_res,
            scramble,
            seed,
            digits: bits / 2,
            sample_digits: log2_spp / 2,
            odd: log2_spp & 1,
            keys: CAMERA_DIMS.map(|d| dim_key(seed, d)),
            pixel: None,
            pixel_morton: 0,
            prefix: [0; 3],
            perms: [[0; 16]; 3],
            words: [0; 3],
            tabled: false,
            sample_bits: [[0; TABLE_SPP as usize]; 3],
            flips: [0; 3],
            morton: 0,
            base_spp: spp,
            base_seed: seed,
            epoch: 0,
            dim: 0,
        };
        s.set_pixel([0, 0]);
        s
    }

    /// The scramble applied to the values.
    ///
    /// ```
    /// use nyquist::{sampler::ZSobolSampler, scramble::Scramble};
    /// let s = ZSobolSampler::new([8, 8], 4, Scramble::Owen, 0).unwrap();
    /// assert_eq!(s.scramble(), Scramble::Owen);
    /// ```
    pub fn scramble(&self) -> Scramble {
        self.scramble
    }

    /// The permuted Sobol index of sample `sample_index < spp` of `pixel` for the request at
    /// dimension `dim` (a value below `2^(2r + log₂ spp)`; `sample_index` wraps modulo `spp`
    /// here, the sampler's epochs past it are not sequence indices of this layout).
    ///
    /// ```
    /// use nyquist::{sampler::ZSobolSampler, scramble::Scramble};
    /// let s = ZSobolSampler::new([2, 2], 1, Scramble::None, 3).unwrap();
    /// // The four pixels of a 2 × 2 image own the four indices 0..4.
    /// let mut all: Vec<u64> = (0..4).map(|k| s.sequence_index([k % 2, k / 2], 0, 7)).collect();
    /// all.sort();
    /// assert_eq!(all, [0, 1, 2, 3]);
    /// ```
    pub fn sequence_index(&self, pixel: [u32; 2], sample_index: u32, dim: u32) -> u64 {
        if self.epoch != 0 {
            let base =
                Self::with_layout(self.log2_res, self.base_spp, self.scramble, self.base_seed);
            return base.sequence_index(pixel, sample_index, dim);
        }
        let morton =
            (self.morton_of(pixel) << self.log2_spp) | u64::from(sample_index & (self.spp - 1));
        let key = dim_key(self.seed, dim);
        let prefix = self.permute_digits(morton, key, self.sample_digits, self.digits);
        self.finish_index(morton, pixel_word(morton >> self.log2_spp, key), prefix)
    }

    fn morton_of(&self, pixel: [u32; 2]) -> u64 {
        let mask = if self.log2_res == 0 {
            0
        } else {
            u32::MAX >> (32 - self.log2_res)
        };
        u64::from(spread(pixel[0] & mask) | (spread(pixel[1] & mask) << 1))
    }

    /// Digits `from .. to` of `morton` (base-4 digit `i` at bit `2i + odd`), permuted.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn permute_digits(&self, morton: u64, key: u64, from: u32, to: u32) -> u64 {
        permute_digits(self.odd, morton, key, from, to)
    }

    /// The whole permuted index from the permuted pixel digits `prefix` and the request's
    /// pixel word `w` ([`pixel_word`]): the sample's digits (base 4, and the last base-2 one
    /// when `log₂ spp` is odd), each permuted by a multiplicative hash of `w` and the sample
    /// digits above it — one 64-bit hash per pixel and request instead of one per digit.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn finish_index(&self, morton: u64, w: u64, prefix: u64) -> u64 {
        finish_index(
            self.sample_digits,
            self.odd,
            self.log2_spp,
            morton,
            w,
            prefix,
        )
    }

    /// The epoch of sample `sample_index` (module docs), entered if it is not the current one,
    /// and the sample's number in it.
    #[cold]
    #[inline(never)]
    fn epoch_sample(&mut self, sample_index: u32) -> u32 {
        let (k, s) = if sample_index < self.base_spp {
            (0, sample_index)
        } else {
            let top = 31 - sample_index.leading_zeros();
            (
                top + 1 - self.base_spp.trailing_zeros(),
                sample_index - (1 << top),
            )
        };
        if k != self.epoch {
            self.enter_epoch(k);
        }
        s
    }

    /// Moves the sampler to epoch `k` (module docs): the layout of `base_spp·2^(k−1)` samples
    /// per pixel under `hash(base_seed, k)`, or the sampler's own for `k = 0`. A renderer that
    /// takes a pixel's samples in order switches `log₂` times per pixel past `spp`; below it,
    /// never.
    #[cold]
    #[inline(never)]
    fn enter_epoch(&mut self, k: u32) {
        let (spp, seed) = match k {
            0 => (self.base_spp, self.base_seed),
            k => (
                self.base_spp << (k - 1),
                hash2(self.base_seed, u64::from(k)),
            ),
        };
        let (base_spp, base_seed) = (self.base_spp, self.base_seed);
        *self = Self::with_layout(self.log2_res, spp, self.scramble, seed);
        (self.base_spp, self.base_seed, self.epoch) = (base_spp, base_seed, k);
    }

    /// Moves the per-pixel caches to `pixel`. The pixel digits' permutations depend only on the
    /// digits above them, so after the first pixel only the digits at and below the highest one
    /// that changed are redone: a step along a scanline or a Morton curve rehashes about one
    /// digit per request instead of all of them.
    fn set_pixel(&mut self, pixel: [u32; 2]) {
        let morton = self.morton_of(pixel) << self.log2_spp;
        let changed = if self.pixel.is_some() {
            morton ^ self.pixel_morton
        } else {
            u64::MAX
        };
        self.pixel = Some(pixel);
        self.pixel_morton = morton;
        let (from, odd) = (self.sample_digits, self.odd);
        if changed != 0 && self.digits > from {
            // The highest pixel digit that changed (a first pixel: all of them).
            let top = if changed == u64::MAX {
                self.digits - 1
            } else {
                ((63 - changed.leading_zeros()) - odd) / 2
            };
            let low_bit = 2 * from + odd;
            let high_bit = 2 * top + odd + 2;
            let mask = (u64::MAX >> (64 - (high_bit - low_bit))) << low_bit;
            for k in 0..CAMERA_DIMS.len() {
                let mut bits = self.prefix[k] & !mask;
                let mut i = top + 1;
                while i > from {
                    i -= 1;
                    let shift = 2 * i + odd;
                    let digit = (morton >> shift) & 3;
                    let slot = (i - from) as usize;
                    // The highest changed digit keeps its permutation (the digits above it did
                    // not change); the ones below draw new ones.
                    if i != top || changed == u64::MAX {
                        self.perms[k][slot] = pixel_node(morton >> (shift + 2), self.keys[k]);
                    }
                    bits |= permuted_digit(self.perms[k][slot], digit, shift);
                }
                self.prefix[k] = bits;
            }
        }
        for k in 0..CAMERA_DIMS.len() {
            self.words[k] = pixel_word(morton >> self.log2_spp, self.keys[k]);
        }
        self.tabled = false;
    }

    /// Fills `sample_bits` and `flips` for the current pixel (`spp ≤ TABLE_SPP`): the same
    /// permutations [`ZSobolSampler::finish_index`] draws, one per node of the digit tree,
    /// applied to every sample at once by expanding the tree one level at a time.
    fn fill_tables(&mut self) {
        let j = self.sample_digits;
        for k in 0..CAMERA_DIMS.len() {
            let w = self.words[k];
            let table = &mut self.sample_bits[k];
            // Entry h: the permuted bits of the digits above the current level, for the value h
            // of those digits.
            table[0] = 0;
            let mut n = 1usize;
            for level in 0..j {
                let shift = 2 * (j - 1 - level) + self.odd;
                // Backwards, so that each entry is read before its slot is overwritten; a node's
                // four entries are one little-endian word (its permutation, one digit per byte).
                for higher in (0..n).rev() {
                    let spread = PERMUTATION_BYTES[sample_node(w, higher as u64, shift)];
                    let word = (u32::from(table[higher]) * 0x0101_0101) | (spread << shift);
                    table[4 * higher..4 * higher + 4].copy_from_slice(&word.to_le_bytes());
                }
                n *= 4;
            }
            self.flips[k] = 0;
            if self.odd == 1 {
                for higher in 0..self.spp >> 1 {
                    let flip = (nested_word(w, u64::from(higher), 0) >> 63) as u32;
                    self.flips[k] |= flip << higher;
                }
            }
        }
        self.tabled = true;
    }

    /// [`ZSobolSampler::finish_index`]'s sample bits through the tables of camera request `k`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn tabled_sample_bits(&self, k: usize, sample: u64) -> u64 {
        let bits = u64::from(
            self.sample_bits[k][(sample >> self.odd) as usize & (TABLE_SPP as usize - 1)],
        );
        if self.odd == 1 {
            bits | ((sample & 1) ^ u64::from((self.flips[k] >> (sample >> 1)) & 1))
        } else {
            bits
        }
    }

    /// The index for the request at `dim`, through the cached pixel digits where there are some.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn index(&self, dim: u32) -> (u64, u64) {
        let k = match dim {
            0 => 0,
            2 => 1,
            3 => 2,
            _ => {
                let key = dim_key(self.seed, dim);
                let prefix = self.permute_digits(self.morton, key, self.sample_digits, self.digits);
                let w = pixel_word(self.morton >> self.log2_spp, key);
                return (self.finish_index(self.morton, w, prefix), key);
            }
        };
        let key = self.keys[k];
        let index = if self.tabled {
            let sample = self.morton & u64::from(self.spp - 1);
            self.prefix[k] | self.tabled_sample_bits(k, sample)
        } else {
            self.finish_index(self.morton, self.words[k], self.prefix[k])
        };
        (index, key)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value_1d(&self, dim: u32) -> f32 {
        let (index, key) = self.index(dim);
        // Sobol dimension 0 reads only the low 32 bits of an index (its columns past 32 are 0).
        let index = index as u32;
        if self.scramble == Scramble::FastOwen {
            return reversed_to_f32(lk_hash(index, key as u32));
        }
        to_f32(scramble_dim0(index, key as u32, self.scramble))
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value_2d(&self, dim: u32) -> [f32; 2] {
        let (wide, key) = self.index(dim);
        let index = wide as u32;
        let y = match self.scramble {
            // The reversed-table form of the fast Owen scramble of Sobol dimension 1: two bit
            // reversals instead of three.
            Scramble::FastOwen => {
                return [
                    reversed_to_f32(lk_hash(index, key as u32)),
                    reversed_to_f32(lk_hash(sobol1_rev(wide), key_seed(key))),
                ];
            }
            how => {
                let y = if (wide >> 32) as u32 == 0 {
                    sobol_u32(index, 1)
                } else {
                    sobol_u64(wide, 1)
                };
                scramble_u32(y, (key >> 32) as u32, how)
            }
        };
        [
            to_f32(scramble_dim0(index, key as u32, self.scramble)),
            to_f32(y),
        ]
    }
}

baked_table! {
    /// `SOBOL1_REVERSED[j][b]`: Sobol dimension 1's columns `8j + k` over the set bits `k` of
    /// `b`, each bit-reversed, so that the reversed value of any index is four reads (4 KiB).
    static SOBOL1_REVERSED: [[u32; 256]; 4] = [[0; 256]; 4], sobol1_reversed,
        sobol1_reversed_at_first_use_equals_the_baked_table;
}

const_unless_lazy! {
    fn sobol1_reversed(t: &mut [[u32; 256]; 4]) {
        let mut j = 0;
        while j < 4 {
            let mut b = 1;
            while b < 256 {
                let k = (b as u32).trailing_zeros() as usize;
                t[j][b] = t[j][b & (b - 1)] ^ SOBOL_MATRICES[1][8 * j + k].reverse_bits();
                b += 1;
            }
            j += 1;
        }
    }
}

/// `reverse(sobol_u64(index, 1))`: four table reads for the low half, and the columns past 32
/// for an upper half (indices past 2³²).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn sobol1_rev(index: u64) -> u32 {
    let [b0, b1, b2, b3] = (index as u32).to_le_bytes();
    let low = SOBOL1_REVERSED[0][b0 as usize]
        ^ SOBOL1_REVERSED[1][b1 as usize]
        ^ SOBOL1_REVERSED[2][b2 as usize]
        ^ SOBOL1_REVERSED[3][b3 as usize];
    let hi = (index >> 32) as u32;
    if hi == 0 {
        low
    } else {
        low ^ sobol1_rev_hi(hi)
    }
}

/// The reversed columns past 32 of Sobol dimension 1 over `hi`, out of line.
#[cold]
#[inline(never)]
fn sobol1_rev_hi(hi: u32) -> u32 {
    sobol_product(&SOBOL_MATRICES_HI[1], hi).reverse_bits()
}

/// Digits `from .. to` of `morton` (base-4 digit `i` at bit `2i + odd`), each permuted by the
/// pixel node of the digits above it under `key`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn permute_digits(odd: u32, morton: u64, key: u64, from: u32, to: u32) -> u64 {
    let mut out = 0u64;
    let mut i = to;
    while i > from {
        i -= 1;
        let shift = 2 * i + odd;
        let digit = (morton >> shift) & 3;
        out |= permuted_digit(pixel_node(morton >> (shift + 2), key), digit, shift);
    }
    out
}

/// The whole permuted index from the permuted pixel digits `prefix` and the request's pixel
/// word `w` ([`pixel_word`]) in a layout of `sample_digits` base-4 sample digits (and a last
/// base-2 one when `odd`): [`ZSobolSampler::finish_index`].
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn finish_index(
    sample_digits: u32,
    odd: u32,
    log2_spp: u32,
    morton: u64,
    w: u64,
    prefix: u64,
) -> u64 {
    let sample = morton & ((1u64 << log2_spp) - 1);
    let mut index = prefix;
    let mut i = sample_digits;
    while i > 0 {
        i -= 1;
        let shift = 2 * i + odd;
        let digit = (sample >> shift) & 3;
        let node = sample_node(w, sample >> (shift + 2), shift);
        index |= permuted_digit(PERMUTATIONS_4[node], digit, shift);
    }
    if odd == 1 {
        index |= (sample & 1) ^ (nested_word(w, sample >> 1, 0) >> 63);
    }
    index
}

/// The 32-bit LK-hash seed of a request's second coordinate, from its (mixed) 64-bit key.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn key_seed(key: u64) -> u32 {
    (key >> 32) as u32
}

/// Sobol dimension 0 at `index` (its bits reversed) scrambled by `how` under the mixed `seed`.
/// The fast Owen scramble of a reversed word is the LK hash of the word itself, reversed: one
/// bit reversal.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn scramble_dim0(index: u32, seed: u32, how: Scramble) -> u32 {
    match how {
        Scramble::FastOwen => lk_hash(index, seed).reverse_bits(),
        how => scramble_u32(index.reverse_bits(), seed, how),
    }
}

/// One of the 24 permutations of four, chosen by a 32-bit hash: `⌊h · 24 / 2³²⌋`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn one_of_24(h: u32) -> usize {
    ((u64::from(h) * 24) >> 32) as usize
}

/// The permutation (a [`PERMUTATIONS_4`] entry) of the pixel digit below `higher`: a 32-bit
/// hash of the higher digits (at most 30 bits) under the request's key.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn pixel_node(higher: u64, key: u64) -> u8 {
    PERMUTATIONS_4[one_of_24(mix32(higher as u32 ^ (key >> 16) as u32))]
}

/// Which permutation (a [`PERMUTATIONS_4`] index) the sample digit at bit `shift` takes, given
/// the sample digits above it: [`nested_word`] of the pixel word.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn sample_node(w: u64, higher: u64, shift: u32) -> usize {
    one_of_24((nested_word(w, higher, shift) >> 32) as u32)
}

/// Base-4 digit `digit` through the packed permutation `perm`, placed at bit `shift`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn permuted_digit(perm: u8, digit: u64, shift: u32) -> u64 {
    ((u64::from(perm) >> (2 * digit)) & 3) << shift
}

/// The random word of a pixel (its Morton code) for the requests keyed `key`: the source of
/// every permutation of its sample digits.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn pixel_word(pixel_morton: u64, key: u64) -> u64 {
    mix64(pixel_morton ^ key.rotate_left(17))
}

/// The word that picks the permutation of the sample digit at bit `shift`, given the sample
/// digits above it (`higher`): the pixel word and `(higher, shift)` through one multiply (the
/// pixel word is already uniformly random, so the top bits of the product are too, and they
/// differ for every `(higher, shift)`).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn nested_word(w: u64, higher: u64, shift: u32) -> u64 {
    (w ^ (higher << 6 | u64::from(shift)).wrapping_mul(0x9e37_79b9_7f4a_7c15))
        .wrapping_mul(0xd1b5_4a32_d192_ed03)
}

/// The hash key of requests at dimension `dim`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn dim_key(seed: u64, dim: u32) -> u64 {
    hash2(seed, u64::from(dim) ^ 0x5a53_4f42_4f4c) // "ZSOBOL"
}

impl Sampler for ZSobolSampler {
    fn samples_per_pixel(&self) -> u32 {
        self.base_spp
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn start_pixel_sample(&mut self, pixel: [u32; 2], sample_index: u32, dim: u32) {
        // Below spp in the first epoch: one test. Else the epoch (module docs) and the
        // sample's number in it.
        let sample_index = if sample_index < self.base_spp && self.epoch == 0 {
            sample_index
        } else {
            self.epoch_sample(sample_index)
        };
        if self.pixel != Some(pixel) {
            self.set_pixel(pixel);
        } else if !self.tabled && self.spp <= TABLE_SPP {
            // A second sample of the same pixel: the rest of its samples likely follow, so draw
            // all the permutations of its camera sample digits now.
            self.fill_tables();
        }
        self.morton = self.pixel_morton | u64::from(sample_index);
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

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn camera_sample(&mut self, pixel: [u32; 2], sample_index: u32) -> CameraSample {
        self.start_pixel_sample(pixel, sample_index, 0);
        let p = self.value_2d(0);
        let time = self.value_1d(2);
        let lens = self.value_2d(3);
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampler::tests::{
        consistent_values, is_zero_two_net, progressive_samples_are_distinct, threads_agree,
    };
    use std::vec::Vec;

    /// The table forms equal the direct ones: the reversed Sobol dimension 1, the float of a
    /// reversed word, and so the fast Owen values are `fast_owen(sobol(index, d))` under the
    /// request's key.
    #[test]
    fn reversed_tables_equal_the_direct_forms() {
        for i in (0..4096u32).chain((0..4096).map(|i| mix32(i ^ 0xabc))) {
            for hi in [0u64, 1, 0xdead_beef] {
                let wide = u64::from(i) | hi << 32;
                assert_eq!(sobol1_rev(wide), sobol_u64(wide, 1).reverse_bits());
            }
            let (i, sobol_u32) = (u64::from(i), |i: u64, d: u32| sobol_u64(i, d));
            let key = hash2(9, i);
            let want = |v: u32, seed: u32| to_f32(lk_hash(v.reverse_bits(), seed).reverse_bits());
            assert_eq!(
                reversed_to_f32(lk_hash(sobol1_rev(i), key_seed(key))),
                want(sobol_u32(i, 1), key_seed(key))
            );
            assert_eq!(
                reversed_to_f32(lk_hash(i as u32, key as u32)),
                want(sobol_u32(i, 0), key as u32)
            );
        }
    }

    /// A pixel's later samples (through the tabled permutations) equal the direct index, for
    /// every spp up to the table's limit and past it, odd and even powers of two.
    #[test]
    fn tabled_indices_equal_sequence_index() {
        for m in 0..=8u32 {
            let mut s = ZSobolSampler::new([50, 20], 1 << m, Scramble::FastOwen, 6).unwrap();
            for pixel in [[0u32, 0u32], [49, 19], [17, 5]] {
                for i in (0..1u32 << m).chain([0, (1u32 << m) - 1]) {
                    s.start_pixel_sample(pixel, i, 0);
                    for d in [0u32, 2, 3] {
                        assert_eq!(
                            s.index(d).0,
                            s.sequence_index(pixel, i, d),
                            "spp 2^{m} {pixel:?} {i} {d}"
                        );
                    }
                }
                assert_eq!(s.tabled, m <= 6, "spp 2^{m}");
            }
        }
    }

    /// The incremental per-pixel update (only the changed pixel digits rehashed) equals the
    /// direct index along scanlines, Morton steps, jumps and wrapped coordinates.
    #[test]
    fn pixel_steps_in_any_order_equal_sequence_index() {
        for (res, spp) in [
            ([64u32, 64u32], 16u32),
            ([1000, 7], 8),
            ([3, 3], 1),
            ([512, 300], 128),
        ] {
            let mut s = ZSobolSampler::new(res, spp, Scramble::FastOwen, 11).unwrap();
            let mut pixels: Vec<[u32; 2]> = Vec::new();
            for y in 0..5 {
                for x in 0..9 {
                    pixels.push([x, y]);
                }
            }
            for i in 0..200u32 {
                let h = mix32(i);
                pixels.push([h % (res[0] + 5), (h >> 16) % (res[1] + 5)]);
            }
            for (n, &pixel) in pixels.iter().enumerate() {
                let i = n as u32 % spp;
                s.start_pixel_sample(pixel, i, 0);
                for d in [0u32, 2, 3] {
                    assert_eq!(
                        s.index(d).0,
                        s.sequence_index(pixel, i, d),
                        "{res:?} {pixel:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn permutation_table_is_every_permutation_of_four_once() {
        let mut seen = std::collections::BTreeSet::new();
        for p in PERMUTATIONS_4 {
            let entries: Vec<u8> = (0..4).map(|k| (p >> (2 * k)) & 3).collect();
            let mut sorted = entries.clone();
            sorted.sort_unstable();
            assert_eq!(sorted, [0, 1, 2, 3]);
            assert!(seen.insert(entries));
        }
        assert_eq!(seen.len(), 24);
    }

    #[test]
    fn zsobol_is_consistent_and_thread_independent() {
        for scramble in Scramble::ALL {
            let s = ZSobolSampler::new([40, 30], 16, scramble, 9).unwrap();
            consistent_values(&s);
            threads_agree(&s);
        }
    }

    #[test]
    fn cached_indices_equal_sequence_index() {
        for spp in [1u32, 2, 8, 32, 128] {
            let mut s = ZSobolSampler::new([100, 37], spp, Scramble::FastOwen, 4).unwrap();
            for pixel in [[0u32, 0u32], [99, 36], [17, 5], [130, 2]] {
                for i in [0u32, 1 % spp, spp - 1, spp / 2] {
                    s.start_pixel_sample(pixel, i, 0);
                    for d in [0u32, 1, 2, 3, 4, 5, 77] {
                        assert_eq!(
                            s.index(d).0,
                            s.sequence_index(pixel, i, d),
                            "{pixel:?} {i} {d}"
                        );
                    }
                }
            }
        }
    }

    /// Every pixel of a 10 × 10 image, every power-of-two spp up to 1024, six seeds and every
    /// scramble: the image samples and the lens samples are (0, m, 2)-nets, the time samples
    /// stratified.
    #[test]
    fn every_pixel_is_a_net_for_every_power_of_two_up_to_1024() {
        for seed in [0u64, 1, 5, 6, 10, 15] {
            for m in 0..=10u32 {
                let scramble = Scramble::ALL[(seed as usize + m as usize) % 4];
                let mut s = ZSobolSampler::new([10, 10], 1 << m, scramble, seed).unwrap();
                for y in 0..10 {
                    for x in 0..10 {
                        let mut image = Vec::new();
                        let mut lens = Vec::new();
                        let mut seen = std::vec![false; 1 << m];
                        for i in 0..1u32 << m {
                            // The camera sample's values (film positions round in f32).
                            s.start_pixel_sample([x, y], i, 0);
                            image.push(s.get_pixel_2d());
                            let time = s.get_1d();
                            lens.push(s.get_2d());
                            assert!((0.0..1.0).contains(&time));
                            let cell = (time * (1u32 << m) as f32) as usize;
                            assert!(!std::mem::replace(&mut seen[cell], true));
                        }
                        assert!(is_zero_two_net(&image), "seed {seed} 2^{m} ({x}, {y})");
                        assert!(is_zero_two_net(&lens), "seed {seed} 2^{m} ({x}, {y}) lens");
                    }
                }
            }
        }
    }

    /// The screen-space property: at 1 spp, the pixels of every aligned 2^k × 2^k square put
    /// their values of any 1D request one in each interval of 1/4^k.
    #[test]
    fn aligned_pixel_squares_are_stratified_at_one_spp() {
        for seed in [0u64, 3] {
            let mut s = ZSobolSampler::new([64, 64], 1, Scramble::FastOwen, seed).unwrap();
            for k in 1..=3u32 {
                let side = 1u32 << k;
                for (bx, by) in [(0u32, 0u32), (1, 2), (3, 3)] {
                    for dim in [2u32, 5, 9] {
                        let n = (side * side) as usize;
                        let mut seen = std::vec![false; n];
                        for y in 0..side {
                            for x in 0..side {
                                s.start_pixel_sample([bx * side + x, by * side + y], 0, dim);
                                let v = s.get_1d();
                                let cell = (v * n as f32) as usize;
                                assert!(
                                    !std::mem::replace(&mut seen[cell], true),
                                    "seed {seed} k {k} block ({bx}, {by}) dim {dim}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn limits_and_errors() {
        assert_eq!(
            ZSobolSampler::new([0, 4], 1, Scramble::None, 0).unwrap_err(),
            Error::ZeroSize { what: "resolution" }
        );
        assert_eq!(
            ZSobolSampler::new([4, 4], 0, Scramble::None, 0).unwrap_err(),
            Error::ZeroSize { what: "spp" }
        );
        assert!(ZSobolSampler::new([65537, 1], 1, Scramble::None, 0).is_err());
        assert!(ZSobolSampler::new([65536, 1], 1, Scramble::None, 0).is_ok());
        assert!(ZSobolSampler::new([32768, 1], 4, Scramble::None, 0).is_ok());
        let mut s = ZSobolSampler::new([1, 1], 3, Scramble::Owen, 2).unwrap();
        assert_eq!(s.samples_per_pixel(), 4);
        s.start_pixel_sample([0, 0], 5, 0);
        let a = s.get_pixel_2d();
        s.start_pixel_sample([0, 0], 1, 0);
        assert_ne!(s.get_pixel_2d(), a, "past spp: a new sample, not a wrap");
        assert_eq!(
            ZSobolSampler::new([65537, 1], 1, Scramble::None, 0).unwrap_err(),
            Error::TooMany {
                what: "resolution",
                value: 65537,
                max: 65536
            }
        );
    }

    /// Past `spp`, sample `i` is sample `i − spp·2^(k−1)` of epoch `k`: the sampler of
    /// `spp·2^(k−1)` samples per pixel under `hash(seed, k)`, every request and scramble.
    #[test]
    fn samples_past_spp_are_their_epochs_samples() {
        for scramble in Scramble::ALL {
            let mut s = ZSobolSampler::new([100, 37], 4, scramble, 4).unwrap();
            for (i, k, first) in [
                (4u32, 1u32, 4u32),
                (7, 1, 4),
                (8, 2, 8),
                (15, 2, 8),
                (100, 5, 64),
            ] {
                let mut e =
                    ZSobolSampler::with_layout(7, 4 << (k - 1), scramble, hash2(4, u64::from(k)));
                for pixel in [[0u32, 0u32], [99, 36], [17, 5]] {
                    for d in [0u32, 2, 3, 5, 77] {
                        s.start_pixel_sample(pixel, i, d);
                        e.start_pixel_sample(pixel, i - first, d);
                        assert_eq!(s.get_2d(), e.get_2d(), "{scramble:?} {pixel:?} {i} {d}");
                        s.start_pixel_sample(pixel, i, d);
                        e.start_pixel_sample(pixel, i - first, d);
                        assert_eq!(s.get_1d(), e.get_1d());
                    }
                    assert_eq!(s.camera_sample(pixel, i), e.camera_sample(pixel, i - first));
                }
            }
        }
    }

    /// Past 2³², the values are the scrambled Sobol points of the 64-bit index: dimension 0 the
    /// low half reversed, dimension 1 `sobol_u64`, each under the request's key.
    #[test]
    fn values_at_64_bit_indices_are_the_scrambled_sobol_points() {
        for how in Scramble::ALL {
            let mut s = ZSobolSampler::new([16384, 16384], 4096, how, 5).unwrap();
            for (pixel, i) in [([16383u32, 9000u32], 4095u32), ([12000, 16000], 77)] {
                let index = s.sequence_index(pixel, i, 0);
                assert!(index >> 32 != 0);
                let key = dim_key(5, 0);
                let x = to_f32(scramble_dim0(index as u32, key as u32, how));
                let v = sobol_u64(index, 1);
                let y = to_f32(match how {
                    // The sampler's fast Owen scramble is the LK hash on the reversed word.
                    Scramble::FastOwen => lk_hash(v.reverse_bits(), key_seed(key)).reverse_bits(),
                    how => scramble_u32(v, key_seed(key), how),
                });
                s.start_pixel_sample(pixel, i, 0);
                assert_eq!(s.get_pixel_2d(), [x, y], "{how:?} {pixel:?} {i}");
            }
        }
    }

    /// The progressive contract: no sample of a pixel repeats over 2^20 samples; every epoch
    /// is a net in the pixel; and 16384² at 4096 spp, a 40-bit index, works.
    #[test]
    fn progressive_epochs_and_64_bit_indices() {
        let mut s = ZSobolSampler::new([640, 480], 16, Scramble::FastOwen, 3).unwrap();
        assert_eq!(
            progressive_samples_are_distinct(&mut s, [100, 200]),
            1 << 20
        );
        for (first, n) in [(16u32, 16u32), (32, 32), (64, 64), (1024, 1024)] {
            let pts: Vec<[f32; 2]> = (first..first + n)
                .map(|i| {
                    s.start_pixel_sample([100, 200], i, 0);
                    s.get_pixel_2d()
                })
                .collect();
            assert!(is_zero_two_net(&pts), "epoch from {first}");
        }
        for scramble in Scramble::ALL {
            let mut big = ZSobolSampler::new([16384, 16384], 4096, scramble, 5).unwrap();
            let pixel = [16383, 9000];
            assert!(big.sequence_index(pixel, 4095, 0) >> 32 != 0);
            let pts: Vec<[f32; 2]> = (0..4096)
                .map(|i| {
                    big.start_pixel_sample(pixel, i, 0);
                    big.get_pixel_2d()
                })
                .collect();
            // The pixel's whole block of 4096 (of its prefixes, only those of whole digits
            // are nets: `prefixes_of_whole_digits_are_nets`).
            assert!(is_zero_two_net(&pts), "{scramble:?}");
        }
    }

    /// Below its spp, a pixel's prefixes of whole base-4 index digits are nets: the first
    /// `4^j` samples, or `2·4^j` when `log₂ spp` is odd (its lowest digit is binary). The
    /// others are not (the sample digits are permuted), which is why a progressive renderer
    /// draws powers of 4 from a sampler made for the most it may reach.
    #[test]
    fn prefixes_of_whole_digits_are_nets() {
        for spp in [1024u32, 2048, 4096] {
            for scramble in Scramble::ALL {
                let mut s = ZSobolSampler::new([8, 8], spp, scramble, 3).unwrap();
                for k in 0..=spp.trailing_zeros() {
                    let whole = (spp.trailing_zeros() - k) % 2 == 0 || k == 0;
                    let nets = (0..16)
                        .filter(|p| {
                            let pts: Vec<[f32; 2]> = (0..1u32 << k)
                                .map(|i| {
                                    s.start_pixel_sample([p % 8, p / 3], i, 0);
                                    s.get_pixel_2d()
                                })
                                .collect();
                            is_zero_two_net(&pts)
                        })
                        .count();
                    // Small sets may be nets by chance; from 8 points on, not all 16 are.
                    if whole {
                        assert_eq!(nets, 16, "{spp} {scramble:?} 2^{k}");
                    } else if k >= 3 {
                        assert!(nets < 16, "{spp} {scramble:?} 2^{k}");
                    }
                }
            }
        }
    }
}
