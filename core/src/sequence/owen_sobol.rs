//! Owen-scrambled Sobol: Burley's hash-based construction (2020, "Practical Hash-based Owen
//! Scrambling", JCGT 9(4)) over the Joe–Kuo Sobol sequence, with Vegdahl's LK-hash constants.
//!
//! Point `i`, dimension `d` under a seed is
//! `fast_owen(sobol(nested_uniform_shuffle(i, s) ^ c, d), s_d)`: one index shuffle per sequence
//! (shared by every dimension, so the dimensions stay jointly stratified) and one Owen scramble
//! per dimension. Both are bijections that keep nets, so the first `2^k` points of dimensions 0
//! and 1 are a (0, k, 2)-net for every seed, and each dimension alone is stratified into `2^k`
//! intervals; different seeds give statistically independent sequences.
//!
//! (`c` a constant XOR of the upper 16 index bits, see [`IndexShuffle`], which keeps the
//! indices below 2¹⁶ below 2¹⁶.) Unlike the `sobol_burley` crate, indices are full 32-bit (no
//! 2¹⁶ limit) and all 1024 dimensions are available.
//!
//! The work runs on bit-reversed words, where the LK hash is an Owen scramble: the reversed
//! shuffled index goes through tables of *reversed* Sobol columns, and one final reversal (or
//! three table reads straight into the `f32`) ends it. Below index 2¹⁶ only 16 index bits reach
//! the product: two byte-table reads for dimensions 0..63, four nibble-table reads (four
//! dimensions per 16-byte read) for the rest. Four-wide values hash, reverse and convert on four
//! lanes at once (plain lane-parallel code that compiles to SSE2).

use super::sobol::product;
use super::{SOBOL_DIMS, SOBOL_MATRICES, SOBOL_MATRICES_HI};
use super::{Sequence, check_fill};
use crate::Error;
use crate::hash::{hash2, mix32};
use crate::lazy_table::{baked_table, const_unless_lazy};
use crate::math::fraction_to_f32 as to_f32;
use crate::scramble::{lk_hash, rev_to_f32, reverse16, reversed_to_f32, scramble_rev_f32x4};

/// Dimensions with all four reversed byte tables: any index is four table reads.
const REV_DIMS: usize = 64;
/// Dimensions with the two byte tables of the 16 low index bits: indices below 2¹⁶ (the
/// shuffle keeps them there, [`IndexShuffle`]) are two table reads; above, the 32-column masked
/// product. Past them, nibble tables below 2¹⁶.
const UPPER_DIMS: usize = 256;

baked_table! {
    /// `SOBOL_REV_LOWER[j][b][d]` (`j` = 0, 1) and `SOBOL_REV_UPPER[j − 2][b][d]` (`j` = 2, 3): the
    /// bit-reversed Sobol product of dimension `d` restricted to byte `j` of the **bit-reversed**
    /// index (bits `8j .. 8j + 8` of `reverse(i)`, index bits `31 − 8j − k`). Dimensions innermost,
    /// so that the dimensions of one point read the same cache lines and four consecutive
    /// dimensions are one 16-byte read. Built from the direction numbers ([`baked_table!`]):
    /// 128 KiB for the index's upper half over 64 dimensions, 512 KiB for its lower half over 256.
    static SOBOL_REV_LOWER: [[[u32; REV_DIMS]; 256]; 2] = [[[0; REV_DIMS]; 256]; 2],
        fill_rev_lower, sobol_rev_lower_at_first_use_equals_the_baked_table;
}
baked_table! {
    /// See [`SOBOL_REV_LOWER`].
    static SOBOL_REV_UPPER: [[[u32; UPPER_DIMS]; 256]; 2] = [[[0; UPPER_DIMS]; 256]; 2],
        fill_rev_upper, sobol_rev_upper_at_first_use_equals_the_baked_table;
}

const_unless_lazy! {
    fn fill_rev_lower(t: &mut [[[u32; REV_DIMS]; 256]; 2]) {
        rev_byte_tables::<REV_DIMS>(0, t)
    }
}

const_unless_lazy! {
    fn fill_rev_upper(t: &mut [[[u32; UPPER_DIMS]; 256]; 2]) {
        rev_byte_tables::<UPPER_DIMS>(2, t)
    }
}

const_unless_lazy! {
    /// Byte tables `first .. first + 2` of the reversed index for dimensions `0..D`, into `t`.
    fn rev_byte_tables<const D: usize>(first: usize, t: &mut [[[u32; D]; 256]; 2]) {
        let mut j = 0;
        while j < 2 {
            let mut b = 1;
            while b < 256 {
                let k = (b as u32).trailing_zeros() as usize;
                let mut d = 0;
                while d < D {
                    // Bit 8j + k of the reversed index is index bit 31 − 8j − k.
                    let column = SOBOL_MATRICES[d][31 - 8 * (first + j) - k];
                    t[j][b][d] = t[j][b & (b - 1)][d] ^ column.reverse_bits();
                    d += 1;
                }
                b += 1;
            }
            j += 1;
        }
    }
}

/// `reverse(sobol(reverse(r), dim))`: the Sobol product on bit-reversed words, `dim < 1024`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev(dim: usize, r: u32) -> u32 {
    if dim < REV_DIMS {
        let [b0, b1, _, _] = r.to_le_bytes();
        let t = &SOBOL_REV_LOWER;
        t[0][b0 as usize][dim] ^ t[1][b1 as usize][dim] ^ product_rev_upper(dim, r)
    } else if r & 0xffff != 0 {
        product(&SOBOL_MATRICES[dim & 1023], r.reverse_bits()).reverse_bits()
    } else if dim < UPPER_DIMS {
        product_rev_upper(dim, r)
    } else {
        product_rev16(dim & 1023, r >> 16)
    }
}

/// Sets of four dimensions with nibble tables: those past [`UPPER_DIMS`].
const NIBBLE_SETS: usize = (1024 - UPPER_DIMS) / 4;

baked_table! {
    /// `SOBOL_REV_NIBBLES16[s][j][n][l]`: dimension `UPPER_DIMS + 4s + l`'s bit-reversed product over
    /// nibble `j` of the upper half of a reversed index (bits `16 + 4j ..` of `r`, index bits
    /// `15 − 4j − b`) for the nibble value `n`: the 16 index bits that indices below 2¹⁶ use, four
    /// dimensions side by side, so a product is four reads (one 16-byte read per nibble for four
    /// dimensions). Built from the direction numbers ([`baked_table!`]); 192 KiB.
    static SOBOL_REV_NIBBLES16: [[[[u32; 4]; 16]; 4]; NIBBLE_SETS] =
        [[[[0; 4]; 16]; 4]; NIBBLE_SETS], rev_nibbles16,
        sobol_rev_nibbles16_at_first_use_equals_the_baked_table;
}

