//! Nested (Owen) scrambles of the radical inverse in any prime base.
//!
//! Φ_b(a) has output digit `j` (weight `b^−(j+1)`) equal to input digit `a_j` (weight `bʲ`). A
//! nested scramble passes digit `j` through a permutation `π_{j, a_0 … a_(j−1)}` of `0..b` that
//! belongs to the node of the digit tree reached by the output digits before it — equivalently,
//! to the pair (`j`, `a mod bʲ`), because `a_0 … a_(j−1)` are exactly the digits of `a mod bʲ`.
//! Every node draws its permutation independently (here: from a hash of the seed, the
//! dimension, `j` and `a mod bʲ`). Two points that share their first `j` digits share them
//! after the scramble, and the `b` children of a node go to `b` distinct children, so every
//! elementary interval `[c/bᵐ, (c + 1)/bᵐ)` maps onto one of the same size: the first `bᵐ`
//! points of the sequence (indeed any aligned block of `bᵐ` indices) still fall one per
//! interval, and Halton's 2-D boxes keep their counts.
//!
//! The digits of `a` above its leading one are zeros, and a nested scramble permutes them too
//! (`π(0)` is rarely 0): without them every scrambled value would sit on a grid of `b^−n` (`n`
//! the digit count of `a`), biased towards the lower edge of its stratum. So the digits are
//! processed until the remaining tail is far below the output precision: `K` digits with
//! `b^K ≥ 2³²` for the `f32` forms and `b^K ≥ 2⁶⁴` for the `f64` forms (32 and 64 digits in
//! base 2, 21 and 41 in base 3, 3 and 5 in base 8161). The result is the exact fraction
//! `R/b^K` of the `K` scrambled digits, rounded once (`f64`) or through `f64` (`f32`, within
//! 1 ulp); the dropped tail is below `2⁻³²` (`f32`) or `2⁻⁶⁴` (`f64`).
//!
//! Sources: Owen, "Randomly permuted (t,m,s)-nets and (t,s)-sequences" (1995) for the nested
//! uniform scramble; the per-digit hash of the digits seen so far is the idea of pbrt-v4's
//! `OwenScrambledRadicalInverse` (Pharr, Jakob & Humphreys, 4th ed., §8.6), implemented here
//! from the description, with the position and the input prefix in the key.

use super::PRIME_COUNT;
use super::exact::fraction_f64;
use super::tables::BASES;
use crate::hash::{self, Permutation, mix64, packed_entry, packed_table};
use crate::math::{ONE_MINUS_EPSILON, ONE_MINUS_EPSILON_F64};

/// Domain tags, so the two scrambles (and other users of `hash3`) draw unrelated keys.
const TAG_UNIFORM: u64 = 0x4f57_454e_5f55_4e49;
const TAG_AFFINE: u64 = 0x4f57_454e_5f41_4646;

/// `⌊2⁶⁴/φ⌋` (the golden-ratio Weyl increment SplitMix64 uses) and an odd multiplier from
/// `⌊2⁶⁴/π⌋ | 1`: the node key is `mix64((key ⊕ prefix·P) + level·G)`, SplitMix64's output for
/// a stream that steps once per level, per (seed, dimension, prefix).
const LEVEL_STEP: u64 = 0x9e37_79b9_7f4a_7c15;
const PREFIX_MUL: u64 = 0x517c_c1b7_2722_0a95;

/// The hash that chooses the permutation of node (`level`, `prefix = a mod b^level`).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn node_hash(key: u64, level: u64, prefix: u64) -> u64 {
    mix64((key ^ prefix.wrapping_mul(PREFIX_MUL)).wrapping_add(level.wrapping_mul(LEVEL_STEP)))
}

/// Hands out the scrambled digits of Φ_b(a), most significant first, for ever (zeros of `a`
/// past its leading digit included). `AFFINE` picks the node permutations: uniform over all
/// `b!` (`false`), or affine (`true`).
struct Digits<const AFFINE: bool> {
    b: u64,
    /// `⌈2⁴⁰/b⌉`: `⌊D/b⌋ = ⌊D·split/2⁴⁰⌋` for `D < b²`.
    split: u64,
    key: u64,
    a: u64,
    /// `⌊a/b^level⌋`: its last digit is the next input digit.
    rest: u64,
    /// `b^level` (only read while `rest > 0`, so while it is at most `a`; it may wrap after).
    pow: u64,
    level: u64,
}

