//! Value parsers for the numeric flags of the command line: each flag states its real range, so
//! a value outside it — negative, fractional, too large for its type, or just past the limit —
//! is refused with that range (`--spp -1: not in 1 ..= 1048576`), not with a type's range
//! (`0..=4294967295`) or a parse error (`invalid digit found in string`).
//!
//! ```
//! use nyquist_lab::flags::whole;
//! let spp = whole(1u32, 1 << 20);
//! assert_eq!(spp("16"), Ok(16));
//! assert_eq!(spp("-1").unwrap_err(), "not in 1 ..= 1048576");
//! assert_eq!(spp("4294967296").unwrap_err(), "not in 1 ..= 1048576");
//! assert_eq!(spp("1.5").unwrap_err(), "not a whole number in 1 ..= 1048576");
//! ```

/// A parser of whole numbers in `min ..= max` (decimal digits, an optional `+`, surrounding
/// spaces ignored). Its errors give the range: `not in MIN ..= MAX` for any integer outside it,
/// however large or negative, and `not a whole number in MIN ..= MAX` for anything else. The
/// command line prints them after the flag and the value.
///
/// ```
/// let seed = nyquist_lab::flags::whole(0u64, u64::MAX);
/// assert_eq!(seed("18446744073709551615"), Ok(u64::MAX));
/// assert_eq!(seed("18446744073709551616").unwrap_err(), "not in 0 ..= 18446744073709551615");
/// ```
pub fn whole<T>(
    min: T,
    max: T,
) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync + 'static
where
    T: Copy + Into<u64> + TryFrom<u64> + std::fmt::Display + Send + Sync + 'static,
{
    move |s: &str| {
        let (lo, hi) = (min.into(), max.into());
        let outside = || format!("not in {min} ..= {max}");
        let t = s.trim();
        let (negative, digits) = match t.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, t.strip_prefix('+').unwrap_or(t)),
        };
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            return Err(format!("not a whole number in {min} ..= {max}"));
        }
        if negative {
            // -0 is 0; any other negative number is below every range here.
            return match digits.bytes().all(|b| b == b'0') && lo == 0 {
                true => T::try_from(0).map_err(|_| outside()),
                false => Err(outside()),
            };
        }
        // Too many digits for u64 is above every range.
        let v: u64 = digits.parse().map_err(|_| outside())?;
        if v < lo || v > hi {
            return Err(outside());
        }
        T::try_from(v).map_err(|_| outside())
    }
}

/// A parser of finite decimal numbers in `min ..= max` (what `f64` reads: `0.01`, `1e-3`;
/// surrounding spaces ignored). Its errors give the range: `not in MIN ..= MAX` for a number
/// outside it, `not a number in MIN ..= MAX` for anything else (`nan`, `inf` included).
///
/// ```
/// let threshold = nyquist_lab::flags::number(0.0, 1.0);
/// assert_eq!(threshold("1e-2"), Ok(0.01));
/// assert_eq!(threshold("-0.5").unwrap_err(), "not in 0 ..= 1");
/// assert_eq!(threshold("nan").unwrap_err(), "not a number in 0 ..= 1");
/// ```
pub fn number(min: f64, max: f64) -> impl Fn(&str) -> Result<f64, String> + Clone + Send + Sync {
    move |s: &str| {
        let v: f64 = s
            .trim()
            .parse()
            .ok()
            .filter(|v: &f64| v.is_finite())
            .ok_or_else(|| format!("not a number in {min} ..= {max}"))?;
        if (min..=max).contains(&v) {
            Ok(v)
        } else {
            Err(format!("not in {min} ..= {max}"))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_range_is_inclusive_and_checked_at_both_ends() {
        let p = whole(2u32, 64);
        assert_eq!(p("2"), Ok(2));
        assert_eq!(p("64"), Ok(64));
        assert_eq!(p(" +8 "), Ok(8));
        assert_eq!(p("007"), Ok(7));
        for bad in ["1", "65", "0", "-2", "-0", "99999999999999999999999"] {
            assert_eq!(p(bad).unwrap_err(), "not in 2 ..= 64", "{bad}");
        }
        for bad in [
            "", "+", "-", "1.5", "1e3", "0x10", "sixteen", "1 6", "--3", "+-3",
        ] {
            assert_eq!(
                p(bad).unwrap_err(),
                "not a whole number in 2 ..= 64",
                "{bad}"
            );
        }
    }

    #[test]
    fn minus_zero_is_zero_where_zero_is_allowed() {
        assert_eq!(whole(0u64, 9)("-0"), Ok(0));
        assert_eq!(whole(0u64, 9)("-00"), Ok(0));
        assert_eq!(whole(0u64, 9)("-1").unwrap_err(), "not in 0 ..= 9");
    }

    #[test]
    fn every_unsigned_width_keeps_its_values() {
        assert_eq!(whole(0u8, u8::MAX)("255"), Ok(255u8));
        assert_eq!(whole(0u8, u8::MAX)("256").unwrap_err(), "not in 0 ..= 255");
        assert_eq!(whole(1u16, 1024)("1024"), Ok(1024u16));
        assert_eq!(whole(0u64, u64::MAX)("0"), Ok(0u64));
        let max = u64::MAX.to_string();
        assert_eq!(whole(0u64, u64::MAX)(&max), Ok(u64::MAX));
    }
}
