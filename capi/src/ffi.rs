//! Pointer checks shared by every entry point. All the raw-pointer reads of the crate go
//! through these helpers, so each caller's `unsafe` block only restates the caller contract.

use alloc::boxed::Box;
use core::ffi::{CStr, c_char};

use crate::NyqStatus;

/// Runs `f` and folds its result into a status.
pub(crate) fn run(f: impl FnOnce() -> Result<(), NyqStatus>) -> NyqStatus {
    match f() {
        Ok(()) => NyqStatus::NYQ_OK,
        Err(s) => s,
    }
}

/// Reads `*handle` with `read` and writes the result through `out` with `write` ([`put`] or
/// [`put_array`]): the shape of every query entry point. `handle` is checked first, then `out`
/// for null, and only then is `read` called, so a null pointer is `NYQ_ERR_NULL` whatever
/// `read` would say.
///
/// # Safety
/// `handle` is null or points to a live `H` not mutated meanwhile; `out` is null or valid for
/// what `write` writes.
pub(crate) unsafe fn query<H, T, V>(
    handle: *const H,
    out: *mut T,
    read: impl FnOnce(&H) -> Result<V, NyqStatus>,
    write: unsafe fn(*mut T, V) -> Result<(), NyqStatus>,
) -> NyqStatus {
    run(|| {
        // SAFETY: `handle` is null or live and not mutated meanwhile (caller).
        let h = unsafe { get(handle)? };
        need(out)?;
        let v = read(h)?;
        // SAFETY: `out` is valid for `write` (caller; null checked above).
        unsafe { write(out, v) }
    })
}

/// [`query`] through an exclusive borrow, for handles that are cursors (samplers): on a null
/// pointer `read` is not called, so the cursor does not move.
///
/// # Safety
/// `handle` is null or points to a live `H` not otherwise accessed meanwhile; `out` is null or
/// valid for what `write` writes.
pub(crate) unsafe fn query_mut<H, T, V>(
    handle: *mut H,
    out: *mut T,
    read: impl FnOnce(&mut H) -> Result<V, NyqStatus>,
    write: unsafe fn(*mut T, V) -> Result<(), NyqStatus>,
) -> NyqStatus {
    run(|| {
        // SAFETY: `handle` is null or live and exclusively ours (caller).
        let h = unsafe { get_mut(handle)? };
        need(out)?;
        let v = read(h)?;
        // SAFETY: `out` is valid for `write` (caller; null checked above).
        unsafe { write(out, v) }
    })
}

/// `NYQ_ERR_NULL` if `p` is null: entry points call it on every pointer before anything
/// else, so a null pointer is reported whatever else is wrong.
pub(crate) fn need<T>(p: *const T) -> Result<(), NyqStatus> {
    if p.is_null() {
        Err(NyqStatus::NYQ_ERR_NULL)
    } else {
        Ok(())
    }
}

/// Checks `p` is non-null and aligned.
fn check<T>(p: *const T) -> Result<(), NyqStatus> {
    if p.is_null() {
        Err(NyqStatus::NYQ_ERR_NULL)
    } else if !p.is_aligned() {
        Err(NyqStatus::NYQ_ERR_BUFFER)
    } else {
        Ok(())
    }
}

/// Writes `value` through `out`.
///
/// # Safety
/// `out` is null or valid for writing one `T` (it may be misaligned or null: both are errors).
pub(crate) unsafe fn put<T>(out: *mut T, value: T) -> Result<(), NyqStatus> {
    check(out)?;
    // SAFETY: non-null and aligned (checked), valid for writes (caller).
    unsafe { out.write(value) };
    Ok(())
}

/// Writes `values` to `out[0..N]`.
///
/// # Safety
/// `out` is null or valid for writing `N` consecutive `T`.
pub(crate) unsafe fn put_array<T: Copy, const N: usize>(
    out: *mut T,
    values: [T; N],
) -> Result<(), NyqStatus> {
    check(out)?;
    // SAFETY: non-null and aligned (checked), valid for `N` writes (caller).
    unsafe { out.cast::<[T; N]>().write(values) };
    Ok(())
}

