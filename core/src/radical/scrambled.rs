//! The digit-permutation scrambled radical inverse: every digit, the infinitely many leading
//! zeros included, through one hashed permutation of `0..b`.

use super::PRIME_COUNT;
use super::exact::{fraction_f32, fraction_f64};
use super::tables::BASES;
use crate::hash;
use crate::math::{ONE_MINUS_EPSILON, ONE_MINUS_EPSILON_F64};

/// The digit permutation π of base `b` under `seed`: a [`hash::Permutation`] keyed by both.
#[inline]
pub(super) fn digit_permutation(seed: u64, b: u64) -> hash::Permutation {
    let key = hash::hash2(seed, b);
    hash::Permutation::new(b as u32, (key ^ (key >> 32)) as u32)
}

/// Scrambled Φ as `(num, den, at_edge)`: `(R·(b−1) + π(0)) / ((b−1)·bⁿ)`, and whether
/// `π(0) = b − 1`, when that value is exactly the upper edge `(R' + 1)/bⁿ` of the point's finest
/// stratum (`R'` the permuted digits).
fn scrambled_fraction(d: usize, mut a: u64, seed: u64) -> (u128, u128, bool) {
    let b = BASES[d].b;
    let pi = digit_permutation(seed, b);
    let mut num = 0u128;
    let mut den = 1u128;
    while a > 0 {
        let digit = (a % b) as u32;
        a /= b;
        num = num * u128::from(b) + u128::from(pi.apply(digit));
        den *= u128::from(b);
    }
    let tail = u64::from(pi.apply(0));
    (
        num * u128::from(b - 1) + u128::from(tail),
        den * u128::from(b - 1),
        tail == b - 1,
    )
}

/// The largest float below the positive finite `x` (for `x` a rounded stratum edge).
#[inline]
pub(super) fn below_f32(x: f32) -> f32 {
    f32::from_bits(x.to_bits() - 1)
}

#[inline]
fn below_f64(x: f64) -> f64 {
    f64::from_bits(x.to_bits() - 1)
}

/// Φ_b(a) with every digit passed through one random permutation π of `0..b`, as an `f32` in
/// `[0, 1)`: `Σ_{j≥0} π(a_j)·b^−(j+1)`, including the infinitely many leading zeros of `a`, whose
/// sum `π(0)·b^−n/(b−1)` is added in closed form — so every seed gives a uniformly distributed,
/// still stratified point set.
///
/// π is a [`hash::Permutation`] keyed by (seed, base): no table, no state, and every digit's
/// image is uniform over seeds. Within 1 ulp, with one exception that keeps the strata: when
/// `π(0) = b − 1` the infinite tail `0.(b−1)(b−1)…` sums to exactly the upper edge `(R + 1)/bⁿ`
/// of the point's stratum (`R` the permuted digits, `n` the digit count of `a`; for `a = 0` the
/// edge is 1), and the result is then the largest `f32` strictly below that edge — within 2 ulp
/// of the exact value, but inside its own stratum instead of on the next one's boundary.
/// Total: `dim` wraps modulo 1024; every seed is valid; the result is always below 1.
///
/// ```
/// use nyquist::radical::scrambled_radical_inverse;
/// // Digit permutation keeps the strata: points 0..9 in base 3 sit one per ninth, all at the
/// // same offset inside their cell.
/// let mut xs: Vec<f64> = (0..9).map(|a| f64::from(scrambled_radical_inverse(1, a, 7))).collect();
/// xs.sort_by(f64::total_cmp);
/// assert!(xs.windows(2).all(|w| (w[1] - w[0] - 1.0 / 9.0).abs() < 1e-6));
/// ```
pub fn scrambled_radical_inverse(dim: u32, a: u64, seed: u64) -> f32 {
    let d = (dim % PRIME_COUNT) as usize;
    let (num, den, at_edge) = scrambled_fraction(d, a, seed);
    let x = if den < (1 << 53) {
        // Both exact in f64: one correctly rounded division, then one narrowing (within 1 ulp).
        (num as f64 / den as f64) as f32
    } else {
        fraction_f32(num, den, 0, false)
    };
    // Within 1 ulp of the edge, `x` is one of the two floats around it (or the edge itself):
    // the float below `x` is strictly below the edge.
    let x = if at_edge { below_f32(x) } else { x };
    x.min(ONE_MINUS_EPSILON)
}

/// The scrambled radical inverse as an `f64` in `[0, 1)`, correctly rounded except at a
/// stratum edge (`π(0) = b − 1`), where it is the largest `f64` below the edge. See
/// [`scrambled_radical_inverse`].
///
/// ```
/// use nyquist::radical::{scrambled_radical_inverse, scrambled_radical_inverse_f64};
/// let x = scrambled_radical_inverse_f64(5, 12345, 99);
/// assert!((0.0..1.0).contains(&x));
/// assert!((x - f64::from(scrambled_radical_inverse(5, 12345, 99))).abs() < 1e-7);
/// ```
pub fn scrambled_radical_inverse_f64(dim: u32, a: u64, seed: u64) -> f64 {
    let d = (dim % PRIME_COUNT) as usize;
    let (num, den, at_edge) = scrambled_fraction(d, a, seed);
    let x = if den < (1 << 53) {
        num as f64 / den as f64
    } else {
        fraction_f64(num, den, 0, false)
    };
    let x = if at_edge { below_f64(x) } else { x };
    x.min(ONE_MINUS_EPSILON_F64)
}
