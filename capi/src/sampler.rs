//! Samplers through an opaque handle: the core's stateless layer (`start_pixel_sample`, then
//! `get_1d`, `get_2d`, `get_pixel_2d`).
//!
//! A [`NyqSampler`] is a cursor: use one per thread ([`nyq_sampler_clone`] makes more). After
//! `nyq_sampler_start_pixel_sample` its values depend only on (pixel, sample index, dimension,
//! seed, construction parameters), so clones on different threads replay the same bits.

use alloc::boxed::Box;
use core::ffi::c_char;
use core::fmt::Debug;

use nyquist::sampler::{CameraSample, NamedSampler, OwenSobolSampler, Sampler, camera_sample};

use crate::NyqStatus;
use crate::ffi::{
    drop_box, get_mut, need, put, put_array, put_box, query, query_mut, run, slice, slice_mut, text,
};

/// A sampler behind an opaque handle, made by [`nyq_sampler_create`],
/// [`nyq_sampler_create_owen_sobol`] or [`nyq_sampler_clone`] and released by
/// [`nyq_sampler_destroy`]. Not safe to use from two threads at once.
///
/// The handle calls its sampler through a vtable that only the constructor that made it names,
/// so a program that creates its samplers with a per-kind constructor links that kind's code
/// and tables alone; [`nyq_sampler_create`], which takes any name, links every kind.
pub struct NyqSampler {
    inner: Box<dyn HandleSampler>,
}

impl Debug for NyqSampler {
    /// The type's name only: formatting the sampler would link every sampler's formatting code
    /// into every program.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("NyqSampler").finish_non_exhaustive()
    }
}

impl NyqSampler {
    /// The current sample as a domain, where the sampler's samples are domains.
    pub(crate) fn domain(&self) -> Option<nyquist::sampler::Domain> {
        self.inner.domain()
    }

    /// A handle over `sampler`.
    fn new(sampler: impl HandleSampler + 'static) -> NyqSampler {
        NyqSampler {
            inner: Box::new(sampler),
        }
    }
}

impl Clone for NyqSampler {
    fn clone(&self) -> NyqSampler {
        NyqSampler {
            inner: self.inner.clone_box(),
        }
    }
}

/// A [`Sampler`] a handle can hold: cloneable behind the box.
trait HandleSampler: Sampler {
    /// A boxed copy, parameters and cursor included.
    fn clone_box(&self) -> Box<dyn HandleSampler>;
}

impl<S: Sampler + Clone + 'static> HandleSampler for S {
    fn clone_box(&self) -> Box<dyn HandleSampler> {
        Box::new(self.clone())
    }
}

/// Checks what [`nyq_sampler_create`] checks before the name: `NYQ_ERR_ZERO_SIZE` if `width`,
/// `height` or `spp` is 0.
fn nonzero_size(width: u32, height: u32, spp: u32) -> Result<(), NyqStatus> {
    if width == 0 || height == 0 || spp == 0 {
        Err(NyqStatus::NYQ_ERR_ZERO_SIZE)
    } else {
        Ok(())
    }
}

