//! Memory as a checked limit. Every subcommand that allocates in proportion to its arguments
//! (film, reference, images, point buffers, spectra) estimates the bytes before it allocates and
//! refuses, in one line naming the flags and the estimate, when the estimate passes the limit:
//! `--max-memory`, by default half of what this process may use — the physical memory, or the
//! address-space limit (`ulimit -v`) when that is lower. The largest buffers are then allocated
//! with `try_reserve`, so an allocator that still says no is a one-line error, not an abort.
//!
//! ```
//! use nyquist_lab::memory::{parse_size, human};
//! assert_eq!(parse_size("1.5G"), Ok(1_500_000_000));
//! assert_eq!(parse_size("512MiB"), Ok(512 << 20));
//! assert_eq!(human(2_147_483_648), "2.1 GB");
//! ```

use anyhow::{Result, bail};
use std::sync::OnceLock;

/// The limit in force and how it was chosen.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limit {
    /// Bytes the estimates may reach.
    pub bytes: u64,
    /// Where the figure comes from, for messages.
    pub source: String,
}

static LIMIT: OnceLock<Limit> = OnceLock::new();

/// Sets the limit from `--max-memory` (`None`: the default). Later calls change nothing.
pub fn set_limit(max: Option<u64>) {
    let _ = LIMIT.set(match max {
        Some(bytes) => Limit {
            bytes,
            source: "--max-memory".into(),
        },
        None => default_limit(),
    });
}

/// The limit in force (the default if [`set_limit`] was not called).
pub fn limit() -> &'static Limit {
    LIMIT.get_or_init(default_limit)
}

/// Half of the physical memory, or of the address-space limit when that is lower (a limit the
/// shell sets with `ulimit -v`); 4 GB if neither can be read.
pub fn default_limit() -> Limit {
    let physical = proc_value("/proc/meminfo", "MemTotal:").map(|kib| kib * 1024);
    let address_space = proc_value("/proc/self/limits", "Max address space");
    match (physical, address_space) {
        (_, Some(a)) if physical.is_none_or(|p| a < p) => Limit {
            bytes: a / 2,
            source: "half the address-space limit (ulimit -v)".into(),
        },
        (Some(p), _) => Limit {
            bytes: p / 2,
            source: "half the physical memory".into(),
        },
        _ => Limit {
            bytes: 4_000_000_000,
            source: "the default when the physical memory cannot be read".into(),
        },
    }
}

/// The first number after `key` on its line of `file` (`None`: no such file or line, or
/// "unlimited").
fn proc_value(file: &str, key: &str) -> Option<u64> {
    let text = std::fs::read_to_string(file).ok()?;
    let line = text.lines().find(|l| l.starts_with(key))?;
    line[key.len()..].split_whitespace().next()?.parse().ok()
}

/// Refuses when `bytes`, the estimate for what `flags` ask for, passes the limit:
/// `--size 8192x8192 --metrics: needs about 4.3 GB of memory, more than the limit of 1.0 GB
/// (half the physical memory); give smaller values or a larger --max-memory`.
///
/// # Errors
/// The one-line refusal.
pub fn check(flags: &str, bytes: u64) -> Result<()> {
    check_against(limit(), flags, bytes)
}

/// [`check`] against a given limit.
///
/// # Errors
/// The one-line refusal.
pub fn check_against(limit: &Limit, flags: &str, bytes: u64) -> Result<()> {
    if bytes > limit.bytes {
        bail!(
            "{flags}: needs about {} of memory, more than the limit of {} ({}); give smaller \
             values or a larger --max-memory",
            human(bytes),
            human(limit.bytes),
            limit.source
        );
    }
    Ok(())
}

/// Bytes of `count` values of `size` bytes each, saturating: for estimates.
pub fn bytes(count: u64, size: u64) -> u64 {
    count.saturating_mul(size)
}

/// `n` copies of `value` in a new vector, or a one-line error naming `what` and the bytes when
/// the allocator refuses (instead of an abort).
///
/// # Errors
/// When the allocation fails.
pub fn try_filled<T: Clone>(n: usize, value: T, what: &str) -> Result<Vec<T>> {
    let mut v = Vec::new();
    if v.try_reserve_exact(n).is_err() {
        bail!(
            "out of memory: {} for {what}",
            human(bytes(n as u64, size_of::<T>() as u64))
        );
    }
    v.resize(n, value);
    Ok(v)
}

