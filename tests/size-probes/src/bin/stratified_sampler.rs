//! A `StratifiedSampler` camera-sample loop.
#![no_std]
#![no_main]
use nyquist::sampler::{Jitter, Sampler, StratifiedSampler};
use nyquist_size_probes::{emit, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = StratifiedSampler::new(4, 4, Jitter::Jittered, 9).unwrap();
    run(|i| {
        let c = s.camera_sample([(i & 63) as u32, (i >> 6 & 63) as u32], (i >> 12) as u32);
        for x in [c.p_film[0], c.p_film[1], c.lens[0], c.lens[1], c.time] {
            emit(x.to_bits());
        }
    })
}
