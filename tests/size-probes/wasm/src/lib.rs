//! Exports Halton point `index`, dimension `dim & 1` (2-D), as `halton2`.
#![no_std]

use nyquist::compact::Halton;
use nyquist::sequence::Sequence;

#[cfg(not(test))]
#[panic_handler]
fn panic(_: &core::panic::PanicInfo<'_>) -> ! {
    loop {}
}

/// Halton 2-D point `index`, dimension `dim` (wrapping modulo 2).
#[unsafe(no_mangle)]
pub extern "C" fn halton2(index: u64, dim: u32) -> f32 {
    Halton::<2>::new().sample(index, dim)
}
