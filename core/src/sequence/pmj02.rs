//! Progressive multi-jittered (0,2) sequences (Christensen, Kensler & Kilpatrick 2018,
//! "Progressive Multi-Jittered Sample Sequences"), made by the stochastic construction of
//! Helmer, Christensen & Kensler 2021 ("Stochastic Generation of (t, s) Sample Sequences").
//!
//! A point is two 32-bit binary fractions. Point 0 is random. At level `L` the `2^L` points
//! made so far are doubled: new point `2^L + i` takes, in dimension `k`, the first `L` digits of
//! old point `i ⊕ c_k[L]`, the opposite of its digit `L + 1`, and random digits below. The
//! old points hold one point per stratum of width `2^−L` in each dimension, so every new point
//! fills the empty half of one such stratum; the per-level XOR constants `c_k` decide which old
//! point a new one pairs with, and are chosen (by the paper's authors) so that every power-of-two
//! prefix — and every aligned block of `2^m` points — is a (0, m, 2)-net. The tests here check
//! that for many seeds.
//!
//! [`pmj02_build`] runs the construction in place into a caller buffer; [`PMJ02_TABLE`] is the
//! same construction for a fixed seed, baked at compile time; [`Pmj02`] reads that table by
//! index, optionally Owen-scrambled per instance.

use super::Sequence;
use crate::Error;
use crate::hash::{hash2, lcg_next, lcg_state};
use crate::math::fraction_to_f32 as to_f32;
use crate::scramble::{
    lk_hash_premixed, lk_premix, reverse16, reversed_to_f32, scramble_premixed_rev_f32x4,
};

/// The most points the construction makes: the published XOR constants cover 16 levels.
///
/// ```
/// assert_eq!(nyquist::sequence::PMJ02_MAX_POINTS, 65536);
/// ```
pub const PMJ02_MAX_POINTS: usize = 1 << 16;

/// The seed [`PMJ02_TABLE`] is built from: of seeds 0 … 1023, the one whose table has the
/// lowest error on centred radial integrands under `pmj02-bn`'s digital shift (the lab's
/// `pmj02-seed`, which `--check`s this value). The Owen-scrambled [`Pmj02`] redraws the
/// digits a seed sets, so its error does not depend on it.
///
/// ```
/// use nyquist::sequence::{pmj02_build, PMJ02_TABLE, PMJ02_TABLE_SEED};
/// let mut first = [[0u32; 2]; 8];
/// pmj02_build(PMJ02_TABLE_SEED, &mut first).unwrap();
/// assert_eq!(first, PMJ02_TABLE[..8]);
/// ```
pub const PMJ02_TABLE_SEED: u32 = 0;

/// The per-level XOR constants for pmj02, dimension x then y, levels 0..15.
///
/// Source: Helmer, Christensen & Kensler 2021, as also shipped by OpenQMC (Apache-2.0,
/// `include/oqmc/stochastic.h`). Constant `c[L]` is below `2^L`, so `i ⊕ c[L]` is an old point.
const XORS: [[usize; 16]; 2] = [
    [
        0x0000, 0x0000, 0x0002, 0x0006, 0x0006, 0x000e, 0x0036, 0x004e, 0x0016, 0x002e, 0x0276,
        0x06ce, 0x0716, 0x0c2e, 0x3076, 0x40ce,
    ],
    [
        0x0000, 0x0001, 0x0003, 0x0003, 0x0007, 0x001b, 0x0027, 0x000b, 0x0017, 0x013b, 0x0367,
        0x038b, 0x0617, 0x183b, 0x2067, 0x008b,
    ],
];

