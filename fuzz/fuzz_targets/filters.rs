//! Filters: spec parsing, constructors, eval, tables, footprints and the importance sampler; see `nyquist_fuzz_checks::filters`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::filters(data));
