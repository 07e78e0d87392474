//! [`scrambled_radical_inverse`](super::scrambled_radical_inverse) for the first five bases
//! (2, 3, 5, 7, 11: a camera sample's dimensions), from digit-group tables built once per seed.
//!
//! The digit-permuted radical inverse sends every digit of `a` through one permutation `π` of
//! its base, so it can take a group of `k` digits at a time: `T[g]` holds the `k` permuted digits
//! of `g < bᵏ` in reversed order. Zero digits that pad the last group are permuted to `π(0)`,
//! which is exactly what the infinite tail of leading zeros gives them, so the value formed from
//! whole groups is the same rational number as the one formed digit by digit, only over a larger
//! power of `b`. When that denominator stays below 2⁵³, numerator and denominator are exact in
//! `f64` and the one division rounds the same number the digit loop rounds: the results are
//! bit-equal (a test holds them to it). Beyond that bound the caller falls back to the digit
//! loop.

use super::scrambled::{below_f32, digit_permutation};
use crate::math::ONE_MINUS_EPSILON;

/// The digit-group tables of one seed for bases 2, 3, 5, 7 and 11.
///
/// Groups of 4 digits of base 2 (16 entries), 3 of base 3 (27), 2 of base 5 (25), 2 of base 7
/// (49) and 1 of base 11 (11): 128 bytes in all, which every `HaltonSampler` carries. Larger
/// groups (8, 5, 3, 2 and 2 digits, 794 bytes) take fewer steps per value, but would make the
/// sampler six times larger on a firmware stack for a camera sample that is already several
/// times faster than pbrt-v4's (the peer table of `docs/performance.md`).
#[derive(Clone, Debug)]
pub(crate) struct PermutedDigitGroups {
    t2: [u8; 16],
    t3: [u8; 27],
    t5: [u8; 25],
    t7: [u8; 49],
    t11: [u8; 11],
    /// `π(0)` of each base: the value of every padding and leading zero digit.
    zero: [u8; 5],
}

/// The largest power `gᵐ` of the group size with `(b − 1)·gᵐ < 2⁵³`: below it, an index has at
/// most `m` groups and the fraction's denominator `(b − 1)·g^(groups)` is exact in `f64`.
const fn group_limit(b: u64, g: u64) -> u64 {
    let mut p = 1u64;
    while (b - 1) * p * g < 1 << 53 {
        p *= g;
    }
    p
}

const LIMITS: [u64; 5] = [
    group_limit(2, 16),
    group_limit(3, 27),
    group_limit(5, 25),
    group_limit(7, 49),
    group_limit(11, 11),
];

/// Fills `table[g]` with the `k` base-`b` digits of `g` (`table.len() = bᵏ`), each through
/// `π`, in reversed order: the lowest digit of `g` becomes the highest of the entry.
fn fill_groups(table: &mut [u8], b: u64, pi: &[u8; 11]) {
    let mut k = 0;
    let mut p = 1usize;
    while p < table.len() {
        p *= b as usize;
        k += 1;
    }
    for (g, entry) in table.iter_mut().enumerate() {
        let (mut rest, mut v) = (g, 0usize);
        for _ in 0..k {
            v = v * b as usize + usize::from(pi[rest % b as usize]);
            rest /= b as usize;
        }
        // `v < bᵏ ≤ 256`.
        *entry = v as u8;
    }
}

impl PermutedDigitGroups {
    /// The tables of `seed`'s permutations (those of
    /// [`scrambled_radical_inverse`](super::scrambled_radical_inverse) under the same seed).
    pub(crate) fn new(seed: u64) -> Self {
        let mut t = PermutedDigitGroups {
            t2: [0; 16],
            t3: [0; 27],
            t5: [0; 25],
            t7: [0; 49],
            t11: [0; 11],
            zero: [0; 5],
        };
        for (i, b) in [2u64, 3, 5, 7, 11].into_iter().enumerate() {
            let perm = digit_permutation(seed, b);
            let mut pi = [0u8; 11];
            for (d, p) in (0u32..).zip(pi.iter_mut().take(b as usize)) {
                // `π(d) < b ≤ 11`.
                *p = perm.apply(d) as u8;
            }
            t.zero[i] = pi[0];
            let table: &mut [u8] = match i {
                0 => &mut t.t2,
                1 => &mut t.t3,
                2 => &mut t.t5,
                3 => &mut t.t7,
                _ => &mut t.t11,
            };
            fill_groups(table, b, &pi);
        }
        t
    }

