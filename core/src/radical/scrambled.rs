//! The digit-permutation scrambled radical inverse: every digit, the infinitely many leading
//! zeros included, through one hashed permutation of `0..b`.

use super::PRIME_COUNT;
use super::exact::{fraction_f32, fraction_f64};
use super::tables::BASES;
use crate::Error;
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

/// The values a column writer puts in `len` slots at `stride` (the last slot may be partial)
/// and the last index it reaches from `first`: `None` for no values.
///
/// # Errors
/// [`Error::ZeroSize`] for `stride == 0`; [`Error::TooMany`] (`what: "first"`) when the last
/// index passes `u64::MAX`.
fn column_span(first: u64, len: usize, stride: usize) -> Result<Option<(u64, u64)>, Error> {
    if stride == 0 {
        return Err(Error::ZeroSize { what: "stride" });
    }
    let count = len.div_ceil(stride) as u64;
    if count == 0 {
        return Ok(None);
    }
    let last = first.checked_add(count - 1).ok_or(Error::TooMany {
        what: "first",
        value: first,
        max: u64::MAX - (count - 1),
    })?;
    Ok(Some((count, last)))
}

/// [`scrambled_radical_inverse_f64`]`(dim, first + k, seed)` for `k = 0, 1, …` into
/// `out[0]`, `out[stride]`, `out[2·stride]`, … (as many as `out` holds), bit for bit, in
/// amortised O(1) per value: a column of a point-major array, for filling many points.
///
/// The index's digits are kept as an odometer, and the permuted digits as one integer
/// `N = Σ_{j<K} π(a_j)·b^(K−1−j)` over a fixed `K` digits (those of the last index): a step
/// changes the low digit and, on a carry, the next ones, and `N` by each changed digit's
/// difference. `(N·(b−1) + π(0)) / ((b−1)·b^K)` is the same fraction
/// [`scrambled_radical_inverse_f64`] divides, scaled by `b^(K−n)`, so the correctly rounded
/// quotient is the same float. Where `(b−1)·b^K` reaches 2⁵³ (indices past about 2⁵³ / b)
/// the values are computed one by one. Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] for `stride == 0`; [`Error::TooMany`] (`what: "first"`) when the last
/// index passes `u64::MAX`.
///
/// ```
/// use nyquist::radical::{scrambled_radical_inverse_column_f64, scrambled_radical_inverse_f64};
/// let mut out = [0.0; 2 * 10];
/// assert_eq!(scrambled_radical_inverse_column_f64(1, 95, 7, &mut out[1..], 2), Ok(10));
/// for k in 0..10 {
///     assert_eq!(out[1 + 2 * k], scrambled_radical_inverse_f64(1, 95 + k as u64, 7));
/// }
/// ```
pub fn scrambled_radical_inverse_column_f64(
    dim: u32,
    first: u64,
    seed: u64,
    out: &mut [f64],
    stride: usize,
) -> Result<u64, Error> {
    let Some((count, last)) = column_span(first, out.len(), stride)? else {
        return Ok(0);
    };
    let d = (dim % PRIME_COUNT) as usize;
    let b = BASES[d].b;
    let pi = digit_permutation(seed, b);
    // π as a table for the small bases (the first 18 dimensions), where a lookup is cheaper
    // than the hash.
    let mut table = [0u32; 64];
    if b <= 64 {
        for (v, t) in table.iter_mut().enumerate().take(b as usize) {
            *t = pi.apply(v as u32);
        }
    }
    let perm = |v: u32| {
        u64::from(if b <= 64 {
            table[v as usize]
        } else {
            pi.apply(v)
        })
    };
    // K: the digits of the last index (at least one), with b^j for each position.
    let mut digits = [0u32; 64];
    let mut weight = [0u64; 64];
    let mut k = 0;
    let mut den = b - 1;
    let mut rest = last;
    loop {
        // (b−1)·b^K must stay below 2⁵³ for the division to be exact in its operands.
        match den.checked_mul(b) {
            Some(next) if next < 1 << 53 => den = next,
            _ => {
                for (x, a) in out.iter_mut().step_by(stride).zip(first..=last) {
                    *x = scrambled_radical_inverse_f64(dim, a, seed);
                }
                return Ok(count);
            }
        }
        k += 1;
        rest /= b;
        if rest == 0 {
            break;
        }
    }
    // weight[j] = b^(K−1−j); the digits of `first`; N. Both cut to K entries, so a carry
    // past them could not go unnoticed.
    let (digits, weight) = (&mut digits[..k], &mut weight[..k]);
    let mut w = 1u64;
    for j in (0..k).rev() {
        weight[j] = w;
        w *= b;
    }
    let mut a = first;
    let mut n = 0u64;
    for j in 0..k {
        digits[j] = (a % b) as u32;
        a /= b;
        n += perm(digits[j]) * weight[j];
    }
    let tail = perm(0);
    let at_edge = tail == b - 1;
    let den = den as f64;
    for (i, x) in out.iter_mut().step_by(stride).enumerate() {
        if i > 0 {
            // The next index: the low digit steps and carries move up. The index stays at
            // most the last one, which has K digits, so no carry leaves the K digits.
            let mut j = 0;
            loop {
                let old = digits[j];
                let new = if old + 1 == b as u32 { 0 } else { old + 1 };
                digits[j] = new;
                n = n + perm(new) * weight[j] - perm(old) * weight[j];
                if new != 0 {
                    break;
                }
                j += 1;
            }
        }
        let v = (n * (b - 1) + tail) as f64 / den;
        let v = if at_edge { below_f64(v) } else { v };
        *x = v.min(ONE_MINUS_EPSILON_F64);
    }
    Ok(count)
}