const_unless_lazy! {
    fn rev_nibbles16(t: &mut [[[[u32; 4]; 16]; 4]; NIBBLE_SETS]) {
        let mut e = 0;
        while e < 4 * NIBBLE_SETS {
            let d = UPPER_DIMS + e;
            let mut j = 0;
            while j < 4 {
                let mut n = 1;
                while n < 16 {
                    let b = (n as u32).trailing_zeros() as usize;
                    let column = SOBOL_MATRICES[d][15 - 4 * j - b].reverse_bits();
                    t[e / 4][j][n][e % 4] = t[e / 4][j][n & (n - 1)][e % 4] ^ column;
                    n += 1;
                }
                j += 1;
            }
            e += 1;
        }
    }
}

/// [`product_rev`] of dimension `UPPER_DIMS <= dim < 1024` for a reversed index whose low 16
/// bits are zero, from its upper half `h < 2^16`: four nibble-table reads.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev16(dim: usize, h: u32) -> u32 {
    let e = dim.wrapping_sub(UPPER_DIMS);
    let t = &SOBOL_REV_NIBBLES16[(e / 4) % NIBBLE_SETS];
    let lane = e % 4;
    t[0][(h & 15) as usize][lane]
        ^ t[1][((h >> 4) & 15) as usize][lane]
        ^ t[2][((h >> 8) & 15) as usize][lane]
        ^ t[3][((h >> 12) & 15) as usize][lane]
}

/// [`product_rev16`] for the four dimensions `UPPER_DIMS + 4·set ..` (four of them).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev16x4(set: usize, h: u32) -> [u32; 4] {
    let t = &SOBOL_REV_NIBBLES16[set % NIBBLE_SETS];
    xor4(
        xor4(t[0][(h & 15) as usize], t[1][((h >> 4) & 15) as usize]),
        xor4(
            t[2][((h >> 8) & 15) as usize],
            t[3][((h >> 12) & 15) as usize],
        ),
    )
}

/// The part of [`product_rev`] from the upper 16 bits of `r` (the 16 low index bits: the two
/// upper-half byte tables), for `dim < UPPER_DIMS`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev_upper(dim: usize, r: u32) -> u32 {
    let [_, _, b2, b3] = r.to_le_bytes();
    let t = &SOBOL_REV_UPPER;
    t[0][b2 as usize][dim] ^ t[1][b3 as usize][dim]
}

/// Four consecutive entries of a dimension row from `d`, `d + 4 <= N`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn four<const N: usize>(row: &[u32; N], d: usize) -> [u32; 4] {
    [row[d], row[d + 1], row[d + 2], row[d + 3]]
}

#[cfg_attr(not(feature = "small-code"), inline(always))]
fn xor4(a: [u32; 4], b: [u32; 4]) -> [u32; 4] {
    [a[0] ^ b[0], a[1] ^ b[1], a[2] ^ b[2], a[3] ^ b[3]]
}

/// [`product_rev`] for the four dimensions `d .. d + 4`, `d + 4 <= 64`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev4(d: usize, r: u32) -> [u32; 4] {
    let [b0, b1, _, _] = r.to_le_bytes();
    let t = &SOBOL_REV_LOWER;
    xor4(
        xor4(four(&t[0][b0 as usize], d), four(&t[1][b1 as usize], d)),
        product_rev_upper4(d, r),
    )
}

/// [`product_rev_upper`] for the four dimensions `d .. d + 4`, `d + 4 <= UPPER_DIMS`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev_upper4(d: usize, r: u32) -> [u32; 4] {
    let [_, _, b2, b3] = r.to_le_bytes();
    let t = &SOBOL_REV_UPPER;
    xor4(four(&t[0][b2 as usize], d), four(&t[1][b3 as usize], d))
}

/// Number of dimensions whose scramble seeds an [`OwenSobol`] keeps precomputed.
const CACHED_SEEDS: usize = 256;

/// The mixed scramble seed of dimension `dim` under the sequence key `key`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn dim_seed(key: u32, dim: u32) -> u32 {
    mix32(key ^ dim.wrapping_mul(0x9e37_79b9))
}

/// The scramble seeds ([`dim_seed`]) of one key's dimensions: the first `N` kept, the rest
/// hashed when asked. [`OwenSobol`] keeps 256, [`OwenSobolSampler`](crate::sampler::OwenSobolSampler)
/// the camera's five per pixel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct DimSeeds<const N: usize> {
    key: u32,
    kept: [u32; N],
}

impl<const N: usize> DimSeeds<N> {
    /// The seeds of `key`, the first `N` computed now.
    pub(crate) fn new(key: u32) -> Self {
        DimSeeds {
            key,
            kept: core::array::from_fn(|d| dim_seed(key, d as u32)),
        }
    }

    /// The seed of dimension `dim`: kept, or hashed past the first `N`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn get(&self, dim: u32) -> u32 {
        match self.kept.get(dim as usize) {
            Some(&s) => s,
            None => dim_seed(self.key, dim),
        }
    }

    /// The kept seeds, of dimensions `0..N`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn kept(&self) -> &[u32; N] {
        &self.kept
    }

    /// The key.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn key(&self) -> u32 {
        self.key
    }
}

/// [`dim_seed`] of the four dimensions `first .. first + 4`, written lane by lane so that it
/// compiles to vector code.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn dim_seeds4(key: u32, first: u32) -> [u32; 4] {
    let mut x: [u32; 4] =
        core::array::from_fn(|k| key ^ first.wrapping_add(k as u32).wrapping_mul(0x9e37_79b9));
    for v in &mut x {
        *v ^= *v >> 16;
    }
    for v in &mut x {
        *v = v.wrapping_mul(0x7feb_352d);
    }
    for v in &mut x {
        *v ^= *v >> 15;
    }
    for v in &mut x {
        *v = v.wrapping_mul(0x846c_a68b);
    }
    for v in &mut x {
        *v ^= *v >> 16;
    }
    x
}

/// The Owen-scrambled Sobol value of dimension `dim` at a reversed shuffled index, as a 32-bit
/// fraction (`dim_seed` mixed).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn owen_sobol_rev_u32(shuffled_rev: u32, dim: u32, dim_seed: u32) -> u32 {
    lk_hash(product_rev((dim & 1023) as usize, shuffled_rev), dim_seed).reverse_bits()
}

/// The Owen-scrambled Sobol value of dimension `dim < 1024` at a shuffled 64-bit index given as
/// [`IndexShuffle::rev64`] splits it, as a 32-bit fraction. Equal to [`owen_sobol_rev_u32`]
/// when the upper half is 0.
#[inline]
pub(crate) fn owen_sobol_u64(shuffled: (u32, u32), dim: u32, dim_seed: u32) -> u32 {
    lk_hash(product_rev64((dim as usize) & 1023, shuffled), dim_seed).reverse_bits()
}