/// The construction into `out` (any length up to [`PMJ02_MAX_POINTS`]; the caller checks).
/// Point `i`'s random digits are draws `2i` (x) and `2i + 1` (y) of OpenQMC's generator from
/// `seed` (`hash::lcg_draw`), so a shorter buffer gets a prefix of a longer one, and
/// seed 0 gives OpenQMC's draws.
const fn construct(seed: u32, out: &mut [[u32; 2]]) {
    let n = out.len();
    if n == 0 {
        return;
    }
    // OpenQMC's generator, drawn in order: two words a point (`lcg_draw` jumps to any one).
    let mut state = lcg_state(seed);
    out[0] = [lcg_next(&mut state), lcg_next(&mut state)];
    let mut level = 0;
    let mut len = 1;
    while len < n {
        let swap = 0x8000_0000u32 >> level;
        let low = swap - 1;
        let (cx, cy) = (XORS[0][level], XORS[1][level]);
        let end = if 2 * len < n { 2 * len } else { n };
        let mut i2 = len;
        while i2 < end {
            let i1 = i2 - len;
            let (rx, ry) = (lcg_next(&mut state), lcg_next(&mut state));
            // Keep digits 1..=L of the paired old point, flip digit L + 1, draw the rest.
            let x = ((out[i1 ^ cx][0] & !low) ^ swap) | (rx & low);
            let y = ((out[i1 ^ cy][1] & !low) ^ swap) | (ry & low);
            out[i2] = [x, y];
            i2 += 1;
        }
        len *= 2;
        level += 1;
    }
}

/// Writes the first `out.len()` points of the pmj02 sequence of `seed` into `out`, as 32-bit
/// binary fractions `[x, y]` (the value is `x / 2³²`). Deterministic per seed, and
/// prefix-consistent: a shorter buffer receives the first points of a longer one. Every
/// power-of-two prefix `2^m` is a (0, m, 2)-net. Reads only points already written, so it needs
/// no scratch memory. Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] if `out` is empty; [`Error::TooMany`] if it holds more than
/// [`PMJ02_MAX_POINTS`] points (the published constants stop at 16 levels).
///
/// ```
/// use nyquist::sequence::pmj02_build;
/// let mut pts = [[0u32; 2]; 16];
/// pmj02_build(7, &mut pts).unwrap();
/// // 16 points: one in each of the 16 columns and each of the 16 rows.
/// let mut cols = [0; 16];
/// let mut rows = [0; 16];
/// for [x, y] in pts {
///     cols[(x >> 28) as usize] += 1;
///     rows[(y >> 28) as usize] += 1;
/// }
/// assert_eq!((cols, rows), ([1; 16], [1; 16]));
/// assert!(pmj02_build(7, &mut []).is_err());
/// ```
pub const fn pmj02_build(seed: u32, out: &mut [[u32; 2]]) -> Result<(), Error> {
    if out.is_empty() {
        return Err(Error::ZeroSize { what: "points" });
    }
    if out.len() > PMJ02_MAX_POINTS {
        return Err(Error::TooMany {
            what: "points",
            value: out.len() as u64,
            max: PMJ02_MAX_POINTS as u64,
        });
    }
    construct(seed, out);
    Ok(())
}

const fn fill_table(t: &mut [[u32; 2]; PMJ02_MAX_POINTS]) {
    construct(PMJ02_TABLE_SEED, t);
}

const fn bake() -> [[u32; 2]; PMJ02_MAX_POINTS] {
    let mut t = [[0u32; 2]; PMJ02_MAX_POINTS];
    fill_table(&mut t);
    t
}

crate::lazy_table::baked_table! {
    /// The table the unscrambled sequence reads: [`PMJ02_TABLE`] itself, or with the
    /// `lazy-tables` feature the same points built at first use (so a program that does not name
    /// `PMJ02_TABLE` does not carry its 512 KiB).
    pub(crate) static PMJ02_POINTS: [[u32; 2]; PMJ02_MAX_POINTS] = [[0; 2]; PMJ02_MAX_POINTS],
        fill_table, pmj02_points_at_first_use_equal_the_stored_table, stored PMJ02_TABLE;
}

