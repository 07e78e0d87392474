//! Radical inverses Φ_b(a), folded Ψ_b(a) and digit-scrambled, for the first 1024 primes.
//!
//! `dim` is the base index: base `b = prime(dim)`, `dim < 1024` (unlike the core, which wraps,
//! the C API reports `dim >= 1024` as `NYQ_ERR_OUT_OF_RANGE`).

use nyquist::radical::{self, PRIME_COUNT};

use crate::NyqStatus;
use crate::ffi::{need, put, run, slice_mut};

fn base(dim: u32) -> Result<u32, NyqStatus> {
    if dim < PRIME_COUNT {
        Ok(dim)
    } else {
        Err(NyqStatus::NYQ_ERR_OUT_OF_RANGE)
    }
}

/// Writes the `dim`-th prime (`dim = 0` → 2) to `*out`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `uint32_t`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_prime};
/// let mut p = 0u32;
/// // SAFETY: `p` is a valid u32.
/// assert_eq!(unsafe { nyq_prime(3, &mut p) }, NyqStatus::NYQ_OK);
/// assert_eq!(p, 7);
/// assert_eq!(unsafe { nyq_prime(1024, &mut p) }, NyqStatus::NYQ_ERR_OUT_OF_RANGE);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_prime(dim: u32, out: *mut u32) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::prime(base(dim)?);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// Φ_b(a) as a `float` in `[0, 1)`, `b = prime(dim)`: the core's
/// [`radical_inverse`](nyquist::radical::radical_inverse).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_radical_inverse};
/// let mut x = 0.0f32;
/// // SAFETY: `x` is a valid f32.
/// assert_eq!(unsafe { nyq_radical_inverse(0, 3, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, 0.75);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_radical_inverse(dim: u32, a: u64, out: *mut f32) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::radical_inverse(base(dim)?, a);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// Φ_b(a) as a `double` in `[0, 1)`: the core's
/// [`radical_inverse_f64`](nyquist::radical::radical_inverse_f64).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `double`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_radical_inverse_f64};
/// let mut x = 0.0f64;
/// // SAFETY: `x` is a valid f64.
/// assert_eq!(unsafe { nyq_radical_inverse_f64(1, 5, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, 7.0 / 9.0);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_radical_inverse_f64(dim: u32, a: u64, out: *mut f64) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::radical_inverse_f64(base(dim)?, a);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// The folded (Zaremba) radical inverse Ψ_b(a) as a `float` in `[0, 1)`: the core's
/// [`folded_radical_inverse`](nyquist::radical::folded_radical_inverse).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_folded_radical_inverse};
/// let mut x = 0.0f32;
/// // SAFETY: `x` is a valid f32.
/// assert_eq!(unsafe { nyq_folded_radical_inverse(0, 0, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, nyquist::radical::folded_radical_inverse(0, 0)); // Ψ₂(0) = 1/3
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_folded_radical_inverse(dim: u32, a: u64, out: *mut f32) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::folded_radical_inverse(base(dim)?, a);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// Ψ_b(a) as a `double` in `[0, 1)`: the core's
/// [`folded_radical_inverse_f64`](nyquist::radical::folded_radical_inverse_f64).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `double`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_folded_radical_inverse_f64};
/// let mut x = 0.0f64;
/// // SAFETY: `x` is a valid f64.
/// assert_eq!(unsafe { nyq_folded_radical_inverse_f64(2, 9, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, nyquist::radical::folded_radical_inverse_f64(2, 9));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_folded_radical_inverse_f64(
    dim: u32,
    a: u64,
    out: *mut f64,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::folded_radical_inverse_f64(base(dim)?, a);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// The digit-permutation scrambled radical inverse as a `float` in `[0, 1)`, the
/// permutations keyed by `seed` (every seed is valid): the core's
/// [`scrambled_radical_inverse`](nyquist::radical::scrambled_radical_inverse).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `float`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_scrambled_radical_inverse};
/// let mut x = 0.0f32;
/// // SAFETY: `x` is a valid f32.
/// assert_eq!(unsafe { nyq_scrambled_radical_inverse(5, 123, 7, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, nyquist::radical::scrambled_radical_inverse(5, 123, 7));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_scrambled_radical_inverse(
    dim: u32,
    a: u64,
    seed: u64,
    out: *mut f32,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::scrambled_radical_inverse(base(dim)?, a, seed);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// The scrambled radical inverse as a `double` in `[0, 1)`: the core's
/// [`scrambled_radical_inverse_f64`](nyquist::radical::scrambled_radical_inverse_f64).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `double`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_scrambled_radical_inverse_f64};
/// let mut x = 0.0f64;
/// // SAFETY: `x` is a valid f64.
/// assert_eq!(unsafe { nyq_scrambled_radical_inverse_f64(5, 123, 7, &mut x) }, NyqStatus::NYQ_OK);
/// assert_eq!(x, nyquist::radical::scrambled_radical_inverse_f64(5, 123, 7));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_scrambled_radical_inverse_f64(
    dim: u32,
    a: u64,
    seed: u64,
    out: *mut f64,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::scrambled_radical_inverse_f64(base(dim)?, a, seed);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}

/// Fills `out[0..len]` with Φ_b(first), Φ_b(first + 1), … (`b = prime(dim)`; indices wrap past
/// `u64::MAX`): the core's [`fill_radical_inverse`](nyquist::radical::fill_radical_inverse).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `len == 0`; `NYQ_ERR_OUT_OF_RANGE`
/// if `dim >= 1024`; `NYQ_ERR_BUFFER` if `out` is misaligned.
///
/// # Safety
/// `out` is null or valid for writing `len` floats.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_fill_radical_inverse};
/// let mut xs = [0.0f32; 4];
/// // SAFETY: `xs` holds 4 floats.
/// assert_eq!(unsafe { nyq_fill_radical_inverse(0, 4, xs.as_mut_ptr(), 4) }, NyqStatus::NYQ_OK);
/// assert_eq!(xs, [0.125, 0.625, 0.375, 0.875]);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_fill_radical_inverse(
    dim: u32,
    first: u64,
    out: *mut f32,
    len: usize,
) -> NyqStatus {
    run(|| {
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        radical::fill_radical_inverse(base(dim)?, first, out);
        Ok(())
    })
}

/// The index whose first `n_digits` base-`b` digits, reversed, are the low `n_digits` digits of
/// `inverse` (`b = prime(dim)`; wraps modulo 2⁶⁴ past 64 bits): the core's
/// [`inverse_radical_inverse`](nyquist::radical::inverse_radical_inverse).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_OUT_OF_RANGE` if `dim >= 1024`.
///
/// # Safety
/// `out` is null or valid for writing one `uint64_t`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_inverse_radical_inverse};
/// let mut a = 0u64;
/// // SAFETY: `a` is a valid u64.
/// assert_eq!(unsafe { nyq_inverse_radical_inverse(0, 0b011, 3, &mut a) }, NyqStatus::NYQ_OK);
/// assert_eq!(a, nyquist::radical::inverse_radical_inverse(0, 0b011, 3));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_inverse_radical_inverse(
    dim: u32,
    inverse: u64,
    n_digits: u32,
    out: *mut u64,
) -> NyqStatus {
    run(|| {
        need(out)?;
        let v = radical::inverse_radical_inverse(base(dim)?, inverse, n_digits);
        // SAFETY: `out` is null or writable (caller).
        unsafe { put(out, v) }
    })
}
