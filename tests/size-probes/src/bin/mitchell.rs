//! The Mitchell filter through its table: one footprint of weights around a sample.
#![no_std]
#![no_main]
use nyquist::filter::{Interpolation, Mitchell, SeparableTable};
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let t = SeparableTable::<16>::new(&Mitchell::default(), Interpolation::Linear).unwrap();
    run(|i| {
        let d = (i & 0xffff) as f32 / 65536.0;
        let mut w = [0.0f32; 4 * 4];
        if t.footprint([-2.0 + d, -1.75 + 0.5 * d], 4, &mut w).is_ok() {
            for x in w {
                emit(x.to_bits());
            }
        }
    })
}
