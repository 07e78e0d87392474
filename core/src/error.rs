//! The one error type of the core crate.

use core::fmt;

/// Why a core function rejected its input.
///
/// Small and `Copy` so that embedders can match on it. Every variant names the parameter, and
/// every variant about a value carries the value and what was allowed, which `Display` prints:
///
/// ```
/// use nyquist::{sequence::Halton, Error};
/// assert_eq!(Halton::new(0).unwrap_err(), Error::ZeroSize { what: "dims" });
/// assert_eq!(Halton::new(0).unwrap_err().to_string(), "dims must be greater than zero");
/// ```
///
/// Floats in messages are written in their shortest round-trip form, as an `f32` when the
/// value is one (filter parameters are `f32`), with an exponent outside `[1e-5, 1e9)`; `∞` is
/// written `∞`.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A count or size (dims, points, resolution, table size) was zero.
    ZeroSize {
        /// The parameter.
        what: &'static str,
    },
    /// A float parameter was NaN or infinite.
    NonFinite {
        /// The parameter.
        what: &'static str,
    },
    /// A float parameter was outside its documented range.
    ///
    /// ```
    /// use nyquist::{error::Interval, filter::Gaussian, Error};
    /// let e = Gaussian::with_sigma([1.5, 1.5], 1e-30).unwrap_err();
    /// assert_eq!(
    ///     e,
    ///     Error::OutOfRange {
    ///         what: "sigma",
    ///         value: f64::from(1e-30f32),
    ///         range: Interval::closed(f64::from(3.8332338e-20f32), f64::from(6.521909e18f32)),
    ///     }
    /// );
    /// assert_eq!(e.to_string(), "sigma 1e-30 is outside [3.8332338e-20, 6.521909e18]");
    /// ```
    OutOfRange {
        /// The parameter.
        what: &'static str,
        /// The value given (an `f32` parameter widened exactly).
        value: f64,
        /// The values accepted.
        range: Interval,
    },
    /// An integer parameter is outside `min..=max` (a dimension count above what a set has,
    /// for example).
    ///
    /// ```
    /// use nyquist::{sequence::Halton, Error};
    /// let e = Halton::new(2000).unwrap_err();
    /// assert_eq!(e, Error::NotInRange { what: "dims", value: 2000, min: 1, max: 1024 });
    /// assert_eq!(e.to_string(), "dims 2000 is outside 1..=1024");
    /// ```
    NotInRange {
        /// The parameter.
        what: &'static str,
        /// The value given.
        value: u64,
        /// The smallest value accepted.
        min: u64,
        /// The largest value accepted.
        max: u64,
    },
    /// An integer parameter breaks a rule that is not a range, stated against another number
    /// (a multiplier must be coprime to the point count; a table has rows for some sizes only).
    /// `Display` prints `"{what} {value} {rule} {other}"`.
    ///
    /// ```
    /// use nyquist::{lattice::Korobov, Error};
    /// let e = Korobov::new(1024, 190, 4).unwrap_err();
    /// assert_eq!(
    ///     e,
    ///     Error::Invalid { what: "a", value: 190, rule: "is not coprime to n =", other: 1024 }
    /// );
    /// assert_eq!(e.to_string(), "a 190 is not coprime to n = 1024");
    /// ```
    Invalid {
        /// The parameter.
        what: &'static str,
        /// The value given.
        value: u64,
        /// The rule it breaks, worded to be followed by `other`.
        rule: &'static str,
        /// The number the rule is stated against.
        other: u64,
    },
    /// `dim` is not below the number of dimensions the set has.
    DimensionOutOfRange {
        /// The dimension asked for.
        dim: u32,
        /// How many dimensions there are.
        dims: u32,
    },
    /// A buffer's length is not a positive multiple of `multiple_of`.
    BufferLength {
        /// The length must be a positive multiple of this.
        multiple_of: usize,
        /// The length that was passed.
        actual: usize,
    },
    /// A buffer is shorter than needed.
    BufferTooShort {
        /// Elements needed.
        needed: usize,
        /// Elements passed.
        actual: usize,
    },
    /// A count is above what fits: a table, the set, a `u32`/`u64`/`usize`, or the work a
    /// computation allows. Where the limit comes from the product of several counts, `what`
    /// says which count is limited and `max` is its limit given the others.
    ///
    /// ```
    /// use nyquist::{sampler::BestCandidateSampler, Error};
    /// let e = BestCandidateSampler::new(5000, 0).unwrap_err();
    /// assert_eq!(e, Error::TooMany { what: "spp", value: 5000, max: 4096 });
    /// assert_eq!(e.to_string(), "spp 5000 is above 4096");
    /// ```
    TooMany {
        /// The parameter.
        what: &'static str,
        /// The value given (or computed from the parameters).
        value: u64,
        /// The largest value accepted.
        max: u64,
    },
    /// A table or sampler that needs a separable filter was given one whose
    /// [`is_separable`](crate::filter::Filter::is_separable) is `false`.
    ///
    /// ```
    /// use nyquist::filter::{Filter, PhaseTable};
    /// use nyquist::Error;
    /// struct Cone;
    /// impl Filter for Cone {
    ///     fn radius(&self) -> [f32; 2] { [1.0, 1.0] }
    ///     fn eval(&self, x: f32, y: f32) -> f32 { (1.0 - (x * x + y * y).sqrt()).max(0.0) }
    /// }
    /// let e = PhaseTable::new(&Cone).unwrap_err();
    /// assert_eq!(e, Error::NotSeparable { what: "phase table" });
    /// assert_eq!(e.to_string(), "phase table needs a separable filter");
    /// ```
    NotSeparable {
        /// What needs it.
        what: &'static str,
    },
}

