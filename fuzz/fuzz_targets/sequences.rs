//! Point sets through the Sequence trait; see `nyquist_fuzz_checks::sequences`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::sequences(data));
