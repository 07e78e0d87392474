//! A `LatticeBlueSampler` camera-sample loop (`camera_sample`, `get_1d`, `get_2d`): the
//! desktop type with its 48 KiB blue-noise tile, and none of the other families' tiles.
#![no_std]
#![no_main]
use nyquist::sampler::LatticeBlueSampler;
use nyquist_size_probes::{camera_loop, run};

#[unsafe(no_mangle)]
extern "C" fn probe_main() -> ! {
    let mut s = LatticeBlueSampler::new(16, 7).unwrap().with_frame(2);
    run(|i| camera_loop(&mut s, i))
}
