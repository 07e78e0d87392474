//! Stratified 1D/2D, Latin hypercubes and shuffles; see `nyquist_fuzz_checks::stratify`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::stratify(data));
