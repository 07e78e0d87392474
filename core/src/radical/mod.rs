//! Radical inverses Φ_b(a) for the first 1024 prime bases, with `u64` indices, in `f32` and `f64`:
//! the plain form, the folded (Zaremba) form Ψ_b, a digit-permutation scrambled form, nested
//! (Owen) scrambled forms ([`owen_scrambled_radical_inverse`]), and the inverse.
//!
//! Dimension `d` uses base [`prime`]`(d)`; dimension 0 is base 2. Every function here is total:
//! `dim >= 1024` wraps to `dim % 1024`, every `u64` index is valid, and results lie in `[0, 1)`
//! (clamped to [`ONE_MINUS_EPSILON`] / [`ONE_MINUS_EPSILON_F64`]). Allocates: never.
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

mod owen;
mod permuted;
mod primes;

use crate::lazy_table::baked_table;
use crate::math::{ONE_MINUS_EPSILON, ONE_MINUS_EPSILON_F64};
use crate::{Error, hash};
pub use owen::{
    fast_owen_scrambled_radical_inverse, fast_owen_scrambled_radical_inverse_f64,
    owen_scrambled_radical_inverse, owen_scrambled_radical_inverse_f64,
};
pub(crate) use permuted::PermutedDigitGroups;
use primes::PRIME_TABLE;
pub use primes::PRIMES;

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

// ---------------------------------------------------------------------------------------------
// Per-base tables, evaluated at compile time.

/// Per-base constants: the base, the digits per chunk `k` (the largest with `b^k < 2³²`), the
/// chunk modulus `b^k`, and the offset of this base's rows in the flat tables below.
#[derive(Clone, Copy)]
#[cfg_attr(test, derive(PartialEq))]
struct BaseInfo {
    b: u64,
    /// `b²`.
    b2: u64,
    /// `⌈2⁴⁰/b⌉`: `⌊D·split/2⁴⁰⌋ = ⌊D/b⌋` for every `D < b²` (the error term is below `b³ < 2⁴⁰`).
    split: u64,
    k: u32,
    big: u64,
    off: u32,
}

const fn chunk_digits(b: u64) -> u32 {
    let mut k = 0;
    let mut p = 1u64;
    while p * b < (1u64 << 32) {
        p *= b;
        k += 1;
    }
    k
}

const fn total_rows() -> usize {
    let mut total = 0;
    let mut i = 0;
    while i < PRIME_TABLE.len() {
        total += chunk_digits(PRIME_TABLE[i] as u64) as usize + 1;
        i += 1;
    }
    total
}

/// Rows in the flat tables: `k + 1` per base (`n = 0 ..= k` digits).
const ROWS: usize = total_rows();

const NO_BASE: BaseInfo = BaseInfo {
    b: 0,
    b2: 0,
    split: 0,
    k: 0,
    big: 0,
    off: 0,
};

const fn build_bases() -> [BaseInfo; 1024] {
    let mut out = [NO_BASE; 1024];
    let mut off = 0u32;
    let mut i = 0;
    while i < 1024 {
        let b = PRIME_TABLE[i] as u64;
        let k = chunk_digits(b);
        out[i] = BaseInfo {
            b,
            b2: b * b,
            split: (1u64 << 40).div_ceil(b),
            k,
            big: b.pow(k),
            off,
        };
        off += k + 1;
        i += 1;
    }
    out
}

const fn fill_bases(t: &mut [BaseInfo; 1024]) {
    *t = build_bases();
}

baked_table! {
    static BASES: [BaseInfo; 1024] = [NO_BASE; 1024], fill_bases,
        bases_at_first_use_equal_the_baked_table;
}

/// `bⁿ` and `⌈2⁶⁴/bⁿ⌉` (0 for `n = 0`, unused), per base and `n`.
#[derive(Clone, Copy)]
#[cfg_attr(test, derive(PartialEq))]
struct Row {
    pow: u64,
    magic: u64,
}

const fn build_rows() -> [Row; ROWS] {
    let bases = build_bases();
    let mut rows = [Row { pow: 0, magic: 0 }; ROWS];
    let mut i = 0;
    while i < 1024 {
        let info = bases[i];
        let mut n = 0;
        let mut p = 1u64;
        while n <= info.k {
            rows[(info.off + n) as usize] = Row {
                pow: p,
                magic: if n == 0 { 0 } else { u64::MAX / p + 1 },
            };
            p = p.wrapping_mul(info.b);
            n += 1;
        }
        i += 1;
    }
    rows
}

const fn fill_rows(t: &mut [Row; ROWS]) {
    *t = build_rows();
}

baked_table! {
    static ROW: [Row; ROWS] = [Row { pow: 0, magic: 0 }; ROWS], fill_rows,
        rows_at_first_use_equal_the_baked_table;
}

/// `DIGITS[d][L]`: the number of base-`b` digits of `2^L − 1`, capped at `k` — an upper bound on
/// the digit count of any chunk of bit length `L` (one more than needed at most, which only
/// costs a zero digit).
const fn build_digits() -> [[u8; 33]; 1024] {
    let bases = build_bases();
    let mut out = [[0u8; 33]; 1024];
    let mut i = 0;
    while i < 1024 {
        let info = bases[i];
        let mut len = 1;
        while len <= 32 {
            let mut x = (1u64 << len) - 1;
            let mut n = 0u32;
            while x > 0 {
                x /= info.b;
                n += 1;
            }
            out[i][len] = if n < info.k { n } else { info.k } as u8;
            len += 1;
        }
        i += 1;
    }
    out
}

