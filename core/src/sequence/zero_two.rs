//! pbrt's (0,2)-sequence: the base-2 van der Corput sequence and Sobol's second generator
//! matrix, each XOR-scrambled by a 32-bit value.
//!
//! Source: Kollig and Keller, "Efficient multidimensional sampling" (Eurographics 2002), whose
//! scrambled (0,2)-sequence pbrt-v2 uses for its `LDSampler` (`VanDerCorput` and `Sobol2`). The
//! second dimension's generator matrix is the one of Sobol dimension 1 (column `k` is
//! `V_{k+1}` with `V_1 = 2^31`, `V_{k+1} = V_k ⊕ (V_k ≫ 1)`, Pascal's triangle mod 2), read
//! here from the checked-in Joe–Kuo table. An XOR scramble is a digital shift, so every
//! aligned block of `2^m` points is a (0, m, 2)-net for every scramble.

use super::{Sequence, sobol_u32};
use crate::hash;
use crate::lazy_table::baked_table;
use crate::math::fraction_to_f32 as to_f32;

/// The scrambled (0,2)-sequence: point `i` is `(Φ₂(i) ⊕ s₀, Sobol₁(i) ⊕ s₁)` in 32-bit binary
/// fractions.
///
/// Values are `f32` from the top 24 bits (truncated, never 1) or `f64` from all 32 bits.
/// Indices are 32-bit: [`Sequence::point_count`] is `Some(2³²)` and `u64` indices wrap modulo
/// `2³²`; `dim` wraps modulo 2. Allocates: no.
///
/// ```
/// use nyquist::sequence::{Sequence, ZeroTwo};
/// let z = ZeroTwo::new([0, 0]);
/// assert_eq!(z.sample_2d(3), [0.75, 0.25]);
/// // Any scramble: the first 4 points fill the four quarter-width columns once each.
/// let z = ZeroTwo::from_seed(42);
/// let mut cols = [0; 4];
/// for i in 0..4 {
///     cols[(z.sample(i, 0) * 4.0) as usize] += 1;
/// }
/// assert_eq!(cols, [1, 1, 1, 1]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ZeroTwo {
    scramble: [u32; 2],
}

impl ZeroTwo {
    /// The sequence XOR-scrambled by `scramble[0]` (first dimension) and `scramble[1]`
    /// (second). `[0, 0]` is the unscrambled sequence; every value is valid.
    ///
    /// ```
    /// use nyquist::sequence::ZeroTwo;
    /// let z = ZeroTwo::new([1 << 31, 0]);
    /// assert_eq!(z.sample_2d(0), [0.5, 0.0]);
    /// ```
    pub const fn new(scramble: [u32; 2]) -> ZeroTwo {
        ZeroTwo { scramble }
    }

    /// The sequence with both scrambles derived from `seed` by hashing (every seed, 0 included,
    /// gives a scrambled sequence).
    ///
    /// ```
    /// use nyquist::sequence::ZeroTwo;
    /// // Any scramble keeps each prefix of 2^m points a (0, m, 2)-net: the first four, one per
    /// // quadrant.
    /// let z = ZeroTwo::from_seed(5);
    /// let mut q: Vec<usize> = (0..4)
    ///     .map(|i| z.sample_2d(i))
    ///     .map(|[x, y]| (x * 2.0) as usize + 2 * (y * 2.0) as usize)
    ///     .collect();
    /// q.sort();
    /// assert_eq!(q, [0, 1, 2, 3]);
    /// assert_ne!(ZeroTwo::from_seed(5).scramble(), ZeroTwo::from_seed(6).scramble());
    /// ```
    pub fn from_seed(seed: u64) -> ZeroTwo {
        let h = hash::hash2(seed, 0x3032_5345_5155_454e);
        ZeroTwo::new([h as u32, (h >> 32) as u32])
    }

    /// The two XOR scrambles.
    ///
    /// ```
    /// assert_eq!(nyquist::sequence::ZeroTwo::new([3, 4]).scramble(), [3, 4]);
    /// ```
    pub const fn scramble(&self) -> [u32; 2] {
        self.scramble
    }