    /// `scrambled_radical_inverse(dim, a, seed)`, bit for bit, for `dim` in `0..5` and `a`
    /// below that base's group limit; `None` otherwise.
    #[cfg_attr(not(feature = "small-code"), inline(always))]
    pub(crate) fn value(&self, dim: u32, a: u64) -> Option<f32> {
        match dim {
            0 => grouped::<2, 16>(&self.t2, self.zero[0], a, LIMITS[0]),
            1 => grouped::<3, 27>(&self.t3, self.zero[1], a, LIMITS[1]),
            2 => grouped::<5, 25>(&self.t5, self.zero[2], a, LIMITS[2]),
            3 => grouped::<7, 49>(&self.t7, self.zero[3], a, LIMITS[3]),
            4 => grouped::<11, 11>(&self.t11, self.zero[4], a, LIMITS[4]),
            _ => None,
        }
    }
}

/// The permuted radical inverse of `a` in base `B` from its group table (`G = Bᵏ` entries) and
/// `π(0)`, or `None` when `a ≥ limit`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn grouped<const B: u64, const G: usize>(
    table: &[u8; G],
    zero: u8,
    mut a: u64,
    limit: u64,
) -> Option<f32> {
    if a >= limit {
        return None;
    }
    let g = G as u64;
    let (mut num, mut den) = (0u64, 1u64);
    while a > 0 {
        num = num * g + u64::from(table[(a % g) as usize]);
        den *= g;
        a /= g;
    }
    // The leading zeros' tail `π(0)/((B − 1)·den)`, over the common denominator; below the
    // limit, `den·(B − 1) < 2⁵³`, so both are exact in `f64`.
    let zero = u64::from(zero);
    let x = ((num * (B - 1) + zero) as f64 / (den * (B - 1)) as f64) as f32;
    // `π(0) = B − 1`: the value is the upper edge of its stratum; keep it inside (as the digit
    // loop does).
    let x = if zero == B - 1 { below_f32(x) } else { x };
    Some(x.min(ONE_MINUS_EPSILON))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::radical::scrambled_radical_inverse;

    /// Bit-equal to the digit loop: every index below 2000, both sides of every power of every
    /// base and of every group limit, and hashed indices up to 2⁶⁴, for seeds whose `π(0)` is
    /// and is not `b − 1`.
    #[test]
    fn grouped_values_equal_the_digit_loop() {
        let bases = [2u64, 3, 5, 7, 11];
        let mut edge_seen = [false; 5];
        for seed in 0..100u64 {
            let t = PermutedDigitGroups::new(seed);
            for (dim, &b) in (0u32..).zip(&bases) {
                edge_seen[dim as usize] |= u64::from(t.zero[dim as usize]) == b - 1;
                let mut indices: std::vec::Vec<u64> = (0..2000).collect();
                let mut p = 1u64;
                while let Some(q) = p.checked_mul(b) {
                    indices.extend([p - 1, p, p + 1]);
                    p = q;
                }
                let limit = LIMITS[dim as usize];
                indices.extend([limit - 1, limit, limit + 1, u64::MAX]);
                indices.extend((0..500u64).map(|i| crate::hash::mix64(i ^ seed)));
                indices.extend((0..1000u64).map(|i| crate::hash::mix64(i ^ seed) % limit));
                for a in indices {
                    let want = scrambled_radical_inverse(dim, a, seed);
                    let got = t.value(dim, a);
                    if a < limit {
                        assert_eq!(
                            got.map(f32::to_bits),
                            Some(want.to_bits()),
                            "{dim} {a} {seed}"
                        );
                    } else {
                        assert_eq!(got, None, "{dim} {a}");
                    }
                }
            }
            assert_eq!(t.value(5, 1), None);
        }
        // The edge case (`π(0) = b − 1`) was exercised in every base.
        assert_eq!(edge_seen, [true; 5]);
    }

    /// The limits are the largest powers of the group size that keep the denominator exact.
    #[test]
    fn group_limits_are_exact_bounds() {
        for (&limit, (b, g)) in
            LIMITS
                .iter()
                .zip([(2u128, 16u128), (3, 27), (5, 25), (7, 49), (11, 11)])
        {
            let limit = u128::from(limit);
            assert!((b - 1) * limit < 1 << 53);
            assert!((b - 1) * limit * g >= 1 << 53);
            let mut p = 1;
            while p < limit {
                p *= g;
            }
            assert_eq!(p, limit);
        }
    }
}