impl<const AFFINE: bool> Digits<AFFINE> {
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn new(d: usize, a: u64, seed: u64) -> Self {
        let info = &BASES[d];
        let tag = if AFFINE { TAG_AFFINE } else { TAG_UNIFORM };
        Digits {
            b: info.b,
            split: info.split,
            key: hash::hash3(seed, d as u64, tag),
            a,
            rest: a,
            pow: 1,
            level: 0,
        }
    }

    #[cfg_attr(not(feature = "small-code"), inline(always))]
    fn next_digit(&mut self) -> u64 {
        let (b, rest) = (self.b, self.rest);
        let (next, digit) = if rest == 0 {
            (0, 0)
        } else if rest >> 32 == 0 {
            // A 32-bit division where it suffices (most of a renderer's indices).
            let (r, b32) = (rest as u32, b as u32);
            let q = r / b32;
            (u64::from(q), u64::from(r - q * b32))
        } else {
            let q = rest / b;
            (q, rest - q * b)
        };
        // a mod b^level = a − ⌊a/b^level⌋·b^level (exact: the product is at most a).
        let prefix = self.a.wrapping_sub(rest.wrapping_mul(self.pow));
        let h = node_hash(self.key, self.level, prefix);
        self.rest = next;
        self.pow = self.pow.wrapping_mul(b);
        self.level += 1;
        if AFFINE {
            // π(x) = (m·x + g) mod b with g uniform in 0..b and m in 1..b, both read from h as
            // mixed-radix digits of the fraction h/2⁶⁴ (uniform to within b²/2⁶⁴).
            let t = u128::from(h) * u128::from(b);
            let g = (t >> 64) as u64;
            let m = 1 + ((u128::from(t as u64) * u128::from(b - 1)) >> 64) as u64;
            let x = m * digit + g; // < b²: the exact split applies
            x - b * ((x * self.split) >> 40)
        } else if b <= 16 {
            u64::from(packed_entry(packed_table(b as u32, h), digit as u32))
        } else {
            u64::from(Permutation::new(b as u32, (h ^ (h >> 32)) as u32).apply(digit as u32))
        }
    }
}

/// The first `K` scrambled digits as `(R, b^K)`, `K` the fewest with `b^K ≥ 2^bits`
/// (`bits ≤ 64`, so `b^K < 2⁷⁷`).
fn nested_fraction<const AFFINE: bool>(d: usize, a: u64, seed: u64, bits: u32) -> (u128, u128) {
    let mut digits = Digits::<AFFINE>::new(d, a, seed);
    let b = u128::from(digits.b);
    let (mut num, mut den) = (0u128, 1u128);
    while den >> bits == 0 {
        num = num * b + u128::from(digits.next_digit());
        den *= b;
    }
    (num, den)
}

#[inline]
fn nested_f32<const AFFINE: bool>(dim: u32, a: u64, seed: u64) -> f32 {
    let d = (dim % PRIME_COUNT) as usize;
    let mut digits = Digits::<AFFINE>::new(d, a, seed);
    let b = digits.b;
    // b^K < 2³²·b ≤ 2⁴⁵: both exact in f64, one rounded division, one narrowing.
    let (mut num, mut den) = (0u64, 1u64);
    while den >> 32 == 0 {
        num = num * b + digits.next_digit();
        den *= b;
    }
    ((num as f64 / den as f64) as f32).min(ONE_MINUS_EPSILON)
}

#[inline]
fn nested_f64<const AFFINE: bool>(dim: u32, a: u64, seed: u64) -> f64 {
    let d = (dim % PRIME_COUNT) as usize;
    let (num, den) = nested_fraction::<AFFINE>(d, a, seed, 64);
    fraction_f64(num, den, 0, false).min(ONE_MINUS_EPSILON_F64)
}