/// A byte count in decimal units with three significant figures at most: `2.1 GB`, `512 kB`.
pub fn human(bytes: u64) -> String {
    const UNITS: [&str; 6] = ["bytes", "kB", "MB", "GB", "TB", "PB"];
    let mut v = bytes as f64;
    let mut unit = 0;
    while v >= 1000.0 && unit + 1 < UNITS.len() {
        v /= 1000.0;
        unit += 1;
    }
    if unit == 0 {
        format!("{bytes} bytes")
    } else if v < 10.0 {
        format!("{v:.1} {}", UNITS[unit])
    } else {
        format!("{v:.0} {}", UNITS[unit])
    }
}

/// Parses a `--max-memory` size: a number with an optional unit, decimal (`k`, `M`, `G`, `T`,
/// with or without `B`) or binary (`KiB`, `MiB`, `GiB`, `TiB`); no unit means bytes.
///
/// # Errors
/// A message naming the accepted forms.
pub fn parse_size(s: &str) -> Result<u64, String> {
    let t = s.trim();
    let split = t
        .find(|c: char| !(c.is_ascii_digit() || c == '.'))
        .unwrap_or(t.len());
    let (number, unit) = t.split_at(split);
    let factor: u64 = match unit.trim().to_ascii_lowercase().as_str() {
        "" | "b" => 1,
        "k" | "kb" => 1_000,
        "m" | "mb" => 1_000_000,
        "g" | "gb" => 1_000_000_000,
        "t" | "tb" => 1_000_000_000_000,
        "kib" => 1 << 10,
        "mib" => 1 << 20,
        "gib" => 1 << 30,
        "tib" => 1 << 40,
        _ => return Err("not a size such as 512M, 2G or 1.5GiB".to_owned()),
    };
    let value: f64 = number
        .parse()
        .map_err(|_| "not a size such as 512M, 2G or 1.5GiB".to_owned())?;
    let bytes = value * factor as f64;
    if !(1.0..1.8e19).contains(&bytes) {
        return Err("not between 1 byte and 18 EB".to_owned());
    }
    Ok(bytes as u64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_in_decimal_and_binary_units() {
        assert_eq!(parse_size("100"), Ok(100));
        assert_eq!(parse_size("2G"), Ok(2_000_000_000));
        assert_eq!(parse_size("2 GB"), Ok(2_000_000_000));
        assert_eq!(parse_size("1GiB"), Ok(1 << 30));
        assert_eq!(parse_size("0.5k"), Ok(500));
        for bad in ["", "G", "-1G", "1X", "0", "1e30", "nan"] {
            assert!(parse_size(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn human_sizes_keep_two_or_three_figures() {
        assert_eq!(human(999), "999 bytes");
        assert_eq!(human(1_000), "1.0 kB");
        assert_eq!(human(4_294_967_296), "4.3 GB");
        assert_eq!(human(123_456_789), "123 MB");
    }

    #[test]
    fn an_estimate_over_the_limit_is_one_line_naming_the_flags() {
        let limit = Limit {
            bytes: 1_000_000,
            source: "--max-memory".into(),
        };
        assert!(check_against(&limit, "--size 10x10", 1_000_000).is_ok());
        let e = check_against(&limit, "--size 8192x8192", 2_147_483_648)
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "--size 8192x8192: needs about 2.1 GB of memory, more than the limit of 1.0 MB \
             (--max-memory); give smaller values or a larger --max-memory"
        );
    }

    #[test]
    fn a_failed_allocation_is_an_error() {
        let e = try_filled(usize::MAX / 8, 0u64, "the test buffer").unwrap_err();
        let e = e.to_string();
        assert!(
            e.starts_with("out of memory: ") && e.ends_with(" for the test buffer"),
            "{e}"
        );
        assert_eq!(try_filled(3, 7u8, "three bytes").unwrap(), [7, 7, 7]);
    }
}