const fn fill_digits(t: &mut [[u8; 33]; 1024]) {
    *t = build_digits();
}

baked_table! {
    static DIGITS: [[u8; 33]; 1024] = [[0; 33]; 1024], fill_digits,
        digits_at_first_use_equal_the_baked_table;
}

/// Index classes of the fast path: class `c = ⌈bit_len(a)/4⌉` (`0 ..= 8`) for `a < 2³²`.
const CLASSES: usize = 9;

/// What the fast path reads for one base and one index class `c`. The class's indices have at
/// most `n` digits (the base-`b` digits of `2^(4c) − 1`, capped at `k`, rounded up to whole
/// table chunks where that stays within `k`); `y = a·⌈2⁶⁴/bⁿ⌉` is the fixed-point fraction
/// `a/bⁿ`. With a digit-reversal table of chunk `c = b^j`, the digits are read as `m = ⌈n/j⌉`
/// whole chunks, the most significant one short by `pad = m·j − n` leading zeros: the first
/// step multiplies `y` by `first = b^(j − pad)` and the rest by `c`, each step's chunk looked up
/// in the table. The reversed chunks sum to `R' = R·b^pad`, exactly (`R` the reversal of the `n`
/// digits), and the value is `R'·inv`, `inv = 1/b^(n + pad) = c^−m` correctly rounded. Without a
/// table (`j = 1`), `m = n` single digits, `first = b`, `pad = 0`.
///
/// The first two multiplies are one: `a·⌈2⁶⁴/bⁿ⌉ < 2⁶⁴` (`a < bⁿ` and `b²ⁿ < 2⁶⁴`), so
/// `y·first = a·lead` as 128-bit products, `lead = ⌈2⁶⁴/bⁿ⌉·first`, which fits 64 bits when
/// there are two steps or more (`first ≤ bⁿ/c`). With one step the chunk is `a` itself.
#[derive(Clone, Copy)]
#[cfg_attr(test, derive(PartialEq))]
struct ClassConsts {
    /// `⌈2⁶⁴/bⁿ⌉·first` (0 with fewer than two steps).
    lead: u64,
    inv: f64,
    /// `b^(j − pad) ≤ max(c, b)`.
    first: u16,
    n: u8,
    /// `m`: the steps, table chunks or single digits.
    steps: u8,
    /// The arm of [`radical_inverse`]'s dispatch that computes this base's values for this
    /// class ([`Arm`]).
    arm: u8,
}

/// Class 0 (the index 0) of every base, base 2's included: no steps, so the loop arm's value 0.
const NO_CLASS: ClassConsts = ClassConsts {
    lead: 0,
    inv: 1.0,
    first: 0,
    n: 0,
    steps: 0,
    arm: Arm::General as u8,
};

/// How [`radical_inverse`] computes the values of one base and one index class: one byte per
/// class record, so a value costs one predictable indirect jump instead of a test of the base,
/// of the fast path's limit and of the step count (their pattern follows the dimensions, which a
/// caller walks in the same order for every index).
#[derive(Clone, Copy)]
#[repr(u8)]
enum Arm {
    /// Base 2: the bit reversal ([`phi2`]).
    Base2,
    /// The class reaches past the base's fast-path limit `b^k`: compare the index with it, then
    /// the fast path or the exact fraction.
    Limit,
    /// No digit-reversal table, 1 ..= 4 single digits (straight-line).
    Digits1,
    Digits2,
    Digits3,
    Digits4,
    /// A digit-reversal table, 1 ..= 3 chunks (straight-line).
    Chunks1,
    Chunks2,
    Chunks3,
    /// Any other step count: [`phi_any_steps`]' loops.
    General,
}

/// The [`Arm`] of base `i` (with digit-reversal chunks of `j` digits and fast-path limit
/// `big`) for index class `c ≥ 1`, whose records take `steps` steps. Class `c` holds indices
/// below `2^(4c)`, and the last class every longer one too, all past every limit (`big < 2³²`);
/// so a class reaches the limit exactly when `big < 2^(4c)`.
const fn arm_of(i: usize, j: u32, big: u64, c: usize, steps: u8) -> Arm {
    if i == 0 {
        Arm::Base2
    } else if big >> (4 * c) == 0 {
        Arm::Limit
    } else if j == 1 {
        match steps {
            1 => Arm::Digits1,
            2 => Arm::Digits2,
            3 => Arm::Digits3,
            4 => Arm::Digits4,
            _ => Arm::General,
        }
    } else {
        match steps {
            1 => Arm::Chunks1,
            2 => Arm::Chunks2,
            3 => Arm::Chunks3,
            _ => Arm::General,
        }
    }
}