    /// Point `index` as two 32-bit binary fractions.
    ///
    /// ```
    /// use nyquist::sequence::ZeroTwo;
    /// let half = 1u32 << 31;
    /// assert_eq!(ZeroTwo::new([0, 0]).sample_2d_u32(1), [half, half]);
    /// ```
    #[inline]
    pub fn sample_2d_u32(&self, index: u32) -> [u32; 2] {
        let [x, y] = match FIRST_POINTS.get(index as usize) {
            // A pixel's first points (any sampler with at most 256 samples a pixel): one read.
            Some(&p) => p,
            None => [index.reverse_bits(), sobol_u32(index, 1)],
        };
        [x ^ self.scramble[0], y ^ self.scramble[1]]
    }

    /// Point `index` as two `f32` in `[0, 1)`.
    ///
    /// ```
    /// use nyquist::sequence::ZeroTwo;
    /// assert_eq!(ZeroTwo::new([0, 0]).sample_2d(2), [0.25, 0.75]);
    /// ```
    #[inline]
    pub fn sample_2d(&self, index: u32) -> [f32; 2] {
        let [x, y] = self.sample_2d_u32(index);
        [to_f32(x), to_f32(y)]
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn sample_u32(&self, index: u64, dim: u32) -> u32 {
        let index = index as u32;
        if dim & 1 == 0 {
            index.reverse_bits() ^ self.scramble[0]
        } else {
            sobol_u32(index, 1) ^ self.scramble[1]
        }
    }
}

baked_table! {
    /// The unscrambled points `0..256`, `[reverse_bits(i), sobol_u32(i, 1)]`, baked
    /// ([`baked_table!`]) from the recurrence of the second dimension's columns (`V_1 = 2³¹`,
    /// `V_{k+1} = V_k ⊕ (V_k ≫ 1)`; checked against the Joe–Kuo table by the tests).
    static FIRST_POINTS: [[u32; 2]; 256] = [[0; 2]; 256], fill_first_points,
        first_points_at_first_use_equal_the_baked_table;
}

const fn fill_first_points(out: &mut [[u32; 2]; 256]) {
    let mut i = 0;
    while i < 256 {
        let (mut y, mut v, mut k) = (0u32, 1u32 << 31, 0);
        while k < 8 {
            if (i >> k) & 1 == 1 {
                y ^= v;
            }
            v ^= v >> 1;
            k += 1;
        }
        out[i] = [(i as u32).reverse_bits(), y];
        i += 1;
    }
}

impl Sequence for ZeroTwo {
    fn dims(&self) -> u32 {
        2
    }

    fn point_count(&self) -> Option<u64> {
        Some(1 << 32)
    }

    #[inline]
    fn sample(&self, index: u64, dim: u32) -> f32 {
        to_f32(self.sample_u32(index, dim))
    }

