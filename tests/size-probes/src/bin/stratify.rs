//! Stratified 2-D, Latin hypercube and shuffle into caller buffers.
#![no_std]
#![no_main]
use nyquist::rng::default_rng;
use nyquist::stratify::{Jitter, latin_hypercube, shuffle, stratified_2d};
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    run(|i| {
        let mut rng = default_rng(i);
        let mut grid = [0.0f32; 4 * 4 * 2];
        let mut lhs = [0.0f32; 8 * 3];
        if stratified_2d(&mut grid, 4, 4, Jitter::Jittered, &mut rng).is_ok()
            && latin_hypercube(&mut lhs, 3, &mut rng).is_ok()
            && shuffle(&mut grid, 16, 2, &mut rng).is_ok()
        {
            emit(grid[(i % 32) as usize].to_bits());
            emit(lhs[(i % 24) as usize].to_bits());
        }
    })
}