/// Everything the `f32` fast path of one base reads: a header and one 24-byte record per index
/// class, so a lookup touches the header's cache line and its class's (plus the base's
/// digit-reversal table, for bases up to 83).
///
/// The digit count per class is coarser than an exact one (up to a few leading zero digits
/// more, which reverse to zeros), but the loop trip count then depends only on the dimension and
/// on the index's length in nibbles, so a renderer's indices — which mostly share a length — do
/// not mispredict the loop exit, and small indices take few steps.
#[derive(Clone, Copy)]
#[cfg_attr(test, derive(PartialEq))]
#[repr(C, align(64))]
struct FastBase {
    b: u32,
    big: u32,
    /// The chunk `c = b^j` of the digit-reversal table (`c = b`, `j = 1`, no table, for bases
    /// above [`CHUNK_LIMIT`]`^(1/2)`).
    chunk: u32,
    /// Offset of this base's table in [`CHUNK_REV`].
    table: u32,
    /// `c²` and `c³` (0 where `c³ ≥ 2³²`; only bases below 256, whose indices take up to four
    /// single digits, read it): the weights of the third and fourth steps' reversals.
    chunk2: u32,
    chunk3: u32,
    class: [ClassConsts; CLASSES],
}

/// The largest chunk `b^j` of a multi-digit table: bases with `b² ≤ CHUNK_LIMIT` (5 ..= 61) take
/// the largest `b^j` up to it.
const CHUNK_LIMIT: u64 = 4096;

/// The largest base with a table: 67 ..= 83 (`b² ≤ 6889`) take two-digit tables beyond
/// [`CHUNK_LIMIT`], which keeps every table within 2¹⁶ entries (124 KB in all, 128 KB with the
/// padding), so a lookup stays one masked read; it saves two of four steps for their indices of
/// 17 to 24 bits, a renderer's usual range.
const TABLE_BASE_LIMIT: u64 = 83;

/// Digits per table chunk for base `b`: the largest `j` with `b^j ≤ CHUNK_LIMIT`, 2 for bases
/// above 61 up to [`TABLE_BASE_LIMIT`], or 1 (no table).
const fn chunk_len(b: u64) -> u32 {
    // Base 3, every Halton point's second coordinate, takes 3⁸ = 6561: the room left below 2¹⁶.
    let limit = if b == 3 { 3u64.pow(8) } else { CHUNK_LIMIT };
    let mut j = 0;
    let mut p = 1u64;
    while p * b <= limit {
        p *= b;
        j += 1;
    }
    if j >= 2 {
        j
    } else if b <= TABLE_BASE_LIMIT {
        2
    } else {
        1
    }
}

const fn table_total() -> usize {
    let mut total = 0;
    let mut i = 1;
    while i < 1024 {
        let b = PRIME_TABLE[i] as u64;
        let j = chunk_len(b);
        if j > 1 {
            total += b.pow(j) as usize;
        }
        i += 1;
    }
    total
}

/// [`CHUNK_REV`]'s length: the tables' total rounded up to a power of two, so the fast path
/// indexes it through a mask instead of a bounds check (every index is in range anyway: a chunk
/// `e < b^j` at its base's offset; the padding is never read).
const CHUNK_REV_LEN: usize = table_total().next_power_of_two();
const _: () = assert!(CHUNK_REV_LEN == 1 << 16);

/// `CHUNK_REV[table + e] = Σ_i d_i·bⁱ` for a chunk `e < b^j` with digits `d_0 d_1 … d_(j−1)`
/// (most significant first): the chunk's digits reversed, as the fast path adds them to `R`.
const fn build_chunk_rev(out: &mut [u16; CHUNK_REV_LEN]) {
    let mut off = 0usize;
    let mut i = 1;
    while i < 1024 {
        let b = PRIME_TABLE[i] as u64;
        let j = chunk_len(b);
        if j > 1 {
            let c = b.pow(j);
            let mut e = 0u64;
            while e < c {
                // Least significant digit of e is d_(j−1), weight b^(j−1).
                let mut x = e;
                let mut rev = 0u64;
                let mut k = 0;
                while k < j {
                    rev = rev * b + x % b;
                    x /= b;
                    k += 1;
                }
                out[off + e as usize] = rev as u16;
                e += 1;
            }
            off += c as usize;
        }
        i += 1;
    }
}

baked_table! {
    static CHUNK_REV: [u16; CHUNK_REV_LEN] = [0; CHUNK_REV_LEN], build_chunk_rev,
        chunk_rev_at_first_use_equals_the_baked_table;
}

/// An all-zero [`FastBase`] (every entry of [`FAST`] is overwritten).
const NO_FAST_BASE: FastBase = FastBase {
    b: 0,
    big: 0,
    chunk: 0,
    table: 0,
    chunk2: 0,
    chunk3: 0,
    class: [ClassConsts {
        lead: 0,
        inv: 0.0,
        first: 0,
        n: 0,
        steps: 0,
        arm: 0,
    }; CLASSES],
};

