//! The CLI's string parsers: sizes, grids, pixels, filter specs and lists, CSV points, value-enum names, compare's lists; see `nyquist_fuzz_checks::cli_parsers`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| nyquist_fuzz_checks::cli_parsers(data));