/// Φ_b(a) under the nested uniform (Owen) scramble chosen by `seed`, as an `f32` in `[0, 1)`
/// (`b = prime(dim)`).
///
/// Digit `j` of the result is `π(a_j)`, `π` a permutation of `0..b` drawn from a hash of
/// `(seed, dim, j, a mod bʲ)`: for `b ≤ 16` uniformly over all `b!` permutations (a packed
/// Fisher–Yates draw, [`hash::Permutation`]'s small-size path), above 16 a keyed
/// [`hash::Permutation`] (every digit's image uniform over seeds). The digits run on past `a`'s
/// leading digit until `b^K ≥ 2³²`, so the result is the scrambled value truncated below
/// `2⁻³²`, rounded to `f32` (within 1 ulp of that fraction); a point within half an ulp of a
/// stratum edge can round onto the edge, as any float rendering of the edge would.
///
/// Properties kept for every seed: each aligned block of `bᵐ` indices falls one per interval
/// `[c/bᵐ, (c + 1)/bᵐ)`; over seeds, each point is uniform on the `b^K` grid.
///
/// Cost: `K` digit steps (32 for base 2, 21 for base 3, 14 for base 5, 10 for base 11, 3 for
/// the largest bases), each one 64-bit hash, a division while `a` has digits left, and the
/// permutation draw (one multiply for `b ≤ 4`, `b − 1` for `5 ≤ b ≤ 16`, a keyed bijection
/// above). Tens of times the cost of [`radical_inverse`](super::radical_inverse); see
/// [`fast_owen_scrambled_radical_inverse`] for a cheaper nested scramble. No allocation.
///
/// Total: `dim` wraps modulo 1024, every `u64` index and seed is valid, the result is clamped
/// to [`ONE_MINUS_EPSILON`].
///
/// ```
/// use nyquist::radical::owen_scrambled_radical_inverse;
/// // Base 3 (dim 1): the first 9 points still fall one per ninth, at seed-dependent offsets.
/// let mut cells: Vec<u32> =
///     (0..9).map(|a| (owen_scrambled_radical_inverse(1, a, 5) * 9.0) as u32).collect();
/// cells.sort();
/// assert_eq!(cells, (0..9).collect::<Vec<u32>>());
/// // Index 0 is not pinned to 0: its zero digits are permuted as well.
/// assert_ne!(owen_scrambled_radical_inverse(1, 0, 5), owen_scrambled_radical_inverse(1, 0, 6));
/// ```
pub fn owen_scrambled_radical_inverse(dim: u32, a: u64, seed: u64) -> f32 {
    nested_f32::<false>(dim, a, seed)
}

/// [`owen_scrambled_radical_inverse`] as an `f64` in `[0, 1)`: the same scramble (its first
/// digits agree with the `f32` form's), carried until `b^K ≥ 2⁶⁴` and correctly rounded from
/// that fraction, clamped to [`ONE_MINUS_EPSILON_F64`]. About twice the `f32` form's cost.
///
/// ```
/// use nyquist::radical::{owen_scrambled_radical_inverse, owen_scrambled_radical_inverse_f64};
/// let x = owen_scrambled_radical_inverse_f64(4, 1234, 9);
/// assert!((0.0..1.0).contains(&x));
/// assert!((x - f64::from(owen_scrambled_radical_inverse(4, 1234, 9))).abs() < 1e-7);
/// ```
pub fn owen_scrambled_radical_inverse_f64(dim: u32, a: u64, seed: u64) -> f64 {
    nested_f64::<false>(dim, a, seed)
}