/// Creates sampler `name` for `spp` samples per pixel of a `width × height` image with `seed`,
/// as the CLI's `--sampler NAME --spp SPP --size WxH --seed SEED` does, and writes the handle
/// to `*out`.
///
/// Names (any ASCII case; also `sobol-owen`, and `halton-plain`, `hammersley-plain` and
/// `sobol-plain` for the unscrambled sequences): `random`; `uniform` and `stratified` (cell
/// centres or jittered, on a √spp × √spp grid for a square spp, else the squarest rectangle of
/// spp cells); `halton`, `hammersley` (digit-permuted by `seed`, every seed 0 included);
/// `zero-two` and `sobol` (digit-permuted too; spp rounded up to a power of two:
/// [`nyq_sampler_samples_per_pixel`] tells); `best-candidate`; `adaptive` ((0,2) values, between
/// spp/4 and spp samples per pixel, driven by [`nyq_sampler_report`]); `owen-sobol`
/// (Owen-scrambled Sobol per pixel); `owen-sobol-bn` (the same with blue-noise error across
/// pixels, from a 128 × 128 tile); `zsobol` (blue-noise ZSobol, fast Owen, spp rounded up to
/// a power of two); `pmj02` (up to 65536 spp); `pmj02-bn` and `lattice-bn` (PMJ(0,2) and a
/// rank-1 lattice per pixel with blue-noise error across pixels); `bluenoise-dithered` (the zero-two set of pixel
/// (0, 0) in every pixel, toroidally shifted by a built-in 64 × 64 blue-noise mask, spp rounded
/// up to a power of two); `fibonacci`, `r2` and `korobov` (the Fibonacci lattice, spp rounded up
/// to a Fibonacci number, R2, or the Korobov lattice of exactly spp points whose multiplier
/// minimises P₂, per dimension pair, rotated per pixel and pair). The image size matters to
/// `halton`, `hammersley`, `sobol` and `zsobol` only, but must be non-zero for all.
///
/// # Errors
/// `NYQ_ERR_NULL` if `name` or `out` is null; `NYQ_ERR_PARSE` for an unknown or non-UTF-8
/// name; `NYQ_ERR_ZERO_SIZE` if `width`, `height` or `spp` is 0; `NYQ_ERR_OUT_OF_RANGE` if
/// `spp` is above the sampler's own limit (4096 for `best-candidate`, 65536 for `pmj02`);
/// `NYQ_ERR_TOO_MANY` (or another core error)
/// if the sampler cannot take `spp` at that size.
///
/// # Safety
/// `name` is null or a NUL-terminated string; `out` is null or valid for writing one pointer.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// // SAFETY: valid NUL-terminated name and out-pointer; the handle is destroyed once.
/// unsafe {
///     assert_eq!(nyq_sampler_create(c"zero-two".as_ptr(), 8, 8, 3, 0, &mut s), NyqStatus::NYQ_OK);
///     let mut spp = 0u32;
///     assert_eq!(nyq_sampler_samples_per_pixel(s, &mut spp), NyqStatus::NYQ_OK);
///     assert_eq!(spp, 4);
///     nyq_sampler_destroy(s);
///     assert_eq!(nyq_sampler_create(c"nope".as_ptr(), 8, 8, 4, 0, &mut s), NyqStatus::NYQ_ERR_PARSE);
/// }
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_create(
    name: *const c_char,
    width: u32,
    height: u32,
    spp: u32,
    seed: u64,
    out: *mut *mut NyqSampler,
) -> NyqStatus {
    run(|| {
        // SAFETY: `name` is null or NUL-terminated (caller).
        let name = unsafe { text(name)? };
        need(out)?;
        let sampler = NamedSampler::new(name, [width, height], spp, seed)?;
        // SAFETY: `out` is writable (caller).
        unsafe { put_box(out, NyqSampler::new(sampler)) }
    })
}

