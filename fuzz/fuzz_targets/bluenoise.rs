//! Masks, Poisson-disk sets and lattices; see `nyquist_fuzz_checks::bluenoise`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::bluenoise(data));
