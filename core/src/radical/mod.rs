//! Radical inverses Φ_b(a) for the first 1024 prime bases, with `u64` indices, in `f32` and `f64`:
//! the plain form, the folded (Zaremba) form Ψ_b, a digit-permutation scrambled form, nested
//! (Owen) scrambled forms ([`owen_scrambled_radical_inverse`]), and the inverse.
//!
//! Dimension `d` uses base [`prime`]`(d)`; dimension 0 is base 2. Every function here is total:
//! `dim >= 1024` wraps to `dim % 1024`, every `u64` index is valid, and results lie in `[0, 1)`
//! (clamped to [`ONE_MINUS_EPSILON`](crate::ONE_MINUS_EPSILON) /
//! [`ONE_MINUS_EPSILON_F64`](crate::ONE_MINUS_EPSILON_F64)). Allocates: never.
//!
//! # How the digits are found
//!
//! Digits come from exact integer arithmetic, never from a rounded floating-point reciprocal.
//! An index is cut into chunks below `B = b^k < 2³²` (at most three chunks for any `u64` and any of
//! the 1024 bases). Inside a chunk `x` with `n` digits, `y = x·⌈2⁶⁴/bⁿ⌉` is the 64-bit fixed-point
//! fraction `x/bⁿ`; multiplying it by `b` hands out one digit per step in the high word, most
//! significant first (the digit-extraction idea of fast integer printing, e.g. Lemire's and
//! Anhalt's decimal printers). The fraction is exact enough because `b²ⁿ < 2⁶⁴`: its error
//! `x·ε < bⁿ` grows by `b` per step and stays below the gap `2⁶⁴/b^(n−j)` to the next digit.
//! Only as many digits as the chunk's bit length can need are extracted. Base 2 is a bit reversal.
//!
//! # Accuracy
//!
//! - [`radical_inverse`], [`radical_inverse_f64`], the scrambled forms: within 1 ulp of the exact
//!   rational value (the `f64` forms and every multi-chunk index are correctly rounded); base 2 is
//!   the correctly rounded bit reversal.
//! - The folded forms: within 1 ulp of the exact (infinite-sum) value; the periodic tail is
//!   summed in closed form to 128 fractional bits.
//!
//! Sources: the radical inverse and Halton's sequence (Halton 1960), the folded radical inverse
//! (Braaten & Weller 1979; Kocis & Whiten 1997, as the "Halton–Zaremba" sequence), digit
//! permutations of the radical inverse (Faure 1992; Kollig & Keller 2002), and pbrt-v3 §7.4 for
//! `InverseRadicalInverse` semantics.

// The code by concern: `tables` builds the per-base constants at compile time (or at first use
// with `lazy-tables`); `fast` is the `f32` fast path and its batch, run and incremental forms;
// `exact` the integer digit engine, the correctly rounded fractions and the `f64` form;
// `folded` the Zaremba form; `scrambled` the digit-permutation form; `owen` the nested
// scrambles; `permuted` the Halton sampler's digit-group tables; `primes` the bases.
mod exact;
mod fast;
mod folded;
mod owen;
mod permuted;
mod primes;
mod scrambled;
mod tables;

pub use exact::radical_inverse_f64;
pub(crate) use exact::{ratio_f32, ratio_f64};
pub(crate) use fast::{fill_consecutive, phi2, radical_inverse_inlined};
pub use fast::{fill_radical_inverse, radical_inverse, radical_inverse_at, radical_inverse_dims};
pub use folded::{folded_radical_inverse, folded_radical_inverse_f64};
pub use owen::{
    fast_owen_scrambled_radical_inverse, fast_owen_scrambled_radical_inverse_f64,
    owen_scrambled_radical_inverse, owen_scrambled_radical_inverse_f64,
};
pub(crate) use permuted::PermutedDigitGroups;
pub use primes::PRIMES;
pub use scrambled::{
    positional_radical_inverse_column_f64, positional_radical_inverse_f64,
    scrambled_radical_inverse, scrambled_radical_inverse_column_f64, scrambled_radical_inverse_f64,
};
#[cfg(test)]
pub(crate) use tables::fast_class_of_table;
pub(crate) use tables::{fast_class, fast_limit};

/// The number of prime bases (and radical-inverse dimensions): 1024.
///
/// ```
/// assert_eq!(nyquist::radical::PRIME_COUNT as usize, nyquist::radical::PRIMES.len());
/// ```
pub const PRIME_COUNT: u32 = 1024;

/// The base of radical-inverse dimension `dim`: the `dim`-th prime (0-based), so `prime(0) == 2`.
///
/// Total: `dim >= 1024` wraps to `dim % 1024`.
///
/// ```
/// use nyquist::radical::prime;
/// assert_eq!((prime(0), prime(1), prime(2), prime(1023)), (2, 3, 5, 8161));
/// assert_eq!(prime(1024 + 1), 3);
/// ```
#[inline]
pub fn prime(dim: u32) -> u32 {
    PRIMES[(dim % PRIME_COUNT) as usize]
}

/// The index whose first `n_digits` base-`b` digits, reversed, are the low `n_digits` digits of
/// `inverse` (`b = prime(dim)`): the integer inverse of the radical inverse, with pbrt-v3's
/// `InverseRadicalInverse` semantics.
///
/// If `rev` is `Φ_b(a)·bⁿ` for an index `a < bⁿ`, then `inverse_radical_inverse(dim, rev, n) == a`.
/// Digits of `inverse` above the first `n_digits` are ignored. Total: when the result does not fit
/// a `u64` (more than 64 bits of digits), it wraps modulo 2⁶⁴ — the arithmetic is
/// `index = index·b + digit` with wrapping. `dim >= 1024` wraps modulo 1024.
///
/// ```
/// use nyquist::radical::inverse_radical_inverse;
/// // 6 = 110₂ reversed over 3 digits is 011₂ = 3.
/// assert_eq!(inverse_radical_inverse(0, 6, 3), 3);
/// // 5 = 12₃ reversed over 2 digits is 21₃ = 7.
/// assert_eq!(inverse_radical_inverse(1, 5, 2), 7);
/// assert_eq!(inverse_radical_inverse(1, 5, 0), 0);
/// ```
pub fn inverse_radical_inverse(dim: u32, mut inverse: u64, n_digits: u32) -> u64 {
    let b = u64::from(prime(dim));
    let mut index = 0u64;
    for done in 0..n_digits {
        if inverse == 0 {
            // Only zero digits remain: multiply by b once per digit, in O(log n) steps.
            return index.wrapping_mul(b.wrapping_pow(n_digits - done));
        }
        let digit = inverse % b;
        inverse /= b;
        index = index.wrapping_mul(b).wrapping_add(digit);
    }
    index
}

#[cfg(test)]
mod tests;
