//! # nyquist
//!
//! Sampling and reconstruction for image synthesis, as a `#![no_std]` library that never
//! allocates: radical inverses and the Halton, Hammersley, Zaremba, Sobol and (0,2) point sets,
//! stratified and Latin-hypercube sampling over caller buffers, and reconstruction filters.
//!
//! ```
//! use nyquist::sequence::{Halton, Sequence};
//!
//! let halton = Halton::new(2).unwrap();
//! // Point 1 of the Halton sequence is (1/2, 1/3).
//! assert_eq!(halton.sample(1, 0), 0.5);
//! assert!((halton.sample(1, 1) - 1.0 / 3.0).abs() < 1e-7);
//! ```
//!
//! ## Conventions
//!
//! - Every value a generator returns lies in `[0, 1)`: results are clamped to
//!   [`ONE_MINUS_EPSILON`] (`f32`) or [`ONE_MINUS_EPSILON_F64`].
//! - Sequence indices are `u64`; dimensions are `u32`.
//! - Functions that can be handed bad input return [`Result`] with [`Error`]; per-value functions
//!   are total and document what they do with out-of-range arguments (they never panic).
//!
//! ## Limits
//!
//! - Radical-inverse based sets (Halton and friends) have 1024 dimensions, one per prime
//!   2 … 8161; Sobol has 1024 dimensions (Joe–Kuo `new-joe-kuo-6.21201`) and 32-bit indices.
//!
//! ## `no_std`
//!
//! The crate is always `#![no_std]` and uses no `alloc`; `tests/nostd-probe` in the repository
//! proves it by linking the crate into a staticlib that has neither. For firmware and WASM, the
//! const-generic point sets of [`compact`] return the `sequence` types' values, bit for bit,
//! without their speed tables and without `f64` arithmetic (`docs/embedded.md` in the
//! repository has sizes and budgets).
//!
//! ## Features
//!
//! - `lazy-tables` (off by default): the samplers' speed tables (about 2.1 MiB: Sobol and
//!   Owen-Sobol products, radical-inverse constants, the baked PMJ(0,2) sequence) are built in
//!   zeroed memory at first use instead of stored in the binary, and so is the best-candidate
//!   table (40 KiB; its generation is the one slow fill: about 0.4 s natively, and 180 KiB of
//!   stack). For WebAssembly, where the module's size is a download; values are identical.
//!   Needs atomic compare-and-swap.
//! - `small-code` (off by default): the hot paths' `#[inline(always)]` attributes are dropped,
//!   so the compiler inlines only where its size heuristics say so. For size-optimised builds
//!   (`opt-level = "z"`) where code size matters more than speed; values are identical.
//!
//! ## `unsafe`
//!
//! Two uses, each with a `// SAFETY:` argument and run under Miri in CI: the call into an SSE2
//! kernel on x86-64 (SSE2 is in that target's baseline), and, with `lazy-tables`, handing out
//! shared references to a table after its one fill. Everything else is safe.
#![no_std]
#![deny(unsafe_code)]
#![deny(missing_docs)]
#![doc(test(attr(deny(warnings))))]

#[cfg(test)]
extern crate std;

pub mod analysis;
pub mod bluenoise;
pub mod compact;
pub mod error;
pub mod filter;
pub mod hash;
pub mod lattice;
mod lazy_table;
pub mod math;
pub mod radical;
pub mod rng;
pub mod sampler;
pub mod scramble;
pub mod sequence;
#[cfg(target_arch = "x86_64")]
mod simd;
pub mod stratify;

#[cfg(test)]
mod tests;

pub use error::Error;
pub use math::{ONE_MINUS_EPSILON, ONE_MINUS_EPSILON_F64};

/// The embedded guide's code blocks, compiled and run as doctests.
#[cfg(doctest)]
#[doc = include_str!("../../docs/embedded.md")]
struct EmbeddedDoctests;