/// A range of real numbers, each end included or excluded, as [`Error::OutOfRange`] states
/// it. `Display` writes it in interval notation: `[0, 1]`, `(0, 8)`, `[0, ∞)`.
///
/// ```
/// use nyquist::error::Interval;
/// assert_eq!(Interval::closed(-1000.0, 1000.0).to_string(), "[-1000, 1000]");
/// assert_eq!(Interval::open(0.0, 8.0).to_string(), "(0, 8)");
/// assert_eq!(Interval::at_least(0.0).to_string(), "[0, ∞)");
/// assert_eq!(Interval::above(0.0).to_string(), "(0, ∞)");
/// assert!(Interval::open(0.0, 8.0).contains(7.5) && !Interval::open(0.0, 8.0).contains(8.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// The lower end (`-∞` for none).
    pub min: f64,
    /// The upper end (`∞` for none).
    pub max: f64,
    /// Whether `min` itself is excluded.
    pub min_open: bool,
    /// Whether `max` itself is excluded.
    pub max_open: bool,
}

impl Interval {
    /// `[min, max]`.
    pub const fn closed(min: f64, max: f64) -> Interval {
        Interval {
            min,
            max,
            min_open: false,
            max_open: false,
        }
    }

    /// `(min, max)`.
    pub const fn open(min: f64, max: f64) -> Interval {
        Interval {
            min,
            max,
            min_open: true,
            max_open: true,
        }
    }

    /// `[min, ∞)`.
    pub const fn at_least(min: f64) -> Interval {
        Interval {
            min,
            max: f64::INFINITY,
            min_open: false,
            max_open: true,
        }
    }

    /// `(min, ∞)`.
    pub const fn above(min: f64) -> Interval {
        Interval {
            min,
            max: f64::INFINITY,
            min_open: true,
            max_open: true,
        }
    }

    /// Whether `x` lies in the interval (never for NaN).
    pub fn contains(&self, x: f64) -> bool {
        let above_min = if self.min_open {
            x > self.min
        } else {
            x >= self.min
        };
        let below_max = if self.max_open {
            x < self.max
        } else {
            x <= self.max
        };
        above_min && below_max
    }
}

impl fmt::Display for Interval {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let open = if self.min_open { '(' } else { '[' };
        let close = if self.max_open { ')' } else { ']' };
        write!(f, "{open}{}, {}{close}", Real(self.min), Real(self.max))
    }
}

/// A float as messages write it: shortest round-trip digits, of the `f32` when the value is
/// one; an exponent outside `[1e-5, 1e9)`; `∞` and `NaN` spelled so.
struct Real(f64);

impl fmt::Display for Real {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v.is_nan() {
            return f.write_str("NaN");
        }
        if v.is_infinite() {
            return f.write_str(if v > 0.0 { "∞" } else { "-∞" });
        }
        let plain = v == 0.0 || (1e-5..1e9).contains(&v.abs());
        let single = v as f32;
        match (f64::from(single) == v, plain) {
            (true, true) => write!(f, "{single}"),
            (true, false) => write!(f, "{single:e}"),
            (false, true) => write!(f, "{v}"),
            (false, false) => write!(f, "{v:e}"),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::ZeroSize { what } => write!(f, "{what} must be greater than zero"),
            Error::NonFinite { what } => write!(f, "{what} must be finite (got NaN or infinity)"),
            Error::OutOfRange { what, value, range } => {
                write!(f, "{what} {} is outside {range}", Real(value))
            }
            Error::NotInRange {
                what,
                value,
                min,
                max,
            } => write!(f, "{what} {value} is outside {min}..={max}"),
            Error::Invalid {
                what,
                value,
                rule,
                other,
            } => write!(f, "{what} {value} {rule} {other}"),
            Error::DimensionOutOfRange { dim, dims } => {
                write!(
                    f,
                    "dimension {dim} is out of range: the set has {dims} dimensions"
                )
            }
            Error::BufferLength {
                multiple_of,
                actual,
            } => write!(
                f,
                "buffer length {actual} is not a positive multiple of {multiple_of}"
            ),
            Error::BufferTooShort { needed, actual } => {
                write!(
                    f,
                    "buffer too short: {needed} elements needed, {actual} given"
                )
            }
            Error::TooMany { what, value, max } => write!(f, "{what} {value} is above {max}"),
            Error::NotSeparable { what } => write!(f, "{what} needs a separable filter"),
        }
    }
}

