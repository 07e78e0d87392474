//! The blue-noise samplers' tiles, for shaders and the C++ header, which take them from the
//! library instead of carrying their own copies.

use core::ffi::c_char;

use nyquist::sampler::screen_blue::{BlueFamily, LatticeBlue, OwenSobolBlue, Pmj02Blue, TILE_SIZE};

use crate::NyqStatus;
use crate::ffi::{run, slice_mut, text};

/// Entries in one tile: 128 × 128.
pub const NYQ_BLUE_TILE_ENTRIES: usize = 16384;

const _: () = assert!(NYQ_BLUE_TILE_ENTRIES == (TILE_SIZE * TILE_SIZE) as usize);

/// Writes `F`'s tile, row-major, to `out`.
fn fill<F: BlueFamily>(out: &mut [u32]) {
    for (i, e) in out.iter_mut().enumerate() {
        let i = i as u32;
        *e = F::entry(i % TILE_SIZE, i / TILE_SIZE);
    }
}

/// Writes the 128 × 128 tile of the blue-noise sampler `name` (`owen-sobol-bn`, `pmj02-bn` or
/// `lattice-bn`, any ASCII case) to `out[0..16384]`, row-major: `out[y·128 + x]` is pixel
/// `(x, y)`'s entry `key << 8 | rank` (a 24-bit key and an 8-bit rank), the core's
/// `BlueFamily::entry(x, y)`. This is the table the C++ header's `OwenSobolBlueSampler`,
/// `Pmj02BlueSampler` and `LatticeBlueSampler` read (64 KiB as `uint32_t`), and one third of
/// the shaders' `nyq_blue_tiles` buffer. Entries past 16384 in `out` are left untouched.
///
/// # Errors
/// `NYQ_ERR_NULL` if `name` or `out` is null; `NYQ_ERR_PARSE` for another name (or non-UTF-8);
/// `NYQ_ERR_BUFFER` if `len < 16384` (or if `out` is misaligned).
///
/// # Safety
/// `name` is null or a NUL-terminated string; `out` is null or valid for writing `len`
/// `uint32_t`s.
///
/// ```
/// use nyquist_capi::{NyqStatus, nyq_blue_tile};
/// let mut tile = vec![0u32; 128 * 128];
/// // SAFETY: a NUL-terminated name and a buffer of 16384 values.
/// let s = unsafe { nyq_blue_tile(c"lattice-bn".as_ptr(), tile.as_mut_ptr(), tile.len()) };
/// assert_eq!(s, NyqStatus::NYQ_OK);
/// use nyquist::sampler::screen_blue::{BlueFamily, LatticeBlue};
/// assert_eq!(tile[77 * 128 + 5], LatticeBlue::entry(5, 77));
/// // SAFETY: as above.
/// let s = unsafe { nyq_blue_tile(c"owen-sobol".as_ptr(), tile.as_mut_ptr(), tile.len()) };
/// assert_eq!(s, NyqStatus::NYQ_ERR_PARSE);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_blue_tile(
    name: *const c_char,
    out: *mut u32,
    len: usize,
) -> NyqStatus {
    run(|| {
        // SAFETY: `name` is null or NUL-terminated (caller).
        let name = unsafe { text(name)? };
        // SAFETY: `out` is null or writable for `len` values (caller).
        let out = unsafe { slice_mut(out, len)? };
        let Some(out) = out.get_mut(..NYQ_BLUE_TILE_ENTRIES) else {
            return Err(NyqStatus::NYQ_ERR_BUFFER);
        };
        let is = |n: &str| name.eq_ignore_ascii_case(n);
        if is(OwenSobolBlue::NAME) {
            fill::<OwenSobolBlue>(out);
        } else if is(Pmj02Blue::NAME) {
            fill::<Pmj02Blue>(out);
        } else if is(LatticeBlue::NAME) {
            fill::<LatticeBlue>(out);
        } else {
            return Err(NyqStatus::NYQ_ERR_PARSE);
        }
        Ok(())
    })
}