const fn build_fast(out: &mut [FastBase; 1024]) {
    let bases = build_bases();
    let digits = build_digits();
    let mut table = 0u32;
    let mut i = 0;
    while i < 1024 {
        let info = bases[i];
        let j = if i == 0 { 1 } else { chunk_len(info.b) };
        let mut f = FastBase {
            b: info.b as u32,
            big: info.big as u32,
            chunk: info.b.pow(j) as u32,
            table,
            chunk2: info.b.pow(2 * j) as u32,
            chunk3: if info.b.pow(3 * j) >> 32 == 0 {
                info.b.pow(3 * j) as u32
            } else {
                0
            },
            class: [NO_CLASS; CLASSES],
        };
        if j > 1 {
            table += info.b.pow(j) as u32;
        }
        let mut c = 1;
        while c < CLASSES {
            let mut n = digits[i][4 * c];
            // Round the digit count up to whole chunks when b^n stays below b^k (extra leading
            // zero digits reverse to zeros): fewer steps, the same value.
            let whole = n.div_ceil(j as u8) * j as u8;
            if j > 1 && whole as u32 <= info.k {
                n = whole;
            }
            let steps = if j > 1 { n.div_ceil(j as u8) } else { n };
            let pad = steps as u32 * j - n as u32;
            f.class[c] = ClassConsts {
                lead: if steps >= 2 {
                    (u64::MAX / info.b.pow(n as u32) + 1) * info.b.pow(j - pad)
                } else {
                    0
                },
                first: info.b.pow(j - pad) as u16,
                inv: 1.0 / info.b.pow(n as u32 + pad) as f64,
                n,
                steps,
                arm: arm_of(i, j, info.big, c, steps) as u8,
            };
            c += 1;
        }
        out[i] = f;
        i += 1;
    }
}

baked_table! {
    static FAST: [FastBase; 1024] = [NO_FAST_BASE; 1024], build_fast,
        fast_at_first_use_equals_the_baked_table;
}

/// The smallest `big` of the bases past base 2 (`1627²`): an index below it takes every base's
/// fast path.
const MIN_BIG: u64 = {
    let bases = build_bases();
    let mut min = u64::MAX;
    let mut i = 1;
    while i < 1024 {
        if bases[i].big < min {
            min = bases[i].big;
        }
        i += 1;
    }
    min
};

/// Dimensions `1 .. TABLE_DIMS` are the bases with a digit-reversal table (up to
/// [`TABLE_BASE_LIMIT`]).
const TABLE_DIMS: usize = {
    let mut d = 1;
    while (PRIME_TABLE[d] as u64) <= TABLE_BASE_LIMIT {
        d += 1;
    }
    d
};

/// The class `⌈bit_len(a)/4⌉` of an index below 2³² (its length in nibbles), an index into
/// [`FastBase::class`].
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn index_class(a: u64) -> usize {
    ((bit_len(a) + 3) >> 2).min(CLASSES - 1)
}

/// `R'·inv` narrowed to `f32` ([`ClassConsts`]): the one rounding rule both the random-access
/// fast path and the incremental fill use, so they agree bit for bit. `R' < 2⁴⁴` is exact in
/// `f64`; the product is within 2⁻⁵² relative, far below `f32`'s rounding step, so the result
/// is within 1 ulp.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn narrow(rev: f64, inv: f64) -> f32 {
    ((rev * inv) as f32).min(ONE_MINUS_EPSILON)
}