/// [`nyq_sampler_create`]`("owen-sobol", width, height, spp, seed, out)`: the same sampler,
/// the same values and errors, without the name. A program that creates its samplers this way
/// links the Owen-Sobol sampler's code and tables alone (about 1 MB of tables, or, in the
/// static library built with the `lazy-tables` feature, the 10 KB they are built from at first
/// use, in about a millisecond: `docs/c.md`).
///
/// # Errors
/// `NYQ_ERR_NULL` if `out` is null; `NYQ_ERR_ZERO_SIZE` if `width`, `height` or `spp` is 0.
///
/// # Safety
/// `out` is null or valid for writing one pointer.
///
/// ```
/// use nyquist_capi::*;
/// let (mut a, mut b): (*mut NyqSampler, *mut NyqSampler) = (std::ptr::null_mut(), std::ptr::null_mut());
/// let (mut x, mut y) = ([0.0f32; 2], [0.0f32; 2]);
/// // SAFETY: valid pointers; each handle is destroyed once.
/// unsafe {
///     assert_eq!(nyq_sampler_create_owen_sobol(64, 64, 16, 7, &mut a), NyqStatus::NYQ_OK);
///     nyq_sampler_create(c"owen-sobol".as_ptr(), 64, 64, 16, 7, &mut b);
///     nyq_sampler_start_pixel_sample(a, 3, 5, 2, 700);
///     nyq_sampler_start_pixel_sample(b, 3, 5, 2, 700);
///     nyq_sampler_get_2d(a, x.as_mut_ptr());
///     nyq_sampler_get_2d(b, y.as_mut_ptr());
///     nyq_sampler_destroy(a);
///     nyq_sampler_destroy(b);
///     assert_eq!(nyq_sampler_create_owen_sobol(64, 64, 0, 7, &mut a), NyqStatus::NYQ_ERR_ZERO_SIZE);
/// }
/// assert_eq!(x, y);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_create_owen_sobol(
    width: u32,
    height: u32,
    spp: u32,
    seed: u64,
    out: *mut *mut NyqSampler,
) -> NyqStatus {
    run(|| {
        need(out)?;
        nonzero_size(width, height, spp)?;
        let sampler = OwenSobolSampler::new(spp, seed)?;
        // SAFETY: `out` is writable (caller).
        unsafe { put_box(out, NyqSampler::new(sampler)) }
    })
}

/// Writes a new handle with the same parameters and cursor as `*sampler` to `*out` (one per
/// thread).
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `sampler` is null or a live handle; `out` is null or valid for writing one pointer.
///
/// ```
/// use nyquist_capi::*;
/// let (mut a, mut b): (*mut NyqSampler, *mut NyqSampler) = (std::ptr::null_mut(), std::ptr::null_mut());
/// let (mut x, mut y) = ([0.0f32; 2], [0.0f32; 2]);
/// // SAFETY: valid pointers; each handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"sobol".as_ptr(), 16, 16, 16, 3, &mut a);
///     nyq_sampler_start_pixel_sample(a, 2, 5, 7, 4);
///     assert_eq!(nyq_sampler_clone(a, &mut b), NyqStatus::NYQ_OK);
///     nyq_sampler_get_2d(a, x.as_mut_ptr());
///     nyq_sampler_get_2d(b, y.as_mut_ptr());
///     nyq_sampler_destroy(a);
///     nyq_sampler_destroy(b);
/// }
/// assert_eq!(x, y);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_clone(
    sampler: *const NyqSampler,
    out: *mut *mut NyqSampler,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(sampler, out, |s| Ok(s.clone()), put_box) }
}

/// Releases a handle from [`nyq_sampler_create`] or [`nyq_sampler_clone`]. Null is a no-op.
///
/// # Safety
/// `sampler` is null or a live handle, not used afterwards.
///
/// ```
/// // SAFETY: null is allowed.
/// unsafe { nyquist_capi::nyq_sampler_destroy(std::ptr::null_mut()) };
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_destroy(sampler: *mut NyqSampler) {
    // SAFETY: `sampler` is null or a live handle from `put_box`, dropped once (caller).
    unsafe { drop_box(sampler) }
}

/// Writes the sampler's samples per pixel (after any rounding; the maximum for `adaptive`) to
/// `*out`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `sampler` is null or a live handle; `out` is null or valid for writing one `uint32_t`.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut spp = 0;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"stratified".as_ptr(), 1, 1, 9, 0, &mut s);
///     assert_eq!(nyq_sampler_samples_per_pixel(s, &mut spp), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert_eq!(spp, 9);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_samples_per_pixel(
    sampler: *const NyqSampler,
    out: *mut u32,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(sampler, out, |s| Ok(s.inner.samples_per_pixel()), put) }
}

