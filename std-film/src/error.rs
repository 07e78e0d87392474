//! Errors of the film crate, by category.

use std::fmt;

/// Why a film or image operation failed.
///
/// ```
/// let e = nyquist_film::Error::Config("resolution must be positive".into());
/// assert_eq!(e.to_string(), "invalid configuration: resolution must be positive");
/// ```
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// Reading or writing failed.
    Io(std::io::Error),
    /// A parameter was invalid (resolution, crop window, extension, …).
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
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Io(e) => write!(f, "i/o error: {e}"),
            Error::Config(m) => write!(f, "invalid configuration: {m}"),
            Error::Core(e) => write!(f, "{e}"),
            Error::Format(m) => write!(f, "image format error: {m}"),
            Error::OutOfMemory { what, bytes } => {
                write!(f, "out of memory: {what} needs {bytes} bytes")
            }
        }
    }
}

impl std::error::Error for Error {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Error::Io(e) => Some(e),
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
