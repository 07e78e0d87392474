//! The folded (Zaremba) radical inverse Ψ_b, whose periodic infinite tail is summed in closed
//! form to 128 fractional bits.

use super::PRIME_COUNT;
use super::exact::{fraction_f32, fraction_f64};
use super::primes::PRIME_TABLE;
use super::tables::BASES;
use crate::lazy_table::baked_table;

/// Bases up to this index (`b ≤ 23`) take the periodic tail from a const table; above it the
/// closed form below is accurate to 2⁻¹²⁷ because `b^−b < 2⁻¹⁴⁰`.
const SMALL_FOLD_BASES: usize = 9;

/// `T_b(r) · 2¹²⁸` for `b ≤ 23`, where `T_b(r) = Σ_{i≥0} ((r+i) mod b)·b^−(i+1)`, summed by
/// Horner from 150 digits out (truncation error below 2⁻¹²⁷).
const fn fill_fold_tails(out: &mut [[u128; 23]; SMALL_FOLD_BASES]) {
    let mut d = 0;
    while d < SMALL_FOLD_BASES {
        let b = PRIME_TABLE[d] as u128;
        let mut r = 0;
        while r < b {
            let mut v = 0u128;
            let mut i = 150u128;
            while i > 0 {
                i -= 1;
                let c = (r + i) % b;
                // v ← (c + v)/b in 128-bit fixed point, by two 64-bit long-division steps.
                let hi = (c << 64) | (v >> 64);
                let qh = hi / b;
                let lo = ((hi % b) << 64) | (v & (u64::MAX as u128));
                v = (qh << 64) | (lo / b);
            }
            out[d][r as usize] = v;
            r += 1;
        }
        d += 1;
    }
}

baked_table! {
    static FOLD_TAILS: [[u128; 23]; SMALL_FOLD_BASES] = [[0; 23]; SMALL_FOLD_BASES],
        fill_fold_tails, fold_tails_at_first_use_equal_the_baked_table;
}

/// The folded tail `T_b(r) = Σ_{i≥0} ((r+i) mod b)·b^−(i+1)` as a 128-bit fraction (error below
/// 2⁻¹²⁶). For `b ≥ 29`, by the closed form
/// `T = (r(b−1)+1)/(b−1)² − b^−(b−1−r)/((b−1)(1−b^−b))` with the `b^−b` term dropped.
pub(super) fn fold_tail(d: usize, b: u64, r: u64) -> u128 {
    if d < SMALL_FOLD_BASES {
        return FOLD_TAILS[d][r as usize];
    }
    let q = u128::from((b - 1) * (b - 1));
    let p = u128::from(r * (b - 1) + 1) % q;
    // frac(p/q)·2¹²⁸ by long division (p < q < 2²⁶).
    let hi = (p << 64) / q;
    let lo = (((p << 64) % q) << 64) / q;
    let first = (hi << 64) | lo;
    // b^−s/(b−1) · 2¹²⁸, s = b−1−r, or 0 when it is below 2⁻¹²⁸.
    let s = b - 1 - r;
    let mut den = u128::from(b - 1);
    let mut second = 0u128;
    let mut ok = true;
    for _ in 0..s {
        match den.checked_mul(u128::from(b)) {
            Some(v) => den = v,
            None => {
                ok = false;
                break;
            }
        }
    }
    if ok {
        second = u128::MAX / den;
    }
    // T < 1, so the difference taken modulo 2¹²⁸ is T·2¹²⁸ (the integer part of the first term
    // cancels).
    first.wrapping_sub(second)
}

/// Ψ_b(a) as `(R, bⁿ, T·2¹²⁸)`: value = `(R + T)/bⁿ`.
fn folded_parts(d: usize, mut a: u64) -> (u128, u128, u128) {
    let b = BASES[d].b;
    let mut num = 0u128;
    let mut den = 1u128;
    let mut jm = 0u64; // j mod b
    while a > 0 {
        let digit = a % b;
        a /= b;
        let mut f = digit + jm;
        if f >= b {
            f -= b;
        }
        num = num * u128::from(b) + u128::from(f);
        den *= u128::from(b);
        jm += 1;
        if jm == b {
            jm = 0;
        }
    }
    (num, den, fold_tail(d, b, jm))
}

/// Ψ_b(a), the folded radical inverse (Zaremba's form), as an `f32` in `[0, 1)`.
///
/// `Ψ_b(a) = Σ_{j≥0} ((a_j + j) mod b)·b^−(j+1)` with `a_j` the base-`b` digits of `a`
/// (`b = prime(dim)`), the sum continued past `a`'s last digit (where `a_j = 0`) to infinity, so
/// `Ψ₂(0) = 1/3`. The infinite tail is periodic and summed in closed form. Within 1 ulp. Total:
/// `dim` wraps modulo 1024; clamped below 1.
///
/// ```
/// use nyquist::radical::folded_radical_inverse;
/// assert_eq!(folded_radical_inverse(0, 0), 1.0 / 3.0);
/// assert_eq!(folded_radical_inverse(0, 1), 5.0 / 6.0);
/// assert_eq!(folded_radical_inverse(0, 2), 1.0 / 12.0);
/// ```
pub fn folded_radical_inverse(dim: u32, a: u64) -> f32 {
    let d = (dim % PRIME_COUNT) as usize;
    let (num, den, tail) = folded_parts(d, a);
    fraction_f32(num, den, tail, true)
}

/// Ψ_b(a) as an `f64` in `[0, 1)`, within 1 ulp. See [`folded_radical_inverse`].
///
/// ```
/// use nyquist::radical::folded_radical_inverse_f64;
/// assert_eq!(folded_radical_inverse_f64(0, 3), 7.0 / 12.0);
/// // Ψ₃(0) has the periodic digits 0.012012…₃ = 5/26.
/// assert!((folded_radical_inverse_f64(1, 0) - 5.0 / 26.0).abs() <= f64::EPSILON / 8.0);
/// ```
pub fn folded_radical_inverse_f64(dim: u32, a: u64) -> f64 {
    let d = (dim % PRIME_COUNT) as usize;
    let (num, den, tail) = folded_parts(d, a);
    fraction_f64(num, den, tail, true)
}