/// Moves the cursor to sample `sample_index` of pixel `(x, y)`, at dimension `dim`.
/// Dimensions 0 and 1 are the image sample; every `uint32_t` value is accepted (samplers with
/// a fixed per-pixel pattern wrap `sample_index` modulo their spp).
///
/// # Errors
/// `NYQ_ERR_NULL` if `sampler` is null.
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"random".as_ptr(), 1, 1, 1, 0, &mut s);
///     assert_eq!(nyq_sampler_start_pixel_sample(s, 0, 0, 0, 0), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
///     assert_eq!(nyq_sampler_start_pixel_sample(std::ptr::null_mut(), 0, 0, 0, 0), NyqStatus::NYQ_ERR_NULL);
/// }
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_start_pixel_sample(
    sampler: *mut NyqSampler,
    x: u32,
    y: u32,
    sample_index: u32,
    dim: u32,
) -> NyqStatus {
    run(|| {
        // SAFETY: `sampler` is null or live and exclusively ours (caller).
        let s = unsafe { get_mut(sampler)? };
        s.inner.start_pixel_sample([x, y], sample_index, dim);
        Ok(())
    })
}

/// Runs `fill` on the sampler behind `sampler` over `out[0..len]`; `len` must be a multiple of
/// `arity` (`NYQ_ERR_BUFFER` otherwise).
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing `len` floats.
unsafe fn array(
    sampler: *mut NyqSampler,
    out: *mut f32,
    len: usize,
    arity: usize,
    fill: impl FnOnce(&mut dyn HandleSampler, &mut [f32]),
) -> NyqStatus {
    run(|| {
        // SAFETY: `sampler` is null or live and exclusively ours (caller).
        let s = unsafe { get_mut(sampler)? };
        // SAFETY: `out` is null or writable for `len` floats (caller).
        let out = unsafe { slice_mut(out, len)? };
        if !len.is_multiple_of(arity) {
            return Err(NyqStatus::NYQ_ERR_BUFFER);
        }
        fill(&mut *s.inner, out);
        Ok(())
    })
}

/// Writes the value of the current dimension, in `[0, 1)`, to `*out` and advances the cursor
/// by one.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null (the cursor does not move).
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing one `float`.
///
/// ```
/// use nyquist::sampler::{RandomSampler, Sampler};
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut v = 0.0f32;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"random".as_ptr(), 1, 1, 4, 7, &mut s);
///     nyq_sampler_start_pixel_sample(s, 3, 5, 2, 6);
///     assert_eq!(nyq_sampler_get_1d(s, &mut v), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// let mut r = RandomSampler::new(4, 7).unwrap();
/// r.start_pixel_sample([3, 5], 2, 6);
/// assert_eq!(v, r.get_1d());
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_get_1d(sampler: *mut NyqSampler, out: *mut f32) -> NyqStatus {
    // SAFETY: the pointers are as `query_mut` needs (caller).
    unsafe { query_mut(sampler, out, |s| Ok(s.inner.get_1d()), put) }
}

/// Writes the values of the current and the next dimension, in `[0, 1)²`, to `out[0]` and
/// `out[1]`, and advances the cursor by two.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null (the cursor does not move).
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing two `float`s.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut uv = [2.0f32; 2];
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"halton-plain".as_ptr(), 64, 64, 16, 0, &mut s);
///     nyq_sampler_start_pixel_sample(s, 0, 0, 0, 2);
///     assert_eq!(nyq_sampler_get_2d(s, uv.as_mut_ptr()), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert_eq!(uv, [0.0, 0.0]); // Halton index 0, dimensions 2 and 3
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_get_2d(sampler: *mut NyqSampler, out: *mut f32) -> NyqStatus {
    // SAFETY: the pointers are as `query_mut` needs (caller).
    unsafe { query_mut(sampler, out, |s| Ok(s.inner.get_2d()), put_array) }
}

