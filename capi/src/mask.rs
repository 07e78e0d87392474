//! Blue-noise threshold masks (void-and-cluster) into a caller buffer.

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
