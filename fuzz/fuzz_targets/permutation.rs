//! Stateless permutations and hash-to-unit conversions; see `nyquist_fuzz_checks::permutation`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::permutation(data));
