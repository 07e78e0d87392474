//! Radical inverses in every form, any dimension and u64 index; see `nyquist_fuzz_checks::radical`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::radical(data));
