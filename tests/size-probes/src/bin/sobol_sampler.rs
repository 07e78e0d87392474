//! A `compact::SobolSampler::<8>` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`),
//! Owen-scrambled (the scramble is a run-time value: every scramble's code is linked).
#![no_std]
#![no_main]
use nyquist::compact::SobolSampler;
use nyquist::scramble::Scramble;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = SobolSampler::<8>::new([64, 64], 16, Scramble::Owen, 7).unwrap();
    run(|i| camera_loop(&mut s, i))
}