// ---------------------------------------------------------------------------------------------
// Digit engine.

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
fn bit_len(x: u64) -> usize {
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
fn phi_fraction(d: usize, mut a: u64) -> (u128, u128) {
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
fn long_divide(num: u128, den: u128, mut frac: u128, inexact: bool) -> (u64, i32) {
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
fn fraction_f32(num: u128, den: u128, frac: u128, inexact: bool) -> f32 {
    let (m, e) = long_divide(num, den, frac, inexact);
    // `m as f32` rounds once; scaling by a power of two in f64 is exact, and so is the narrowing
    // (the value is 0 or far above f32's smallest normal).
    (((m as f32) as f64 * pow2(e)) as f32).min(ONE_MINUS_EPSILON)
}

/// `num / den` rounded to `f64` (correctly, when `inexact` is false), clamped below 1.
fn fraction_f64(num: u128, den: u128, frac: u128, inexact: bool) -> f64 {
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

// ---------------------------------------------------------------------------------------------
// Φ_b.

/// Φ₂(a) for `a < 2³²`: the 32-bit reversal, rounded once to `f32` (the scaling by 2⁻³² is
/// exact), clamped below 1. Simple enough for the compiler to vectorise over a run of indices.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn base2_u32(a: u32) -> f32 {
    let x = a.reverse_bits() as f32 * (1.0 / 4_294_967_296.0);
    // Not NaN, so a plain comparison (one `minps` when vectorised) is the clamp.
    if x < ONE_MINUS_EPSILON {
        x
    } else {
        ONE_MINUS_EPSILON
    }
}

/// Φ₂(a) for any `a`, correctly rounded to `f32`, clamped below 1: `f32` arithmetic only.
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn phi2(a: u64) -> f32 {
    if a >> 32 == 0 {
        // The usual case: a 32-bit reversal, exactly representable before one rounding.
        return base2_u32(a as u32);
    }
    // When the top bit is set, halve the reversal keeping the lost bit as a sticky bit (the
    // value then has 63 significant bits, so rounding is unchanged): the signed conversion is
    // one instruction.
    let r = a.reverse_bits();
    let top = r >> 63;
    let m = ((r >> top) | (r & top)) as i64;
    let scale = f32::from_bits((127 - 64 + top as u32) << 23);
    ((m as f32) * scale).min(ONE_MINUS_EPSILON)
}

/// What the fast path of base `PRIME_TABLE[d]` (`1 <= d < 1024`) does for an index of class
/// `c` (`1 ..= 8`, [`index_class`]), for paths that compute it without the tables: the digits
/// `N = n + pad` its reversal spans (`R' = Σ a_i b^(N−1−i)` over the index's digits `a_i`) and
/// the bits of its `inv = 1/b^N` as an `f64`. Equal to [`FAST`]'s constants (a test holds them
/// so); the value is `narrow(R', inv)`.
pub(crate) const fn fast_class(d: usize, c: usize) -> (u32, u64) {
    let b = PRIME_TABLE[d] as u64;
    let k = chunk_digits(b);
    let j = chunk_len(b);
    let mut x = (1u64 << (4 * c)) - 1;
    let mut n = 0u32;
    while x > 0 {
        x /= b;
        n += 1;
    }
    if n > k {
        n = k;
    }
    // The reversal spans whole chunks of `j` digits. `build_fast` rounds the digit count up to
    // them where that stays within `k` and pads the first chunk otherwise (it needs the split for
    // its `lead` and `first`), but either way the digits spanned, `n + pad`, are the count
    // rounded up to a multiple of `j` (with `j = 1`, the count itself), and only that sum and its
    // reciprocal are needed here.
    let spanned = n.div_ceil(j) * j;
    let inv = 1.0 / b.pow(spanned) as f64;
    (spanned, inv.to_bits())
}

/// [`fast_class`] read back from [`FAST`]'s constants, for the test that holds them equal.
#[cfg(test)]
pub(crate) fn fast_class_of_table(d: usize, c: usize) -> (u32, u64) {
    let f = &FAST[d];
    let class = &f.class[c];
    let (mut j, mut p) = (0u32, 1u32);
    while p < f.chunk {
        p *= f.b;
        j += 1;
    }
    let pad = u32::from(class.steps) * j - u32::from(class.n);
    (u32::from(class.n) + pad, class.inv.to_bits())
}

/// `b^k`, `k` the largest with `b^k < 2³²`, for base `PRIME_TABLE[d]`: indices below it take
/// the fast path.
pub(crate) const fn fast_limit(d: usize) -> u64 {
    let b = PRIME_TABLE[d] as u64;
    b.pow(chunk_digits(b))
}

/// Φ_b(a), the radical inverse of `a` in base `b = prime(dim)`, as an `f32` in `[0, 1)`.
///
/// The base-`b` digits of `a` mirrored about the radix point: `a = Σ a_j b^j` gives
/// `Φ_b(a) = Σ a_j b^−(j+1)`. Within 1 ulp of the exact value; base 2 (`dim % 1024 == 0`) is the
/// bit reversal of the 64-bit index, correctly rounded (for `a < 2³²` that is
/// `reverse_bits(a as u32) · 2⁻³²` rounded to `f32`). Total: `dim >= 1024` wraps modulo 1024; a
/// value that would round to 1 is clamped to [`ONE_MINUS_EPSILON`].
///
/// ```
/// use nyquist::radical::radical_inverse;
/// let vdc: Vec<f32> = (0..8).map(|i| radical_inverse(0, i)).collect();
/// assert_eq!(vdc, [0.0, 0.5, 0.25, 0.75, 0.125, 0.625, 0.375, 0.875]);
/// assert_eq!(radical_inverse(1, 5), 7.0 / 9.0); // 5 = 12₃ → 0.21₃
/// assert!(radical_inverse(1023, u64::MAX) < 1.0);
/// ```
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub fn radical_inverse(dim: u32, a: u64) -> f32 {
    let d = (dim % PRIME_COUNT) as usize;
    phi_class(&FAST[d], index_class(a), a, d)
}

/// With the `small-code` feature [`phi_steps`] hands every step count to one loop per kind of
/// base ([`phi_any_steps`]) instead of a straight-line copy per count: the same values from less
/// code.
const STEPS_AS_LOOPS: bool = cfg!(feature = "small-code");

/// A chunk `e` of base `f`'s digits, reversed: its entry in the digit-reversal table with
/// `TABLE`, else `e` itself (a single digit).
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn reversed_chunk<const TABLE: bool>(f: &FastBase, e: u64) -> u64 {
    if TABLE {
        u64::from(CHUNK_REV[(f.table as usize + e as usize) & (CHUNK_REV_LEN - 1)])
    } else {
        e
    }
}

/// The fast path of one base and class in exactly `N` steps (`1 ..= 4`, the class's `steps`):
/// the multiplies hand out the digits (single digits, or with `TABLE` chunks looked up in the
/// base's digit-reversal table), most significant first, and their reversals are summed with
/// their weights, `R' = r₀ + r₁·c + r₂·c² + r₃·c³` (`R' < 2⁴⁴`), exactly in integers: the
/// same `R'`, so the same bits, as any other grouping.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phi_steps<const N: usize, const TABLE: bool>(f: &FastBase, k: &ClassConsts, a: u64) -> f32 {
    if STEPS_AS_LOOPS {
        return phi_any_steps::<TABLE>(f, k, a);
    }
    let c = u64::from(f.chunk);
    let reverse = |e: u64| reversed_chunk::<TABLE>(f, e);
    if N == 1 {
        // One step: the chunk is the index itself.
        return narrow(reverse(a) as i64 as f64, k.inv);
    }
    let mut r = [0u64; N];
    let t = u128::from(a) * u128::from(k.lead);
    r[0] = reverse((t >> 64) as u64);
    let mut y = t as u64;
    for x in r.iter_mut().skip(1) {
        let t = u128::from(y) * u128::from(c);
        *x = reverse((t >> 64) as u64);
        y = t as u64;
    }
    // Digits4 arms are bases below 256 (b⁴ < 2³²), whose `chunk3` is b³.
    let weight = [1, c, u64::from(f.chunk2), u64::from(f.chunk3)];
    let mut rev = r[0];
    for i in 1..N {
        rev += r[i] * weight[i];
    }
    narrow(rev as i64 as f64, k.inv)
}

/// The fast path of one base and class in any number of steps (the class's `steps`, 0 for the
/// index 0): [`phi_steps`] as a loop.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phi_any_steps<const TABLE: bool>(f: &FastBase, k: &ClassConsts, a: u64) -> f32 {
    let c = u64::from(f.chunk);
    let reverse = |e: u64| reversed_chunk::<TABLE>(f, e);
    let rev = match k.steps {
        0 => 0,
        1 => reverse(a),
        steps => {
            let t = u128::from(a) * u128::from(k.lead);
            let (mut rev, mut y, mut weight) = (reverse((t >> 64) as u64), t as u64, c);
            for _ in 1..steps {
                let t = u128::from(y) * u128::from(c);
                rev += reverse((t >> 64) as u64) * weight;
                weight = weight.wrapping_mul(c);
                y = t as u64;
            }
            rev
        }
    };
    narrow(rev as i64 as f64, k.inv)
}

/// [`radical_inverse`], always inlined: with `dim` a constant the base's table reads fold away
/// (a sampler's fixed camera dimensions).
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(crate) fn radical_inverse_inlined(dim: u32, a: u64) -> f32 {
    let d = (dim % PRIME_COUNT) as usize;
    if d == 0 {
        return phi2(a);
    }
    let fast = &FAST[d];
    if a < u64::from(fast.big) {
        return phi_fast(fast, a);
    }
    let (num, den) = phi_fraction(d, a);
    fraction_f32(num, den, 0, false)
}

/// Φ_b(a) for each index of `indices`, written to the matching entry of `out`: bit for bit what
/// [`radical_inverse`] returns for each, for a batch of arbitrary (not consecutive) indices in
/// one dimension, as a wavefront renderer asks for them. The per-base constants are loaded once;
/// base 2 over indices below 2³² runs as a vectorised loop.
///
/// `out` may be longer than `indices`; its entries past `indices.len()` are left untouched.
/// `dim` wraps modulo 1024.
///
/// # Errors
/// [`Error::BufferTooShort`] if `out` is shorter than `indices`.
///
/// ```
/// use nyquist::radical::{radical_inverse, radical_inverse_at};
/// let indices = [7u64, 123_456, 3, 1 << 40];
/// let mut out = [0.0f32; 4];
/// radical_inverse_at(5, &indices, &mut out).unwrap();
/// assert!((0..4).all(|i| out[i] == radical_inverse(5, indices[i])));
/// assert!(radical_inverse_at(5, &indices, &mut [0.0; 3]).is_err());
/// ```
pub fn radical_inverse_at(dim: u32, indices: &[u64], out: &mut [f32]) -> Result<(), Error> {
    let Some(out) = out.get_mut(..indices.len()) else {
        return Err(Error::BufferTooShort {
            needed: indices.len(),
            actual: out.len(),
        });
    };
    let d = (dim % PRIME_COUNT) as usize;
    if d == 0 {
        // Runs of 32-bit indices (checked a block at a time, so both loops stay branch-free
        // and vectorise) take the 32-bit reversal; a block with a wider index goes value by
        // value.
        const BLOCK: usize = 64;
        for (xs, idx) in out.chunks_mut(BLOCK).zip(indices.chunks(BLOCK)) {
            // Narrowed first (with the high words ORed together on the way), so the reversal
            // runs four 32-bit lanes at a time.
            let mut low = [0u32; BLOCK];
            let mut high = 0u64;
            for (l, &a) in low.iter_mut().zip(idx) {
                *l = a as u32;
                high |= a;
            }
            if high >> 32 == 0 {
                for (x, &l) in xs.iter_mut().zip(&low) {
                    *x = base2_u32(l);
                }
            } else {
                for (x, &a) in xs.iter_mut().zip(idx) {
                    *x = phi2(a);
                }
            }
        }
        return Ok(());
    }
    let fast = &FAST[d];
    let big = u64::from(fast.big);
    for (x, &a) in out.iter_mut().zip(indices) {
        *x = if a < big {
            phi_fast(fast, a)
        } else {
            let (num, den) = phi_fraction(d, a);
            fraction_f32(num, den, 0, false)
        };
    }
    Ok(())
}

/// Φ_{prime(dim + i)}(a) written to `out[i]` for every `i`: one index across consecutive
/// dimensions — a Halton point, or a global sampler's run of dimensions for one sample (pbrt-v2's
/// Halton arrays). Bit for bit what [`radical_inverse`] returns for each; the index's length
/// class is found once for all dimensions instead of once per value. Dimensions wrap modulo
/// 1024 (past dimension 1023 comes dimension 0). Total: any `out` length, empty included.
///
/// ```
/// use nyquist::radical::{radical_inverse, radical_inverse_dims};
/// let mut point = [0.0f32; 6];
/// radical_inverse_dims(1021, 77, &mut point);
/// let dims = [1021, 1022, 1023, 0, 1, 2];
/// assert!((0..6).all(|i| point[i] == radical_inverse(dims[i], 77)));
/// ```
#[inline]
pub fn radical_inverse_dims(dim: u32, a: u64, out: &mut [f32]) {
    let class = index_class(a);
    let first = (dim % PRIME_COUNT) as usize;
    // The usual run: clear of base 2 and of the wrap, so no per-dimension checks but the
    // index's size.
    if first != 0
        && let Some(bases) = FAST.get(first..first + out.len())
    {
        if a < MIN_BIG && first + out.len() <= TABLE_DIMS {
            // The class a constant in each arm, so its record is a fixed offset in each base's.
            match class {
                0 => table_lane::<0>(bases, a, out),
                1 => table_lane::<1>(bases, a, out),
                2 => table_lane::<2>(bases, a, out),
                3 => table_lane::<3>(bases, a, out),
                4 => table_lane::<4>(bases, a, out),
                5 => table_lane::<5>(bases, a, out),
                6 => table_lane::<6>(bases, a, out),
                7 => table_lane::<7>(bases, a, out),
                _ => table_lane::<8>(bases, a, out),
            }
        } else {
            // Each base's class record names its arm; only the arms of classes that reach a
            // base's limit compare the index with it.
            for ((x, fast), d) in out.iter_mut().zip(bases).zip(first..) {
                *x = phi_class(fast, class, a, d);
            }
        }
        return;
    }
    let mut d = first;
    for x in out {
        *x = phi_class(&FAST[d], class, a, d);
        d += 1;
        if d == PRIME_COUNT as usize {
            d = 0;
        }
    }
}

/// `out[i] = Φ(a)` in `bases[i]`, every one with a table and `a` below its `big`, `a` of class
/// `C`.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn table_lane<const C: usize>(bases: &[FastBase], a: u64, out: &mut [f32]) {
    for (x, fast) in out.iter_mut().zip(bases) {
        *x = phi_chunks(fast, &fast.class[C], a);
    }
}