/// The digits [`positional_radical_inverse_f64`] keeps in base `b`: the most `K` with
/// `b^K ≤ 2⁵³`, and `b^K`.
fn positional_digits(b: u64) -> (usize, u64) {
    let (mut k, mut p) = (0, 1u64);
    // p·b ≤ 2⁵³·8161 < 2⁶⁶ could overflow; p ≤ 2⁵³ / b cannot.
    while p <= (1 << 53) / b {
        p *= b;
        k += 1;
    }
    (k, p)
}

/// The permutation of digit position `j` (0 for the digit just after the point) in base `b`.
#[inline]
fn position_permutation(seed: u64, b: u64, j: usize) -> hash::Permutation {
    let key = hash::hash3(seed, b, j as u64);
    hash::Permutation::new(b as u32, (key ^ (key >> 32)) as u32)
}

/// Φ_b(a) with each digit position through its own random permutation: digit `a_j` (the
/// coefficient of `b^j` in `a`, which lands at `b^−(j+1)`) becomes `π_j(a_j)`, with `π_j` a
/// [`hash::Permutation`] keyed by (seed, base, j). This is the randomized Halton of A. B. Owen,
/// "A randomized Halton algorithm in R" (2017), and the law of SciPy's scrambled `Halton`: far
/// more randomizations than one permutation per base (base 2 has only two of those).
///
/// The first `K` positions count, `K` the most with `b^K ≤ 2⁵³` (53 in base 2, 4 in base
/// 8161): the value `Σ_{j<K} π_j(a_j)·b^(K−1−j) / b^K` is one correctly rounded division of
/// exact integers, in `[0, 1)`. Indices that agree in their low `K` digits get the same value;
/// below 2⁴² every base keeps them apart (`b^K ≥ 5.8·10¹²` for all 1024 bases). Total: `dim`
/// wraps modulo 1024; every seed is valid.
///
/// ```
/// use nyquist::radical::positional_radical_inverse_f64;
/// // Still stratified: the first 9 points in base 3 fall one per ninth.
/// let mut cells: Vec<u32> =
///     (0..9).map(|a| (positional_radical_inverse_f64(1, a, 4) * 9.0) as u32).collect();
/// cells.sort();
/// assert_eq!(cells, [0, 1, 2, 3, 4, 5, 6, 7, 8]);
/// ```
pub fn positional_radical_inverse_f64(dim: u32, a: u64, seed: u64) -> f64 {
    let b = BASES[(dim % PRIME_COUNT) as usize].b;
    let (k, den) = positional_digits(b);
    let (mut rest, mut num) = (a, 0u64);
    for j in 0..k {
        num = num * b + u64::from(position_permutation(seed, b, j).apply((rest % b) as u32));
        rest /= b;
    }
    num as f64 / den as f64
}

