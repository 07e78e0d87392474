//! A `compact::HaltonSampler::<8>` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`),
//! `Scramble::FastOwen` (a run-time value: every scramble's code is linked).
#![no_std]
#![no_main]
use nyquist::compact::HaltonSampler;
use nyquist::scramble::Scramble;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = HaltonSampler::<8>::new([64, 64], 16, Scramble::FastOwen, 7).unwrap();
    run(|i| camera_loop(&mut s, i))
}
