//! Sobol 4-D by index.
#![no_std]
#![no_main]
use nyquist::compact::Sobol;
use nyquist::sequence::Sequence;
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let s = Sobol::<4>::new();
    run(|i| {
        for d in 0..4 {
            emit(s.sample(i, d).to_bits());
        }
    })
}