/// The bit-reversed Sobol product of dimension `d < 1024` at a shuffled 64-bit index split as
/// [`IndexShuffle::rev64`] splits it: the low half through the 32 columns, the upper half
/// through the columns past 32 ([`SOBOL_MATRICES_HI`]).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn product_rev64(d: usize, (lo_rev, hi): (u32, u32)) -> u32 {
    let p = product_rev(d, lo_rev);
    if hi == 0 {
        p
    } else {
        p ^ product(&SOBOL_MATRICES_HI[d], hi).reverse_bits()
    }
}

/// A padding dimension (Burley 2020, §6): dimension `dim` of point `index` from the
/// independently seeded Owen-scrambled 4-D block `dim / 4` of the stream `key`. Each block
/// has its own index shuffle; its four dimensions are Sobol dimensions 0..3 under their own
/// scrambles (seeds [`dim_seed`]`(key, dim)`). So every block is a 4-D Owen-scrambled Sobol
/// sequence (its first two dimensions a (0, k, 2)-net at every `2^k`), statistically
/// independent of every other block and of the stream's first 1024 dimensions; no dimension
/// is a copy of another under a different scramble, as a wrap modulo 1024 would make it.
#[inline]
pub(crate) fn padded_u32(key: u32, index: u64, dim: u32) -> u32 {
    padded_u32_by(key, index, dim, product_rev64)
}

/// [`padded_u32`] with the bit-reversed product of Sobol dimension `d < 4` at a split shuffled
/// index ([`IndexShuffle::rev64`]) given by `product_rev`: the compact samplers pass their
/// constant rows.
#[inline]
pub(crate) fn padded_u32_by(
    key: u32,
    index: u64,
    dim: u32,
    product_rev: impl Fn(usize, (u32, u32)) -> u32,
) -> u32 {
    let shuffle = IndexShuffle::new(dim_seed(!key, dim >> 2));
    let p = product_rev((dim & 3) as usize, shuffle.rev64(index));
    lk_hash(p, dim_seed(key, dim)).reverse_bits()
}

/// As [`owen_sobol_rev_u32`], as an `f32` (top 24 bits, truncated).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn owen_sobol_rev_f32(shuffled_rev: u32, dim: u32, dim_seed: u32) -> f32 {
    rev_to_f32(lk_hash(
        product_rev((dim & 1023) as usize, shuffled_rev),
        dim_seed,
    ))
}

/// [`owen_sobol_rev_f32`] for four dimensions at one reversed shuffled index, lane by lane
/// (`dim_seeds[k]` mixed, for `dims[k]`); the scrambles run four-wide.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn owen_sobol_rev_f32x4(
    shuffled_rev: u32,
    dims: [u32; 4],
    dim_seeds: [u32; 4],
) -> [f32; 4] {
    scramble_rev_f32x4(
        dims.map(|d| product_rev((d & 1023) as usize, shuffled_rev)),
        dim_seeds,
    )
}

/// Burley's nested uniform index shuffle on the reversed index, with a fixed XOR that sends the
/// indices below 2¹⁶ to the first block: `rev(i) ↦ lk_hash(rev(i), seed) ^ fix`.
///
/// The shuffle maps `0..2^16` onto one aligned block of 2¹⁶ indices whose upper half (the low
/// half of the reversed word) depends only on the seed; `fix` is that half, so the block is
/// always `0..2^16`. An XOR with a constant is itself a nested permutation, so the map stays a
/// nested uniform shuffle; and since the Sobol points of block `c` are those of block 0 under a
/// digital shift, which the per-dimension Owen scramble absorbs, the sequence's law is the same.
/// Below 2¹⁶ only 16 index bits then reach the Sobol product.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub(crate) struct IndexShuffle {
    seed: u32,
    fix: u32,
}

impl IndexShuffle {
    /// The shuffle for a mixed 32-bit seed.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn new(seed: u32) -> IndexShuffle {
        IndexShuffle {
            seed,
            fix: lk_hash(0, seed) & 0xffff,
        }
    }

    /// The reversed shuffled index of `index`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn rev(&self, index: u32) -> u32 {
        lk_hash(index.reverse_bits(), self.seed) ^ self.fix
    }

    /// The shuffle of a 64-bit index, as the reversed shuffled low half ([`IndexShuffle::rev`]'s
    /// form) and the shuffled upper half. Below 2³² it is `(rev(index), 0)`: the same bits as
    /// the 32-bit shuffle.
    ///
    /// Past 2³² it is still a nested uniform shuffle, one that keeps `0..2^k` for every `k`: the
    /// upper half goes through its own nested shuffle XOR-ed with that shuffle's image of 0 (so 0
    /// stays 0, and `0..2^j` onto itself), and the low half through a shuffle whose seed also
    /// hashes the upper half (its bits lie above every low bit, so a flip may depend on them).
    /// The first `2^k` points of a sequence are then a (0, k, 2)-net for every `k ≤ 64`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn rev64(&self, index: u64) -> (u32, u32) {
        let (lo, hi) = (index as u32, (index >> 32) as u32);
        if hi == 0 {
            return (self.rev(lo), 0);
        }
        let upper = mix32(self.seed ^ 0x5bd1_e995);
        let hi = (lk_hash(hi.reverse_bits(), upper) ^ lk_hash(0, upper)).reverse_bits();
        let low = IndexShuffle::new(mix32(self.seed ^ mix32(hi ^ 0x68e3_1da4)));
        (low.rev(lo), hi)
    }

    /// [`IndexShuffle::rev`] of `index < 2^16` in its upper half only (the low half, `fix`
    /// there, is left unfixed): what the upper-half tables read.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn rev_low_upper(&self, index: u32) -> u32 {
        lk_hash(reverse16(index) << 16, self.seed)
    }

    /// [`IndexShuffle::rev`], reversing indices below 2¹⁶ by two table reads ([`reverse16`]).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn rev_fast(&self, index: u32) -> u32 {
        if index < LOW_BLOCK {
            lk_hash(reverse16(index) << 16, self.seed) ^ self.fix
        } else {
            self.rev(index)
        }
    }
}

/// Indices below this shuffle to indices below it ([`IndexShuffle`]).
const LOW_BLOCK: u32 = 1 << 16;

