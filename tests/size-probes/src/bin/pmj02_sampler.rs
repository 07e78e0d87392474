//! A `compact::Pmj02Sampler` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`).
#![no_std]
#![no_main]
use nyquist::compact::Pmj02Sampler;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = Pmj02Sampler::new(16, 7).unwrap();
    run(|i| camera_loop(&mut s, i))
}