impl core::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::ToString;

    #[test]
    fn display_names_the_parameter_the_value_and_the_limit() {
        let cases = [
            (
                Error::ZeroSize { what: "dims" },
                "dims must be greater than zero",
            ),
            (
                Error::NonFinite { what: "radius" },
                "radius must be finite (got NaN or infinity)",
            ),
            (
                Error::OutOfRange {
                    what: "sigma",
                    value: 1e10,
                    range: Interval::closed(0.0001, 1000.0),
                },
                "sigma 1e10 is outside [0.0001, 1000]",
            ),
            (
                Error::OutOfRange {
                    what: "filter radius",
                    value: 8.0,
                    range: Interval::open(0.0, 8.0),
                },
                "filter radius 8 is outside (0, 8)",
            ),
            (
                Error::OutOfRange {
                    what: "threshold",
                    value: -0.5,
                    range: Interval::at_least(0.0),
                },
                "threshold -0.5 is outside [0, ∞)",
            ),
            (
                Error::OutOfRange {
                    what: "filter radius",
                    value: f64::NAN,
                    range: Interval::above(0.0),
                },
                "filter radius NaN is outside (0, ∞)",
            ),
            (
                Error::NotInRange {
                    what: "dims",
                    value: 2000,
                    min: 1,
                    max: 1024,
                },
                "dims 2000 is outside 1..=1024",
            ),
            (
                Error::Invalid {
                    what: "a",
                    value: 190,
                    rule: "is not coprime to n =",
                    other: 1024,
                },
                "a 190 is not coprime to n = 1024",
            ),
            (
                Error::DimensionOutOfRange { dim: 9, dims: 2 },
                "dimension 9 is out of range: the set has 2 dimensions",
            ),
            (
                Error::BufferLength {
                    multiple_of: 3,
                    actual: 7,
                },
                "buffer length 7 is not a positive multiple of 3",
            ),
            (
                Error::BufferTooShort {
                    needed: 8,
                    actual: 5,
                },
                "buffer too short: 8 elements needed, 5 given",
            ),
            (
                Error::TooMany {
                    what: "count",
                    value: 5000,
                    max: 4096,
                },
                "count 5000 is above 4096",
            ),
            (
                Error::NotSeparable {
                    what: "phase table",
                },
                "phase table needs a separable filter",
            ),
        ];
        for (e, want) in cases {
            assert_eq!(e.to_string(), want, "{e:?}");
        }
    }

    /// Values print as typed: an `f32` widened to `f64` with the `f32`'s digits, an `f64` with
    /// its own, an exponent for very small or large magnitudes.
    #[test]
    fn reals_print_their_shortest_digits() {
        let s = |v: f64| Real(v).to_string();
        assert_eq!(s(f64::from(0.1f32)), "0.1");
        assert_eq!(s(0.1), "0.1");
        assert_eq!(s(f64::from(1.0f32 / 65_536.0)), "0.000015258789");
        assert_eq!(s(f64::from(f32::MIN_POSITIVE)), "1.1754944e-38");
        assert_eq!(s(f64::from(f32::MAX)), "3.4028235e38");
        assert_eq!(s(1e308), "1e308");
        assert_eq!(s(1e9), "1e9");
        assert_eq!(s(999_999_999.0), "999999999");
        assert_eq!(s(1e-5), "0.00001");
        assert_eq!(s(-0.0), "-0");
        assert_eq!(s(f64::NEG_INFINITY), "-∞");
    }

    #[test]
    fn intervals_contain_what_they_print() {
        let closed = Interval::closed(0.0, 1.0);
        assert!(closed.contains(0.0) && closed.contains(1.0) && !closed.contains(1.5));
        let open = Interval::open(0.0, 8.0);
        assert!(!open.contains(0.0) && open.contains(1e-45) && !open.contains(8.0));
        assert!(Interval::at_least(0.0).contains(0.0));
        assert!(!Interval::above(0.0).contains(0.0) && !Interval::above(0.0).contains(f64::NAN));
        assert!(!Interval::above(0.0).contains(f64::INFINITY));
    }
}
