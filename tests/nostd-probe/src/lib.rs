//! Proves that `nyquist` needs neither `std` nor `alloc`: this staticlib has neither, defines its
//! own panic handler and calls into the core through `extern "C"` functions.
#![no_std]

use core::panic::PanicInfo;
use nyquist::sequence::{Halton, Sequence, Sobol, ZeroTwo};

#[panic_handler]
fn panic(_: &PanicInfo<'_>) -> ! {
    loop {}
}

/// Φ of `index` in the base of dimension `dim`.
#[unsafe(no_mangle)]
pub extern "C" fn probe_radical_inverse(dim: u32, index: u64) -> f32 {
    nyquist::radical::radical_inverse(dim, index)
}

/// Halton point `index`, dimension `dim` (0 for a bad request).
#[unsafe(no_mangle)]
pub extern "C" fn probe_halton(index: u64, dim: u32) -> f32 {
    Halton::new(8).map_or(0.0, |h| h.sample(index, dim))
}

/// Sobol point `index`, dimension `dim`.
#[unsafe(no_mangle)]
pub extern "C" fn probe_sobol(index: u64, dim: u32) -> f32 {
    Sobol::new(1024).map_or(0.0, |s| s.sample(index, dim))
}

/// (0,2)-sequence point `index`, dimension `dim`.
#[unsafe(no_mangle)]
pub extern "C" fn probe_zero_two(index: u64, dim: u32, seed: u64) -> f32 {
    ZeroTwo::from_seed(seed).sample(index, dim)
}

/// Latin hypercube of 16 points in 3 dimensions on the stack; returns the sum of the values.
#[unsafe(no_mangle)]
pub extern "C" fn probe_lhs(seed: u64) -> f32 {
    let mut buf = [0.0f32; 48];
    let mut rng = nyquist::rng::default_rng(seed);
    match nyquist::stratify::latin_hypercube(&mut buf, 3, &mut rng) {
        Ok(_) => buf.iter().sum(),
        Err(_) => -1.0,
    }
}