    #[inline]
    fn sample_f64(&self, index: u64, dim: u32) -> f64 {
        f64::from(self.sample_u32(index, dim)) * crate::math::TWO_POW_MINUS_32
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tests::sobol_oracle::assert_elementary_intervals;

    #[test]
    fn unscrambled_is_sobol_dims_0_and_1() {
        let z = ZeroTwo::new([0, 0]);
        for i in (0..5000u32).chain([u32::MAX, 0xdead_beef]) {
            assert_eq!(z.sample_2d_u32(i), [sobol_u32(i, 0), sobol_u32(i, 1)]);
        }
    }

    #[test]
    fn second_dimension_is_the_pascal_recurrence() {
        // pbrt-v2's Sobol2 recurrence as a fact: columns V_1 = 2^31, V_{k+1} = V_k ^ (V_k >> 1).
        let mut v = 1u32 << 31;
        for k in 0..32 {
            assert_eq!(sobol_u32(1 << k, 1), v, "column {k}");
            v ^= v >> 1;
        }
    }

    #[test]
    fn first_2_pow_m_points_are_0_m_2_nets_for_any_scramble() {
        let scrambles = [
            [0, 0],
            [u32::MAX, 0],
            [0x1234_5678, 0x9abc_def0],
            ZeroTwo::from_seed(0).scramble(),
            ZeroTwo::from_seed(77).scramble(),
        ];
        for scramble in scrambles {
            let z = ZeroTwo::new(scramble);
            for m in 1..=12 {
                let pts: std::vec::Vec<[u32; 2]> =
                    (0..1u32 << m).map(|i| z.sample_2d_u32(i)).collect();
                assert_elementary_intervals(&pts, m);
                // Every aligned block of 2^m points too (here the second one).
                let pts: std::vec::Vec<[u32; 2]> =
                    (1u32 << m..2 << m).map(|i| z.sample_2d_u32(i)).collect();
                assert_elementary_intervals(&pts, m);
            }
        }
    }

    /// Point 0 of the unscrambled sequence is the origin, so a scrambled sequence's point 0 is
    /// its two XOR words: `scramble()` reports what `new` was given, and `from_seed` scrambles
    /// both dimensions with words that differ between the dimensions and between seeds.
    #[test]
    fn scrambles_are_the_xor_words_of_point_zero_and_seeds_reach_both_dimensions() {
        for words in [
            [0, 0],
            [3, 4],
            [u32::MAX, 1 << 31],
            [0x9e37_79b9, 0x7f4a_7c15],
        ] {
            let z = ZeroTwo::new(words);
            assert_eq!(z.scramble(), words);
            assert_eq!(z.sample_2d_u32(0), words);
        }
        let mut xs = std::vec::Vec::new();
        let mut ys = std::vec::Vec::new();
        for seed in 0..256u64 {
            let z = ZeroTwo::from_seed(seed);
            let [x, y] = z.sample_2d_u32(0);
            assert_eq!(z.scramble(), [x, y]);
            assert_ne!(x, y, "seed {seed}: both dimensions got the same word");
            xs.push(x);
            ys.push(y);
        }
        for words in [&mut xs, &mut ys] {
            words.sort_unstable();
            words.dedup();
            // 256 seeds, 32-bit words: a repeat has probability below 2⁻¹⁶ for a good hash.
            assert_eq!(words.len(), 256, "seeds share a scramble word");
            // Every bit position is flipped by some seed (a shifted-out half would leave 0s).
            assert_eq!(words.iter().fold(0, |a, w| a | w), u32::MAX);
        }
    }

    #[test]
    fn sequence_impl_wraps_and_agrees_with_sample_2d() {
        let z = ZeroTwo::from_seed(3);
        assert_eq!(z.dims(), 2);
        assert_eq!(z.point_count(), Some(1 << 32));
        for i in [0u32, 1, 999, u32::MAX] {
            let [x, y] = z.sample_2d(i);
            assert_eq!(z.sample(u64::from(i), 0), x);
            assert_eq!(z.sample(u64::from(i), 1), y);
            assert_eq!(z.sample(u64::from(i) + (1 << 32), 3), y);
            assert_eq!(z.sample(u64::from(i), 4), x);
            let [xu, yu] = z.sample_2d_u32(i);
            assert_eq!(
                z.sample_f64(u64::from(i), 0),
                f64::from(xu) / 4_294_967_296.0
            );
            assert_eq!(
                z.sample_f64(u64::from(i), 1),
                f64::from(yu) / 4_294_967_296.0
            );
        }
        let mut buf = [0.0f32; 6];
        assert_eq!(z.fill(10, 2, &mut buf), Ok(3));
        assert_eq!(buf[4], z.sample(12, 0));
    }

    proptest::proptest! {
        #[test]
        fn values_in_unit_interval(index: u64, dim: u32, seed: u64, s0: u32, s1: u32) {
            for z in [ZeroTwo::from_seed(seed), ZeroTwo::new([s0, s1])] {
                let x = z.sample(index, dim);
                proptest::prop_assert!((0.0..1.0).contains(&x));
                let y = z.sample_f64(index, dim);
                proptest::prop_assert!((0.0..1.0).contains(&y));
            }
        }
    }
}