/// Writes the image sample (the offset inside the pixel, dimensions 0 and 1 whatever the
/// cursor), in `[0, 1)²`, to `out[0]` and `out[1]`; the cursor moves to `max(cursor, 2)`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null (the cursor does not move).
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing two `float`s.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut p = [2.0f32; 2];
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"uniform".as_ptr(), 1, 1, 1, 0, &mut s);
///     nyq_sampler_start_pixel_sample(s, 4, 4, 0, 9);
///     assert_eq!(nyq_sampler_get_pixel_2d(s, p.as_mut_ptr()), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert_eq!(p, [0.5, 0.5]);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_get_pixel_2d(
    sampler: *mut NyqSampler,
    out: *mut f32,
) -> NyqStatus {
    // SAFETY: the pointers are as `query_mut` needs (caller).
    unsafe { query_mut(sampler, out, |s| Ok(s.inner.get_pixel_2d()), put_array) }
}

/// Fills `out[0..len]` with an array of `len` values for the current sample at the current
/// dimension (stratified samplers stratify the array): the core's `Sampler::get_array_1d`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_ZERO_SIZE` if `len == 0`; `NYQ_ERR_BUFFER` if
/// `out` is misaligned.
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing `len` floats.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut a = [2.0f32; 4];
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"stratified".as_ptr(), 1, 1, 4, 1, &mut s);
///     nyq_sampler_start_pixel_sample(s, 0, 0, 0, 5);
///     assert_eq!(nyq_sampler_get_array_1d(s, a.as_mut_ptr(), 4), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert!(a.iter().all(|x| (0.0..1.0).contains(x)));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_get_array_1d(
    sampler: *mut NyqSampler,
    out: *mut f32,
    len: usize,
) -> NyqStatus {
    // SAFETY: the caller's contract is `array`'s.
    unsafe { array(sampler, out, len, 1, |s, out| s.get_array_1d(out)) }
}

/// Fills `out[0..len]` with `len / 2` 2D values `[u0, v0, u1, v1, …]` for the current sample:
/// the core's `Sampler::get_array_2d`. `len` must be even.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_ZERO_SIZE` if `len == 0`; `NYQ_ERR_BUFFER` if
/// `len` is odd or `out` is misaligned.
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing `len` floats.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut a = [2.0f32; 5];
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"random".as_ptr(), 1, 1, 4, 1, &mut s);
///     assert_eq!(nyq_sampler_get_array_2d(s, a.as_mut_ptr(), 5), NyqStatus::NYQ_ERR_BUFFER);
///     assert_eq!(nyq_sampler_get_array_2d(s, a.as_mut_ptr(), 4), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert!(a[..4].iter().all(|x| (0.0..1.0).contains(x)));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_get_array_2d(
    sampler: *mut NyqSampler,
    out: *mut f32,
    len: usize,
) -> NyqStatus {
    // SAFETY: the caller's contract is `array`'s.
    unsafe { array(sampler, out, len, 2, |s, out| s.get_array_2d(out)) }
}

/// What a camera needs for one pixel sample.
///
/// ```
/// let c = nyquist_capi::NyqCameraSample { p_film: [0.5, 0.5], lens: [0.0, 0.0], time: 0.0 };
/// assert_eq!(c.p_film[0], 0.5);
/// ```
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NyqCameraSample {
    /// Position on the film in pixels: the pixel plus the image sample, inside the pixel.
    pub p_film: [f32; 2],
    /// Lens sample in `[0, 1)²` (dimensions 3 and 4).
    pub lens: [f32; 2],
    /// Time in `[0, 1)` (dimension 2).
    pub time: f32,
}

impl From<CameraSample> for NyqCameraSample {
    fn from(c: CameraSample) -> NyqCameraSample {
        let CameraSample { p_film, lens, time } = c;
        NyqCameraSample { p_film, lens, time }
    }
}

