//! Mitchell filter evaluated directly.
#![no_std]
#![no_main]
use nyquist::filter::{Filter, Mitchell};
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let m = Mitchell::default();
    run(|i| {
        let x = (i & 0xffff) as f32 / 8192.0 - 4.0;
        emit(m.eval(x, 0.5 * x).to_bits());
    })
}
