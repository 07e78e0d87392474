//! The one error type of the core crate.

use core::fmt;

/// Why a core function rejected its input.
///
/// Small and `Copy` so that embedders can match on it; every variant names the parameter.
///
/// ```
/// use nyquist::{sequence::Halton, Error};
/// assert_eq!(Halton::new(0).unwrap_err(), Error::ZeroSize { what: "dims" });
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
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
    /// A finite parameter was outside its documented range.
    OutOfRange {
        /// The parameter.
        what: &'static str,
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
    /// A count or index range does not fit the set (or a `u32`/`u64`/`usize`).
    TooMany {
        /// The parameter.
        what: &'static str,
    },
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::ZeroSize { what } => write!(f, "{what} must be greater than zero"),
            Error::NonFinite { what } => write!(f, "{what} must be finite (got NaN or infinity)"),
            Error::OutOfRange { what } => write!(f, "{what} is out of range"),
            Error::NotInRange {
                what,
                value,
                min,
                max,
            } => write!(f, "{what} {value} is outside {min}..={max}"),
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
            Error::TooMany { what } => write!(f, "{what} is too large"),
        }
    }
}

impl core::error::Error for Error {}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::ToString;

    #[test]
    fn display_names_the_parameter_and_numbers() {
        let e = Error::BufferLength {
            multiple_of: 3,
            actual: 7,
        };
        assert_eq!(
            e.to_string(),
            "buffer length 7 is not a positive multiple of 3"
        );
        let e = Error::DimensionOutOfRange { dim: 9, dims: 2 };
        assert!(e.to_string().contains('9') && e.to_string().contains('2'));
        assert!(
            Error::ZeroSize { what: "dims" }
                .to_string()
                .contains("dims")
        );
    }
}
