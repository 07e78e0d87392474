//! Per-base constants of the radical inverse, evaluated at compile time (or, with the
//! `lazy-tables` feature, at first use): chunk moduli and magic reciprocals for the exact digit
//! engine, and the `f32` fast path's per-class records, arms and digit-reversal tables.

use super::primes::PRIME_TABLE;
use crate::lazy_table::baked_table;

/// Per-base constants: the base, the digits per chunk `k` (the largest with `b^k < 2³²`), the
/// chunk modulus `b^k`, and the offset of this base's rows in the flat tables below.
#[derive(Clone, Copy)]
#[cfg_attr(test, derive(PartialEq))]
pub(super) struct BaseInfo {
    pub(super) b: u64,
    /// `b²`.
    pub(super) b2: u64,
    /// `⌈2⁴⁰/b⌉`: `⌊D·split/2⁴⁰⌋ = ⌊D/b⌋` for every `D < b²` (the error term is below `b³ < 2⁴⁰`).
    pub(super) split: u64,
    pub(super) k: u32,
    pub(super) big: u64,
    pub(super) off: u32,
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
pub(super) const ROWS: usize = total_rows();

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
    pub(super) static BASES: [BaseInfo; 1024] = [NO_BASE; 1024], fill_bases,
        bases_at_first_use_equal_the_baked_table;
}

/// `bⁿ` and `⌈2⁶⁴/bⁿ⌉` (0 for `n = 0`, unused), per base and `n`.
#[derive(Clone, Copy)]
#[cfg_attr(test, derive(PartialEq))]
pub(super) struct Row {
    pub(super) pow: u64,
    pub(super) magic: u64,
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
    pub(super) static ROW: [Row; ROWS] = [Row { pow: 0, magic: 0 }; ROWS], fill_rows,
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
    pub(super) static DIGITS: [[u8; 33]; 1024] = [[0; 33]; 1024], fill_digits,
        digits_at_first_use_equal_the_baked_table;
}

/// Index classes of the fast path: class `c = ⌈bit_len(a)/4⌉` (`0 ..= 8`) for `a < 2³²`.
pub(super) const CLASSES: usize = 9;

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
pub(super) struct ClassConsts {
    /// `⌈2⁶⁴/bⁿ⌉·first` (0 with fewer than two steps).
    pub(super) lead: u64,
    pub(super) inv: f64,
    /// `b^(j − pad) ≤ max(c, b)`.
    pub(super) first: u16,
    pub(super) n: u8,
    /// `m`: the steps, table chunks or single digits.
    pub(super) steps: u8,
    /// The arm of [`radical_inverse`](super::radical_inverse)'s dispatch that computes this
    /// base's values for this class ([`Arm`]).
    pub(super) arm: u8,
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

/// How [`radical_inverse`](super::radical_inverse) computes the values of one base and one index
/// class: one byte per class record, so a value costs one predictable indirect jump instead of a
/// test of the base, of the fast path's limit and of the step count (their pattern follows the
/// dimensions, which a caller walks in the same order for every index).
#[derive(Clone, Copy)]
#[repr(u8)]
pub(super) enum Arm {
    /// Base 2: the bit reversal ([`phi2`](super::fast::phi2)).
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
    /// Any other step count: [`phi_any_steps`](super::fast::phi_any_steps)' loops.
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
pub(super) struct FastBase {
    pub(super) b: u32,
    pub(super) big: u32,
    /// The chunk `c = b^j` of the digit-reversal table (`c = b`, `j = 1`, no table, for bases
    /// above [`CHUNK_LIMIT`]`^(1/2)`).
    pub(super) chunk: u32,
    /// Offset of this base's table in [`CHUNK_REV`].
    pub(super) table: u32,
    /// `c²` and `c³` (0 where `c³ ≥ 2³²`; only bases below 256, whose indices take up to four
    /// single digits, read it): the weights of the third and fourth steps' reversals.
    pub(super) chunk2: u32,
    pub(super) chunk3: u32,
    pub(super) class: [ClassConsts; CLASSES],
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
pub(super) const CHUNK_REV_LEN: usize = table_total().next_power_of_two();
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
    pub(super) static CHUNK_REV: [u16; CHUNK_REV_LEN] = [0; CHUNK_REV_LEN], build_chunk_rev,
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
    pub(super) static FAST: [FastBase; 1024] = [NO_FAST_BASE; 1024], build_fast,
        fast_at_first_use_equals_the_baked_table;
}

/// The smallest `big` of the bases past base 2 (`1627²`): an index below it takes every base's
/// fast path.
pub(super) const MIN_BIG: u64 = {
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
pub(super) const TABLE_DIMS: usize = {
    let mut d = 1;
    while (PRIME_TABLE[d] as u64) <= TABLE_BASE_LIMIT {
        d += 1;
    }
    d
};

/// What the fast path of base `PRIME_TABLE[d]` (`1 <= d < 1024`) does for an index of class
/// `c` (`1 ..= 8`, [`index_class`](super::fast::index_class)), for paths that compute it without
/// the tables: the digits `N = n + pad` its reversal spans (`R' = Σ a_i b^(N−1−i)` over the
/// index's digits `a_i`) and the bits of its `inv = 1/b^N` as an `f64`. Equal to [`FAST`]'s
/// constants (a test holds them so); the value is `narrow(R', inv)`.
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