/// Φ_b(a) under a nested scramble with **affine** node permutations, as an `f32` in `[0, 1)`:
/// the scramble behind [`Scramble::FastOwen`](crate::scramble::Scramble::FastOwen) for Halton.
///
/// The same digit tree, digit count and rounding as [`owen_scrambled_radical_inverse`], but the
/// permutation of node (`j`, `a mod bʲ`) is `x ↦ (m·x + g) mod b` with `m` uniform in `1..b` and
/// `g` uniform in `0..b`, both read from the node's hash by two multiplies — instead of a
/// uniform draw from all `b!` permutations. It is still a nested scramble (every node its own
/// independent permutation), so it keeps every stratification property the Owen scramble
/// keeps. Because `b` is prime, each such map sends every digit to a uniform digit and every
/// pair of distinct digits to a uniform pair of distinct digits; the joint law of any two
/// scrambled points (their shared digits uniform, the first differing digits a uniform
/// distinct pair, the rest independent) is then the one the nested uniform scramble gives, so
/// estimator variances are the same. For `b = 2` and `b = 3` the affine maps are all the
/// permutations: the scramble is the nested uniform one in law. (Sets of three or more points
/// can differ in law for `b ≥ 5`.)
///
/// Cost: as [`owen_scrambled_radical_inverse`] minus the permutation draws — per digit one
/// hash, two multiplies and a multiply-shift. pbrt-v4 has no fast Owen scramble for Halton.
/// Total as [`owen_scrambled_radical_inverse`].
///
/// ```
/// use nyquist::radical::fast_owen_scrambled_radical_inverse;
/// // Base 5 (dim 2): 25 points, one per 1/25.
/// let mut cells: Vec<u32> =
///     (0..25).map(|a| (fast_owen_scrambled_radical_inverse(2, a, 1) * 25.0) as u32).collect();
/// cells.sort();
/// assert_eq!(cells, (0..25).collect::<Vec<u32>>());
/// ```
pub fn fast_owen_scrambled_radical_inverse(dim: u32, a: u64, seed: u64) -> f32 {
    nested_f32::<true>(dim, a, seed)
}