/// Owen-scrambled Sobol sequence in any number of dimensions (module docs above).
///
/// - `f32` values are the top 24 bits (never 1); `f64` values all 32 bits, exactly.
/// - Indices are 64-bit ([`Sequence::point_count`] is `None`): past 2³² the index shuffle and
///   the Sobol product take the upper half too (a nested shuffle of 64 bits, the columns past 32),
///   so the first `2^k` points of dimensions 0 and 1 are a (0, k, 2)-net for every `k ≤ 64`.
///   Below 2³² the values are those of the 32-bit construction, bit for bit.
/// - Dimensions from [`SOBOL_DIMS`] (1024) on are padding: independently seeded
///   Owen-scrambled 4-D blocks (Burley 2020, §6), never a second scramble of a lower
///   dimension. `dim >= dims()` wraps modulo `dims()`.
///
/// Allocates: no. Stateless, `&self` everywhere (1056 bytes: the scramble seeds of the first 256
/// dimensions are kept).
///
/// ```
/// use nyquist::sequence::{OwenSobol, Sequence};
/// let s = OwenSobol::new(4, 7).unwrap();
/// // Any seed: the first 4 points put one value in each quarter of every dimension.
/// for d in 0..4 {
///     let mut q: Vec<u32> = (0..4).map(|i| (s.sample(i, d) * 4.0) as u32).collect();
///     q.sort();
///     assert_eq!(q, [0, 1, 2, 3]);
/// }
/// assert_ne!(s.sample(1, 0), OwenSobol::new(4, 8).unwrap().sample(1, 0));
/// // 64-bit indices, and dimensions past 1024.
/// let wide = OwenSobol::new(4096, 7).unwrap();
/// assert_ne!(wide.sample(1 << 40, 0), wide.sample(0, 0));
/// assert!((0.0..1.0).contains(&wide.sample(3, 3000)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OwenSobol {
    dims: u32,
    seed: u64,
    shuffle: IndexShuffle,
    /// `min(dims, UPPER_DIMS) − 3` (0 if negative): [`OwenSobol::sample_4d`]'s fast case is
    /// `first_dim < low4_end`.
    low4_end: u32,
    seeds: DimSeeds<CACHED_SEEDS>,
}

impl OwenSobol {
    /// The sequence with `dims` dimensions, scrambled by `seed` (every seed, 0 included, is a
    /// scramble).
    ///
    /// # Errors
    /// [`Error::ZeroSize`] if `dims == 0`.
    ///
    /// ```
    /// use nyquist::{sequence::OwenSobol, Error};
    /// assert!(OwenSobol::new(1024, 0).is_ok());
    /// assert!(OwenSobol::new(100_000, 0).is_ok());
    /// assert_eq!(OwenSobol::new(0, 1), Err(Error::ZeroSize { what: "dims" }));
    /// ```
    pub fn new(dims: u32, seed: u64) -> Result<OwenSobol, Error> {
        super::dims_within(dims, u32::MAX)?;
        let h = hash2(seed, 0x4f57_454e); // "OWEN"
        Ok(OwenSobol {
            dims,
            seed,
            shuffle: IndexShuffle::new(mix32((h >> 32) as u32)),
            low4_end: dims.min(UPPER_DIMS as u32).saturating_sub(3),
            seeds: DimSeeds::new(h as u32),
        })
    }

    /// The seed this sequence was built with.
    ///
    /// ```
    /// assert_eq!(nyquist::sequence::OwenSobol::new(2, 9).unwrap().seed(), 9);
    /// ```
    pub fn seed(&self) -> u64 {
        self.seed
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn wrap(&self, dim: u32) -> u32 {
        if dim < self.dims {
            dim
        } else {
            dim % self.dims
        }
    }

    /// The scrambled reversed value (before the final reversal) of dimension `dim` at the
    /// reversed shuffled index `r` ([`IndexShuffle::rev`]), if `dim`'s seed is kept (`None`
    /// past them).
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn table_value_rev(&self, r: u32, dim: u32) -> Option<u32> {
        let d = dim as usize;
        let &s = self.seeds.kept().get(d)?;
        let p = if d < UPPER_DIMS && r & 0xffff == 0 {
            product_rev_upper(d, r)
        } else {
            product_rev(d, r)
        };
        Some(lk_hash(p, s))
    }

    /// Dimension `dim < min(dims(), 1024)` at the reversed shuffled index `r` of an index below
    /// 2³², as an `f32`.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn value_f32(&self, r: u32, dim: u32) -> f32 {
        match self.table_value_rev(r, dim) {
            Some(w) => reversed_to_f32(w),
            None => owen_sobol_rev_f32(r, dim, self.seeds.get(dim)),
        }
    }

    /// Dimension `dim < dims()` (wrapped) of a point past the 32-bit paths: a 64-bit index or
    /// a padding dimension.
    #[inline(never)]
    fn wide_u32(&self, index: u64, dim: u32) -> u32 {
        if dim >= SOBOL_DIMS {
            padded_u32(self.seeds.key(), index, dim)
        } else {
            owen_sobol_u64(self.shuffle.rev64(index), dim, self.seeds.get(dim))
        }
    }

    /// Point `index`, dimension `dim` as a 32-bit binary fraction. Total: `dim` wraps modulo
    /// [`Sequence::dims`].
    ///
    /// ```
    /// use nyquist::sequence::OwenSobol;
    /// let s = OwenSobol::new(3, 1).unwrap();
    /// // Two points share their first digit in dimension 0 iff they are in the same half of
    /// // the first two points' block.
    /// assert_ne!(s.sample_u32(0, 0) >> 31, s.sample_u32(1, 0) >> 31);
    /// assert_eq!(s.sample_u32(5, 3), s.sample_u32(5, 0));
    /// ```
    #[inline]
    pub fn sample_u32(&self, index: u64, dim: u32) -> u32 {
        let dim = self.wrap(dim);
        if index >> 32 != 0 || dim >= SOBOL_DIMS {
            return self.wide_u32(index, dim);
        }
        let r = self.shuffle.rev(index as u32);
        match self.table_value_rev(r, dim) {
            Some(w) => w.reverse_bits(),
            None => owen_sobol_rev_u32(r, dim, self.seeds.get(dim)),
        }
    }

    /// Four consecutive dimensions `first_dim .. first_dim + 4` (each wrapping) of point
    /// `index`, as `f32`s, sharing the index shuffle: the 4-wide form of
    /// [`Sequence::sample`], equal to it value for value.
    ///
    /// ```
    /// use nyquist::sequence::{OwenSobol, Sequence};
    /// let s = OwenSobol::new(8, 3).unwrap();
    /// let v = s.sample_4d(77, 4);
    /// assert_eq!(v, [4, 5, 6, 7].map(|d| s.sample(77, d)));
    /// ```
    #[inline]
    pub fn sample_4d(&self, index: u64, first_dim: u32) -> [f32; 4] {
        // The common case in one test: an index below 2^16, whose reversed shuffled index has
        // a low half of `fix` that no table reads, and four dimensions inside the sequence and
        // the low-half byte tables, with their seeds kept: two 16-byte table reads and the
        // scramble, four lanes at once. (`min` only proves the bounds; the test already did.)
        if index < u64::from(LOW_BLOCK) && first_dim < self.low4_end {
            let r = self.shuffle.rev_low_upper(index as u32);
            let d = (first_dim as usize).min(UPPER_DIMS - 4);
            return scramble_rev_f32x4(product_rev_upper4(d, r), four(self.seeds.kept(), d));
        }
        self.sample_4d_rest(index, first_dim)
    }

