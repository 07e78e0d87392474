//! PMJ(0,2) 2-D: 1024 points built into a caller buffer.
#![no_std]
#![no_main]
use nyquist::sequence::pmj02_build;
use nyquist_size_probes::{emit, run};

static mut POINTS: [[u32; 2]; 1024] = [[0; 2]; 1024];

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    // The one mutable static, borrowed once here.
    let points = unsafe { &mut *&raw mut POINTS };
    run(|i| {
        if pmj02_build(i >> 10, points).is_ok() {
            let [x, y] = points[(i & 1023) as usize];
            emit(x);
            emit(y);
        }
    })
}
