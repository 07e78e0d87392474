//! The exact digit engine: a chunk's digits reversed by multiply-high steps, Φ_b(a) as an exact
//! fraction for any `u64` index, and its correct rounding to `f32` and `f64` by long division.

use super::PRIME_COUNT;
use super::tables::{BASES, BaseInfo, DIGITS, ROW, Row};
use crate::math::{ONE_MINUS_EPSILON, ONE_MINUS_EPSILON_F64};

/// The digits of `x < bⁿ` (`n ≤ k`) reversed: `Σ_j d_j·b^(n−1−j)`, exactly.
///
/// Two digits per step: the high word of `y·b²` is the next digit pair `D = d·b + d'` (`d` the
/// more significant), split by an exact multiply-shift `d = ⌊D·⌈2⁴⁰/b⌉ / 2⁴⁰⌋` (exact because
/// `D < b² ` and `b³ < 2⁴⁰`), and the swapped pair `d + d'·b = b·D − (b² − 1)·d` is added at its
/// weight.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn reverse_chunk(info: &BaseInfo, x: u64, n: u32, magic: u64) -> u64 {
    let (b, b2, split) = (info.b, info.b2, info.split);
    // y = x/bⁿ as a 64-bit fraction (no overflow: x·magic < 2⁶⁴ because b²ⁿ < 2⁶⁴).
    let mut y = x.wrapping_mul(magic);
    let mut rev = 0u64;
    let mut weight = 1u64;
    if n & 1 == 1 {
        let t = u128::from(y) * u128::from(b);
        rev = (t >> 64) as u64;
        y = t as u64;
        weight = b;
    }
    for _ in 0..n / 2 {
        let t = u128::from(y) * u128::from(b2);
        let pair = (t >> 64) as u64;
        y = t as u64;
        let hi = (pair * split) >> 40;
        let swapped = (b * pair).wrapping_sub((b2 - 1) * hi);
        rev = rev.wrapping_add(swapped.wrapping_mul(weight));
        weight = weight.wrapping_mul(b2);
    }
    rev
}

/// Bit length of `x` (0 for 0).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn bit_len(x: u64) -> usize {
    (64 - x.leading_zeros()) as usize
}

/// Reversed digits of a single chunk `x < b^k`, and the row (`off + n`) of its digit count.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn single_chunk(d: usize, info: &BaseInfo, x: u64) -> (u64, &'static Row) {
    let n = u32::from(DIGITS[d][bit_len(x)]);
    let row = &ROW[(info.off + n) as usize];
    (reverse_chunk(info, x, n, row.magic), row)
}

/// Φ_b(a) as an exact fraction `num / den` (`num < den < 2⁹⁶`) for any `u64` index.
pub(super) fn phi_fraction(d: usize, mut a: u64) -> (u128, u128) {
    let info = &BASES[d];
    let mut num = 0u128;
    let mut den = 1u128;
    while a >= info.big {
        let chunk = a % info.big;
        a /= info.big;
        let rev = reverse_chunk(info, chunk, info.k, ROW[(info.off + info.k) as usize].magic);
        num = num * u128::from(info.big) + u128::from(rev);
        den *= u128::from(info.big);
    }
    let (rev, row) = single_chunk(d, info, a);
    let p = u128::from(row.pow);
    (num * p + u128::from(rev), den * p)
}

/// `2^e` as an `f64`, for `-1022 <= e <= 1023`.
#[inline]
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// Long division of `(num + frac·2⁻¹²⁸) / den` (`num < den < 2⁹⁶`) into a 64-bit mantissa whose
/// lowest bit is sticky, and its binary exponent: value ≈ `m · 2^e`, such that rounding `m` to 24
/// or 53 bits rounds the value correctly (given `frac` exact and `inexact == false`).
pub(super) fn long_divide(num: u128, den: u128, mut frac: u128, inexact: bool) -> (u64, i32) {
    let mut r = num;
    let mut acc = 0u128;
    let mut exp = 0i32;
    let mut words = 0;
    // The value is 0 or at least 2⁻²⁰⁰ for every caller, so 10 words reach 66 significant bits.
    while acc < (1u128 << 66) && words < 10 {
        let t = (r << 32) | (frac >> 96);
        frac <<= 32;
        acc = (acc << 32) | (t / den);
        r = t % den;
        exp -= 32;
        words += 1;
    }
    let sticky = r != 0 || frac != 0 || inexact;
    let shift = (128 - acc.leading_zeros()).saturating_sub(64);
    let lost = acc & ((1u128 << shift) - 1) != 0;
    let m = (acc >> shift) as u64 | u64::from(lost || sticky);
    (m, exp + shift as i32)
}

/// `num / den` rounded to `f32` (correctly, when `inexact` is false), clamped below 1.
pub(super) fn fraction_f32(num: u128, den: u128, frac: u128, inexact: bool) -> f32 {
    let (m, e) = long_divide(num, den, frac, inexact);
    // `m as f32` rounds once; scaling by a power of two in f64 is exact, and so is the narrowing
    // (the value is 0 or far above f32's smallest normal).
    (((m as f32) as f64 * pow2(e)) as f32).min(ONE_MINUS_EPSILON)
}

/// `num / den` rounded to `f64` (correctly, when `inexact` is false), clamped below 1.
pub(super) fn fraction_f64(num: u128, den: u128, frac: u128, inexact: bool) -> f64 {
    let (m, e) = long_divide(num, den, frac, inexact);
    ((m as f64) * pow2(e)).min(ONE_MINUS_EPSILON_F64)
}

/// `num / den` correctly rounded to `f32` for `num < den < 2⁹⁶`, clamped below 1
/// (crate-internal helper, used by Hammersley's first coordinate).
pub(crate) fn ratio_f32(num: u128, den: u128) -> f32 {
    fraction_f32(num, den, 0, false)
}

/// `num / den` correctly rounded to `f64` for `num < den < 2⁹⁶`, clamped below 1.
pub(crate) fn ratio_f64(num: u128, den: u128) -> f64 {
    fraction_f64(num, den, 0, false)
}

/// Φ_b(a) as an `f64` in `[0, 1)`, correctly rounded (so within ½ ulp).
///
/// Same digits and wrapping rules as [`radical_inverse`](super::radical_inverse).
///
/// ```
/// use nyquist::radical::radical_inverse_f64;
/// assert_eq!(radical_inverse_f64(0, 3), 0.75);
/// assert_eq!(radical_inverse_f64(1, 1), 1.0 / 3.0);
/// assert_eq!(radical_inverse_f64(2, 7), 11.0 / 25.0); // 7 = 12₅ → 0.21₅
/// ```
#[inline]
pub fn radical_inverse_f64(dim: u32, a: u64) -> f64 {
    let d = (dim % PRIME_COUNT) as usize;
    if d == 0 {
        let r = a.reverse_bits();
        let top = r >> 63;
        let m = ((r >> top) | (r & top)) as i64;
        let scale = f64::from_bits((1023 - 64 + top) << 52);
        return ((m as f64) * scale).min(ONE_MINUS_EPSILON_F64);
    }
    let info = &BASES[d];
    if a < info.big {
        let (rev, row) = single_chunk(d, info, a);
        // Both operands are exact (< 2³²): one correctly rounded division.
        return (rev as i64 as f64 / row.pow as i64 as f64).min(ONE_MINUS_EPSILON_F64);
    }
    let (num, den) = phi_fraction(d, a);
    fraction_f64(num, den, 0, false)
}
