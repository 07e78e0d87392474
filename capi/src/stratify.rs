//! Stratified 1D/2D samples, Latin hypercube points and shuffles into caller buffers.
//!
//! Each call draws from the core's default generator ([`nyquist::rng::default_rng`], PCG32)
//! seeded with `seed`, so the same arguments give the same bits as the Rust functions called
//! with `&mut default_rng(seed)`.

use nyquist::rng::default_rng;
use nyquist::stratify::{self, Jitter};

use crate::NyqStatus;
use crate::ffi::{need, put, run, slice_mut};

fn jitter(jittered: bool) -> Jitter {
    if jittered {
        Jitter::Jittered
    } else {
        Jitter::Centered
    }
}

/// Fills `out[0..len]` with `len` stratified samples of `[0, 1)`, sample `k` in stratum
/// `[k/len, (k+1)/len)`, jittered (`jittered` true) or at the stratum centres: the core's
/// [`stratified_1d`](nyquist::stratify::stratified_1d) with `default_rng(seed)`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `len == 0`; `NYQ_ERR_BUFFER` if `out`
/// is misaligned; `NYQ_ERR_TOO_MANY` if `len > UINT32_MAX`.
///
/// # Safety
/// `out` is null or valid for writing `len` floats.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_stratified_1d};
/// let mut xs = [0.0f32; 4];
/// // SAFETY: `xs` holds 4 floats.
/// assert_eq!(unsafe { nyq_stratified_1d(xs.as_mut_ptr(), 4, false, 0) }, NyqStatus::NYQ_OK);
/// assert_eq!(xs, [0.125, 0.375, 0.625, 0.875]);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_stratified_1d(
    out: *mut f32,
    len: usize,
    jittered: bool,
    seed: u64,
) -> NyqStatus {
    run(|| {
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        Ok(stratify::stratified_1d(
            out,
            jitter(jittered),
            &mut default_rng(seed),
        )?)
    })
}

/// Fills `out[0..len]` with one point per cell of an `nx × ny` grid over `[0, 1)²`,
/// `[x0, y0, x1, y1, …]`, cell `(i, j)` at point `j·nx + i`; `len` must be exactly `2·nx·ny`:
/// the core's [`stratified_2d`](nyquist::stratify::stratified_2d) with `default_rng(seed)`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `len`, `nx` or `ny` is 0;
/// `NYQ_ERR_BUFFER` if `len != 2·nx·ny` or `out` is misaligned; `NYQ_ERR_TOO_MANY` if `2·nx·ny`
/// overflows.
///
/// # Safety
/// `out` is null or valid for writing `len` floats.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_stratified_2d};
/// let mut pts = [0.0f32; 8];
/// // SAFETY: `pts` holds 8 floats.
/// assert_eq!(unsafe { nyq_stratified_2d(pts.as_mut_ptr(), 8, 2, 2, false, 0) }, NyqStatus::NYQ_OK);
/// assert_eq!(pts, [0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75]);
/// assert_eq!(unsafe { nyq_stratified_2d(pts.as_mut_ptr(), 8, 3, 2, true, 0) }, NyqStatus::NYQ_ERR_BUFFER);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_stratified_2d(
    out: *mut f32,
    len: usize,
    nx: u32,
    ny: u32,
    jittered: bool,
    seed: u64,
) -> NyqStatus {
    run(|| {
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        Ok(stratify::stratified_2d(
            out,
            nx,
            ny,
            jitter(jittered),
            &mut default_rng(seed),
        )?)
    })
}

/// Fills `out[0..len]` with `len / dims` Latin hypercube points in `[0, 1)^dims`, point-major,
/// and writes their number to `*written`: the core's
/// [`latin_hypercube`](nyquist::stratify::latin_hypercube) with `default_rng(seed)`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` or `written` is null; `NYQ_ERR_ZERO_SIZE` if `len` or `dims` is 0;
/// `NYQ_ERR_BUFFER` if `len` is not a multiple of `dims` or `out` is misaligned;
/// `NYQ_ERR_TOO_MANY` for more than `UINT32_MAX` points.
///
/// # Safety
/// `out` is null or valid for writing `len` floats; `written` is null or valid for writing one
/// `uint32_t`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_latin_hypercube};
/// let (mut pts, mut n) = ([0.0f32; 24], 0u32);
/// // SAFETY: `pts` holds 24 floats, `n` is a valid u32.
/// assert_eq!(unsafe { nyq_latin_hypercube(pts.as_mut_ptr(), 24, 3, 2, &mut n) }, NyqStatus::NYQ_OK);
/// assert_eq!(n, 8);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_latin_hypercube(
    out: *mut f32,
    len: usize,
    dims: u32,
    seed: u64,
    written: *mut u32,
) -> NyqStatus {
    run(|| {
        need(written)?;
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        if dims == 0 {
            return Err(NyqStatus::NYQ_ERR_ZERO_SIZE);
        }
        let n = stratify::latin_hypercube(out, dims, &mut default_rng(seed))?;
        // SAFETY: `written` is writable (caller; null checked above).
        unsafe { put(written, n) }
    })
}

/// Shuffles the first `count` blocks of `dims` floats of `buf[0..len]` (`len` must be exactly
/// `count·dims`) into a uniformly random order, keeping each block together: the core's
/// [`shuffle`](nyquist::stratify::shuffle) with `default_rng(seed)`.
///
/// # Errors
/// `NYQ_ERR_NULL` if `buf` is null; `NYQ_ERR_ZERO_SIZE` if `len` or `dims` is 0;
/// `NYQ_ERR_BUFFER` if `len` is not a multiple of `dims`, shorter than `count·dims`, or `buf`
/// is misaligned; `NYQ_ERR_OUT_OF_RANGE` if `len` is longer than `count·dims`;
/// `NYQ_ERR_TOO_MANY` if `count·dims` overflows.
///
/// # Safety
/// `buf` is null or valid for reading and writing `len` floats.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_shuffle};
/// let mut xs = [0.0f32, 1.0, 2.0, 3.0, 4.0, 5.0];
/// // SAFETY: `xs` holds 6 floats.
/// assert_eq!(unsafe { nyq_shuffle(xs.as_mut_ptr(), 6, 3, 2, 9) }, NyqStatus::NYQ_OK);
/// let mut blocks: Vec<[u32; 2]> = xs.chunks(2).map(|b| [b[0] as u32, b[1] as u32]).collect();
/// blocks.sort();
/// assert_eq!(blocks, [[0, 1], [2, 3], [4, 5]]);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_shuffle(
    buf: *mut f32,
    len: usize,
    count: usize,
    dims: usize,
    seed: u64,
) -> NyqStatus {
    run(|| {
        // SAFETY: `buf` is null or readable and writable for `len` floats (caller).
        let buf = unsafe { slice_mut(buf, len)? };
        Ok(stratify::shuffle(buf, count, dims, &mut default_rng(seed))?)
    })
}