/// [`PMJ02_TABLE`] for the Owen-scrambled reads: point `reverse16(m)` in row `m`, each coordinate
/// bit-reversed and passed through the LK hash's seedless first step
/// ([`lk_premix`]). The fast Owen scramble works on bit-reversed words and the camera samples'
/// nested index shuffle ends in a reversed row index; with this table neither needs a bit
/// reversal, which x86-64 has no instruction for, and every read hashes with one multiply
/// fewer (every reader hashes: the plain sequence reads [`PMJ02_TABLE`]).
const fn fill_premixed(t: &mut [[u32; 2]; PMJ02_MAX_POINTS]) {
    fill_table(t);
    let mut m = 0;
    while m < PMJ02_MAX_POINTS {
        // The row order is an involution: swap each pair once.
        let r = reverse16(m as u32) as usize;
        if m <= r {
            let (a0, a1, b0, b1) = (t[m][0], t[m][1], t[r][0], t[r][1]);
            t[m][0] = lk_premix(b0.reverse_bits());
            t[m][1] = lk_premix(b1.reverse_bits());
            t[r][0] = lk_premix(a0.reverse_bits());
            t[r][1] = lk_premix(a1.reverse_bits());
        }
        m += 1;
    }
}

crate::lazy_table::baked_table! {
    /// [`fill_premixed`]'s table (512 KiB): what the Owen-scrambled sequence and
    /// [`Pmj02Sampler`](crate::sampler::Pmj02Sampler) read.
    pub(crate) static PMJ02_PREMIXED: [[u32; 2]; PMJ02_MAX_POINTS] = [[0; 2]; PMJ02_MAX_POINTS],
        fill_premixed, pmj02_premixed_at_first_use_equals_the_baked_table;
}

/// [`PMJ02_MAX_POINTS`] pmj02 points of seed [`PMJ02_TABLE_SEED`] (512 KiB), built by
/// [`pmj02_build`]'s construction at compile time. Every power-of-two prefix and every aligned
/// block of `2^m` points is a (0, m, 2)-net (the tests check it).
///
/// ```
/// use nyquist::sequence::PMJ02_TABLE;
/// // The first two points sit in opposite halves in both dimensions.
/// assert_ne!(PMJ02_TABLE[0][0] >> 31, PMJ02_TABLE[1][0] >> 31);
/// assert_ne!(PMJ02_TABLE[0][1] >> 31, PMJ02_TABLE[1][1] >> 31);
/// ```
pub static PMJ02_TABLE: [[u32; 2]; PMJ02_MAX_POINTS] = bake();

/// The baked pmj02 sequence ([`PMJ02_TABLE`]) by index, plain or Owen-scrambled.
///
/// [`Pmj02::new`] reads the table as it is; [`Pmj02::scrambled`] passes each dimension through
/// its own fast Owen scramble chosen by a seed. An Owen scramble maps every elementary interval
/// onto one of the same shape, so every scrambled instance keeps the net and stratification
/// properties of the table: many independent pmj02 sequences from one table.
///
/// Two dimensions; [`Sequence::point_count`] is `Some(65536)`: indices wrap modulo
/// [`PMJ02_MAX_POINTS`] and `dim` modulo 2. Values are `f32` from the top 24 bits (truncated,
/// never 1) or `f64` from all 32. Allocates: no.
///
/// ```
/// use nyquist::sequence::{Pmj02, Sequence, PMJ02_TABLE};
/// let p = Pmj02::new();
/// assert_eq!(p.sample_2d_u32(5), PMJ02_TABLE[5]);
/// assert_eq!(p.sample(5 + 65536, 3), p.sample(5, 1)); // index and dim wrap
/// // Any scramble: the first 4 points fill the four quarter-width rows once each.
/// let s = Pmj02::scrambled(9);
/// let mut rows = [0; 4];
/// for i in 0..4 {
///     rows[(s.sample(i, 1) * 4.0) as usize] += 1;
/// }
/// assert_eq!(rows, [1, 1, 1, 1]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Pmj02 {
    /// The mixed Owen keys of x and y, or `None` for the plain table.
    keys: Option<[u32; 2]>,
}