/// Φ_b(a) for `a < b^k` (so `a < 2³²`): the reversed digits `R' = Σ_s T[e_s]·c^s` (`e_s` the
/// index's chunks, most significant first, `T` the digit-reversal table, or single digits)
/// summed exactly, then [`narrow`]ed by the class's `inv` (see [`ClassConsts`]).
///
/// One 64×64→128 multiply per chunk hands it out (see the module docs). The step count comes
/// from the index's length in nibbles ([`FastBase`]), so its branch is predictable. Tests the
/// base's kind first, then the steps: for a constant dimension (a sampler's camera dimensions)
/// or one base over a batch the first test folds or is hoisted, and the code stays one kind's.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phi_fast(f: &FastBase, a: u64) -> f32 {
    let k = &f.class[index_class(a)];
    if f.chunk != f.b {
        return phi_chunks(f, k, a);
    }
    match k.steps {
        2 => phi_steps::<2, false>(f, k, a),
        3 => phi_steps::<3, false>(f, k, a),
        4 => phi_steps::<4, false>(f, k, a),
        _ => phi_any_steps::<false>(f, k, a),
    }
}

/// [`phi_fast`] for a base with a digit-reversal table.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phi_chunks(f: &FastBase, k: &ClassConsts, a: u64) -> f32 {
    match k.steps {
        2 => phi_steps::<2, true>(f, k, a),
        3 => phi_steps::<3, true>(f, k, a),
        _ => phi_any_steps::<true>(f, k, a),
    }
}