    /// [`OwenSobol::sample_4d`] past its common case.
    #[inline(never)]
    fn sample_4d_rest(&self, index: u64, first_dim: u32) -> [f32; 4] {
        let dims = core::array::from_fn(|k| self.wrap(first_dim.wrapping_add(k as u32)));
        if index >> 32 != 0 || dims.iter().any(|&d| d >= SOBOL_DIMS) {
            return dims.map(|d| to_f32(self.wide_u32(index, d)));
        }
        let r = self.shuffle.rev_fast(index as u32);
        let fits = first_dim.checked_add(4).is_some_and(|e| e <= self.dims);
        let d = first_dim as usize;
        if fits && d + 4 <= REV_DIMS {
            return scramble_rev_f32x4(product_rev4(d, r), four(self.seeds.kept(), d));
        }
        // Past the byte tables, an aligned set of four below index 2^16: the nibble tables
        // four-wide.
        if fits && r & 0xffff == 0 && d >= UPPER_DIMS && d.is_multiple_of(4) {
            let p = product_rev16x4((d - UPPER_DIMS) / 4, r >> 16);
            return scramble_rev_f32x4(p, dim_seeds4(self.seeds.key(), first_dim));
        }
        owen_sobol_rev_f32x4(r, dims, dims.map(|d| self.seeds.get(d)))
    }

    /// Dimensions `first_dim, first_dim + 1, …` (each wrapping) of point `index` into `out`:
    /// one shuffle for the whole run. Equal to repeated [`Sequence::sample`].
    ///
    /// ```
    /// use nyquist::sequence::{OwenSobol, Sequence};
    /// let s = OwenSobol::new(32, 5).unwrap();
    /// let mut run = [0.0f32; 10];
    /// s.sample_dims(123, 20, &mut run);
    /// assert_eq!(run[9], s.sample(123, 29));
    /// ```
    #[inline]
    pub fn sample_dims(&self, index: u64, first_dim: u32, out: &mut [f32]) {
        let r = self.shuffle.rev(index as u32);
        let narrow = index >> 32 == 0;
        let mut d = first_dim;
        for x in out {
            let dim = self.wrap(d);
            *x = if narrow && dim < SOBOL_DIMS {
                self.value_f32(r, dim)
            } else {
                to_f32(self.wide_u32(index, dim))
            };
            d = d.wrapping_add(1);
        }
    }
}

impl Sequence for OwenSobol {
    fn dims(&self) -> u32 {
        self.dims
    }

    fn point_count(&self) -> Option<u64> {
        None
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        let dim = self.wrap(dim);
        if index >> 32 != 0 || dim >= SOBOL_DIMS {
            return to_f32(self.wide_u32(index, dim));
        }
        let r = self.shuffle.rev_fast(index as u32);
        self.value_f32(r, dim)
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        f64::from(self.sample_u32(index, dim)) * crate::math::TWO_POW_MINUS_32
    }

