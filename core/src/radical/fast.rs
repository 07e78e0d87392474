//! The `f32` radical inverse: base 2 by bit reversal, other bases by one record per index class
//! ([`FastBase`]) with straight-line digit steps, for one value, a batch of indices, a run of
//! dimensions, and consecutive indices (digits incremented with carries).

use super::PRIME_COUNT;
use super::exact::{bit_len, fraction_f32, phi_fraction};
use super::tables::{
    Arm, CHUNK_REV, CHUNK_REV_LEN, CLASSES, ClassConsts, FAST, FastBase, MIN_BIG, TABLE_DIMS,
};
use crate::Error;
use crate::math::ONE_MINUS_EPSILON;

/// The class `⌈bit_len(a)/4⌉` of an index below 2³² (its length in nibbles), an index into
/// [`FastBase::class`].
#[cfg_attr(not(feature = "small-code"), inline(always))]
pub(super) fn index_class(a: u64) -> usize {
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
pub(super) fn phi_any_steps<const TABLE: bool>(f: &FastBase, k: &ClassConsts, a: u64) -> f32 {
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
pub(super) fn phi_class(f: &FastBase, class: usize, a: u64, d: usize) -> f32 {
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

/// Writes Φ_b(first), Φ_b(first + 1), … (`b = prime(dim)`) into `out[offset]`,
/// `out[offset + stride]`, …: bit for bit what [`radical_inverse`] returns for each index, in
/// amortised O(1) per value.
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
