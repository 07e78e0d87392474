//! Wording shared by the messages of every front end.

/// `n` and the noun, plural unless `n` is 1: `1 point`, `2 points`, `0 points`. For the regular
/// nouns of the messages (point, value, run, render, sample, dimension, realisation, sampler).
///
/// ```
/// use nyquist_lab::words::count;
/// assert_eq!(count(1u32, "run"), "1 run");
/// assert_eq!(count(64u64, "run"), "64 runs");
/// assert_eq!(count(0u8, "point"), "0 points");
/// ```
pub fn count(n: impl Into<u64>, noun: &str) -> String {
    let n = n.into();
    format!("{n} {noun}{}", if n == 1 { "" } else { "s" })
}
