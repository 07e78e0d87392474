//! Errors of the film crate, by category.

use std::fmt;
use std::path::PathBuf;

/// Why a film or image operation failed. Each message names the parameter, the value given and
/// what was allowed, or the file.
///
/// ```
/// use nyquist_film::{Film, FilmConfig};
/// let e = Film::new(FilmConfig::new(0, 480), &nyquist::filter::Boxcar::default()).unwrap_err();
/// assert_eq!(e.to_string(), "width 0 is outside 1..=4294967295");
/// ```
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// Reading or writing a stream failed ([`Error::File`] when the stream is a file).
    Io(std::io::Error),
    /// Reading or writing the file at `path` failed.
    File {
        /// The file.
        path: PathBuf,
        /// What the operating system reported.
        source: std::io::Error,
    },
    /// A number was outside its range: `min ..= max` (no upper bound when `max` is infinite).
    OutOfRange {
        /// The parameter.
        what: &'static str,
        /// The value given.
        value: f64,
        /// The smallest value allowed.
        min: f64,
        /// The largest value allowed.
        max: f64,
    },
    /// A parameter was invalid in another way (crop window, extension, tile, image size, …);
    /// the message names it and the values involved.
    Config(String),
    /// The core library rejected a parameter.
    Core(nyquist::Error),
    /// An encoder or decoder rejected the data (PNG, OpenEXR, PFM).
    Format(String),
    /// The allocator could not provide `bytes` bytes for `what` (the film's pixels, an image).
    OutOfMemory {
        /// What the memory was for.
        what: &'static str,
        /// How many bytes were asked for.
        bytes: usize,
    },
    /// [`Film::try_image`](crate::Film::try_image) found film pixels that no merged tile
    /// covered: a tile is missing. [`Film::image`](crate::Film::image) resolves such a film
    /// anyway, when a partial image is what is wanted.
    Incomplete {
        /// Film pixels inside no merged (or held) tile's bounds.
        uncovered: u64,
        /// The film's pixels.
        pixels: u64,
        /// Merged tiles held back because a tile before them in the merge order is missing.
        held: usize,
    },
}

impl Error {
    /// `Error::OutOfRange` for an integer parameter with no upper bound but its type's.
    pub(crate) fn below_one(what: &'static str, value: u64, max: f64) -> Error {
        Error::OutOfRange {
            what,
            value: value as f64,
            min: 1.0,
            max,
        }
    }

    /// This error with `path` named: a stream error becomes [`Error::File`]; others are kept.
    #[cfg(feature = "output")]
    pub(crate) fn at(self, path: &std::path::Path) -> Error {
        match self {
            Error::Io(source) => Error::File {
                path: path.to_path_buf(),
                source,
            },
            e => e,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Io(e) => write!(f, "i/o error: {e}"),
            Error::File { path, source } => write!(f, "{}: {source}", path.display()),
            Error::OutOfRange {
                what,
                value,
                min,
                max,
            } if max.is_infinite() => write!(f, "{what} {value} is outside {min}.."),
            Error::OutOfRange {
                what,
                value,
                min,
                max,
            } => write!(f, "{what} {value} is outside {min}..={max}"),
            Error::Config(m) => write!(f, "invalid configuration: {m}"),
            Error::Core(e) => write!(f, "{e}"),
            Error::Format(m) => write!(f, "image format error: {m}"),
            Error::OutOfMemory { what, bytes } => {
                write!(f, "out of memory: {bytes} bytes for {what}")
            }
            Error::Incomplete {
                uncovered,
                pixels,
                held,
            } => {
                write!(
                    f,
                    "film incomplete: {uncovered} of its {pixels} pixels lie in no merged tile"
                )?;
                if *held > 0 {
                    write!(f, ", and {held} merged tiles wait for a missing one")?;
                }
                write!(
                    f,
                    " (merge every tile, or resolve a partial image with Film::image)"
                )
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io(e) => Some(e),
            Error::File { source, .. } => Some(source),
            Error::Core(e) => Some(e),
            _ => None,
        }
    }
}

impl From<std::io::Error> for Error {
    fn from(e: std::io::Error) -> Self {
        Error::Io(e)
    }
}

impl From<nyquist::Error> for Error {
    fn from(e: nyquist::Error) -> Self {
        Error::Core(e)
    }
}

/// `n` copies of `value` in a new vector, or [`Error::OutOfMemory`] when the allocator refuses
/// (instead of aborting the process): the film's and images' large buffers go through here.
pub(crate) fn try_filled<T: Clone>(
    n: usize,
    value: T,
    what: &'static str,
) -> Result<Vec<T>, Error> {
    let mut v = Vec::new();
    let bytes = n.saturating_mul(size_of::<T>());
    v.try_reserve_exact(n)
        .map_err(|_| Error::OutOfMemory { what, bytes })?;
    v.resize(n, value);
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// Every message carries the numbers or the file it is about.
    #[test]
    fn messages_name_the_value_the_limit_and_the_file() {
        let e = Error::below_one("thread count", 0, f64::INFINITY);
        assert_eq!(e.to_string(), "thread count 0 is outside 1..");
        let e = Error::OutOfRange {
            what: "crop window x0",
            value: 1.5,
            min: 0.0,
            max: 1.0,
        };
        assert_eq!(e.to_string(), "crop window x0 1.5 is outside 0..=1");
        let io = std::io::Error::new(std::io::ErrorKind::NotFound, "gone");
        let e = Error::Io(io).at(Path::new("/no/such/x.png"));
        assert_eq!(e.to_string(), "/no/such/x.png: gone");
        assert!(std::error::Error::source(&e).is_some());
        let e = Error::Incomplete {
            uncovered: 4,
            pixels: 16,
            held: 2,
        };
        assert!(e.to_string().contains("4 of its 16 pixels"), "{e}");
        assert!(e.to_string().contains("2 merged tiles wait"), "{e}");
        let e = Error::Incomplete {
            uncovered: 4,
            pixels: 16,
            held: 0,
        };
        assert_eq!(
            e.to_string(),
            "film incomplete: 4 of its 16 pixels lie in no merged tile (merge every tile, or \
             resolve a partial image with Film::image)"
        );
        // The stream's and the core's errors are the sources of theirs.
        let io = Error::Io(std::io::Error::other("disk"));
        assert_eq!(std::error::Error::source(&io).unwrap().to_string(), "disk");
        let core = Error::Core(nyquist::Error::TooMany {
            what: "points",
            value: 5000,
            max: 4096,
        });
        assert!(std::error::Error::source(&core).is_some());
        assert!(std::error::Error::source(&Error::Config("x".into())).is_none());
        // Errors that carry no stream keep their kind when a path is attached.
        let e = Error::Format("PNG: bad".into()).at(Path::new("x.png"));
        assert!(matches!(e, Error::Format(_)));
    }
}
