//! Samplers, the layout and the pixel-range driver; see `nyquist_fuzz_checks::samplers`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::samplers(data));
