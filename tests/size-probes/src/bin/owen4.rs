//! Owen-scrambled Sobol 4-D, through `sample` and `sample_4d`.
#![no_std]
#![no_main]
use nyquist::compact::OwenSobol;
use nyquist::sequence::Sequence;
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let s = OwenSobol::<4>::new(7);
    run(|i| {
        for d in 0..4 {
            emit(s.sample(i, d).to_bits());
        }
        for x in s.sample_4d(i, 0) {
            emit(x.to_bits());
        }
    })
}