/// [`fast_owen_scrambled_radical_inverse`] as an `f64` in `[0, 1)`, as
/// [`owen_scrambled_radical_inverse_f64`] is to its `f32` form.
///
/// ```
/// use nyquist::radical::fast_owen_scrambled_radical_inverse_f64;
/// let x = fast_owen_scrambled_radical_inverse_f64(1023, u64::MAX, u64::MAX);
/// assert!((0.0..1.0).contains(&x));
/// ```
pub fn fast_owen_scrambled_radical_inverse_f64(dim: u32, a: u64, seed: u64) -> f64 {
    nested_f64::<true>(dim, a, seed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tests::chi_square_uniform;
    use proptest::prelude::*;
    use std::vec::Vec;

    /// Golden values: in bases above 16 each digit's permutation comes from the keyed
    /// permutation of `hash`, seeded from the node hash folded to 32 bits; the values a seed gives
    /// are this code's own, pinned so that a change to them (the fold included) is deliberate.
    #[test]
    fn scrambled_values_past_base_16_are_pinned() {
        for (dim, a, seed, want32, want64) in [
            (6u32, 0u64, 0u64, 0x3e74_c450u32, 0x3fce_9889_fdb9_9cccu64),
            (6, 12_345, 1, 0x3f2f_19cd, 0x3fe5_e339_a400_dbe7),
            (40, 987_654_321, 0xfeed, 0x3e28_5ba6, 0x3fc5_0b74_b155_ad7a),
            (1000, u64::MAX, 3, 0x3f24_53d8, 0x3fe4_8a7a_fb2a_f20d),
        ] {
            let at = (dim, a, seed);
            assert_eq!(
                owen_scrambled_radical_inverse(dim, a, seed).to_bits(),
                want32,
                "{at:?}"
            );
            assert_eq!(
                owen_scrambled_radical_inverse_f64(dim, a, seed).to_bits(),
                want64,
                "{at:?}"
            );
        }
    }

    /// A node's hash is a SplitMix64 stream (Steele, Lea & Flood 2014: the state steps by the
    /// Weyl increment 0x9e3779b97f4a7c15, each output is the finaliser of the state) started at
    /// `key ⊕ prefix·P`: the node at level ℓ reads the state after ℓ steps, so one prefix's
    /// levels are successive outputs and every prefix has its own start.
    #[test]
    fn node_hash_is_a_splitmix64_stream_per_prefix() {
        for key in [0u64, 1, 0xdead_beef_0123_4567, u64::MAX] {
            for prefix in [0u64, 1, 2, 8, 242, 1 << 40] {
                let mut state = key ^ prefix.wrapping_mul(0x517c_c1b7_2722_0a95);
                for level in 0..40 {
                    assert_eq!(node_hash(key, level, prefix), mix64(state), "level {level}");
                    state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
                }
            }
        }
    }

    /// `(R, b^K)` with `K` digits of the `f32` forms (`bits = 32`) for either scramble.
    fn fraction(affine: bool, d: usize, a: u64, seed: u64, bits: u32) -> (u128, u128) {
        if affine {
            nested_fraction::<true>(d, a, seed, bits)
        } else {
            nested_fraction::<false>(d, a, seed, bits)
        }
    }

    fn value_f64(affine: bool, dim: u32, a: u64, seed: u64) -> f64 {
        if affine {
            fast_owen_scrambled_radical_inverse_f64(dim, a, seed)
        } else {
            owen_scrambled_radical_inverse_f64(dim, a, seed)
        }
    }

    fn value_f32(affine: bool, dim: u32, a: u64, seed: u64) -> f32 {
        if affine {
            fast_owen_scrambled_radical_inverse(dim, a, seed)
        } else {
            owen_scrambled_radical_inverse(dim, a, seed)
        }
    }

    /// Dimensions 0..5: bases 2, 3, 5, 7, 11, and for each the largest `m` tested.
    const BASES_M: [(usize, u32); 5] = [(0, 14), (1, 9), (2, 6), (3, 5), (4, 4)];

    /// The digit count is the fewest `K` with `b^K ≥ 2^bits`, and `R < b^K`.
    #[test]
    fn digit_count_reaches_the_output_precision() {
        for d in [0usize, 1, 2, 4, 30, 1023] {
            let b = u128::from(BASES[d].b);
            for bits in [32u32, 64] {
                let (num, den) = fraction(false, d, 77, 3, bits);
                assert!(num < den);
                assert!(
                    den >= 1 << bits && den / b < 1 << bits,
                    "base {b} bits {bits}"
                );
                assert_eq!(den % b, 0);
            }
        }
        assert_eq!(fraction(true, 0, 5, 1, 32).1, 1 << 32);
        assert_eq!(fraction(true, 1, 5, 1, 64).1, 3u128.pow(41));
    }

    /// Exactly: among indices `c·bᵐ .. (c + 1)·bᵐ` the first `m` scrambled digits take every
    /// value once, for every `m` up to the limit, for blocks at the start and far out.
    #[test]
    fn aligned_blocks_of_b_pow_m_points_are_one_per_interval() {
        for affine in [false, true] {
            for &(d, m_max) in &BASES_M {
                let b = BASES[d].b;
                for seed in [0u64, 0x5eed] {
                    for start in [0u64, 1 << 40] {
                        let n = b.pow(m_max);
                        let base = start / n * n;
                        let frac: Vec<(u128, u128)> = (0..n)
                            .map(|i| fraction(affine, d, base + i, seed, 32))
                            .collect();
                        for m in 1..=m_max {
                            let cells = b.pow(m) as usize;
                            let mut seen = std::vec![false; cells];
                            for &(num, den) in &frac[..cells] {
                                let cell = (num * cells as u128 / den) as usize;
                                assert!(
                                    !std::mem::replace(&mut seen[cell], true),
                                    "affine {affine} base {b} m {m} seed {seed} start {start}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }

    /// The same through the public `f64` and `f32` values (first `bᵐ` points, smaller `m` for
    /// `f32`, where a value rounding onto a stratum edge becomes likely as strata shrink).
    #[test]
    fn first_points_are_stratified_as_floats() {
        for affine in [false, true] {
            for &(d, m_max) in &BASES_M {
                let b = BASES[d].b;
                let n = b.pow(m_max);
                let xs: Vec<f64> = (0..n).map(|i| value_f64(affine, d as u32, i, 9)).collect();
                for m in 1..=m_max {
                    let cells = b.pow(m);
                    let mut seen = std::vec![false; cells as usize];
                    for &x in &xs[..cells as usize] {
                        assert!((0.0..1.0).contains(&x));
                        let c = (x * cells as f64) as usize;
                        assert!(!std::mem::replace(&mut seen[c], true), "base {b} m {m}");
                    }
                }
                let cells = b.pow(2);
                let mut seen = std::vec![false; cells as usize];
                for i in 0..cells {
                    let x = value_f32(affine, d as u32, i, 9);
                    assert!((0.0..1.0).contains(&x));
                    let c = (f64::from(x) * cells as f64) as usize;
                    assert!(!std::mem::replace(&mut seen[c], true), "f32 base {b}");
                }
            }
        }
    }

    /// Halton's first two dimensions (bases 2 and 3), each scrambled: for `n = 6ᵏ` points every
    /// `2ⁱ × 3ʲ` box grid with `2ⁱ·3ʲ` dividing `n` holds `n/(2ⁱ3ʲ)` points per box.
    #[test]
    fn first_2d_points_fill_every_elementary_box_evenly() {
        for affine in [false, true] {
            for seed in [1u64, 77] {
                for k in 1..=4u32 {
                    let n = 6u64.pow(k);
                    let pts: Vec<(f64, f64)> = (0..n)
                        .map(|i| (value_f64(affine, 0, i, seed), value_f64(affine, 1, i, seed)))
                        .collect();
                    for i in 0..=k {
                        for j in 0..=k {
                            let (nx, ny) = (1u64 << i, 3u64.pow(j));
                            let mut count = std::vec![0u64; (nx * ny) as usize];
                            for &(x, y) in &pts {
                                let cx = (x * nx as f64) as u64;
                                let cy = (y * ny as f64) as u64;
                                count[(cy * nx + cx) as usize] += 1;
                            }
                            let want = n / (nx * ny);
                            assert!(
                                count.iter().all(|&c| c == want),
                                "affine {affine} seed {seed} n {n} box 2^{i} x 3^{j}"
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn the_scramble_depends_on_the_seed() {
        for affine in [false, true] {
            for dim in [0u32, 1, 2, 10, 500] {
                let a: Vec<u64> = (0..32)
                    .map(|i| value_f64(affine, dim, i, 1).to_bits())
                    .collect();
                let b: Vec<u64> = (0..32)
                    .map(|i| value_f64(affine, dim, i, 2).to_bits())
                    .collect();
                let c: Vec<u64> = (0..32)
                    .map(|i| value_f64(affine, dim + 1024, i, 1).to_bits())
                    .collect();
                assert_ne!(a, b, "affine {affine} dim {dim}");
                assert_eq!(a, c, "dims wrap modulo 1024");
            }
        }
    }

    /// Chi-square bound at a false-alarm rate far below 10⁻⁶ for `df` degrees of freedom.
    fn chi2_limit(df: f64) -> f64 {
        df + 6.0 * (2.0 * df).sqrt() + 10.0
    }

    /// For a fixed index, each of the first three scrambled digits is uniform over seeds —
    /// including the digits that come from `a`'s zeros past its leading digit — and the value's
    /// mean over seeds is ½ (a scramble that stopped at `a`'s last digit would give index 0 the
    /// value 0 and index 1 the mean `(b − 1)/2b`).
    #[test]
    fn digits_of_a_fixed_index_are_uniform_over_seeds() {
        const SEEDS: u32 = 6000;
        for affine in [false, true] {
            for d in [0usize, 1, 2, 4, 6, 20] {
                let b = BASES[d].b as usize;
                for a in [0u64, 1, 2 * b as u64 + 1, 12345] {
                    let mut counts = std::vec![0u32; 3 * b];
                    let mut sum = 0.0;
                    for seed in 0..SEEDS {
                        let (num, den) = fraction(affine, d, a, u64::from(seed) * 0x1_0001, 32);
                        sum += num as f64 / den as f64;
                        let top = (num * (b * b * b) as u128 / den) as usize;
                        let digits = [top / (b * b), top / b % b, top % b];
                        for (j, &digit) in digits.iter().enumerate() {
                            counts[j * b + digit] += 1;
                        }
                    }
                    for j in 0..3 {
                        let c = chi_square_uniform(&counts[j * b..(j + 1) * b]);
                        assert!(
                            c < chi2_limit((b - 1) as f64),
                            "affine {affine} base {b} a {a} digit {j}: chi2 {c:.1}"
                        );
                    }
                    // sd of the mean of 6000 uniforms: 0.0037; 6 sd.
                    let mean = sum / f64::from(SEEDS);
                    assert!((mean - 0.5).abs() < 0.023, "base {b} a {a}: mean {mean}");
                }
            }
        }
    }

    /// Indices 1 and 2 share the root node: over seeds their first digits form a uniform pair of
    /// distinct digits (the two-point property both scrambles have). Indices 1 and 2 then sit in
    /// different subtrees, so their second digits are independent and uniform: all `b²` pairs.
    #[test]
    fn a_node_permutes_pairs_uniformly_and_subtrees_are_independent() {
        const SEEDS: u32 = 20_000;
        for affine in [false, true] {
            let dims: &[usize] = if affine {
                &[1, 2, 3, 6, 8]
            } else {
                &[1, 2, 3, 5]
            };
            for &d in dims {
                let b = BASES[d].b as usize;
                let mut first = std::vec![0u32; b * b];
                let mut second = std::vec![0u32; b * b];
                for seed in 0..SEEDS {
                    let digits = |a: u64| {
                        let (num, den) = fraction(affine, d, a, u64::from(seed), 32);
                        let t = num * (b * b) as u128 / den;
                        ((t / b as u128) as usize, (t % b as u128) as usize)
                    };
                    let (x1, y1) = digits(1);
                    let (x2, y2) = digits(2);
                    assert_ne!(x1, x2);
                    first[x1 * b + x2] += 1;
                    second[y1 * b + y2] += 1;
                }
                // Only the b(b − 1) off-diagonal pairs occur.
                let off: Vec<u32> = (0..b * b)
                    .filter(|k| k / b != k % b)
                    .map(|k| first[k])
                    .collect();
                let c = chi_square_uniform(&off);
                let df = (b * (b - 1) - 1) as f64;
                assert!(c < chi2_limit(df), "affine {affine} base {b} pairs: {c:.1}");
                let c = chi_square_uniform(&second);
                let df = (b * b - 1) as f64;
                assert!(
                    c < chi2_limit(df),
                    "affine {affine} base {b} subtrees: {c:.1}"
                );
            }
        }
    }

    /// The two precisions share their digits: the `f32` value is the `f64` one to within the
    /// `f32` rounding and the `2⁻³²` truncation.
    #[test]
    fn f32_and_f64_forms_agree() {
        for affine in [false, true] {
            for (dim, a, seed) in [
                (0u32, 0u64, 0u64),
                (1, 5, 1),
                (7, 1 << 33, 2),
                (1023, 99, 3),
            ] {
                let x = value_f64(affine, dim, a, seed);
                let y = f64::from(value_f32(affine, dim, a, seed));
                assert!(
                    (x - y).abs() <= 2f64.powi(-24) + 2f64.powi(-32),
                    "{dim} {a}"
                );
            }
        }
    }

    proptest! {
        #[test]
        fn values_are_always_in_the_unit_interval(
            dim in any::<u32>(), a in any::<u64>(), seed in any::<u64>(),
        ) {
            for affine in [false, true] {
                let x = value_f32(affine, dim, a, seed);
                prop_assert!((0.0..1.0).contains(&x), "{x}");
                let y = value_f64(affine, dim, a, seed);
                prop_assert!((0.0..1.0).contains(&y), "{y}");
                prop_assert!((f64::from(x) - y).abs() <= 2f64.powi(-24) + 2f64.powi(-32));
            }
        }

        /// Any aligned block of `b²` indices, anywhere in `u64`, fills the `b²` strata.
        #[test]
        fn any_aligned_block_is_stratified(dim in 0u32..1024, block in any::<u64>(), seed in any::<u64>()) {
            let d = dim as usize;
            let b = BASES[d].b;
            let n = b * b;
            let base = (block / n) * n;
            for affine in [false, true] {
                let mut seen = std::vec![false; n as usize];
                for i in 0..n.min(512) {
                    let (num, den) = fraction(affine, d, base + i, seed, 32);
                    let cell = (num * u128::from(n) / den) as usize;
                    prop_assert!(!std::mem::replace(&mut seen[cell], true));
                }
            }
        }
    }
}