    /// Point-major fill: one shuffle per point.
    fn fill(&self, first: u64, dims: u32, out: &mut [f32]) -> Result<u64, Error> {
        let n = check_fill(self.dims, None, first, dims, out.len())?;
        for (k, point) in out.chunks_exact_mut(dims as usize).enumerate() {
            self.sample_dims(first + k as u64, 0, point);
        }
        Ok(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scramble::{fast_owen_scramble, nested_uniform_shuffle};
    use crate::sequence::sobol_u32;
    use crate::tests::sobol_oracle;
    use std::vec::Vec;

    /// The reversed tables give the reversed product, in every dimension with tables and past
    /// them. `0xffff_0000` reverses to the one word whose low half is all ones, the boundary
    /// of the test that sends words with a zero low half to the upper-half tables.
    #[test]
    fn reversed_tables_are_the_reversed_product() {
        let indices: Vec<u32> = (0..512u32)
            .chain((0..512).map(|i| mix32(i ^ 0x77)))
            .chain([u32::MAX, 1 << 31, 1, 0xffff_0000, 0xfffe_0000, 0x0001_0000])
            .collect();
        for dim in (0..REV_DIMS + 3).chain([200, 255, 256, 257, 700, 1023]) {
            for &i in &indices {
                let want = sobol_u32(i, dim as u32).reverse_bits();
                assert_eq!(product_rev(dim, i.reverse_bits()), want, "dim {dim} i {i}");
            }
        }
    }

    /// `seed` returns the seed given, whatever it is.
    #[test]
    fn seed_is_the_seed_given() {
        for seed in [0u64, 1, 9, u64::MAX] {
            assert_eq!(OwenSobol::new(3, seed).unwrap().seed(), seed);
        }
    }

    /// The value is Burley's composition of the public pieces: the Sobol point at the
    /// nested-uniform-shuffled index, fast-Owen scrambled.
    #[test]
    fn value_is_scrambled_sobol_at_the_shuffled_index() {
        let s = OwenSobol::new(1024, 42).unwrap();
        // The raw seeds behind the mixed ones: mix32 of (raw ^ const) must equal the mixed seed,
        // so compare through the reversed-domain identities instead.
        for i in [0u32, 1, 2, 3, 1000, 65_535, 65_536, 1 << 31, u32::MAX] {
            let r = s.shuffle.rev(i);
            let shuffled = r.reverse_bits();
            for d in [0u32, 1, 2, 17, 63, 64, 500, 1023] {
                let v = sobol_u32(shuffled, d);
                let want = lk_hash(v.reverse_bits(), s.seeds.get(d)).reverse_bits();
                assert_eq!(s.sample_u32(i.into(), d), want, "i {i} d {d}");
                assert_eq!(s.sample(u64::from(i), d), (want >> 8) as f32 / 16_777_216.0);
                assert_eq!(
                    s.sample_f64(u64::from(i), d),
                    f64::from(want) / 4_294_967_296.0
                );
            }
        }
        // And the public shuffle and scramble are these same reversed-domain hashes.
        assert_eq!(
            nested_uniform_shuffle(77, 5).reverse_bits(),
            lk_hash(77u32.reverse_bits(), mix32(5 ^ 0x6a09_e667))
        );
        assert_eq!(
            fast_owen_scramble(77, 5).reverse_bits(),
            lk_hash(77u32.reverse_bits(), mix32(5 ^ 0x6a09_e667))
        );
    }

    /// Past 2³²: the Owen scramble of `sobol_u64` at the 64-bit shuffled index, for the
    /// sequence's dimensions and for the padding (Sobol dimensions 0..3 of a block's own
    /// shuffle, under the dimension's own seed).
    #[test]
    fn values_past_2_32_are_scrambled_sobol_u64_at_the_shuffled_index() {
        use crate::sequence::sobol_u64;
        let s = OwenSobol::new(3000, 42).unwrap();
        let key = s.seeds.key();
        for i in [
            1u64 << 32,
            (1 << 32) + 1,
            0xabcd_ef01_2345_6789,
            u64::MAX,
            7,
        ] {
            let (r, hi) = s.shuffle.rev64(i);
            let shuffled = (u64::from(hi) << 32) | u64::from(r.reverse_bits());
            for d in [0u32, 1, 2, 17, 63, 64, 500, 1023] {
                let v = sobol_u64(shuffled, d);
                let want = lk_hash(v.reverse_bits(), s.seeds.get(d)).reverse_bits();
                assert_eq!(s.sample_u32(i, d), want, "i {i} d {d}");
            }
            for d in [1024u32, 1027, 2999] {
                let (r, hi) = IndexShuffle::new(dim_seed(!key, d / 4)).rev64(i);
                let shuffled = (u64::from(hi) << 32) | u64::from(r.reverse_bits());
                let v = sobol_u64(shuffled, d % 4);
                let want = lk_hash(v.reverse_bits(), dim_seed(key, d)).reverse_bits();
                assert_eq!(s.sample_u32(i, d), want, "i {i} d {d}");
                assert_eq!(padded_u32(key, i, d), want);
            }
        }
    }

    /// The values past 2³² and in the padding, pinned: the shuffle's and the blocks' seed
    /// derivations are part of the sequence (a renderer's images depend on them).
    #[test]
    fn values_past_2_32_and_padding_are_pinned() {
        let s = OwenSobol::new(3000, 42).unwrap();
        for (i, want) in [
            (1u64 << 32, [0x84c9_a0b0, 0x1cff_06bf, 0xd96e_0605]),
            (
                0xabcd_ef01_2345_6789,
                [0xf94b_104d, 0x3fa7_4c51, 0xc071_4805],
            ),
            (u64::MAX, [0xbecb_09f7, 0x87b7_463d, 0x34b3_30d7]),
        ] {
            assert_eq!([0, 5, 2000].map(|d| s.sample_u32(i, d)), want, "{i:#x}");
        }
    }

    #[test]
    fn dims_0_1_are_nets_and_every_dimension_is_stratified() {
        for seed in [0u64, 1, 5, 6, 10, 15, 0xdead_beef] {
            let s = OwenSobol::new(1024, seed).unwrap();
            for m in 0..=10 {
                let pts: Vec<[u32; 2]> = (0..1u32 << m)
                    .map(|i| [s.sample_u32(i.into(), 0), s.sample_u32(i.into(), 1)])
                    .collect();
                sobol_oracle::assert_elementary_intervals(&pts, m);
                for dim in [2u32, 3, 7, 31, 63, 64, 100, 1023] {
                    let mut seen = std::vec![false; 1 << m];
                    for i in 0..1u32 << m {
                        let x = s.sample(u64::from(i), dim);
                        assert!((0.0..1.0).contains(&x));
                        let cell = (x * (1u32 << m) as f32) as usize;
                        assert!(!std::mem::replace(&mut seen[cell], true), "dim {dim} m {m}");
                    }
                }
            }
        }
    }

    /// For a fixed index and dimension, the value over 10⁵ seeds is uniform: a chi-square test
    /// over 64 cells at a false-alarm rate far below 10⁻⁶.
    #[test]
    fn values_are_uniform_over_seeds() {
        const SEEDS: u64 = 100_000;
        const CELLS: usize = 64;
        for (index, dim) in [
            (0u32, 0u32),
            (1, 0),
            (5, 1),
            (1000, 2),
            (3, 63),
            (7, 64),
            (9, 900),
        ] {
            let mut counts = [0u32; CELLS];
            for seed in 0..SEEDS {
                let x = OwenSobol::new(1024, seed)
                    .unwrap()
                    .sample(u64::from(index), dim);
                counts[(x * CELLS as f32) as usize] += 1;
            }
            let chi2 = crate::tests::chi_square_uniform(&counts);
            // 63 degrees of freedom: mean 63, sd 11.2; 130 is past 6 sd.
            assert!(chi2 < 130.0, "index {index} dim {dim}: chi2 {chi2:.1}");
        }
    }

    #[test]
    fn wide_and_run_forms_equal_single_values() {
        for (s, firsts) in [
            (OwenSobol::new(100, 9).unwrap(), [0u32, 13, 60, 97, 99]),
            (
                OwenSobol::new(2000, 9).unwrap(),
                [1019, 1022, 1024, 1997, 5],
            ),
        ] {
            for i in [
                0u64,
                3,
                70_000,
                u64::from(u32::MAX),
                1 << 32,
                5 << 40,
                u64::MAX,
            ] {
                for first in firsts {
                    let w = s.sample_4d(i, first);
                    let mut run = [0.0f32; 9];
                    s.sample_dims(i, first, &mut run);
                    for k in 0..9u32 {
                        let one = s.sample(i, first + k);
                        assert_eq!(run[k as usize], one);
                        assert_eq!(one, to_f32(s.sample_u32(i, first + k)));
                        if k < 4 {
                            assert_eq!(w[k as usize], one);
                        }
                    }
                }
            }
            let mut buf = [0.0f32; 30];
            assert_eq!(s.fill(5, 3, &mut buf), Ok(10));
            assert_eq!(buf[3 * 4 + 2], s.sample(9, 2));
            assert_eq!(s.fill((1 << 32) - 2, 3, &mut buf), Ok(10));
            assert_eq!(buf[3 * 4 + 2], s.sample((1 << 32) + 2, 2));
            assert!(s.fill(u64::MAX - 2, 3, &mut buf).is_err());
        }
    }

    /// The index whose reversed shuffled word is `0x0000_ffff`, the one word with a nonzero low
    /// half that a test for a zero low half confuses with zero under `^`. The word's low half
    /// depends only on the index's high half (a nested uniform shuffle), so that is found
    /// first, then the low half.
    fn index_with_word_ffff(s: &OwenSobol) -> u32 {
        let hi = (0..=0xffffu32)
            .find(|&h| s.shuffle.rev(h << 16) & 0xffff == 0xffff)
            .unwrap();
        (0..=0xffffu32)
            .map(|l| hi << 16 | l)
            .find(|&i| s.shuffle.rev(i) == 0xffff)
            .unwrap()
    }

    /// At that index, every path (the kept seeds' tables, the 4-wide nibble tables past them)
    /// gives the general path's value.
    #[test]
    fn the_word_with_a_full_low_half_takes_the_general_product() {
        for seed in [42u64, 7] {
            let s = OwenSobol::new(1024, seed).unwrap();
            let i = index_with_word_ffff(&s);
            assert_eq!(s.shuffle.rev_fast(i), 0xffff);
            for d in [0u32, 1, 63, 64, 65, 200, 255, 256, 300, 1023] {
                assert_eq!(
                    s.sample_u32(i.into(), d),
                    reference_u32(&s, i, d),
                    "seed {seed} d {d}"
                );
            }
            for first in [0u32, 60, 64, 252, 256, 512, 1020] {
                let want = core::array::from_fn(|k| {
                    (reference_u32(&s, i, first + k as u32) >> 8) as f32 / 16_777_216.0
                });
                assert_eq!(
                    s.sample_4d(i.into(), first),
                    want,
                    "seed {seed} first {first}"
                );
            }
        }
    }

    /// The 64-bit shuffle: the 32-bit one below 2³², and past it a bijection of the upper half
    /// that keeps `0..2^j` for every `j` (so the first `2^k` indices stay the first `2^k`).
    #[test]
    fn the_64_bit_shuffle_keeps_every_power_of_two_prefix() {
        for seed in [0u32, 7, 0xdead_beef] {
            let shuffle = IndexShuffle::new(mix32(seed));
            for i in [0u32, 1, 77, u32::MAX] {
                assert_eq!(shuffle.rev64(u64::from(i)), (shuffle.rev(i), 0));
            }
            let his: std::vec::Vec<u32> = (0..1024u64).map(|h| shuffle.rev64(h << 32).1).collect();
            for j in 0..=10 {
                let mut prefix: std::vec::Vec<u32> = his[..1 << j].to_vec();
                prefix.sort_unstable();
                assert_eq!(
                    prefix,
                    (0..1u32 << j).collect::<std::vec::Vec<_>>(),
                    "seed {seed} j {j}"
                );
            }
            // The low half is shuffled under a seed that depends on the upper half.
            assert_ne!(shuffle.rev64(1 << 32).0, shuffle.rev64(2 << 32).0);
        }
    }

    /// Aligned blocks past 2³² and across it are (0, m, 2)-nets in dimensions 0 and 1.
    #[test]
    fn blocks_past_2_32_are_nets() {
        for seed in 0..4 {
            let s = OwenSobol::new(4, seed).unwrap();
            for first in [1u64 << 32, 0x1234_5678 << 32, u64::MAX - 0xfff] {
                for m in [1u32, 6, 12] {
                    let first = first & !((1 << m) - 1);
                    let pts: std::vec::Vec<[u32; 2]> = (0..1u64 << m)
                        .map(|k| first + k)
                        .map(|i| [s.sample_u32(i, 0), s.sample_u32(i, 1)])
                        .collect();
                    crate::tests::sobol_oracle::assert_elementary_intervals(&pts, m);
                }
            }
        }
    }

    /// Padding: the (0, m, 2)-net in each padded block's first two dimensions, far past 1024,
    /// and no correlation between a dimension and the one 1024 above it.
    ///
    /// The correlation bound: for independent uniform pairs the sample correlation of 4096
    /// points has standard deviation 1/64, so `|r| < 4/64` fails with probability about 6e-5
    /// per pair (40 pairs here, fixed seeds: deterministic once run). A dimension wrapped onto
    /// a lower one under a second nested scramble would give `|r|` near 0.75 or more.
    #[test]
    fn padding_blocks_are_nets_and_uncorrelated_with_lower_dimensions() {
        let n = 4096u64;
        for seed in 0..8 {
            let s = OwenSobol::new(u32::MAX, seed).unwrap();
            for first in [1024u32, 4000, 1 << 20, u32::MAX - 3] {
                let block = first & !3;
                for m in [2u32, 7, 12] {
                    let pts: std::vec::Vec<[u32; 2]> = (0..1u64 << m)
                        .map(|i| [s.sample_u32(i, block), s.sample_u32(i, block + 1)])
                        .collect();
                    crate::tests::sobol_oracle::assert_elementary_intervals(&pts, m);
                }
            }
            for d in [0u32, 1, 5, 100, 1000] {
                let (mut sx, mut sy, mut sxx, mut syy, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
                for i in 0..n {
                    let x = f64::from(s.sample(i, d));
                    let y = f64::from(s.sample(i, d + 1024));
                    (sx, sy, sxx, syy, sxy) =
                        (sx + x, sy + y, sxx + x * x, syy + y * y, sxy + x * y);
                }
                let nf = n as f64;
                let cov = sxy / nf - sx * sy / (nf * nf);
                let r =
                    cov / ((sxx / nf - (sx / nf).powi(2)) * (syy / nf - (sy / nf).powi(2))).sqrt();
                assert!(r.abs() < 4.0 / 64.0, "seed {seed} dim {d}: r = {r}");
            }
        }
    }

    /// The `Sequence` facts: the dimension count given, a point for every `u64` index.
    #[test]
    fn dims_and_point_count() {
        for dims in [1u32, 2, 100, 1024, 1025, u32::MAX] {
            let s = OwenSobol::new(dims, 3).unwrap();
            assert_eq!(Sequence::dims(&s), dims);
            assert_eq!(s.point_count(), None);
        }
    }

    #[test]
    fn indices_past_2_pow_16_are_new_points() {
        // sobol_burley stops at 2^16; here the next block is a net of its own, not a repeat.
        let s = OwenSobol::new(2, 3).unwrap();
        let a: Vec<u32> = (0..64u64).map(|i| s.sample_u32(i, 0)).collect();
        let b: Vec<u32> = (0..64).map(|i| s.sample_u32(i + 65_536, 0)).collect();
        assert_ne!(a, b);
        let pts: Vec<[u32; 2]> = (0..1u32 << 17)
            .map(|i| [s.sample_u32(i.into(), 0), s.sample_u32(i.into(), 1)])
            .collect();
        sobol_oracle::assert_elementary_intervals(&pts, 17);
    }

    /// The value by the general path alone: shuffle, byte-table or masked product, hash.
    fn reference_u32(s: &OwenSobol, index: u32, dim: u32) -> u32 {
        let dim = dim % s.dims;
        owen_sobol_rev_u32(s.shuffle.rev(index), dim, dim_seed(s.seeds.key(), dim))
    }

    /// Indices around the 2^8 and 2^16 edges, the ends, and scattered ones.
    fn edge_indices() -> Vec<u32> {
        (0..300u32)
            .chain(65_000..66_100)
            .chain((0..200).map(|i| mix32(i ^ 0x5151)))
            .chain((0..200).map(|i| mix32(i ^ 0x7171) & 0xffff))
            .chain([
                1 << 17,
                1 << 24,
                (1 << 31) - 1,
                1 << 31,
                u32::MAX - 1,
                u32::MAX,
            ])
            .collect()
    }

    /// Below 2^16 the product reads only the upper-half tables (or the 16 columns past them),
    /// and the index reversal and the f32 conversion go through tables: every form equals the
    /// general path, in and past the tables, across the 2^8 and 2^16 edges, for many seeds.
    #[test]
    fn fast_paths_equal_the_general_path() {
        for seed in [0u64, 1, 7, 0x5eed, 0xdead_beef, u64::MAX] {
            let s = OwenSobol::new(1024, seed).unwrap();
            for i in edge_indices() {
                let mut run = [0.0f32; 70];
                s.sample_dims(i.into(), 0, &mut run);
                for dim in (0..REV_DIMS as u32 + 2).chain([200, 255, 256, 500, 1023]) {
                    let want = reference_u32(&s, i, dim);
                    let want_f32 = (want >> 8) as f32 / 16_777_216.0;
                    assert_eq!(
                        s.sample_u32(i.into(), dim),
                        want,
                        "seed {seed} i {i} dim {dim}"
                    );
                    assert_eq!(s.sample(u64::from(i), dim), want_f32, "i {i} dim {dim}");
                    if let Some(&x) = run.get(dim as usize) {
                        assert_eq!(x, want_f32, "run: i {i} dim {dim}");
                    }
                }
                for first in
                    (0..REV_DIMS as u32 + 2).chain([64, 68, 200, 250, 252, 253, 256, 260, 1020])
                {
                    let want = core::array::from_fn(|k| {
                        (reference_u32(&s, i, first + k as u32) >> 8) as f32 / 16_777_216.0
                    });
                    assert_eq!(
                        s.sample_4d(i.into(), first),
                        want,
                        "4d: i {i} first {first}"
                    );
                }
            }
        }
    }

    /// Every dims count around the table edge, every first dimension: the 4-wide form takes its
    /// fast lane only when all four dimensions are in the tables and in the sequence, and wraps
    /// like single values otherwise.
    #[test]
    fn wide_form_at_every_dims_count_and_wrap_edge() {
        for dims in (1..=8)
            .chain(56..=70)
            .chain([100, 255, 256, 257, 259, 260, 1024])
        {
            let s = OwenSobol::new(dims, u64::from(dims) * 31).unwrap();
            for i in [0u32, 1, 255, 256, 65_535, 65_536, 70_000, u32::MAX] {
                let edge = 248..264; // the last sets of the low-half byte tables
                for first in
                    (0..dims.min(72) + 5)
                        .chain(edge)
                        .chain([dims + 60, u32::MAX - 1, u32::MAX])
                {
                    let want = [0u32, 1, 2, 3].map(|k| {
                        let d = first.wrapping_add(k);
                        (reference_u32(&s, i, d) >> 8) as f32 / 16_777_216.0
                    });
                    assert_eq!(
                        s.sample_4d(i.into(), first),
                        want,
                        "dims {dims} i {i} first {first}"
                    );
                    assert_eq!(want[0], s.sample(u64::from(i), first));
                }
            }
        }
    }

    /// The small compile-time tables (the index reversal, the f32 conversion) and the shuffle's
    /// block: every index below 2^16 shuffles to one below 2^16, each prefix `0..2^k` onto an
    /// aligned block, and there the product needs only the upper-half tables or the 16 columns.
    #[test]
    fn small_tables_and_the_low_block() {
        for seed in [0x9e37_79b9u32, 77, 0, u32::MAX] {
            let sh = IndexShuffle::new(seed);
            for k in 0..=16u32 {
                let base = sh.rev(0).reverse_bits() >> k;
                let mut seen = std::vec![false; 1 << k];
                for i in 0..1u32 << k {
                    let r = sh.rev(i);
                    assert_eq!(r & 0xffff, 0, "seed {seed} i {i}");
                    let j = r.reverse_bits();
                    assert_eq!(j >> k, base, "seed {seed} k {k} i {i}");
                    assert!(!std::mem::replace(
                        &mut seen[(j & ((1 << k) - 1)) as usize],
                        true
                    ));
                }
            }
            for i in (0..1u32 << 16)
                .step_by(7)
                .chain([1 << 16, 1 << 20, u32::MAX])
            {
                assert_eq!(sh.rev_fast(i), sh.rev(i), "i {i}");
            }
        }
        let words = (0..1u32 << 16)
            .map(|w| w << 8 | w >> 8)
            .chain((0..100_000).map(mix32))
            .chain([0, u32::MAX, 1, 1 << 31, 0x00ff_ffff, 0xff00_0000]);
        for w in words {
            assert_eq!(reversed_to_f32(w), rev_to_f32(w), "w {w:#x}");
            assert_eq!(scramble_rev_f32x4([w; 4], [0x1357_9bdf; 4])[2], {
                rev_to_f32(lk_hash(w, 0x1357_9bdf))
            });
        }
        for h in (0..1u32 << 16).step_by(13).chain([0xffff]) {
            let r = h << 16;
            for d in 0..1024usize {
                let want = product(&SOBOL_MATRICES[d], r.reverse_bits()).reverse_bits();
                assert_eq!(product_rev(d, r), want, "d {d} h {h}");
                if d >= UPPER_DIMS {
                    assert_eq!(product_rev16(d, h), want, "d {d} h {h}");
                    assert_eq!(product_rev16x4((d - UPPER_DIMS) / 4, h)[d % 4], want);
                } else {
                    assert_eq!(product_rev_upper(d, r), want);
                }
            }
        }
        assert_eq!(size_of::<OwenSobol>(), 1056);
    }

    #[test]
    fn four_lane_seeds_are_the_dimension_seeds() {
        for key in [0u32, 1, 0xdead_beef] {
            for first in [0u32, 64, 1020, u32::MAX - 2] {
                let want: [u32; 4] =
                    core::array::from_fn(|k| dim_seed(key, first.wrapping_add(k as u32)));
                assert_eq!(dim_seeds4(key, first), want);
            }
        }
    }

    #[test]
    fn helpers_agree_lane_by_lane() {
        let s = OwenSobol::new(1024, 4).unwrap();
        for i in [0u32, 9, 65_536, u32::MAX] {
            let r = s.shuffle.rev(i);
            for dims in [[0u32, 1, 2, 3], [62, 63, 64, 65], [1020, 1021, 1022, 1023]] {
                let seeds = dims.map(|d| s.seeds.get(d));
                let want = core::array::from_fn(|k| owen_sobol_rev_f32(r, dims[k], seeds[k]));
                assert_eq!(owen_sobol_rev_f32x4(r, dims, seeds), want);
            }
        }
    }

    proptest::proptest! {
        #[test]
        fn values_in_unit_interval(index: u64, dim: u32, seed: u64) {
            let s = OwenSobol::new(1024, seed).unwrap();
            let x = s.sample(index, dim);
            proptest::prop_assert!((0.0..1.0).contains(&x));
            let y = s.sample_f64(index, dim);
            proptest::prop_assert!((0.0..1.0).contains(&y));
        }
    }
}