impl Pmj02 {
    /// The baked table as it is.
    ///
    /// ```
    /// use nyquist::sequence::{Pmj02, PMJ02_TABLE};
    /// assert_eq!(Pmj02::new().sample_u32(3, 1), PMJ02_TABLE[3][1]);
    /// ```
    pub const fn new() -> Pmj02 {
        Pmj02 { keys: None }
    }

    /// The table with each dimension fast-Owen-scrambled by a key hashed from `seed` (every
    /// seed, 0 included, gives a scrambled instance).
    ///
    /// ```
    /// use nyquist::sequence::Pmj02;
    /// // Scrambling keeps every prefix a net: the first four points, one per quadrant.
    /// let q: Vec<usize> = (0..4)
    ///     .map(|i| Pmj02::scrambled(4).sample_2d(i))
    ///     .map(|[x, y]| (x * 2.0) as usize + 2 * (y * 2.0) as usize)
    ///     .collect();
    /// let mut sorted = q.clone();
    /// sorted.sort();
    /// assert_eq!(sorted, [0, 1, 2, 3]);
    /// assert_ne!(Pmj02::scrambled(4).sample_2d(0), Pmj02::scrambled(5).sample_2d(0));
    /// ```
    pub const fn scrambled(seed: u64) -> Pmj02 {
        let h = hash2(seed, 0x706d_6a30_325f_6f77);
        Pmj02 {
            keys: Some([h as u32, (h >> 32) as u32]),
        }
    }

    /// Coordinate `dim & 1` of point `index & 0xffff`, as a 32-bit binary fraction.
    ///
    /// ```
    /// use nyquist::sequence::Pmj02;
    /// let p = Pmj02::scrambled(1);
    /// assert_eq!(p.sample_u32(70_000, 2), p.sample_2d_u32(70_000 - 65_536)[0]);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn sample_u32(&self, index: u32, dim: u32) -> u32 {
        let d = (dim & 1) as usize;
        match self.keys {
            None => PMJ02_POINTS[index as usize & (PMJ02_MAX_POINTS - 1)][d],
            Some(keys) => lk_hash_premixed(PMJ02_PREMIXED[reverse16(index) as usize][d], keys[d])
                .reverse_bits(),
        }
    }

    /// Point `index & 0xffff` as two 32-bit binary fractions.
    ///
    /// ```
    /// use nyquist::sequence::{Pmj02, PMJ02_TABLE};
    /// assert_eq!(Pmj02::new().sample_2d_u32(65_536 + 2), PMJ02_TABLE[2]);
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn sample_2d_u32(&self, index: u32) -> [u32; 2] {
        match self.keys {
            None => PMJ02_POINTS[index as usize & (PMJ02_MAX_POINTS - 1)],
            Some([kx, ky]) => {
                let [x, y] = PMJ02_PREMIXED[reverse16(index) as usize];
                [
                    lk_hash_premixed(x, kx).reverse_bits(),
                    lk_hash_premixed(y, ky).reverse_bits(),
                ]
            }
        }
    }

    /// Point `index & 0xffff` as two `f32` in `[0, 1)`.
    ///
    /// ```
    /// use nyquist::sequence::Pmj02;
    /// let [x, y] = Pmj02::scrambled(3).sample_2d(12);
    /// assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
    /// ```
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub fn sample_2d(&self, index: u32) -> [f32; 2] {
        match self.keys {
            None => {
                let [x, y] = PMJ02_POINTS[index as usize & (PMJ02_MAX_POINTS - 1)];
                [to_f32(x), to_f32(y)]
            }
            Some([kx, ky]) => {
                let [x, y] = PMJ02_PREMIXED[reverse16(index) as usize];
                [
                    reversed_to_f32(lk_hash_premixed(x, kx)),
                    reversed_to_f32(lk_hash_premixed(y, ky)),
                ]
            }
        }
    }

    /// The points at many indices at once: `out[k] = sample_2d(indices[k])`, the same values.
    /// Scrambled, four coordinates (two points) hash at a time on vector lanes, a higher
    /// throughput than per-point calls on x86-64 (the `pmj02` rows of `docs/performance.md`).
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `out` is as long as `indices`.
    ///
    /// ```
    /// use nyquist::sequence::Pmj02;
    /// let p = Pmj02::scrambled(5);
    /// let indices = [3, 70_000, 12, 9, 65_535];
    /// let mut out = [[0.0f32; 2]; 5];
    /// p.fill_2d(&indices, &mut out).unwrap();
    /// assert!(indices.iter().zip(&out).all(|(&i, &o)| o == p.sample_2d(i)));
    /// assert!(p.fill_2d(&indices[..4], &mut out).is_err());
    /// ```
    pub fn fill_2d(&self, indices: &[u32], out: &mut [[f32; 2]]) -> Result<(), Error> {
        if out.len() != indices.len() {
            return Err(Error::BufferLength {
                multiple_of: indices.len(),
                actual: out.len(),
            });
        }
        let Some([kx, ky]) = self.keys else {
            for (o, &i) in out.iter_mut().zip(indices) {
                *o = self.sample_2d(i);
            }
            return Ok(());
        };
        let seeds = [kx, ky, kx, ky];
        let mut outs = out.chunks_exact_mut(4);
        let mut ins = indices.chunks_exact(4);
        for (o, i) in (&mut outs).zip(&mut ins) {
            // Four table reads first, so that their latencies overlap.
            let [x0, y0] = PMJ02_PREMIXED[reverse16(i[0]) as usize];
            let [x1, y1] = PMJ02_PREMIXED[reverse16(i[1]) as usize];
            let [x2, y2] = PMJ02_PREMIXED[reverse16(i[2]) as usize];
            let [x3, y3] = PMJ02_PREMIXED[reverse16(i[3]) as usize];
            let [a0, b0, a1, b1] = scramble_premixed_rev_f32x4([x0, y0, x1, y1], seeds);
            let [a2, b2, a3, b3] = scramble_premixed_rev_f32x4([x2, y2, x3, y3], seeds);
            o.copy_from_slice(&[[a0, b0], [a1, b1], [a2, b2], [a3, b3]]);
        }
        for (o, &i) in outs.into_remainder().iter_mut().zip(ins.remainder()) {
            *o = self.sample_2d(i);
        }
        Ok(())
    }
}

