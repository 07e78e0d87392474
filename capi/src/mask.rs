//! Blue-noise threshold masks (void-and-cluster) and Poisson-disk sets into caller buffers.

use alloc::vec;

use nyquist::bluenoise::VoidAndCluster;

use crate::NyqStatus;
use crate::ffi::{run, slice_mut};

/// Writes a `width × height` void-and-cluster threshold mask of `len / (width·height)` channels
/// to `out[0..len]`, channel-major (channel `c` at `out[c·W·H ..]`, each row-major), every
/// channel a permutation of the ranks `0 … W·H − 1`: the core's
/// [`VoidAndCluster::generate_channels`] (tileable, channels decorrelated). A rank `r` is the
/// threshold value `(r + ½)/(W·H)`. The working memory (about 16 bytes per pixel) is allocated
/// and freed inside the call.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `width` or `height` is 0;
/// `NYQ_ERR_TOO_MANY` above 2²⁰ pixels; `NYQ_ERR_BUFFER` unless `len` is a positive multiple of
/// `width·height` (or if `out` is misaligned).
///
/// # Safety
/// `out` is null or valid for writing `len` `uint32_t`s.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_mask_generate};
/// let mut ranks = [0u32; 2 * 16 * 16];
/// // SAFETY: `ranks` holds 512 values.
/// assert_eq!(unsafe { nyq_mask_generate(16, 16, 5, ranks.as_mut_ptr(), 512) }, NyqStatus::NYQ_OK);
/// let mut sorted = ranks[256..].to_vec();
/// sorted.sort();
/// assert!(sorted.iter().copied().eq(0..256));
/// assert_eq!(unsafe { nyq_mask_generate(16, 16, 5, ranks.as_mut_ptr(), 500) }, NyqStatus::NYQ_ERR_BUFFER);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_mask_generate(
    width: u32,
    height: u32,
    seed: u64,
    out: *mut u32,
    len: usize,
) -> NyqStatus {
    run(|| {
        let vc = VoidAndCluster::new(width, height, seed)?;
        // SAFETY: `out` is null or writable for `len` values (caller).
        let out = unsafe { slice_mut(out, len)? };
        let (el, sl) = vc.scratch_len();
        vc.generate_channels(out, &mut vec![0.0; el], &mut vec![0; sl])?;
        Ok(())
    })
}

/// Writes a Poisson-disk set of the unit square (`torus` false) or torus, points at least
/// `radius` apart, `[x0, y0, x1, y1, …]`, to `out[0..len]` and its point count to `*count`:
/// the core's [`PoissonDisk`](nyquist::bluenoise::PoissonDisk) (Bridson's algorithm; with
/// `maximal`, the gap-filling pass that makes the set maximal). `len` must be at least
/// `2·⌈√2/radius⌉²`. The grid and active list (8 bytes per cell) are allocated inside the call.
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` or `count` is null; `NYQ_ERR_NON_FINITE` for a NaN or infinite
/// radius; `NYQ_ERR_OUT_OF_RANGE` outside `[1/1448, 1]`; `NYQ_ERR_BUFFER` if `len` is too short.
///
/// # Safety
/// `out` is null or valid for writing `len` doubles; `count` is null or valid for writing one
/// `size_t`.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_poisson_disk};
/// let mut pts = vec![0.0f64; 2 * 15 * 15];
/// let mut n = 0usize;
/// // SAFETY: `pts` holds 450 doubles, `n` one size_t.
/// let s = unsafe { nyq_poisson_disk(0.1, false, true, 3, pts.as_mut_ptr(), pts.len(), &mut n) };
/// assert_eq!(s, NyqStatus::NYQ_OK);
/// assert!(n > 40);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_poisson_disk(
    radius: f64,
    torus: bool,
    maximal: bool,
    seed: u64,
    out: *mut f64,
    len: usize,
    count: *mut usize,
) -> NyqStatus {
    use nyquist::analysis::Topology;
    use nyquist::bluenoise::PoissonDisk;
    run(|| {
        crate::ffi::need(count)?;
        let topology = if torus {
            Topology::Torus
        } else {
            Topology::Square
        };
        let pd = PoissonDisk::new(radius, topology, seed)?;
        let pd = if maximal { pd.maximal() } else { pd };
        // SAFETY: `out` is null or writable for `len` doubles (caller).
        let out = unsafe { slice_mut(out, len)? };
        let (g, a) = pd.scratch_len();
        let n = pd.generate(out, &mut vec![0; g], &mut vec![0; a])?;
        // SAFETY: `count` is non-null (checked) and writable (caller).
        unsafe { crate::ffi::put(count, n)? };
        Ok(())
    })
}
