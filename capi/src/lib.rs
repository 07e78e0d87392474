//! C ABI for [`nyquist`]: radical inverses, sequences, stratification, samplers and
//! reconstruction filters as `extern "C"` functions over caller buffers.
//!
//! Every function has the `nyq_` prefix, returns a [`NyqStatus`] and writes its results through
//! out-parameters, which are left untouched when the status is not [`NyqStatus::NYQ_OK`]. Null
//! pointers, empty or misaligned buffers, bad sizes and bad specs return an error code; nothing
//! here panics. Pointers are checked first: a null pointer gives `NYQ_ERR_NULL` whatever else
//! is wrong. Samplers and filters live behind opaque handles (`NyqSampler`, `NyqFilter`)
//! made by a `*_create` function and released by the matching `*_destroy`.
//!
//! The C header, `capi/include/nyquist.h`, is generated from this crate by cbindgen and
//! committed; the test `header` checks it is current (`NYQUIST_BLESS=1 cargo test -p
//! nyquist-capi --test header` rewrites it). The staticlib is `libnyquist_capi.a`; link it with
//! `-lm -lpthread -ldl`.
//!
//! # Features and the small static library
//!
//! - `std` (default): link Rust's standard library for the heap and panics. Without it the
//!   crate is `no_std` and brings its own (the C library's `malloc` family; a panic aborts),
//!   so a C program links none of the standard library's panic and backtrace machinery; the
//!   Rust tests need `std`.
//! - `lazy-tables`: the core's speed tables built in zeroed memory at first use instead of
//!   stored (the `nyquist` feature of that name).
//!
//! `cargo rustc --profile capi -p nyquist-capi --no-default-features --features lazy-tables
//! --lib --crate-type staticlib` builds the small static library; with the per-kind entry
//! points ([`nyq_halton_sample`], [`nyq_sampler_create_owen_sobol`]) a program links only the
//! kind it calls. `docs/c.md` gives the link line and the sizes.
//!
//! # Unsafe code
//!
//! The core forbids `unsafe`; this crate uses it only to read C pointers (null-checked and
//! alignment-checked first), to turn `(pointer, length)` pairs into slices, to own handles
//! through `Box::into_raw`/`Box::from_raw`, to call a C filter callback, and, without `std`,
//! to call the C library's allocator and `abort`. Each block states why it is sound under the
//! caller's documented obligations (`# Safety` on each function).
//!
//! ```
//! use nyquist_capi::{NyqStatus, nyq_radical_inverse};
//! let mut x = 0.0f32;
//! // SAFETY: `x` is a valid, aligned f32.
//! assert_eq!(unsafe { nyq_radical_inverse(1, 5, &mut x) }, NyqStatus::NYQ_OK);
//! assert_eq!(x, 7.0 / 9.0);
//! assert_eq!(unsafe { nyq_radical_inverse(1, 5, std::ptr::null_mut()) }, NyqStatus::NYQ_ERR_NULL);
//! ```

#![no_std]
#![deny(missing_docs, unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks, clippy::missing_safety_doc)]

extern crate alloc;
#[cfg(feature = "std")]
extern crate std;

mod blue_tile;
mod domain;
mod ffi;
mod filter;
mod mask;
mod pixel_stats;
mod radical;
/// cbindgen:ignore
#[cfg(not(feature = "std"))]
mod runtime;
mod sampler;
mod sequence;
mod status;
mod stratify;

pub use blue_tile::*;
pub use domain::*;
pub use filter::*;
pub use mask::*;
pub use pixel_stats::*;
pub use radical::*;
pub use sampler::*;
pub use sequence::*;
pub use status::*;
pub use stratify::*;
