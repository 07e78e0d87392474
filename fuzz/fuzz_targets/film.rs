//! Film: resolutions, crop windows, filters, tile rectangles, non-finite samples and splats, merges in any order; see `nyquist_fuzz_checks::film`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::film(data));