impl Sequence for Pmj02 {
    fn dims(&self) -> u32 {
        2
    }

    fn point_count(&self) -> Option<u64> {
        Some(PMJ02_MAX_POINTS as u64)
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        let d = (dim & 1) as usize;
        match self.keys {
            None => to_f32(PMJ02_POINTS[index as usize & (PMJ02_MAX_POINTS - 1)][d]),
            Some(keys) => reversed_to_f32(lk_hash_premixed(
                PMJ02_PREMIXED[reverse16(index as u32) as usize][d],
                keys[d],
            )),
        }
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        f64::from(self.sample_u32(index as u32, dim)) * crate::math::TWO_POW_MINUS_32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hash::mix32;
    use crate::tests::sobol_oracle::assert_elementary_intervals;
    use std::vec;
    use std::vec::Vec;

    const SEEDS: [u32; 6] = [0, 1, 5, 6, 10, 15];

    /// Whether `pts` (a power-of-two count `2^m`) has one point in every `2^a × 2^(m−a)`
    /// elementary interval.
    fn is_net(pts: &[[u32; 2]]) -> bool {
        let m = pts.len().trailing_zeros();
        assert!(pts.len().is_power_of_two());
        (0..=m).all(|a| {
            let mut seen = vec![false; pts.len()];
            pts.iter().all(|&[x, y]| {
                let cx = if a == 0 { 0 } else { (x >> (32 - a)) as usize };
                let cy = if a == m {
                    0
                } else {
                    (y >> (32 - (m - a))) as usize
                };
                !core::mem::replace(&mut seen[(cx << (m - a)) | cy], true)
            })
        })
    }

    fn built(seed: u32, n: usize) -> Vec<[u32; 2]> {
        let mut v = vec![[0u32; 2]; n];
        pmj02_build(seed, &mut v).unwrap();
        v
    }

    #[test]
    fn pmj02_net_checker_rejects_a_non_net() {
        // The checker must be able to fail: the four corners of the 2 × 2 grid fill its cells
        // but pair up in the columns of width 1/4.
        assert!(!is_net(&[
            [0, 0],
            [0, 1 << 31],
            [1 << 31, 0],
            [1 << 31, 1 << 31]
        ]));
        assert!(is_net(&[[0, 0], [1 << 31, 1 << 31]]));
        assert!(is_net(&[
            [0, 0],
            [1 << 30, 1 << 31],
            [2 << 30, 1 << 30],
            [3 << 30, 3 << 30]
        ]));
    }

    #[test]
    fn pmj02_built_prefixes_are_nets_at_every_power_of_two_for_many_seeds() {
        for seed in SEEDS.into_iter().chain([2, 3, 99, u32::MAX]) {
            let pts = built(seed, PMJ02_MAX_POINTS);
            for m in 0..=16 {
                assert!(is_net(&pts[..1 << m]), "seed {seed} 2^{m}");
            }
            // The independent oracle agrees on the small ones.
            for m in 0..=10 {
                assert_elementary_intervals(&pts[..1 << m], m);
            }
        }
    }

    #[test]
    fn pmj02_table_equals_build_and_aligned_blocks_are_nets() {
        assert_eq!(
            &PMJ02_TABLE[..],
            &built(PMJ02_TABLE_SEED, PMJ02_MAX_POINTS)[..]
        );
        for m in 0..=16u32 {
            for block in PMJ02_TABLE.chunks_exact(1 << m) {
                assert!(is_net(block), "2^{m} block");
            }
        }
    }

    #[test]
    fn pmj02_build_is_prefix_consistent_and_seeded() {
        let long = built(3, 5000);
        for n in [1, 2, 3, 7, 64, 100, 4097] {
            assert_eq!(built(3, n)[..], long[..n], "n={n}");
        }
        let other = built(4, 5000);
        assert!(long.iter().zip(&other).all(|(a, b)| a != b));
        // Point 0 is two whole random words of the seed's stream, one per coordinate: over 256
        // seeds each coordinate's words are distinct (a repeat has probability below 2⁻¹⁶) and
        // together flip every bit.
        for axis in 0..2 {
            let mut words: Vec<u32> = (0..256).map(|seed| built(seed, 1)[0][axis]).collect();
            assert_eq!(words.iter().fold(0, |a, w| a | w), u32::MAX, "axis {axis}");
            words.sort_unstable();
            words.dedup();
            assert_eq!(words.len(), 256, "axis {axis}: seeds share point 0's word");
        }
    }

    /// Below the digits the construction fixes (the first `L + 1` of a point at level `L`),
    /// every coordinate is jittered by the seed's random words: over points 1..4096 the low 16
    /// bits of each axis are uniform (their mean within 4σ of ½, σ = 1/√(12·4095): a false alarm
    /// has probability under 10⁻⁴, and the seed is fixed) and every one of them is set somewhere.
    #[test]
    fn pmj02_points_are_jittered_below_their_fixed_digits() {
        let pts = built(3, 4096);
        for axis in 0..2 {
            let low: Vec<u32> = pts[1..].iter().map(|p| p[axis] & 0xffff).collect();
            assert_eq!(low.iter().fold(0, |a, w| a | w), 0xffff, "axis {axis}");
            let mean = low.iter().map(|&w| f64::from(w) / 65536.0).sum::<f64>() / 4095.0;
            let sigma = 1.0 / (12.0f64 * 4095.0).sqrt();
            assert!((mean - 0.5).abs() < 4.0 * sigma, "axis {axis}: mean {mean}");
        }
    }

    #[test]
    fn pmj02_build_rejects_bad_buffer_sizes() {
        assert_eq!(
            pmj02_build(0, &mut []),
            Err(Error::ZeroSize { what: "points" })
        );
        let mut big = vec![[7u32; 2]; PMJ02_MAX_POINTS + 1];
        assert_eq!(
            pmj02_build(0, &mut big),
            Err(Error::TooMany {
                what: "points",
                value: PMJ02_MAX_POINTS as u64 + 1,
                max: PMJ02_MAX_POINTS as u64,
            })
        );
        assert!(big.iter().all(|&p| p == [7, 7]), "left untouched");
        assert_eq!(pmj02_build(0, &mut big[..PMJ02_MAX_POINTS]), Ok(()));
    }

    #[test]
    fn pmj02_is_progressively_multi_jittered_in_1d() {
        // At every 2^m each axis has one point per stratum of width 2^-m, and in between
        // (2^m < n < 2^(m+1)) no stratum of width 2^-(m+1) holds two: new points only fill
        // empty halves.
        for seed in SEEDS {
            let pts = built(seed, 4096);
            for d in 0..2 {
                for m in 0..12u32 {
                    let fine = m + 1;
                    let mut seen = vec![false; 1 << fine];
                    for (i, p) in pts[..2 << m].iter().enumerate() {
                        let s = (p[d] >> (32 - fine)) as usize;
                        assert!(!core::mem::replace(&mut seen[s], true), "{seed} {d} {i}");
                        if i + 1 == 1 << m {
                            // Exactly one per coarse stratum.
                            let coarse: Vec<usize> = (0..1 << m)
                                .map(|c| usize::from(seen[2 * c]) + usize::from(seen[2 * c + 1]))
                                .collect();
                            assert!(coarse.iter().all(|&k| k == 1), "{seed} {d} 2^{m}");
                        }
                    }
                }
            }
        }
    }

    /// Row `m` of the premixed table is point `reverse16(m)` with both coordinates reversed and
    /// premixed, and the scrambled reads through it give the fast Owen scramble of the plain
    /// table's values.
    #[test]
    fn pmj02_premixed_table_is_the_plain_table_reordered_reversed_and_premixed() {
        use crate::scramble::{fast_owen_keyed, fast_owen_keyed_f32};
        for m in 0..PMJ02_MAX_POINTS {
            let [x, y] = PMJ02_TABLE[reverse16(m as u32) as usize];
            assert_eq!(
                PMJ02_PREMIXED[m],
                [lk_premix(x.reverse_bits()), lk_premix(y.reverse_bits())],
                "row {m}"
            );
        }
        assert_eq!(reverse16(1), 0x8000);
        assert_eq!(reverse16(0x1_0003), 0xc000);
        for seed in SEEDS {
            let s = Pmj02::scrambled(u64::from(seed));
            let [kx, ky] = s.keys.unwrap();
            for i in (0..70_000u32).step_by(7) {
                let [x, y] = PMJ02_TABLE[i as usize & 0xffff];
                let want = [fast_owen_keyed(x, kx), fast_owen_keyed(y, ky)];
                assert_eq!(s.sample_2d_u32(i), want, "seed {seed} index {i}");
                assert_eq!([s.sample_u32(i, 0), s.sample_u32(i, 3)], want);
                let want = [fast_owen_keyed_f32(x, kx), fast_owen_keyed_f32(y, ky)];
                assert_eq!(s.sample_2d(i), want);
                let i = u64::from(i);
                assert_eq!([s.sample(i, 0), s.sample(i, 1)], want);
            }
        }
    }

    #[test]
    fn pmj02_scrambles_keep_nets_and_unit_range() {
        for seed in SEEDS {
            let s = Pmj02::scrambled(u64::from(seed));
            let pts: Vec<[u32; 2]> = (0..1024).map(|i| s.sample_2d_u32(i)).collect();
            for m in 0..=10 {
                assert!(is_net(&pts[..1 << m]), "seed {seed} 2^{m}");
            }
            for i in 0..1024u32 {
                let [x, y] = s.sample_2d(i);
                assert!((0.0..1.0).contains(&x) && (0.0..1.0).contains(&y));
            }
            // The scramble changes the points.
            assert!(pts.iter().zip(PMJ02_TABLE.iter()).all(|(a, b)| a != b));
        }
        assert_ne!(
            Pmj02::scrambled(1).sample_2d_u32(0),
            Pmj02::scrambled(2).sample_2d_u32(0)
        );
        // Each coordinate has its own seeded scramble: over 64 seeds, point 0's value on each
        // axis is a different 32-bit word (a repeat has probability below 10⁻⁶).
        for axis in 0..2 {
            let mut v: Vec<u32> = (0..64)
                .map(|seed| Pmj02::scrambled(seed).sample_2d_u32(0)[axis])
                .collect();
            v.sort_unstable();
            v.dedup();
            assert_eq!(v.len(), 64, "axis {axis}: seeds share a scramble");
        }
    }

    /// The batch read is the per-point read for every length around the four-point step (the
    /// remainder path), plain and scrambled, with indices past the table; lengths must match.
    #[test]
    fn pmj02_fill_2d_equals_sample_2d() {
        let indices: Vec<u32> = (0..23u32).map(|i| mix32(i) % 200_000).collect();
        for p in [
            Pmj02::new(),
            Pmj02::scrambled(0),
            Pmj02::scrambled(u64::MAX),
        ] {
            for n in 0..indices.len() {
                let mut out = vec![[2.0f32; 2]; n];
                p.fill_2d(&indices[..n], &mut out).unwrap();
                for (k, (&i, o)) in indices.iter().zip(&out).enumerate() {
                    assert_eq!(o.map(f32::to_bits), p.sample_2d(i).map(f32::to_bits), "{k}");
                }
            }
            let mut out = [[0.0f32; 2]; 3];
            let e = Error::BufferLength {
                multiple_of: 4,
                actual: 3,
            };
            assert_eq!(p.fill_2d(&indices[..4], &mut out), Err(e));
            assert!(p.fill_2d(&indices[..2], &mut out).is_err());
        }
    }

    #[test]
    fn pmj02_sequence_impl_wraps_and_agrees() {
        for p in [Pmj02::new(), Pmj02::scrambled(8)] {
            assert_eq!(p.dims(), 2);
            assert_eq!(p.point_count(), Some(65536));
            for i in [0u32, 1, 777, 65535] {
                let [xu, yu] = p.sample_2d_u32(i);
                let [x, y] = p.sample_2d(i);
                let i64 = u64::from(i);
                assert_eq!(p.sample(i64, 0), x);
                assert_eq!(p.sample(i64 + 65536 * 3, 5), y);
                assert_eq!(p.sample_u32(i + 65536, 2), xu);
                assert_eq!(p.sample_f64(i64, 1), f64::from(yu) / 4_294_967_296.0);
            }
            let mut buf = [0.0f32; 6];
            assert_eq!(p.fill(10, 2, &mut buf), Ok(3));
            assert_eq!(buf[5], p.sample(12, 1));
        }
    }

    proptest::proptest! {
        #[test]
        fn pmj02_never_panics_and_stays_in_unit_interval(
            seed: u64, index: u64, dim: u32, n in 0usize..70_000,
        ) {
            for p in [Pmj02::new(), Pmj02::scrambled(seed)] {
                let x = p.sample(index, dim);
                proptest::prop_assert!((0.0..1.0).contains(&x));
                proptest::prop_assert!((0.0..1.0).contains(&p.sample_f64(index, dim)));
            }
            let mut v = vec![[0u32; 2]; n.min(PMJ02_MAX_POINTS + 1)];
            let r = pmj02_build(seed as u32, &mut v);
            proptest::prop_assert_eq!(r.is_ok(), (1..=PMJ02_MAX_POINTS).contains(&v.len()));
        }
    }
}