/// Starts sample `sample_index` of pixel `(x, y)` at dimension 0 and writes its camera sample
/// (image position, time, lens) to `*out`; the cursor is left at dimension 5, where an
/// integrator's own values begin: the core's
/// [`camera_sample`](nyquist::sampler::camera_sample).
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null (the cursor does not move).
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `out` is null or
/// valid for writing one `NyqCameraSample`.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut c = NyqCameraSample { p_film: [0.0; 2], lens: [0.0; 2], time: 0.0 };
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"uniform".as_ptr(), 1, 1, 1, 0, &mut s);
///     assert_eq!(nyq_sampler_camera_sample(s, 10, 20, 0, &mut c), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert_eq!(c.p_film, [10.5, 20.5]);
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_camera_sample(
    sampler: *mut NyqSampler,
    x: u32,
    y: u32,
    sample_index: u32,
    out: *mut NyqCameraSample,
) -> NyqStatus {
    let camera = |s: &mut NyqSampler| Ok(camera_sample(&mut *s.inner, [x, y], sample_index).into());
    // SAFETY: the pointers are as `query_mut` needs (caller).
    unsafe { query_mut(sampler, out, camera, put) }
}

/// Reports the radiance (`len` channels, any number) that sample `sample_index` of pixel
/// `(x, y)` produced; only `adaptive` uses it, to decide [`nyq_sampler_pixel_samples`].
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null; `NYQ_ERR_ZERO_SIZE` if `len == 0`; `NYQ_ERR_BUFFER` if
/// `radiance` is misaligned.
///
/// # Safety
/// `sampler` is null or a live handle not used by another thread meanwhile; `radiance` is null
/// or valid for reading `len` floats and not written meanwhile.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut l = [1.0f32, 0.5, 0.25];
/// let mut n = 0;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"random".as_ptr(), 1, 1, 4, 0, &mut s);
///     assert_eq!(nyq_sampler_report(s, 0, 0, 0, l.as_mut_ptr(), 3), NyqStatus::NYQ_OK);
///     nyq_sampler_pixel_samples(s, 0, 0, &mut n);
///     nyq_sampler_destroy(s);
/// }
/// assert_eq!(n, 4); // ignored by non-adaptive samplers
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_report(
    sampler: *mut NyqSampler,
    x: u32,
    y: u32,
    sample_index: u32,
    radiance: *const f32,
    len: usize,
) -> NyqStatus {
    run(|| {
        // SAFETY: `sampler` is null or live and exclusively ours (caller).
        let s = unsafe { get_mut(sampler)? };
        // SAFETY: `radiance` is null or readable for `len` floats, not written meanwhile
        // (caller).
        let radiance = unsafe { slice(radiance, len)? };
        s.inner.report([x, y], sample_index, radiance);
        Ok(())
    })
}

/// Writes how many samples pixel `(x, y)` takes, given what was reported for it so far, to
/// `*out`: spp for every sampler but `adaptive`.
///
/// # Errors
/// `NYQ_ERR_NULL` if a pointer is null.
///
/// # Safety
/// `sampler` is null or a live handle; `out` is null or valid for writing one `uint32_t`.
///
/// ```
/// use nyquist_capi::*;
/// let mut s: *mut NyqSampler = std::ptr::null_mut();
/// let mut n = 0;
/// // SAFETY: valid pointers; the handle is destroyed once.
/// unsafe {
///     nyq_sampler_create(c"adaptive".as_ptr(), 1, 1, 16, 0, &mut s);
///     assert_eq!(nyq_sampler_pixel_samples(s, 0, 0, &mut n), NyqStatus::NYQ_OK);
///     nyq_sampler_destroy(s);
/// }
/// assert!((4..=16).contains(&n));
/// ```
#[unsafe(no_mangle)]
pub unsafe extern "C" fn nyq_sampler_pixel_samples(
    sampler: *const NyqSampler,
    x: u32,
    y: u32,
    out: *mut u32,
) -> NyqStatus {
    // SAFETY: the pointers are as `query` needs (caller).
    unsafe { query(sampler, out, |s| Ok(s.inner.pixel_samples([x, y])), put) }
}
