//! Contract checks for the nyquist fuzz targets, one function per public entry family of the
//! core, plus the film (`nyquist-film`) and the command line's string parsers (`nyquist-cli`). Each takes arbitrary bytes, decodes them into arguments with [`Bytes`] (missing bytes
//! read as zero, so every byte string is a valid input), calls the API and asserts its documented
//! contract: no panic, values in range, counts exact, errors typed and the ones the docs name.
//! A failed assertion panics, which libFuzzer reports as a crash and the stable replay test
//! (`tests/fuzz_regressions.rs` in the main workspace) reports as a failure.

mod analysis;
mod bluenoise;
mod bytes;
mod cli_parsers;
mod film;
mod filters;
mod permutation;
mod radical;
mod samplers;
mod sequences;
mod stratify;

pub use analysis::analysis;
pub use bluenoise::bluenoise;
pub use bytes::Bytes;
pub use cli_parsers::cli_parsers;
pub use film::film;
pub use filters::filters;
pub use permutation::permutation;
pub use radical::radical;
pub use samplers::samplers;
pub use sequences::sequences;
pub use stratify::stratify;

/// A target's check: panics when the contract does not hold for this input.
pub type Check = fn(&[u8]);

/// Every target, by the name of its cargo-fuzz binary and of its folders under `corpus/` and
/// `regressions/`.
pub const TARGETS: &[(&str, Check)] = &[
    ("analysis", analysis),
    ("bluenoise", bluenoise),
    ("cli_parsers", cli_parsers),
    ("film", film),
    ("filters", filters),
    ("permutation", permutation),
    ("radical", radical),
    ("samplers", samplers),
    ("sequences", sequences),
    ("stratify", stratify),
];

/// The check function of target `name`.
pub fn target(name: &str) -> Option<Check> {
    TARGETS.iter().find(|(n, _)| *n == name).map(|(_, f)| *f)
}

/// `x` is in `[0, 1)` (false for NaN).
pub fn in_unit(x: f32) -> bool {
    (0.0..1.0).contains(&x)
}

/// `x` is in `[0, 1)` (false for NaN).
pub fn in_unit_f64(x: f64) -> bool {
    (0.0..1.0).contains(&x)
}

/// Whether a core error's numbers state a real violation: the value it carries lies outside
/// the range it names, or above the maximum. Variants without such numbers pass.
pub fn error_numbers_hold(e: &nyquist::Error) -> bool {
    use nyquist::Error;
    match *e {
        Error::OutOfRange { value, range, .. } => !range.contains(value),
        Error::NotInRange {
            value, min, max, ..
        } => min <= max && !(min..=max).contains(&value),
        Error::TooMany { value, max, .. } => value > max,
        _ => true,
    }
}
