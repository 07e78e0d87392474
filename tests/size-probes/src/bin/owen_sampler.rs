//! A `compact::OwenSobolSampler::<8>` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`).
#![no_std]
#![no_main]
use nyquist::compact::OwenSobolSampler;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = OwenSobolSampler::<8>::new(16, 7).unwrap().with_frame(2);
    run(|i| camera_loop(&mut s, i))
}
