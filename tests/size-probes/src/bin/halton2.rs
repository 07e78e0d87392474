//! Halton 2-D by index (any `u64`).
#![no_std]
#![no_main]
use nyquist::compact::Halton;
use nyquist::sequence::Sequence;
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let h = Halton::<2>::new();
    run(|i| {
        for d in 0..2 {
            emit(h.sample(i, d).to_bits());
        }
    })
}
