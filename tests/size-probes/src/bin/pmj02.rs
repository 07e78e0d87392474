//! PMJ(0,2) 2-D: 1024 points built into a caller buffer.
#![no_std]
#![no_main]
use nyquist::sequence::pmj02_build;
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    // The caller's buffer, on the stack.
    let mut points = [[0u32; 2]; 1024];
    run(|i| {
        if pmj02_build((i >> 10) as u32, &mut points).is_ok() {
            let [x, y] = points[(i & 1023) as usize];
            emit(x);
            emit(y);
        }
    })
}
