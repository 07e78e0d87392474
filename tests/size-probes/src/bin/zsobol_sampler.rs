//! A `compact::ZSobolSampler` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`).
#![no_std]
#![no_main]
use nyquist::compact::ZSobolSampler;
use nyquist::scramble::Scramble;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = ZSobolSampler::new([64, 64], 16, Scramble::FastOwen, 7).unwrap();
    run(|i| camera_loop(&mut s, i))
}
