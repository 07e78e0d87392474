//! A `LatticeSampler::fibonacci` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`): the desktop type, which
//! links no large table.
#![no_std]
#![no_main]
use nyquist::sampler::LatticeSampler;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = LatticeSampler::fibonacci(16, 7).unwrap();
    run(|i| camera_loop(&mut s, i))
}
