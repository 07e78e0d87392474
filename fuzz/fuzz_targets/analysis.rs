//! Point-set analysis: any point set (duplicates, 0 and 1, invalid values); see `nyquist_fuzz_checks::analysis`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::analysis(data));