/// Φ of base `f` (dimension `d`) at `a`, of [`index_class`] `class`, by the class record's arm
/// ([`Arm`]): one jump, whose target follows the dimension when a caller asks one index for a
/// run of dimensions, so it predicts well; each arm's steps run straight-line.
#[cfg_attr(not(feature = "small-code"), inline(always))]
fn phi_class(f: &FastBase, class: usize, a: u64, d: usize) -> f32 {
    let k = &f.class[class];
    match k.arm {
        x if x == Arm::Base2 as u8 => phi2(a),
        x if x == Arm::Digits1 as u8 => phi_steps::<1, false>(f, k, a),
        x if x == Arm::Digits2 as u8 => phi_steps::<2, false>(f, k, a),
        x if x == Arm::Digits3 as u8 => phi_steps::<3, false>(f, k, a),
        x if x == Arm::Digits4 as u8 => phi_steps::<4, false>(f, k, a),
        x if x == Arm::Chunks1 as u8 => phi_steps::<1, true>(f, k, a),
        x if x == Arm::Chunks2 as u8 => phi_steps::<2, true>(f, k, a),
        x if x == Arm::Chunks3 as u8 => phi_steps::<3, true>(f, k, a),
        x if x == Arm::Limit as u8 && a >= u64::from(f.big) => {
            let (num, den) = phi_fraction(d, a);
            fraction_f32(num, den, 0, false)
        }
        _ if f.chunk == f.b => phi_any_steps::<false>(f, k, a),
        _ => phi_any_steps::<true>(f, k, a),
    }
}