/// [`positional_radical_inverse_f64`]`(dim, first + k, seed)` for `k = 0, 1, …` into
/// `out[0]`, `out[stride]`, … (as many as `out` holds), bit for bit, in amortised O(1) per
/// value: the index's digits as an odometer and the numerator updated by the changed digits
/// only; position 0's permutation is tabulated for bases up to 64. Allocates: no.
///
/// # Errors
/// [`Error::ZeroSize`] for `stride == 0`; [`Error::TooMany`] (`what: "first"`) when the last
/// index passes `u64::MAX`.
///
/// ```
/// use nyquist::radical::{positional_radical_inverse_column_f64, positional_radical_inverse_f64};
/// let mut out = [0.0; 12];
/// assert_eq!(positional_radical_inverse_column_f64(2, 40, 3, &mut out, 1), Ok(12));
/// assert!(out.iter().zip(40..).all(|(&x, a)| x == positional_radical_inverse_f64(2, a, 3)));
/// ```
pub fn positional_radical_inverse_column_f64(
    dim: u32,
    first: u64,
    seed: u64,
    out: &mut [f64],
    stride: usize,
) -> Result<u64, Error> {
    let Some((count, _)) = column_span(first, out.len(), stride)? else {
        return Ok(0);
    };
    let b = BASES[(dim % PRIME_COUNT) as usize].b;
    let (k, den) = positional_digits(b);
    let mut digits = [0u32; 64];
    let mut weight = [0u64; 64];
    let (digits, weight) = (&mut digits[..k], &mut weight[..k]);
    let mut w = 1u64;
    for j in (0..k).rev() {
        weight[j] = w;
        w *= b;
    }
    // Each position's permutation built once (a carry reaches position j once per b^j steps,
    // position 1 every other step in base 2), and position 0's as a table for bases up to 64.
    let mut perms = [position_permutation(seed, b, 0); 64];
    for (j, p) in perms.iter_mut().enumerate().take(k).skip(1) {
        *p = position_permutation(seed, b, j);
    }
    let mut table = [0u32; 64];
    if b <= 64 {
        for (v, t) in table.iter_mut().enumerate().take(b as usize) {
            *t = perms[0].apply(v as u32);
        }
    }
    let perm = |j: usize, v: u32| {
        u64::from(if j == 0 && b <= 64 {
            table[v as usize]
        } else {
            perms[j].apply(v)
        })
    };
    let (mut rest, mut num) = (first, 0u64);
    for j in 0..k {
        digits[j] = (rest % b) as u32;
        rest /= b;
        num += perm(j, digits[j]) * weight[j];
    }
    let den = den as f64;
    for (i, x) in out.iter_mut().step_by(stride).enumerate() {
        if i > 0 {
            // The next index's low K digits: a carry out of the top digit wraps, as the value
            // keeps only those digits.
            let mut j = 0;
            while j < k {
                let old = digits[j];
                let new = if old + 1 == b as u32 { 0 } else { old + 1 };
                digits[j] = new;
                num = num + perm(j, new) * weight[j] - perm(j, old) * weight[j];
                if new != 0 {
                    break;
                }
                j += 1;
            }
        }
        *x = num as f64 / den;
    }
    Ok(count)
}