/// Borrows `*p`.
///
/// # Safety
/// `p` is null or points to a live `T` not mutated for `'a`.
pub(crate) unsafe fn get<'a, T>(p: *const T) -> Result<&'a T, NyqStatus> {
    check(p)?;
    // SAFETY: non-null and aligned (checked), live and unaliased by writes (caller).
    Ok(unsafe { &*p })
}

/// Borrows `*p` mutably.
///
/// # Safety
/// `p` is null or points to a live `T` not otherwise accessed for `'a`.
pub(crate) unsafe fn get_mut<'a, T>(p: *mut T) -> Result<&'a mut T, NyqStatus> {
    check(p)?;
    // SAFETY: non-null and aligned (checked), live and exclusively ours (caller).
    Ok(unsafe { &mut *p })
}

/// Checks `(p, len)` can be a slice: null → `NYQ_ERR_NULL`, `len == 0` →
/// `NYQ_ERR_ZERO_SIZE`, misaligned or more bytes than `isize::MAX` → `NYQ_ERR_BUFFER`.
fn check_slice<T>(p: *const T, len: usize) -> Result<(), NyqStatus> {
    check(p)?;
    if len == 0 {
        return Err(NyqStatus::NYQ_ERR_ZERO_SIZE);
    }
    if len > isize::MAX as usize / core::mem::size_of::<T>().max(1) {
        return Err(NyqStatus::NYQ_ERR_BUFFER);
    }
    Ok(())
}

/// The slice `p[0..len]`: null → `NYQ_ERR_NULL`, `len == 0` → `NYQ_ERR_ZERO_SIZE`, misaligned
/// or more bytes than `isize::MAX` → `NYQ_ERR_BUFFER`.
///
/// # Safety
/// `p` is null or valid for reads and writes of `len` consecutive `T`, not otherwise accessed
/// for `'a`.
pub(crate) unsafe fn slice_mut<'a, T>(p: *mut T, len: usize) -> Result<&'a mut [T], NyqStatus> {
    check_slice(p, len)?;
    // SAFETY: non-null, aligned, total size ≤ isize::MAX (checked); valid and exclusive for
    // `len` elements (caller).
    Ok(unsafe { core::slice::from_raw_parts_mut(p, len) })
}

/// The read-only slice `p[0..len]`, with [`slice_mut`]'s checks.
///
/// # Safety
/// `p` is null or valid for reads of `len` consecutive `T`, not written for `'a`.
pub(crate) unsafe fn slice<'a, T>(p: *const T, len: usize) -> Result<&'a [T], NyqStatus> {
    check_slice(p, len)?;
    // SAFETY: non-null, aligned, total size ≤ isize::MAX (checked); valid for reads and not
    // written for `len` elements (caller).
    Ok(unsafe { core::slice::from_raw_parts(p, len) })
}

/// The UTF-8 text of a NUL-terminated string: null → `NYQ_ERR_NULL`, not UTF-8 →
/// `NYQ_ERR_PARSE`.
///
/// # Safety
/// `s` is null or points to a NUL-terminated string that outlives `'a` and is not written
/// meanwhile.
pub(crate) unsafe fn text<'a>(s: *const c_char) -> Result<&'a str, NyqStatus> {
    if s.is_null() {
        return Err(NyqStatus::NYQ_ERR_NULL);
    }
    // SAFETY: non-null (checked), NUL-terminated and live (caller).
    let c = unsafe { CStr::from_ptr(s) };
    c.to_str().map_err(|_| NyqStatus::NYQ_ERR_PARSE)
}

/// Moves `value` to the heap and writes the owning pointer through `out`.
///
/// # Safety
/// `out` is null or valid for writing one pointer.
pub(crate) unsafe fn put_box<T>(out: *mut *mut T, value: T) -> Result<(), NyqStatus> {
    check(out)?;
    let p = Box::into_raw(Box::new(value));
    // SAFETY: non-null and aligned (checked), valid for writes (caller).
    unsafe { out.write(p) };
    Ok(())
}

/// Drops a handle made by [`put_box`]; null is a no-op.
///
/// # Safety
/// `p` is null or a pointer from [`put_box`] for the same `T`, not yet dropped, and not used
/// afterwards.
pub(crate) unsafe fn drop_box<T>(p: *mut T) {
    if !p.is_null() {
        // SAFETY: `p` came from `Box::into_raw` and is dropped once (caller).
        drop(unsafe { Box::from_raw(p) });
    }
}
