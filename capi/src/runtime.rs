//! What the standard library would otherwise provide, for the build without the `std` feature
//! (the small static library, `docs/c.md`): memory from the C library's `malloc` family and a
//! panic handler that calls `abort`. Without them the library links none of Rust's standard
//! library, whose panic and backtrace machinery alone is about 300 KB in every program.
//!
//! Nothing in the C API panics (bad input gets a status code); the handler is there because the
//! compiler requires one, and aborts as the `std` build's `panic = "abort"` profile would.

use core::alloc::{GlobalAlloc, Layout};
use core::ffi::c_void;

unsafe extern "C" {
    fn malloc(size: usize) -> *mut c_void;
    fn calloc(count: usize, size: usize) -> *mut c_void;
    fn realloc(p: *mut c_void, size: usize) -> *mut c_void;
    fn free(p: *mut c_void);
    fn posix_memalign(out: *mut *mut c_void, align: usize, size: usize) -> i32;
    fn abort() -> !;
}

/// The alignment every `malloc` block has (C's `max_align_t` is at least this on the targets
/// Rust supports with a C library: 8 on 32-bit ones, 16 on x86-64 and AArch64).
const MALLOC_ALIGN: usize = 2 * core::mem::size_of::<usize>();

/// Rust's heap on the C library's allocator, as the standard library's `System` does on Unix:
/// `malloc` when its alignment suffices, `posix_memalign` otherwise.
struct Malloc;

impl Malloc {
    /// Whether a plain `malloc` block is aligned enough for `layout`.
    fn plain(layout: Layout) -> bool {
        layout.align() <= MALLOC_ALIGN && layout.align() <= layout.size()
    }

    /// A block of `layout` from `posix_memalign` (null on failure).
    fn aligned(layout: Layout) -> *mut u8 {
        let mut p = core::ptr::null_mut();
        // `posix_memalign` wants a power of two that is a multiple of the pointer size.
        let align = layout.align().max(core::mem::size_of::<usize>());
        // SAFETY: `p` is a valid out-pointer; `align` is a power of two (a `Layout`'s
        // alignment, or the pointer size) and a multiple of the pointer size.
        let status = unsafe { posix_memalign(&mut p, align, layout.size()) };
        if status == 0 {
            p.cast()
        } else {
            core::ptr::null_mut()
        }
    }
}

// SAFETY: every block comes from the C allocator with at least the layout's size and alignment
// (`plain` or `posix_memalign`) and goes back to it with `free`, which takes both kinds.
unsafe impl GlobalAlloc for Malloc {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if Self::plain(layout) {
            // SAFETY: `malloc` takes any size.
            unsafe { malloc(layout.size()) }.cast()
        } else {
            Self::aligned(layout)
        }
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        if Self::plain(layout) {
            // SAFETY: `calloc` takes any size.
            unsafe { calloc(layout.size(), 1) }.cast()
        } else {
            let p = Self::aligned(layout);
            if !p.is_null() {
                // SAFETY: `p` is a fresh block of `layout.size()` bytes.
                unsafe { p.write_bytes(0, layout.size()) };
            }
            p
        }
    }

    unsafe fn dealloc(&self, p: *mut u8, _layout: Layout) {
        // SAFETY: `p` came from `alloc` or `realloc` above (the `GlobalAlloc` contract).
        unsafe { free(p.cast()) }
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: `layout` with `new_size` is a valid layout (the `GlobalAlloc` contract).
        let new = unsafe { Layout::from_size_align_unchecked(new_size, layout.align()) };
        if Self::plain(new) {
            // SAFETY: `p` came from the C allocator (above) and is not used again on success.
            unsafe { realloc(p.cast(), new_size) }.cast()
        } else {
            let q = Self::aligned(new);
            if !q.is_null() {
                // SAFETY: both blocks are live, distinct and at least `min(old, new)` bytes;
                // `p` came from `alloc` and is freed once.
                unsafe {
                    core::ptr::copy_nonoverlapping(p, q, layout.size().min(new_size));
                    free(p.cast());
                }
            }
            q
        }
    }
}

#[global_allocator]
static ALLOCATOR: Malloc = Malloc;

#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    // SAFETY: `abort` takes no arguments and does not return.
    unsafe { abort() }
}

/// The unwinding personality that the prebuilt `alloc` crate's unwind tables name. Panics abort
/// here (the `capi` profile and the handler above), so nothing unwinds and it is never called; it
/// only resolves the symbol.
#[unsafe(no_mangle)]
extern "C" fn rust_eh_personality() {}