/// Writes Φ_b(first), Φ_b(first + 1), … (`b = prime(dim)`) into `out[offset], out[offset + stride], …`, bit for
/// bit what [`radical_inverse`] returns for each index, in amortised O(1) per value.
///
/// Inside one index class the digits of the index are kept and incremented with carries, and the
/// reversed integer `R` is updated by the changed digits' weights; a new class (or an index past
/// `b^k`) starts over from the random-access path. Indices wrap at `u64::MAX`.
pub(crate) fn fill_consecutive(
    dim: u32,
    first: u64,
    out: &mut [f32],
    offset: usize,
    stride: usize,
) {
    let d = (dim % PRIME_COUNT) as usize;
    let mut slots = (offset..out.len()).step_by(stride.max(1));
    let mut a = first;
    if d == 0 {
        if stride <= 1
            && first
                .checked_add(out.len() as u64)
                .is_some_and(|end| end < 1 << 32)
        {
            // Contiguous and below 2³²: a plain map the compiler vectorises.
            for (x, a) in out[offset..].iter_mut().zip(first as u32..) {
                *x = base2_u32(a);
            }
            return;
        }
        for k in slots {
            out[k] = phi2(a);
            a = a.wrapping_add(1);
        }
        return;
    }
    let f = &FAST[d];
    let b = u64::from(f.b);
    let mut next = slots.next();
    while let Some(mut k) = next {
        if a >= u64::from(f.big) {
            out[k] = radical_inverse_inlined(dim, a);
            a = a.wrapping_add(1);
            next = slots.next();
            continue;
        }
        let c = index_class(a);
        let class = &f.class[c];
        let n = usize::from(class.n).min(32);
        let end = (1u64 << (4 * c)).min(u64::from(f.big));
        // Digits of a, least significant first, and their weights b^(n−1−j) in R.
        let mut digits = [0u64; 32];
        let mut weights = [0u64; 32];
        let mut rest = a;
        let mut rev = 0u64;
        let mut w = 1u64;
        for j in (0..n).rev() {
            weights[j] = w;
            w *= b;
        }
        for j in 0..n {
            digits[j] = rest % b;
            rest /= b;
            rev += digits[j] * weights[j];
        }
        // R' = R·b^pad, and b^pad = c / b^(j − pad) = chunk / first (1 without a table, where
        // first = chunk = b, and for class 0, whose first is 0).
        let scale = f.chunk.checked_div(u32::from(class.first)).unwrap_or(1);
        let (scale, inv) = (f64::from(scale), class.inv);
        loop {
            // R·b^pad is exact (below b^(n + pad) < 2⁴⁴): the fast path's R', bit for bit.
            out[k] = narrow(rev as i64 as f64 * scale, inv);
            a += 1;
            // Increment the digits, carrying; R follows each changed digit.
            for j in 0..n {
                if digits[j] + 1 < b {
                    digits[j] += 1;
                    rev += weights[j];
                    break;
                }
                rev -= (b - 1) * weights[j];
                digits[j] = 0;
            }
            next = slots.next();
            match next {
                Some(slot) if a < end => k = slot,
                _ => break,
            }
        }
    }
}

/// Φ_b(a) as an `f64` in `[0, 1)`, correctly rounded (so within ½ ulp).
///
/// Same digits and wrapping rules as [`radical_inverse`].
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

/// Φ_b(first), Φ_b(first + 1), … (`b = prime(dim)`) written into `out`: bit for bit what
/// [`radical_inverse`] returns for each index, in amortised O(1) per value (the digits of the
/// index are incremented with carries instead of being recomputed).
///
/// Total: `dim` wraps modulo 1024 and indices wrap at `u64::MAX`.
///
/// ```
/// use nyquist::radical::{fill_radical_inverse, radical_inverse};
/// let mut out = [0.0f32; 100];
/// fill_radical_inverse(3, 9_999_950, &mut out);
/// assert!((0..100).all(|i| out[i] == radical_inverse(3, 9_999_950 + i as u64)));
/// ```
pub fn fill_radical_inverse(dim: u32, first: u64, out: &mut [f32]) {
    fill_consecutive(dim, first, out, 0, 1);
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

// ---------------------------------------------------------------------------------------------
// Folded (Zaremba) form Ψ_b.

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
fn fold_tail(d: usize, b: u64, r: u64) -> u128 {
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

// ---------------------------------------------------------------------------------------------
// Digit-permutation scrambling.

/// The digit permutation π of base `b` under `seed`: a [`hash::Permutation`] keyed by both.
#[inline]
fn digit_permutation(seed: u64, b: u64) -> hash::Permutation {
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
fn below_f32(x: f32) -> f32 {
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

#[cfg(test)]
mod tests;
